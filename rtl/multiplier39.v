// Multiplier 39: register 9 (signed) x ROM 38's K(n) (unsigned), SHIFT fraction bits
// dropped rounding half up, saturated to the norm format (between the two passes
// register 9 holds up to ~16 000; that saturates silently, by design).
// SHIFT = REG9_FRAC + ROM38_FRAC - NORM_FRAC. Same bits as arith::mul39.
`default_nettype none

module multiplier39 #(
  parameter A_W = 37,         // register 9, signed
  parameter K_W = 24,         // ROM 38 word, unsigned
  parameter OUT_W = 31,       // norm format (1 + NORM_INT + NORM_FRAC), signed
  parameter SHIFT = 18
) (
  input  wire [A_W-1:0]   reg9,
  input  wire [K_W-1:0]   k,
  output wire [OUT_W-1:0] norm
);
  localparam PROD_W = A_W + K_W + 1;
  localparam SUM_W = (PROD_W + 1 > SHIFT + OUT_W) ? PROD_W + 1 : SHIFT + OUT_W;

  wire signed [A_W-1:0] a = reg9;
  wire signed [K_W:0] b = {1'b0, k};  // unsigned, one sign bit added
  wire signed [SUM_W-1:0] full = a * b;
  localparam [SUM_W-1:0] BIAS = (SHIFT > 0) ? ({{(SUM_W-1){1'b0}}, 1'b1} << (SHIFT - 1)) : 0;
  wire [SUM_W-1:0] biased = full + BIAS;

  // floor(biased / 2^SHIFT) fits the output when every bit from OUT_W-1 up is a copy
  // of the sign; otherwise saturate to the format's minimum or maximum code.
  wire [SUM_W-SHIFT-OUT_W:0] above = biased[SUM_W-1:SHIFT+OUT_W-1];
  wire in_range = (above == {(SUM_W-SHIFT-OUT_W+1){1'b0}}) ||
                  (above == {(SUM_W-SHIFT-OUT_W+1){1'b1}});
  wire negative = biased[SUM_W-1];
  assign norm = in_range ? biased[SHIFT +: OUT_W]
                         : (negative ? {1'b1, {(OUT_W-1){1'b0}}} : {1'b0, {(OUT_W-1){1'b1}}});

  generate
    if (SHIFT > 0) begin : dropped
      wire unused_ok = &{1'b0, biased[SHIFT-1:0]};
    end
  endgenerate
endmodule

`default_nettype wire
