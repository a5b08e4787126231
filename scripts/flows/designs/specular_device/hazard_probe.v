// Fig. 2's hazards measured in the gate-level simulation (scripts/flows/gatelevel/gatesim.sh, compiled
// beside rtl/tb/specular_device_tb.v as a second top; docs/silicon.md, hazards). It
// reads the mapped control unit's nets by name (scripts/flows/synthesis/fig2_cells.v keeps
// them; gatesim_sdf.py turns the dots of escaped names into "__") and prints one
// HAZARD line at the end:
//   - select 36 (flip-flop 43) after clk's falling edge: the delay the SDF annotates
//     (DFFSR CLK->Q into select 36's load), min and max;
//   - the reset pulse of flip-flop 41 (AND 40's output, R of DFFSR 41): pulses, the
//     narrowest, and whether Q41 was low after each;
//   - recovery margin: the shortest time from R's release to the next start (27) rise;
//     removal margin: the shortest time from a start rise to the next R release;
//   - setup margin of flip-flop 42: the shortest time from Q41's rise to inverter 44's
//     rising output (the falling clk edge that takes Q41 into 42);
//   - register 9's D (adder 8's sum) settling in pass 2: its latest change between the
//     clk fall at which select 36 rises and the next rising edge (strobe 37's second
//     write), measured from that fall: the longest select-36 path the vectors
//     sensitise, to hold against STA's pass-2 path (no load strobe falls in that half
//     period, so nothing else moves D there).
`timescale 1ns / 1ps
module hazard_probe;
  wire clk = specular_device_tb.pin28_clk;
  wire start = specular_device_tb.pin27_start;
  wire select36 = specular_device_tb.dut.cu16.\dff43__q ;
  wire r41 = specular_device_tb.dut.cu16.\and40__y ;
  wire q41 = specular_device_tb.dut.cu16.\dff41__q ;
  wire clk42 = specular_device_tb.dut.cu16.\dff42__c ;
  wire [36:0] reg9_d = specular_device_tb.dut.adder8_sum;

  real t_clk_fall = -1.0, t_r_fall = -1.0, t_r_rise = -1.0, t_start = -1.0, t_q41 = -1.0;
  real sel_min = 1.0e9, sel_max = -1.0, r_narrowest = 1.0e9, r_widest = -1.0;
  real recovery = 1.0e9, removal = 1.0e9, setup42 = 1.0e9, settle = 0.0;
  integer sel_rises = 0, r_pulses = 0, r_not_cleared = 0;

  always @(negedge clk) t_clk_fall = $realtime;
  always @(posedge select36) if (t_clk_fall >= 0) begin
    sel_rises = sel_rises + 1;
    if ($realtime - t_clk_fall < sel_min) sel_min = $realtime - t_clk_fall;
    if ($realtime - t_clk_fall > sel_max) sel_max = $realtime - t_clk_fall;
  end
  // Reset pulses of flip-flop 41 made by NAND 45 -> AND 40 while pin 29 is high (pin
  // 29's own resets are the testbench's, not Fig. 2's pulse).
  always @(negedge r41) t_r_fall = specular_device_tb.pin29_reset_n === 1'b1 ? $realtime : -1.0;
  always @(posedge r41) begin
    if (t_r_fall >= 0) begin
      r_pulses = r_pulses + 1;
      if ($realtime - t_r_fall < r_narrowest) r_narrowest = $realtime - t_r_fall;
      if ($realtime - t_r_fall > r_widest) r_widest = $realtime - t_r_fall;
      if (q41 !== 1'b0) r_not_cleared = r_not_cleared + 1;
      if (t_start >= 0 && $realtime - t_start < removal) removal = $realtime - t_start;
      t_r_rise = $realtime;
    end
    t_r_fall = -1.0;
  end
  always @(posedge start) begin
    t_start = $realtime;
    if (t_r_rise >= 0 && $realtime - t_r_rise < recovery) recovery = $realtime - t_r_rise;
  end
  always @(posedge q41) t_q41 = $realtime;
  reg pass2_phase = 1'b0;
  always @(posedge select36) pass2_phase = 1'b1;
  always @(posedge clk) pass2_phase = 1'b0;
  always @(reg9_d) if (pass2_phase && clk === 1'b0 && $realtime - t_clk_fall > settle)
    settle = $realtime - t_clk_fall;
  always @(posedge clk42) if (q41 === 1'b1 && t_q41 >= 0 && $realtime - t_q41 < setup42)
    setup42 = $realtime - t_q41;

  // The testbench calls $finish after its PASS line; a final block would need SV, so
  // print on every PASS-time event instead: at the end of the run (the testbench's
  // watchdog is far later), once the testbench has counted its operations.
  initial begin
    wait (specular_device_tb.done_seen > 0);
    forever begin
      @(specular_device_tb.done_seen);
      $display("HAZARD select36_after_clk_fall_ns %.4f %.4f rises %0d reset41_pulses %0d narrowest_ns %.4f widest_ns %.4f not_cleared %0d recovery_margin_ns %.4f removal_margin_ns %.4f setup42_margin_ns %.4f reg9_d_settle_ns %.4f",
               sel_min, sel_max, sel_rises, r_pulses, r_narrowest, r_widest, r_not_cleared,
               recovery, removal, setup42, settle);
    end
  end
endmodule
