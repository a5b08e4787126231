// The patent's device behind the design variants' common ports (docs/design_space.md,
// "Conventions"): the synchronous variant specular_device_sync with the default
// configuration tied off (patent constants on pins 19/20, carry 34 = 1, clamp, ROM 38's
// patent bank), every operand register loaded with the start, so that the variants'
// one testbench, harness and silicon flow read it as they read the others.
// A start is taken when ready (idle); valid is high for the clock after pass 2's write.
`default_nettype none

module specular_patent #(
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex"
) (
`include "variant_ports.vh"
);
  // The outputs an always block drives (the common ports are wires).
  reg valid_out;
  assign valid = valid_out;
  wire pass1, pass2;
  wire take = start & ready;
  // The observation outputs the wrapper does not read.
  wire unused_select37, unused_done35;
  wire [16:0] unused_reg1;
  wire [36:0] unused_reg9;
  wire [24:0] unused_rom38;

  specular_device_sync #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) device (
    .pin17_cos(cos), .pin18_n(n),
    .pin19_h(18'd128),               // 1/2 on U10.8
    .pin20_a(37'sd4194304),          // 1.0 on S14.22
    .pin21_r(r), .pin22_g(g), .pin23_b(b),
    .pin24_r(out_r), .pin25_g(out_g), .pin26_b(out_b),
    .pin27_start(take), .pin28_clk(clk), .pin29_reset_n(reset_n),
    .pin30_load_n(take), .pin31_load_r(take), .pin32_load_g(take), .pin33_load_b(take),
    .pin34_carry(1'b1), .pin35_done(unused_done35),
    .cfg_literal(1'b0), .cfg_rom38_bank(4'd0),
    .obs_select36(pass2), .obs_write37(unused_select37), .obs_pass1(pass1),
    .obs_reg1_q(unused_reg1), .obs_reg9_q(unused_reg9), .obs_rom38_k(unused_rom38),
    .obs_mul39_norm(lobe));

  // Idle: neither pass running. The result stands from pass 2's write until the next
  // start's first edge, so the next start waits for the clock after valid.
  assign ready = ~pass1 & ~pass2;
  always @(posedge clk)
    valid_out <= reset_n & pass2;
  wire unused_ok = &{1'b0, unused_select37, unused_done35, unused_reg1, unused_reg9, unused_rom38};
endmodule

`default_nettype wire
