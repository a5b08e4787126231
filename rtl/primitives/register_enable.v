// A data register of the synchronous variant (specular_device_sync): every flip-flop on
// the rising edge of the one clock (pin 28); the write strobe of Fig. 1 (pin 27, 30-33,
// or the sequencer's write 37) becomes a clock enable sampled at that edge. No reset,
// as the patent's data registers (register.v): defined from the first write on.
`default_nettype none

module register_enable #(
  parameter W = 8
) (
  input  wire         clk,
  input  wire         enable,  // sampled at the rising clock edge: 1 captures d
  input  wire [W-1:0] d,
  output reg  [W-1:0] q
);
  always @(posedge clk)
    if (enable)
      q <= d;
endmodule

`default_nettype wire
