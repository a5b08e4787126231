// The design variants' common ports (docs/design_space/flow.md, "Conventions (every variant follows them)"), written once:
// every top here opens with `module specular_NAME #(...) (` followed by
// `include "variant_ports.vh"`. One result per start; what differs between the tops is
// only when a start is taken (ready) and how many clocks later valid rises.
// Compile with this folder on the include path (-I rtl/design_space).
  input  wire               clk,
  input  wire               reset_n,   // synchronous, active low
  input  wire               start,     // operands valid; taken at a rising edge while ready
  output wire               ready,
  input  wire [16:0]        cos,       // register 1's code, U1.16
  input  wire [9:0]         n,
  input  wire [7:0]         r, g, b,
  output wire               valid,     // one clock per result, in start order: lobe and out_* hold it
  output wire signed [30:0] lobe,      // K(n)*cos^n, multiplier 39's format S10.20
  output wire signed [31:0] out_r, out_g, out_b  // pins 24-26, S18.13
