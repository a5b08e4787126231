// NAND 47 of Fig. 2: register-9 write strobe 37 = NAND(NAND 45, NAND 46).
`default_nettype none

module nand2 (
  input  wire a,
  input  wire b,
  output wire y
);
  assign y = ~(a & b);
endmodule

`default_nettype wire
