// One pass, two ROMs, pipelined (issue 26, docs/variants/one_pass.md): specular_one_pass
// cut into stages so that the clock is set by one pass, not by two passes and the tail.
//   edge 1  operand registers 1, 2, 10-12 (with every start)
//   edge 2  pass 1's sum                       (ROM 5, multiplier 6, inverter 7, adder 8)
//   edge 3  pass 2's sum (register 9's A)
//   edge 4  ROM 38's K(n) and multiplier 39's K·A
//   edge 5  multipliers 13-15 into the output registers; valid
// Multipliers 39 and 13-15 get a stage each: together they are longer than a pass.
// A start is taken on every clock (ready is always 1); each result is valid five clocks
// after its start, in order. n and the intensities ride along to ROM 38 and multipliers 13-15.
// The configuration is a build-time parameter set; the defaults are the patent's
// (specular_patent.v): h = 1/2 on U10.8, a = 1.0 on S14.22, clamp, ROM 38 bank 0.
`default_nettype none

module specular_one_pass_pipelined #(
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex",
  parameter [17:0] H19 = 18'd128,         // pin 19: h on U10.8
  parameter [36:0] A20 = 37'd4194304,     // pin 20: a on S14.22
  parameter LITERAL = 0,                  // 1: Saturation::literal, 0: clamp
  parameter [3:0] ROM38_BANK = 4'd0       // ROM 38 bank: the Normalisation enum value
) (
`include "variant_ports.vh"
);
  // The outputs an always block drives (the common ports are wires).
  reg valid_out;
  assign valid = valid_out;
  // The default widths (docs/design.md) and the formats derived from them.
  localparam COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8, MUX4_FRAC = 8;
  localparam REG9_INT = 14, REG9_FRAC = 22, ROM38_INT = 9, ROM38_FRAC = 16;
  localparam NORM_INT = 10, NORM_FRAC = 20, OUT_INT = 18, OUT_FRAC = 13;
  localparam COS_W = 1 + COS_FRAC, REG9_W = 1 + REG9_INT + REG9_FRAC;
  localparam ROM38_W = ROM38_INT + ROM38_FRAC, NORM_W = 1 + NORM_INT + NORM_FRAC;
  localparam OUT_W = 1 + OUT_INT + OUT_FRAC, RGB_W = 3 * RGB_BITS;

  assign ready = 1'b1;  // one result per clock: nothing to wait for

  // Stage valid flags: stage s holds a start's values after edge s.
  reg valid1_q, valid2_q, valid3_q, valid4_q;
  always @(posedge clk) begin
    valid1_q <= reset_n & start;
    valid2_q <= reset_n & valid1_q;
    valid3_q <= reset_n & valid2_q;
    valid4_q <= reset_n & valid3_q;
    valid_out    <= reset_n & valid4_q;
  end

  // Stage 1: operand registers 1, 2, 10-12, loaded with every start.
  wire [COS_W-1:0]  reg1_q;
  wire [N_BITS-1:0] reg2_q;
  wire [RGB_W-1:0]  rgb1_q;
  register_enable #(.W(COS_W))  reg1  (.clk(clk), .enable(start), .d(cos),       .q(reg1_q));
  register_enable #(.W(N_BITS)) reg2  (.clk(clk), .enable(start), .d(n),         .q(reg2_q));
  register_enable #(.W(RGB_W))  reg10_12 (.clk(clk), .enable(start), .d({r, g, b}), .q(rgb1_q));

  // Stage 2: pass 1 (what multiplexers 3/4 give at select 36 = 0): a - n·log2 cos.
  wire [REG9_W-1:0] pass1_sum, pass1_q;
  wire [N_BITS-1:0] n2_q;
  wire [RGB_W-1:0]  rgb2_q;
  pass_datapath #(.ROM5_IMAGE(ROM5_IMAGE)) pass1 (
    .literal(LITERAL != 0), .address({{(REG9_W-COS_W-REG9_FRAC+COS_FRAC){1'b0}}, reg1_q,
                                      {(REG9_FRAC-COS_FRAC){1'b0}}}),
    .operand({reg2_q, {MUX4_FRAC{1'b0}}}), .a20(A20), .carry34(1'b1), .sum(pass1_sum));
  register_enable #(.W(REG9_W)) pass1_reg (.clk(clk), .enable(valid1_q), .d(pass1_sum), .q(pass1_q));
  register_enable #(.W(N_BITS)) n2_reg    (.clk(clk), .enable(valid1_q), .d(reg2_q),    .q(n2_q));
  register_enable #(.W(RGB_W))  rgb2_reg  (.clk(clk), .enable(valid1_q), .d(rgb1_q),    .q(rgb2_q));

  // Stage 3: pass 2 on its own ROM 5 (select 36 = 1): a - h·log2(pass 1) = register 9's A.
  wire [REG9_W-1:0] pass2_sum, reg9_q;
  wire [N_BITS-1:0] n3_q;
  wire [RGB_W-1:0]  rgb3_q;
  pass_datapath #(.ROM5_IMAGE(ROM5_IMAGE)) pass2 (
    .literal(LITERAL != 0), .address(pass1_q), .operand(H19), .a20(A20), .carry34(1'b1),
    .sum(pass2_sum));
  register_enable #(.W(REG9_W)) reg9     (.clk(clk), .enable(valid2_q), .d(pass2_sum), .q(reg9_q));
  register_enable #(.W(N_BITS)) n3_reg   (.clk(clk), .enable(valid2_q), .d(n2_q),      .q(n3_q));
  register_enable #(.W(RGB_W))  rgb3_reg (.clk(clk), .enable(valid2_q), .d(rgb2_q),    .q(rgb3_q));

  // Stage 4: ROM 38's K(n) and multiplier 39, K(n)·A (ROM 38's access and multiplier 39
  // together are shorter than a pass: n rides along, 10 bits instead of K's 25).
  wire [ROM38_W-1:0] rom38_k;
  wire [NORM_W-1:0]  mul39_norm, norm4_q;
  wire [RGB_W-1:0]   rgb4_q;
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(4), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(ROM38_BANK), .reg2(n3_q), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W),
                 .SHIFT(REG9_FRAC + ROM38_FRAC - NORM_FRAC)) mul39 (
    .reg9(reg9_q), .k(rom38_k), .norm(mul39_norm));
  register_enable #(.W(NORM_W)) norm4_reg (.clk(clk), .enable(valid3_q), .d(mul39_norm), .q(norm4_q));
  register_enable #(.W(RGB_W))  rgb4_reg  (.clk(clk), .enable(valid3_q), .d(rgb3_q),     .q(rgb4_q));

  // Stage 5: multipliers 13-15 into the output registers, held until the next result.
  wire [OUT_W-1:0] mul13_r, mul14_g, mul15_b;
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul13 (
    .norm(norm4_q), .intensity(rgb4_q[2*RGB_BITS +: RGB_BITS]), .out(mul13_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul14 (
    .norm(norm4_q), .intensity(rgb4_q[RGB_BITS +: RGB_BITS]), .out(mul14_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul15 (
    .norm(norm4_q), .intensity(rgb4_q[0 +: RGB_BITS]), .out(mul15_b));
  register_enable #(.W(NORM_W)) lobe_reg  (.clk(clk), .enable(valid4_q), .d(norm4_q), .q(lobe));
  register_enable #(.W(OUT_W))  out_r_reg (.clk(clk), .enable(valid4_q), .d(mul13_r), .q(out_r));
  register_enable #(.W(OUT_W))  out_g_reg (.clk(clk), .enable(valid4_q), .d(mul14_g), .q(out_g));
  register_enable #(.W(OUT_W))  out_b_reg (.clk(clk), .enable(valid4_q), .d(mul15_b), .q(out_b));
endmodule

`default_nettype wire
