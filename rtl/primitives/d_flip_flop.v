// D flip-flops 41, 42, 43 of Fig. 2: rising edge of C, asynchronous active-low reset R
// and set S, R wins when both are low (as control/d_flip_flop.cpp). No initial value:
// the control unit is defined from reset (pin 29) on.
`default_nettype none

module d_flip_flop (
  input  wire d,
  input  wire c,
  input  wire s_n,
  input  wire r_n,
  output reg  q,
  output wire q_n
);
  always @(posedge c or negedge r_n or negedge s_n)
    if (!r_n)
      q <= 1'b0;
    else if (!s_n)
      q <= 1'b1;
    else
      q <= d;
  assign q_n = ~q;
endmodule

`default_nettype wire
