// Control unit 16 (Fig. 2) exactly as drawn: three D flip-flops and five gates sequence
// the two passes (spec section 3, modules/src/control/control_unit16.cpp):
//   inv44 = NOT clk;  and40 = rst_n AND nand45 -> R of 41
//   dff41: C = start, D = 1;  dff42: C = inv44, D = Q41;  dff43: C = inv44, D = Q42
//   nand45 = NAND(/Q43, Q42, clk);  nand46 = NAND(clk, /Q42, Q43)
//   nand47 = NAND(nand45, nand46);  36 = Q43, 37 = nand47, 35 = nand46
// Not a re-timed state machine: a data pin (start) clocks 41, the inverted clock clocks
// 42 and 43, and the write strobe 37 is a gated clock (docs/rtl.md says what that means
// and what a synchronous variant would change). The S inputs are tied to logic 1 as in
// the figure but present.
`default_nettype none

module control_unit16 (
  input  wire start,      // input 1 <- pin 27
  input  wire clk,        // input 2 <- pin 28
  input  wire reset_n,    // input 3 <- pin 29
  output wire select36,   // output 1: multiplexers 3 and 4 (Q43)
  output wire write37,    // output 2: register 9 write strobe (NAND 47)
  output wire done35,     // output 3 -> pin 35 (NAND 46)
  // observation of Fig. 2's nets for harnesses and checkers
  output wire obs_q41,
  output wire obs_q42,
  output wire obs_nand45
);
  wire logic_one = 1'b1;  // the "logic 1" source of Fig. 2
  wire and40_y, inv44_y, nand45_y;
  wire q41, q42, q42_n, q43_n;
  wire unused_q41_n;      // /Q41 is not used in Fig. 2

  inverter inv44 (.a(clk), .y(inv44_y));
  and2     and40 (.a(reset_n), .b(nand45_y), .y(and40_y));

  d_flip_flop dff41 (.d(logic_one), .c(start),   .s_n(logic_one), .r_n(and40_y),
                     .q(q41), .q_n(unused_q41_n));
  d_flip_flop dff42 (.d(q41),       .c(inv44_y), .s_n(logic_one), .r_n(reset_n),
                     .q(q42), .q_n(q42_n));
  d_flip_flop dff43 (.d(q42),       .c(inv44_y), .s_n(logic_one), .r_n(reset_n),
                     .q(select36), .q_n(q43_n));

  nand3 nand45 (.a(q43_n), .b(q42),   .c(clk),      .y(nand45_y));
  nand3 nand46 (.a(clk),   .b(q42_n), .c(select36), .y(done35));
  nand2 nand47 (.a(nand45_y), .b(done35), .y(write37));

  assign obs_q41 = q41;
  assign obs_q42 = q42;
  assign obs_nand45 = nand45_y;
endmodule

`default_nettype wire
