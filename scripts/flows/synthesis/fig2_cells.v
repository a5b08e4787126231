// Fig. 2's gates as OSU 0.18 um library cells, read by scripts/flows/synthesis/silicon.sh over the
// behavioural leaf modules of rtl/ (read_verilog -overwrite): one library cell per gate
// and flip-flop of the figure, so ABC never rewrites the control unit and the timing
// analysis is of the circuit as drawn. The library's DFFSR has no /Q output: /Q42 and
// /Q43 come from an inverter each (ABC maps `~q` to INVX1; /Q41 is unused and removed).
`default_nettype none

module inverter (input wire a, output wire y);  // inverter 44
  INVX1 cell (.A(a), .Y(y));
endmodule

module and2 (input wire a, input wire b, output wire y);  // AND 40
  AND2X1 cell (.A(a), .B(b), .Y(y));
endmodule

module nand3 (input wire a, input wire b, input wire c, output wire y);  // NANDs 45, 46
  NAND3X1 cell (.A(a), .B(b), .C(c), .Y(y));
endmodule

module nand2 (input wire a, input wire b, output wire y);  // NAND 47
  NAND2X1 cell (.A(a), .B(b), .Y(y));
endmodule

module d_flip_flop (input wire d, input wire c, input wire s_n, input wire r_n,
                    output wire q, output wire q_n);  // flip-flops 41, 42, 43
  DFFSR cell (.CLK(c), .D(d), .S(s_n), .R(r_n), .Q(q));
  assign q_n = ~q;
endmodule

`default_nettype wire
