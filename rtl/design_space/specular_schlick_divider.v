// Variant schlick_divider (issue 26, docs/variants/schlick.md) behind the common ports
// (docs/design_space/flow.md, "Conventions (every variant follows them)"): Schlick's x / (n - (n-1)*x) as variant
// schlick, the quotient by a restoring divider (one bit per clock) instead of a
// reciprocal table and multipliers: the smallest datapath, 24 clocks per result.
//   start edge: d = n*2^16 - (n-1)*cos (schlick_denominator) and the divider's first
//               step; n, R, G, B into their registers
//   23 more edges: one quotient bit each; the last writes register 9 =
//               (floor(cos*2^23/d) + 1) / 2 = x/d rounded half up to S14.22
// then the device's tail (ROM 38, multiplier 39, multipliers 13-15) from register 9.
// Same bits as specular::variants::SchlickDivider.
`default_nettype none

module specular_schlick_divider #(
  parameter ROM38_IMAGE = "rom38.hex",
  parameter [3:0] ROM38_BANK = 4'd0    // 4*constants + normalisation: 0 patent, 1 energy, 2 none
) (
`include "variant_ports.vh"
);
  // The outputs an always block drives (the common ports are wires).
  reg valid_out;
  assign valid = valid_out;
  localparam COS_W = 17, COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8;
  localparam D_W = 26;                 // d as U10.16
  localparam Q_BITS = 24;              // floor(x/d * 2^23): 2^0 .. 2^-23
  localparam REG9_W = 37, REG9_FRAC = 22;
  localparam ROM38_W = 25, NORM_W = 31, OUT_W = 32;

  wire busy, last;
  wire [Q_BITS-1:0] quotient;
  assign ready = ~busy;
  wire take = start & ready;

  wire [D_W-1:0] denominator;
  schlick_denominator #(.COS_FRAC(COS_FRAC), .N_BITS(N_BITS)) denom (.cos(cos), .n(n), .d(denominator));
  restoring_divider #(.D_W(D_W), .Q_BITS(Q_BITS)) divider (
    .clk(clk), .reset_n(reset_n), .load(take),
    .a({{(D_W-COS_W){1'b0}}, cos}), .d(denominator),
    .busy(busy), .last(last), .quotient(quotient));

  // Operands for the tail, then the result registers: the outputs hold while the next
  // operation runs.
  reg [N_BITS-1:0] n_q, n_result_q;
  reg [3*RGB_BITS-1:0] rgb_q, rgb_result_q;
  reg [REG9_W-1:0] reg9_q;
  wire [Q_BITS:0] rounded = {1'b0, quotient} + 1'b1;   // + 2^-23: half up
  always @(posedge clk) begin
    if (take) begin
      n_q <= n;
      rgb_q <= {r, g, b};
    end
    if (last) begin
      reg9_q <= {{(REG9_W-REG9_FRAC-1){1'b0}}, rounded[REG9_FRAC+1:1]};  // <= 2^22
      n_result_q <= n_q;
      rgb_result_q <= rgb_q;
    end
    valid_out <= reset_n & last;
  end

  wire [ROM38_W-1:0] rom38_k;
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(4), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(ROM38_BANK), .reg2(n_result_q), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W), .SHIFT(18)) mul39 (
    .reg9(reg9_q), .k(rom38_k), .norm(lobe));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul13 (
    .norm(lobe), .intensity(rgb_result_q[3*RGB_BITS-1 -: RGB_BITS]), .out(out_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul14 (
    .norm(lobe), .intensity(rgb_result_q[2*RGB_BITS-1 -: RGB_BITS]), .out(out_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W), .SHIFT(7)) mul15 (
    .norm(lobe), .intensity(rgb_result_q[RGB_BITS-1:0]), .out(out_b));

  // The rounded quotient is at most 2^22 (x <= d): the bit above 1.0 is always 0, the
  // rounding bit is dropped.
  wire unused_ok = &{1'b0, rounded[Q_BITS], rounded[0]};
endmodule

`default_nettype wire
