// Multiplexer 3: ROM 5's address bus. in0 = register 1 (cos, U1.COS_FRAC) aligned to
// register 9's format by a left shift; in1 = register 9. Select = control output 36.
// Same bits as arith::mux3.
`default_nettype none

module multiplexer3 #(
  parameter COS_W = 17,      // register 1 width (1 + COS_FRAC)
  parameter REG9_W = 37,     // bus width (1 + REG9_INT + REG9_FRAC)
  parameter ALIGN = 6        // REG9_FRAC - COS_FRAC
) (
  input  wire              select36,
  input  wire [COS_W-1:0]  reg1,
  input  wire [REG9_W-1:0] reg9,
  output wire [REG9_W-1:0] address
);
  wire [REG9_W-1:0] reg1_aligned = {{(REG9_W-COS_W){1'b0}}, reg1} << ALIGN;
  assign address = select36 ? reg9 : reg1_aligned;
endmodule

`default_nettype wire
