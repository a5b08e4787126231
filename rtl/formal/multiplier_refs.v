// Behavioural references for the formal equivalence of multipliers 6, 39 and 13–15
// (rtl/formal/CMakeLists.txt): the arithmetic of docs/design.md §4 written the plain way,
// independently of rtl/multiplier*.v: the exact product on 64 signed bits, plus half an
// LSB, arithmetic shift right (floor: round half up), then wrap (multiplier 6) or clamp
// to the output format's range (39, 13–15). 64 bits hold every product at the default
// widths (at most 37 + 25 = 62 bits). With `BREAK_ROUNDING defined the bias is left
// out, so the miter must fail: the proof can tell a wrong reference from a right one.
`default_nettype none

`ifdef BREAK_ROUNDING
  `define HALF_LSB(shift) (64'sd0)
`else
  `define HALF_LSB(shift) (64'sd1 <<< ((shift) - 1))
`endif

module multiplier6_ref #(
  parameter LOG2_W = 28, parameter OPERAND_W = 11, parameter OUT_W = 37, parameter SHIFT = 1
) (
  input  wire [LOG2_W-1:0]    log2,     // signed
  input  wire [OPERAND_W-1:0] operand,  // unsigned
  output wire [OUT_W-1:0]     product   // wraps
);
  wire signed [63:0] exact = $signed(log2) * $signed({1'b0, operand});
  wire signed [63:0] rounded = (exact + `HALF_LSB(SHIFT)) >>> SHIFT;
  assign product = rounded[OUT_W-1:0];
endmodule

// Round half up, then saturate to a signed OUT_W-bit code: multipliers 39 and 13–15.
// Each module stands alone (no parameterised submodule), so a script that reads it
// needs no `hierarchy` pass to derive parameters.
module multiplier39_ref #(
  parameter A_W = 37, parameter K_W = 24, parameter OUT_W = 31, parameter SHIFT = 18
) (
  input  wire [A_W-1:0]   reg9,   // signed
  input  wire [K_W-1:0]   k,      // unsigned
  output wire [OUT_W-1:0] norm    // saturates
);
  localparam signed [63:0] MAX = (64'sd1 <<< (OUT_W - 1)) - 64'sd1;
  localparam signed [63:0] MIN = -(64'sd1 <<< (OUT_W - 1));
  wire signed [63:0] exact = $signed(reg9) * $signed({1'b0, k});
  wire signed [63:0] rounded = (exact + `HALF_LSB(SHIFT)) >>> SHIFT;
  wire signed [63:0] clamped = rounded > MAX ? MAX : (rounded < MIN ? MIN : rounded);
  assign norm = clamped[OUT_W-1:0];
endmodule

module multiplier_rgb_ref #(
  parameter NORM_W = 31, parameter RGB_BITS = 8, parameter OUT_W = 32, parameter SHIFT = 7
) (
  input  wire [NORM_W-1:0]   norm,       // signed
  input  wire [RGB_BITS-1:0] intensity,  // unsigned
  output wire [OUT_W-1:0]    out         // saturates
);
  localparam signed [63:0] MAX = (64'sd1 <<< (OUT_W - 1)) - 64'sd1;
  localparam signed [63:0] MIN = -(64'sd1 <<< (OUT_W - 1));
  wire signed [63:0] exact = $signed(norm) * $signed({1'b0, intensity});
  wire signed [63:0] rounded = (exact + `HALF_LSB(SHIFT)) >>> SHIFT;
  wire signed [63:0] clamped = rounded > MAX ? MAX : (rounded < MIN ? MIN : rounded);
  assign out = clamped[OUT_W-1:0];
endmodule

`undef HALF_LSB
`default_nettype wire
