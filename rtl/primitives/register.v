// Registers 1, 2, 9, 10, 11, 12 of Fig. 1: one bus captured on the rising edge of its
// write strobe (pin 27, 30-33, or control-unit output 37). No reset: the patent gives
// the data registers none, so equivalence with the SystemC model is claimed from the
// first write on (docs/rtl.md).
`default_nettype none

module register #(
  parameter W = 8
) (
  input  wire         load,  // write strobe: rising edge captures d
  input  wire [W-1:0] d,
  output reg  [W-1:0] q
);
  always @(posedge load)
    q <= d;
endmodule

`default_nettype wire
