// The device as the AXI4-Lite proof sees it (rtl/formal/axi_lite_bmc.cmake): the
// interface of specular_device_sync with every output free at every cycle. The adapter's
// handshakes and its operation timing (op_pass1, op_pass2, op_result) never read the
// device's outputs, so proving them against any output is sound, and it keeps the
// multipliers and ROMs, which stall z3, out of the model.
`default_nettype none

module specular_device_sync #(
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex"
) (
  input  wire [16:0]        pin17_cos,
  input  wire [9:0]         pin18_n,
  input  wire [17:0]        pin19_h,
  input  wire signed [36:0] pin20_a,
  input  wire [7:0]         pin21_r, pin22_g, pin23_b,
  output wire signed [31:0] pin24_r, pin25_g, pin26_b,
  input  wire pin27_start, pin28_clk, pin29_reset_n,
  input  wire pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b, pin34_carry,
  output wire pin35_done,
  input  wire cfg_literal,
  input  wire [3:0] cfg_rom38_bank,
  output wire obs_select36, obs_write37, obs_pass1,
  output wire [16:0]        obs_reg1_q,
  output wire signed [36:0] obs_reg9_q,
  output wire [24:0]        obs_rom38_k,
  output wire signed [30:0] obs_mul39_norm
);
  (* anyseq *) reg [31:0] r24, r25, r26;
  (* anyseq *) reg [2:0] bits;
  (* anyseq *) reg [16:0] reg1;
  (* anyseq *) reg [36:0] reg9;
  (* anyseq *) reg [24:0] k;
  (* anyseq *) reg [30:0] norm;
  assign pin24_r = r24;
  assign pin25_g = r25;
  assign pin26_b = r26;
  assign {pin35_done, obs_select36, obs_write37} = bits;
  assign obs_pass1 = 1'b0;
  assign obs_reg1_q = reg1;
  assign obs_reg9_q = reg9;
  assign obs_rom38_k = k;
  assign obs_mul39_norm = norm;
endmodule

`default_nettype wire
