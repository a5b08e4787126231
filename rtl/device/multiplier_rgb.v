// Multipliers 13, 14, 15: multiplier 39's K*A (signed) x an intensity (register 10, 11
// or 12, unsigned), SHIFT fraction bits dropped rounding half up, saturated to the
// output pins' format: the shared primitive multiply_round_saturate.v at their widths.
// SHIFT = NORM_FRAC - OUT_FRAC. Same bits as arith::mul_rgb.
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
  multiply_round_saturate #(.A_W(NORM_W), .B_W(RGB_BITS), .OUT_W(OUT_W), .SHIFT(SHIFT)) mul (
    .a(norm),
    .b(intensity),
    .out(out)
  );
endmodule

`default_nettype wire
