// Variant exp2 behind the design variants' common ports (docs/design_space.md,
// "Conventions"; docs/variants/exp2.md): cos^n as a GPU's pow computes it, 2^(n·log2 cos).
// ROM 5's log2 of register 1 times n as multiplier 6 does in pass 1 (no adder 8), the
// exp2 unit (table + linear interpolation, the integer part a shift) to cos^n on register
// 9's format, then ROM 38, multiplier 39 and multipliers 13-15 as in the device.
// A zero cos code gives cos^n = 0 (a shader's pow(0, n): log2 0 = -infinity).
//
// Pipeline, one result per clock: a start is taken at every edge (ready from the clock
// after reset); stage 0 holds the operands, stage 1 x = n·log2 cos, stage 2 cos^n, and
// the outputs with valid 3 clocks after the start's edge.
`default_nettype none

module specular_exp2 #(
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex", EXP2_IMAGE = "exp2.hex"
) (
`include "variant_ports.vh"
);
  // The outputs an always block drives (the common ports are wires).
  reg ready_out;
  reg valid_out;
  reg signed [30:0] lobe_out;
  reg signed [31:0] out_r_out, out_g_out, out_b_out;
  assign ready = ready_out;
  assign valid = valid_out;
  assign lobe = lobe_out;
  assign out_r = out_r_out;
  assign out_g = out_g_out;
  assign out_b = out_b_out;
  // The device's default widths (docs/design.md).
  localparam COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8;
  localparam ROM5_ADDR_BITS = 15, ROM5_WORD_BITS = 22;
  localparam REG9_INT = 14, REG9_FRAC = 22, MUX4_FRAC = 8;
  localparam ROM38_INT = 9, ROM38_FRAC = 16, ROM38_BANK_BITS = 4;
  localparam NORM_FRAC = 20, OUT_FRAC = 13;
  localparam COS_W = 1 + COS_FRAC;
  localparam LOG2_INT = $clog2((REG9_FRAC > REG9_INT ? REG9_FRAC : REG9_INT) + 1);
  localparam LOG2_W = 1 + LOG2_INT + ROM5_WORD_BITS;  // S5.22, as format.cpp sizes it
  localparam REG9_W = 1 + REG9_INT + REG9_FRAC;
  localparam ROM38_W = ROM38_INT + ROM38_FRAC;
  localparam NORM_W = 31, OUT_W = 32;
  localparam MUX4_W = N_BITS + MUX4_FRAC;
  localparam MUL6_SHIFT = ROM5_WORD_BITS + MUX4_FRAC - REG9_FRAC;
  localparam MUL39_SHIFT = REG9_FRAC + ROM38_FRAC - NORM_FRAC;
  localparam RGB_SHIFT = NORM_FRAC - OUT_FRAC;
  localparam [ROM38_BANK_BITS-1:0] PATENT_BANK = 0;  // constants patent, normalisation patent

  wire take = start & ready_out;
  always @(posedge clk)
    ready_out <= reset_n;

  // Stage 0: the operand registers (register 1, 2, 10-12), loaded by a start.
  reg [COS_W-1:0]    cos0;
  reg [N_BITS-1:0]   n0;
  reg [RGB_BITS-1:0] r0, g0, b0;
  reg                valid0;
  always @(posedge clk) begin
    valid0 <= reset_n & take;
    if (take) begin
      cos0 <= cos; n0 <= n; r0 <= r; g0 <= g; b0 <= b;
    end
  end

  // Stage 1: x = n·log2 cos on register 9's format (ROM 5, multiplier 6: pass 1's product).
  wire [REG9_W-1:0] rom5_bus = {{(REG9_W-COS_W){1'b0}}, cos0} << (REG9_FRAC - COS_FRAC);
  wire [LOG2_W-1:0] rom5_log2;
  wire [REG9_W-1:0] mul6_x;
  rom5 #(.ADDR_BITS(ROM5_ADDR_BITS), .WORD_BITS(ROM5_WORD_BITS), .BUS_W(REG9_W),
         .BUS_FRAC(REG9_FRAC), .COS_FRAC(COS_FRAC), .LOG2_W(LOG2_W),
         .IMAGE(ROM5_IMAGE)) rom5 (
    .bus(rom5_bus), .log2(rom5_log2));
  multiplier6 #(.LOG2_W(LOG2_W), .OPERAND_W(MUX4_W), .OUT_W(REG9_W),
                .SHIFT(MUL6_SHIFT)) mul6 (
    .log2(rom5_log2), .operand({n0, {MUX4_FRAC{1'b0}}}), .product(mul6_x));

  reg [REG9_W-1:0]   x1;
  reg                zero1;
  reg [N_BITS-1:0]   n1;
  reg [RGB_BITS-1:0] r1, g1, b1;
  reg                valid1;
  always @(posedge clk) begin
    valid1 <= reset_n & valid0;
    x1 <= mul6_x; zero1 <= (cos0 == {COS_W{1'b0}});
    n1 <= n0; r1 <= r0; g1 <= g0; b1 <= b0;
  end

  // Stage 2: cos^n = 2^x on register 9's format (0 for a zero cos code).
  wire [REG9_W-1:0] exp2_pow2;
  exp2_unit #(.X_W(REG9_W), .X_FRAC(REG9_FRAC), .OUT_W(REG9_W), .OUT_FRAC(REG9_FRAC),
              .IMAGE(EXP2_IMAGE)) exp2 (
    .x(x1), .pow2(exp2_pow2));

  reg [REG9_W-1:0]   cosn2;
  reg [N_BITS-1:0]   n2;
  reg [RGB_BITS-1:0] r2, g2, b2;
  reg                valid2;
  always @(posedge clk) begin
    valid2 <= reset_n & valid1;
    cosn2 <= zero1 ? {REG9_W{1'b0}} : exp2_pow2;
    n2 <= n1; r2 <= r1; g2 <= g1; b2 <= b1;
  end

  // Stage 3: ROM 38 -> multiplier 39 -> multipliers 13-15, into the output registers.
  wire [ROM38_W-1:0] rom38_k;
  wire [NORM_W-1:0]  mul39_norm;
  wire [OUT_W-1:0]   mul13_r, mul14_g, mul15_b;
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(ROM38_BANK_BITS),
          .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(PATENT_BANK), .reg2(n2), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W), .SHIFT(MUL39_SHIFT)) mul39 (
    .reg9(cosn2), .k(rom38_k), .norm(mul39_norm));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul13 (
    .norm(mul39_norm), .intensity(r2), .out(mul13_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul14 (
    .norm(mul39_norm), .intensity(g2), .out(mul14_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul15 (
    .norm(mul39_norm), .intensity(b2), .out(mul15_b));

  // Outputs hold until the next valid.
  always @(posedge clk) begin
    valid_out <= reset_n & valid2;
    if (valid2) begin
      lobe_out <= mul39_norm; out_r_out <= mul13_r; out_g_out <= mul14_g; out_b_out <= mul15_b;
    end
  end
endmodule

`default_nettype wire
