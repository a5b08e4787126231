// One pass, two ROMs (issue 26, docs/variants/one_pass.md): the patent's arithmetic with
// its loop unrolled. Pass 1 (ROM 5, multipliers 6, inverter 7, adder 8 on cos and n) and
// pass 2 (a second set of the same blocks on pass 1's sum and h) run in series, then the
// device's tail (ROM 38, multiplier 39, multipliers 13-15): one combinational path from
// the operand registers into the output registers. No multiplexer 3/4 and no sequencer:
// a start is taken on every clock (ready is always 1), its result is valid two clocks
// later (edge 1 loads the operands, edge 2 the outputs).
// The configuration is a build-time parameter set; the defaults are the patent's
// (specular_patent.v): h = 1/2 on U10.8, a = 1.0 on S14.22, clamp, ROM 38 bank 0.
`default_nettype none

module specular_one_pass #(
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
  localparam OUT_W = 1 + OUT_INT + OUT_FRAC;

  assign ready = 1'b1;  // one result per clock: nothing to wait for

  // Operand registers 1, 2, 10-12: loaded with every start.
  wire [COS_W-1:0]    reg1_q;
  wire [N_BITS-1:0]   reg2_q;
  wire [RGB_BITS-1:0] reg10_q, reg11_q, reg12_q;
  reg                 loaded_q;  // registers 1, 2, 10-12 hold a start's operands
  register_enable #(.W(COS_W))    reg1  (.clk(clk), .enable(start), .d(cos), .q(reg1_q));
  register_enable #(.W(N_BITS))   reg2  (.clk(clk), .enable(start), .d(n),   .q(reg2_q));
  register_enable #(.W(RGB_BITS)) reg10 (.clk(clk), .enable(start), .d(r),   .q(reg10_q));
  register_enable #(.W(RGB_BITS)) reg11 (.clk(clk), .enable(start), .d(g),   .q(reg11_q));
  register_enable #(.W(RGB_BITS)) reg12 (.clk(clk), .enable(start), .d(b),   .q(reg12_q));

  // Pass 1 (what multiplexers 3/4 give at select 36 = 0): a - n·log2 cos.
  wire [REG9_W-1:0] pass1_sum, pass2_sum;
  pass_datapath #(.ROM5_IMAGE(ROM5_IMAGE)) pass1 (
    .literal(LITERAL != 0), .address({{(REG9_W-COS_W-REG9_FRAC+COS_FRAC){1'b0}}, reg1_q,
                                      {(REG9_FRAC-COS_FRAC){1'b0}}}),
    .operand({reg2_q, {MUX4_FRAC{1'b0}}}), .a20(A20), .carry34(1'b1), .sum(pass1_sum));
  // Pass 2 on its own ROM 5 (select 36 = 1): a - h·log2(pass 1) = register 9's A.
  pass_datapath #(.ROM5_IMAGE(ROM5_IMAGE)) pass2 (
    .literal(LITERAL != 0), .address(pass1_sum), .operand(H19), .a20(A20), .carry34(1'b1),
    .sum(pass2_sum));

  // The device's tail: ROM 38 -> multiplier 39 -> multipliers 13-15.
  wire [ROM38_W-1:0] rom38_k;
  wire [NORM_W-1:0]  mul39_norm;
  wire [OUT_W-1:0]   mul13_r, mul14_g, mul15_b;
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(4), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(ROM38_BANK), .reg2(reg2_q), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W),
                 .SHIFT(REG9_FRAC + ROM38_FRAC - NORM_FRAC)) mul39 (
    .reg9(pass2_sum), .k(rom38_k), .norm(mul39_norm));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul13 (
    .norm(mul39_norm), .intensity(reg10_q), .out(mul13_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul14 (
    .norm(mul39_norm), .intensity(reg11_q), .out(mul14_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(NORM_FRAC - OUT_FRAC)) mul15 (
    .norm(mul39_norm), .intensity(reg12_q), .out(mul15_b));

  // Output registers: loaded the clock after a start, held until the next result.
  register_enable #(.W(NORM_W)) lobe_reg  (.clk(clk), .enable(loaded_q), .d(mul39_norm), .q(lobe));
  register_enable #(.W(OUT_W))  out_r_reg (.clk(clk), .enable(loaded_q), .d(mul13_r), .q(out_r));
  register_enable #(.W(OUT_W))  out_g_reg (.clk(clk), .enable(loaded_q), .d(mul14_g), .q(out_g));
  register_enable #(.W(OUT_W))  out_b_reg (.clk(clk), .enable(loaded_q), .d(mul15_b), .q(out_b));

  always @(posedge clk) begin
    loaded_q <= reset_n & start;
    valid_out <= reset_n & loaded_q;
  end
endmodule

`default_nettype wire
