// A squarer: y² for y in U1.FRAC (0 <= y <= 1), FRAC fraction bits dropped rounding half
// up: the shared primitive multiply_round_saturate.v with both operands y (y² <= 1, so
// it never saturates). Design variant us5739820 squares its base k times with one of
// these. Same bits as arith::square.
`default_nettype none

module squarer #(
  parameter FRAC = 30
) (
  input  wire [FRAC:0] y,
  output wire [FRAC:0] square
);
  wire [FRAC+1:0] product;  // signed U1.FRAC: its sign bit is 0
  multiply_round_saturate #(.A_W(FRAC + 2), .B_W(FRAC + 1), .OUT_W(FRAC + 2), .SHIFT(FRAC)) mul (
    .a({1'b0, y}),
    .b(y),
    .out(product)
  );
  assign square = product[FRAC:0];
  wire unused_ok = &{1'b0, product[FRAC+1]};
endmodule

`default_nettype wire
