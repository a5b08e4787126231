// Inverter 44 of Fig. 2: its output clocks flip-flops 42 and 43 on the clock's falling
// edge.
`default_nettype none

module inverter (
  input  wire a,
  output wire y
);
  assign y = ~a;
endmodule

`default_nettype wire
