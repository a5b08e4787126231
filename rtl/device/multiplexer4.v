// Multiplexer 4: multiplier 6's second operand on the U(N_BITS).FRAC bus.
// in0 = register 2 (n) shifted to the bus's fraction, in1 = pin 19 (the constant 1/2).
// Same bits as arith::mux4.
`default_nettype none

module multiplexer4 #(
  parameter N_BITS = 10,
  parameter FRAC = 1          // the bus's fraction bits (MUX4_FRAC)
) (
  input  wire                   select36,
  input  wire [N_BITS-1:0]      reg2,
  input  wire [N_BITS+FRAC-1:0] h19,
  output wire [N_BITS+FRAC-1:0] operand
);
  assign operand = select36 ? h19 : {reg2, {FRAC{1'b0}}};
endmodule

`default_nettype wire
