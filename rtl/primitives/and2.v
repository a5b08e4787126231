// AND 40 of Fig. 2: reset of flip-flop 41 = reset pin 29 AND NAND 45.
`default_nettype none

module and2 (
  input  wire a,
  input  wire b,
  output wire y
);
  assign y = a & b;
endmodule

`default_nettype wire
