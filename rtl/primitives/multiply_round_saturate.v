// What multiplier 39 and multipliers 13–15 share, as arith::multiply_round_saturate on
// the SystemC side: a signed A_W-bit code times an unsigned B_W-bit code, SHIFT
// fraction bits dropped rounding half up (floor of product + 2^(SHIFT-1)), saturated
// to a signed OUT_W-bit code (the format's minimum or maximum when the rounded value
// does not fit). SHIFT >= 0.
`default_nettype none

module multiply_round_saturate #(
  parameter A_W = 37,         // signed operand
  parameter B_W = 24,         // unsigned operand
  parameter OUT_W = 31,       // the output format (1 + INT + FRAC), signed
  parameter SHIFT = 18        // fraction bits dropped
) (
  input  wire [A_W-1:0]   a,
  input  wire [B_W-1:0]   b,
  output wire [OUT_W-1:0] out
);
  // Wide enough for the exact product, its rounding bias and the kept bits.
  localparam PROD_W = A_W + B_W + 1;
  localparam SUM_W = (PROD_W + 1 > SHIFT + OUT_W) ? PROD_W + 1 : SHIFT + OUT_W;

  wire signed [A_W-1:0] a_signed = a;
  wire signed [B_W:0] b_signed = {1'b0, b};  // unsigned, one sign bit added
  wire signed [SUM_W-1:0] full = a_signed * b_signed;
  localparam [SUM_W-1:0] BIAS = (SHIFT > 0) ? ({{(SUM_W-1){1'b0}}, 1'b1} << (SHIFT - 1)) : 0;
  wire [SUM_W-1:0] biased = full + BIAS;

  // floor(biased / 2^SHIFT) fits the output when every bit from OUT_W-1 up is a copy
  // of the sign; otherwise saturate to the format's minimum or maximum code.
  wire [SUM_W-SHIFT-OUT_W:0] above = biased[SUM_W-1:SHIFT+OUT_W-1];
  wire in_range = (above == {(SUM_W-SHIFT-OUT_W+1){1'b0}}) ||
                  (above == {(SUM_W-SHIFT-OUT_W+1){1'b1}});
  wire negative = biased[SUM_W-1];
  assign out = in_range ? biased[SHIFT +: OUT_W]
                        : (negative ? {1'b1, {(OUT_W-1){1'b0}}} : {1'b0, {(OUT_W-1){1'b1}}});

  generate
    if (SHIFT > 0) begin : dropped
      wire unused_ok = &{1'b0, biased[SHIFT-1:0]};
    end
  endgenerate
endmodule

`default_nettype wire
