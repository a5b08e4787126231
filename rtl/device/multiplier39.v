// Multiplier 39: register 9 (signed) x ROM 38's K(n) (unsigned), SHIFT fraction bits
// dropped rounding half up, saturated to the norm format: the shared primitive
// multiply_round_saturate.v at multiplier 39's widths (between the two passes register
// 9 holds up to ~16 000; that saturates silently, by design).
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
  multiply_round_saturate #(.A_W(A_W), .B_W(K_W), .OUT_W(OUT_W), .SHIFT(SHIFT)) mul (
    .a(reg9),
    .b(k),
    .out(norm)
  );
endmodule

`default_nettype wire
