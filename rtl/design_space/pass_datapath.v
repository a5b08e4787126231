// One pass of Fig. 1 without the multiplexers: ROM 5 -> multiplier 6 -> inverter 7 ->
// adder 8, from an address bus and an operand already chosen. The patent visits this
// path twice through multiplexers 3 and 4; a one-pass design instantiates it twice in
// series (pass 1: cos and n; pass 2: pass 1's sum and h). Same bits as arith::pass for
// the select 36 whose operands the caller wires in (arith::mux3, arith::mux4).
`default_nettype none

module pass_datapath #(
  parameter COS_FRAC = 16, N_BITS = 10,
  parameter ROM5_ADDR_BITS = 15, ROM5_WORD_BITS = 22,
  parameter REG9_INT = 14, REG9_FRAC = 22,
  parameter MUX4_FRAC = 8,
  parameter ROM5_IMAGE = "rom5.hex"
) (
  input  wire                           literal,   // 1: Saturation::literal, 0: clamp
  input  wire [REG9_INT+REG9_FRAC:0]    address,   // multiplexer 3's bus: cos aligned, or a sum
  input  wire [N_BITS+MUX4_FRAC-1:0]    operand,   // multiplexer 4's bus: n or h
  input  wire [REG9_INT+REG9_FRAC:0]    a20,       // the constant a (pin 20)
  input  wire                           carry34,
  output wire [REG9_INT+REG9_FRAC:0]    sum        // adder 8: a - operand * log2(address)
);
  // Derived widths, as specular_device_sync derives them (format.cpp).
  localparam LOG2_INT = $clog2((REG9_FRAC > REG9_INT ? REG9_FRAC : REG9_INT) + 1);
  localparam LOG2_W = 1 + LOG2_INT + ROM5_WORD_BITS;
  localparam REG9_W = 1 + REG9_INT + REG9_FRAC;
  localparam MUX4_W = N_BITS + MUX4_FRAC;
  localparam MUL6_SHIFT = ROM5_WORD_BITS + MUX4_FRAC - REG9_FRAC;

  wire [LOG2_W-1:0] rom5_log2;
  wire [REG9_W-1:0] mul6_product, inv7_inverted;

  rom5 #(.ADDR_BITS(ROM5_ADDR_BITS), .WORD_BITS(ROM5_WORD_BITS), .BUS_W(REG9_W),
         .BUS_FRAC(REG9_FRAC), .COS_FRAC(COS_FRAC), .LOG2_W(LOG2_W),
         .IMAGE(ROM5_IMAGE)) rom5 (
    .bus(address), .log2(rom5_log2));
  multiplier6 #(.LOG2_W(LOG2_W), .OPERAND_W(MUX4_W), .OUT_W(REG9_W),
                .SHIFT(MUL6_SHIFT)) mul6 (
    .log2(rom5_log2), .operand(operand), .product(mul6_product));
  inverter7 #(.W(REG9_W)) inv7 (.product(mul6_product), .inverted(inv7_inverted));
  adder8 #(.W(REG9_W)) adder8 (
    .literal(literal), .a20(a20), .inverted(inv7_inverted), .carry34(carry34), .sum(sum));
endmodule

`default_nettype wire
