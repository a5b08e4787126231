// Inverter block 7: bitwise NOT of multiplier 6's product; with carry-in 34 it makes
// adder 8 subtract (two's complement). Same bits as arith::inv7.
`default_nettype none

module inverter7 #(
  parameter W = 37
) (
  input  wire [W-1:0] product,
  output wire [W-1:0] inverted
);
  assign inverted = ~product;
endmodule

`default_nettype wire
