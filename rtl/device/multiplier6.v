// Multiplier 6: ROM 5's log2 (signed) x multiplexer 4's operand (unsigned, n or 1/2),
// SHIFT fraction bits dropped rounding half up, wrapped to adder 8's bus width.
// SHIFT = ROM5_WORD_BITS + MUX4_FRAC - REG9_FRAC. Same bits as arith::mul6.
`default_nettype none

module multiplier6 #(
  parameter LOG2_W = 28,      // ROM 5 output, signed
  parameter OPERAND_W = 11,   // multiplexer 4 output, unsigned
  parameter OUT_W = 37,       // adder 8 / register 9 bus
  parameter SHIFT = 1
) (
  input  wire [LOG2_W-1:0]    log2,
  input  wire [OPERAND_W-1:0] operand,
  output wire [OUT_W-1:0]     product
);
  // Wide enough for the exact product, its rounding bias and the kept bits.
  localparam PROD_W = LOG2_W + OPERAND_W + 1;
  localparam SUM_W = (PROD_W + 1 > SHIFT + OUT_W) ? PROD_W + 1 : SHIFT + OUT_W;

  wire signed [LOG2_W-1:0] a = log2;
  wire signed [OPERAND_W:0] b = {1'b0, operand};  // unsigned, one sign bit added
  wire signed [SUM_W-1:0] full = a * b;

  generate
    if (SHIFT > 0) begin : round
      localparam [SUM_W-1:0] ONE = 1;
      wire [SUM_W-1:0] biased = full + (ONE << (SHIFT - 1));
      // Bits SHIFT .. SHIFT+OUT_W-1 of product + bias: floor((p + bias) / 2^SHIFT)
      // modulo 2^OUT_W, i.e. round half up, then wrap.
      assign product = biased[SHIFT +: OUT_W];
      wire unused_ok = &{1'b0, biased[SHIFT-1:0], biased[SUM_W-1:SHIFT+OUT_W-1]};
    end else begin : widen
      wire [SUM_W-1:0] shifted = full << (-SHIFT);
      assign product = shifted[OUT_W-1:0];
      wire unused_ok = &{1'b0, shifted[SUM_W-1:OUT_W-1]};
    end
  endgenerate
endmodule

`default_nettype wire
