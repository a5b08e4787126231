// Variant schlick (issue 26, docs/variants/schlick.md) behind the common ports
// (docs/design_space/flow.md, "Conventions (every variant follows them)"): cos^n by Schlick's rational approximation
// x / (n - (n-1)*x) instead of the patent's two log2 passes, then the device's own tail
// (ROM 38, multiplier 39, multipliers 13-15). A pipeline: a start on every clock; a
// start taken at edge t is in register 9 at edge t+2, valid in the clock after it.
//   stage 1: d = n*2^16 - (n-1)*cos (U10.16, exact), normalised by a leading-one detector
//   stage 2: y1 ~ 2^26/m by reciprocal_nr (1024-word table, one Newton-Raphson step)
//   stage 3: register 9 = cos*y1 / 2^(msb+4), rounded half up: x/d as S14.22
// Same bits as specular::variants::Schlick.
`default_nettype none

module specular_schlick #(
  parameter ROM38_IMAGE = "rom38.hex", RECIP_IMAGE = "recip.hex",
  parameter [3:0] ROM38_BANK = 4'd0    // 4*constants + normalisation: 0 patent, 1 energy, 2 none
) (
`include "variant_ports.vh"
);
  localparam COS_W = 17, COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8;
  localparam D_W = 26, POS_W = 5;      // d as U10.16 and a bit index of it
  localparam RECIP_FRAC = 26;          // y1, U0.26
  localparam REG9_W = 37, REG9_FRAC = 22;
  localparam QUOT_W = COS_W + RECIP_FRAC + 1;  // cos*y1 and its rounding bias
  localparam ROM38_W = 25, NORM_W = 31, OUT_W = 32;

  assign ready = 1'b1;                 // a pipeline: never busy

  // ---- stage 1: the denominator and its normalisation, from the sampled operands ----
  wire [D_W-1:0] denominator;
  schlick_denominator #(.COS_FRAC(COS_FRAC), .N_BITS(N_BITS)) denom (.cos(cos), .n(n), .d(denominator));
  wire [POS_W-1:0] d_msb;
  wire [D_W-1:0] d_normalised;
  leading_one_normaliser #(.W(D_W)) lod (.x(denominator), .msb(d_msb), .normalised(d_normalised));

  reg             v1_q, v2_q, v3_q;
  reg [D_W-1:0]   m1_q;
  reg [POS_W-1:0] msb1_q, msb2_q;
  reg [COS_W-1:0] cos1_q, cos2_q;
  reg [N_BITS-1:0] n1_q, n2_q, n3_q;
  reg [3*RGB_BITS-1:0] rgb1_q, rgb2_q, rgb3_q;
  always @(posedge clk) begin
    v1_q <= reset_n & start;
    m1_q <= d_normalised;
    msb1_q <= d_msb;
    cos1_q <= cos;
    n1_q <= n;
    rgb1_q <= {r, g, b};
  end

  // ---- stage 2: the reciprocal of the mantissa ----
  wire [RECIP_FRAC-1:0] y1;
  reciprocal_nr #(.IMAGE(RECIP_IMAGE)) recip (.mantissa(m1_q), .y1(y1));
  reg [RECIP_FRAC-1:0] y1_q;
  always @(posedge clk) begin
    v2_q <= reset_n & v1_q;
    y1_q <= y1;
    msb2_q <= msb1_q;
    cos2_q <= cos1_q;
    n2_q <= n1_q;
    rgb2_q <= rgb1_q;
  end

  // ---- stage 3: register 9 = x/d = cos*y1 * 2^(22 - msb - 26), rounded half up ----
  wire [QUOT_W-1:0] cos_y1 = {{(QUOT_W-COS_W){1'b0}}, cos2_q} * {{(QUOT_W-RECIP_FRAC){1'b0}}, y1_q};
  wire [POS_W:0] shift = {1'b0, msb2_q} + (RECIP_FRAC - REG9_FRAC);  // 20 .. 29
  wire [QUOT_W-1:0] half = {{(QUOT_W-1){1'b0}}, 1'b1} << (shift - 1'b1);
  wire [QUOT_W-1:0] quotient = (cos_y1 + half) >> shift;   // <= 2^22: x/d <= 1
  reg [REG9_W-1:0] reg9_q;
  always @(posedge clk) begin
    v3_q <= reset_n & v2_q;
    if (v2_q) begin                    // the outputs hold until the next result
      reg9_q <= {{(REG9_W-REG9_FRAC-1){1'b0}}, quotient[REG9_FRAC:0]};
      n3_q <= n2_q;
      rgb3_q <= rgb2_q;
    end
  end
  assign valid = v3_q;

  // ---- the device's tail: ROM 38, multiplier 39, multipliers 13-15 ----
  wire [ROM38_W-1:0] rom38_k;
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(4), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(ROM38_BANK), .reg2(n3_q), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W), .SHIFT(18)) mul39 (
    .reg9(reg9_q), .k(rom38_k), .norm(lobe));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul13 (
    .norm(lobe), .intensity(rgb3_q[3*RGB_BITS-1 -: RGB_BITS]), .out(out_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul14 (
    .norm(lobe), .intensity(rgb3_q[2*RGB_BITS-1 -: RGB_BITS]), .out(out_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul15 (
    .norm(lobe), .intensity(rgb3_q[RGB_BITS-1:0]), .out(out_b));

  // The quotient's bits above 1.0 are zero (x <= d); the detector's msb >= 16.
  wire unused_ok = &{1'b0, quotient[QUOT_W-1:REG9_FRAC+1]};
endmodule

`default_nettype wire
