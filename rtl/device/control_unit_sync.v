// The synchronous control unit of specular_device_sync, replacing Fig. 2's flip-flops
// 41-43 and gates 44-47 (docs/rtl/sync.md, "The synchronous variant"): one clock (pin 28),
// every flip-flop on its rising edge, reset (29) synchronous and active low, start (27)
// a level sampled at the edge, no gated clock and no falling-edge state change.
//   sequencer: idle -> pass 1 -> pass 2 -> idle, one-hot in pass1_q / pass2_q (idle:
//     both 0). Start is accepted in idle and in pass 2 (the next operation's pass 1
//     follows the current one's pass 2 directly: one result every 2 T); a start in
//     pass 1 is ignored (the operation in flight keeps register 1).
//   select 36 = pass2_q (multiplexers 3 and 4 take register 9 and pin 19).
//   write 37  = pass1_q | pass2_q: register 9's clock enable; it captures pass 1 at the
//     edge that ends pass 1 and pass 2 at the edge that ends pass 2.
//   done 35   = done_q, its own flip-flop: low while pass 2 runs, so it falls 1 T and
//     rises 2 T after the start edge, with register 9's pass-2 write; high when idle.
//   load 1    = start accepted: register 1's clock enable.
`default_nettype none

module control_unit_sync (
  input  wire clk,        // pin 28
  input  wire reset_n,    // pin 29, synchronous
  input  wire start,      // pin 27, a level sampled at the rising edge
  output wire load1,      // register 1's clock enable
  output wire select36,   // multiplexers 3 and 4
  output wire write37,    // register 9's clock enable
  output wire done35,     // pin 35, registered
  output wire obs_pass1   // the sequencer's pass-1 state, for harnesses and checkers
);
  reg pass1_q, pass2_q, done_q;
  wire accept = start & ~pass1_q;

  always @(posedge clk)
    if (!reset_n) begin
      pass1_q <= 1'b0;
      pass2_q <= 1'b0;
      done_q <= 1'b1;
    end else begin
      pass1_q <= accept;
      pass2_q <= pass1_q;
      done_q <= ~pass1_q;  // low exactly while pass2_q is high
    end

  assign load1 = accept;
  assign select36 = pass2_q;
  assign write37 = pass1_q | pass2_q;
  assign done35 = done_q;
  assign obs_pass1 = pass1_q;
endmodule

`default_nettype wire
