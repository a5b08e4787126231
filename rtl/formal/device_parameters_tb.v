// Prints the parameters specular_device passes multipliers 6, 39 and 13 at the widths
// given by the macros ROM5_WORD_BITS and REG9_FRAC, in the form rtl/formal/CMakeLists.txt
// lists them, so check_parameters.cmake can prove the formal tests use the device's
// widths. Not synthesizable: a testbench for Icarus.
`default_nettype none

module device_parameters_tb;
  specular_device #(.ROM5_WORD_BITS(`ROM5_WORD_BITS), .REG9_FRAC(`REG9_FRAC)) dut (
    .pin17_cos(), .pin18_n(), .pin19_h(), .pin20_a(), .pin21_r(), .pin22_g(), .pin23_b(),
    .pin24_r(), .pin25_g(), .pin26_b(), .pin27_start(), .pin28_clk(), .pin29_reset_n(),
    .pin30_load_n(), .pin31_load_r(), .pin32_load_g(), .pin33_load_b(), .pin34_carry(),
    .pin35_done(), .cfg_literal(), .cfg_rom38_bank(), .obs_select36(), .obs_write37(),
    .obs_q41(), .obs_q42(), .obs_nand45(), .obs_reg1_q(), .obs_reg9_q(), .obs_rom38_k(),
    .obs_mul39_norm());
  initial begin
    $display("multiplier6 LOG2_W=%0d,OPERAND_W=%0d,OUT_W=%0d,SHIFT=%0d",
             dut.mul6.LOG2_W, dut.mul6.OPERAND_W, dut.mul6.OUT_W, dut.mul6.SHIFT);
    $display("multiplier39 A_W=%0d,K_W=%0d,OUT_W=%0d,SHIFT=%0d",
             dut.mul39.A_W, dut.mul39.K_W, dut.mul39.OUT_W, dut.mul39.SHIFT);
    $display("multiplier_rgb NORM_W=%0d,RGB_BITS=%0d,OUT_W=%0d,SHIFT=%0d",
             dut.mul13.NORM_W, dut.mul13.RGB_BITS, dut.mul13.OUT_W, dut.mul13.SHIFT);
    $finish;
  end
endmodule

`default_nettype wire
