// Combinational adder 8: pin 20 (1.0) + inverted product + carry-in 34 = 1 - product,
// modulo the bus width. Under the clamp policy (literal = 0) a negative sum saturates
// at 0 (spec, Decision). Same bits as arith::adder8.
`default_nettype none

module adder8 #(
  parameter W = 37
) (
  input  wire         literal,   // configuration: 1 = Saturation::literal, 0 = clamp
  input  wire [W-1:0] a20,
  input  wire [W-1:0] inverted,
  input  wire         carry34,
  output wire [W-1:0] sum
);
  wire [W-1:0] raw = a20 + inverted + {{(W-1){1'b0}}, carry34};
  assign sum = (!literal && raw[W-1]) ? {W{1'b0}} : raw;
endmodule

`default_nettype wire
