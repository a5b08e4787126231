// NANDs 45 and 46 of Fig. 2: decode the pass-1 and pass-2 write windows from Q42, Q43
// and the clock.
`default_nettype none

module nand3 (
  input  wire a,
  input  wire b,
  input  wire c,
  output wire y
);
  assign y = ~(a & b & c);
endmodule

`default_nettype wire
