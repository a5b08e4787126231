// Multipliers 13, 14, 15: multiplier 39's K*A (signed) x an intensity (register 10, 11
// or 12, unsigned), SHIFT fraction bits dropped rounding half up, saturated to the
// output pins' format. SHIFT = NORM_FRAC - OUT_FRAC. Same bits as arith::mul_rgb.
`default_nettype none

module multiplier_rgb #(
  parameter NORM_W = 31,      // multiplier 39 output, signed
  parameter RGB_BITS = 8,     // register 10/11/12, unsigned
  parameter OUT_W = 32,       // pins 24-26 (1 + OUT_INT + OUT_FRAC), signed
  parameter SHIFT = 7
) (
  input  wire [NORM_W-1:0]   norm,
  input  wire [RGB_BITS-1:0] intensity,
  output wire [OUT_W-1:0]    out
);
  localparam PROD_W = NORM_W + RGB_BITS + 1;
  localparam SUM_W = (PROD_W + 1 > SHIFT + OUT_W) ? PROD_W + 1 : SHIFT + OUT_W;

  wire signed [NORM_W-1:0] a = norm;
  wire signed [RGB_BITS:0] b = {1'b0, intensity};  // unsigned, one sign bit added
  wire signed [SUM_W-1:0] full = a * b;
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
