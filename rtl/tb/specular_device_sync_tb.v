// Self-checking Icarus testbench of the synchronous variant (specular_device_sync):
// replays the vectors that `specular_tb --format csv` wrote (the hex columns: register
// 1, register 9 after each pass, pins 24-26) through pins 17-35 with the variant's
// protocol (docs/rtl/sync.md, "The synchronous variant"), as specular_device_tb.v does for
// the drawn device:
//   - start (27), pin 17, and (when n, R, G, B change) pins 18, 21-23 with their loads
//     30-33 are set a quarter period before the start edge (a rising clock edge) and
//     start and the loads fall a quarter period after it: levels sampled at one edge;
//   - starts back to back every 2 T while n, R, G, B are unchanged, 3 T when they change;
//   - register 1 and register 9's pass 1 are checked at the rising edge of select 36,
//     which must come 1 T after start; register 9's pass 2 and pins 24-26 at the rising
//     edge of 35, which must come 2 T after start (35 falls at 1 T);
//   - every RESET_EVERY-th operation is preceded by one aborted by reset (29, synchronous:
//     held low one period) at a quarter-period phase cycling through the operation;
//     after the clock edge inside the reset and after its release 35 must be high and
//     the sequencer idle (pass 1 = select 36 = write 37 = 0), and the next operation
//     correct;
//   - misuse, first: a start held over the edge that ends pass 1 is ignored (register 1
//     keeps its operation's cos λ, 35 rises once, no second operation follows).
// Stops with $fatal (non-zero exit) on the first mismatch. The policy reaches the
// device as the twin's wrapper ties it: pins 19, 20 (CONSTANTS) and the configuration
// inputs cfg_rom38_bank (4 * CONSTANTS + NORMALISATION) and cfg_literal (LITERAL).
`default_nettype none
`timescale 1ns / 1ps

module specular_device_sync_tb;
  `include "specular_device_parameters.vh"  // VECTORS, ROM images, the policy, T, ...
  // (Gate level: select 36 and 35 change a clock-to-Q delay after the clock edge,
  // within EDGE_TOLERANCE.)

  // Default widths (docs/design.md), as specular_tb uses them.
  localparam COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8, MUX4_FRAC = 8;
  localparam COS_W = 1 + COS_FRAC, MUX4_W = N_BITS + MUX4_FRAC;
  localparam REG9_W = 37, REG9_FRAC = 22, OUT_W = 32, ROM38_W = 25, NORM_W = 31;
  localparam ROM38_BANK_BITS = 4;  // bank = 4 * constants + normalisation (twin/rom38_banks.h)
  // The protocol's timing (specular_device_bench.vh): select 36 rises at 1 T, 35 falls at
  // 1 T and rises at 2 T, each read at the next rising clock edge; the sequencer checked
  // idle after the clock edge inside the reset (held low one period) and T/100 after it.
  localparam TB_NAME = "specular_device_sync_tb";
  localparam real SELECT36_AT = 1.0, FALL35_AT = 1.0, RISE35_AT = 2.0;
  localparam SAMPLE_AT_NEXT_EDGE = 1;
  localparam real RESET_CHECK_DURING = T - T / 100, RESET_REST = T / 100, RESET_CHECK_AFTER = T / 100;

  `include "specular_device_bench.vh"  // pins, clock, vectors, monitors, schedule
  wire obs_pass1;

`ifdef GATE_LEVEL
  // The mapped netlist (scripts/flows/synthesis/silicon.sh --top specular_device_sync) with the SDF
  // delays; its ROM macros read their images themselves.
  specular_device_sync dut (
`else
  specular_device_sync #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
`endif
    .obs_pass1(obs_pass1),
    `include "specular_device_ports.vh"
  );

`ifdef GATE_LEVEL
  // Hazard watch at gate level: every transition of pin 35, select 36 and write 37 and
  // the narrowest interval between two transitions of each (a glitch shows as an
  // interval far below T/2; Icarus's cell delays are inertial, so a pulse narrower than
  // the driving cell's delay is filtered as silicon would mostly filter it).
  integer edges35 = 0, edges36 = 0, edges37 = 0;
  real last35 = -1.0, last36 = -1.0, last37 = -1.0;
  real narrowest35 = 1.0e9, narrowest36 = 1.0e9, narrowest37 = 1.0e9;
  always @(pin35_done) if (pin29_reset_n === 1'b1) begin
    if (last35 >= 0 && $realtime - last35 < narrowest35) narrowest35 = $realtime - last35;
    last35 = $realtime;
    edges35 = edges35 + 1;
  end
  always @(obs_select36) if (pin29_reset_n === 1'b1) begin
    if (last36 >= 0 && $realtime - last36 < narrowest36) narrowest36 = $realtime - last36;
    last36 = $realtime;
    edges36 = edges36 + 1;
  end
  always @(obs_write37) if (pin29_reset_n === 1'b1) begin
    if (last37 >= 0 && $realtime - last37 < narrowest37) narrowest37 = $realtime - last37;
    last37 = $realtime;
    edges37 = edges37 + 1;
  end
  task report_pulses;
    $display("specular_device_sync_tb: gate-level transitions: 35 %0d (narrowest interval %f ns), select 36 %0d (%f ns), write 37 %0d (%f ns), T %f ns",
             edges35, narrowest35, edges36, narrowest36, edges37, narrowest37, T);
  endtask
`else
  task report_pulses;
    ;
  endtask
`endif

  // ---- driver ----
  // A start's data, start and loads come a quarter period before its edge.
  function real earliest_start(input real now);
    earliest_start = now + T / 4;
  endfunction

  task expect_idle(input [8*16-1:0] when);
    if (pin35_done !== 1'b1 || obs_pass1 !== 1'b0 || obs_select36 !== 1'b0 || obs_write37 !== 1'b0)
      $fatal(1, "specular_device_sync_tb: sequencer not idle %0s reset at %0t: 35=%b pass1=%b 36=%b 37=%b",
             when, $realtime, pin35_done, obs_pass1, obs_select36, obs_write37);
  endtask

  // Start an operation at `at` (a rising clock edge): start, data and loads a quarter
  // period before; returns at the start edge (the caller lowers start and the loads
  // a quarter period later).
  task raise_start(input real at, input [COS_W-1:0] cos_code, input integer index);
    reg reload;
    begin
      reload = !same_operands(index);
      #(at - T / 4 - $realtime);
      pin17_cos = cos_code;
      if (reload) begin
        pin18_n = v_n[index];
        pin21_r = v_r[index]; pin22_g = v_g[index]; pin23_b = v_b[index];
        {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b1111;
        note_loaded(index);
      end
      pin27_start = 1;
      #(T / 4);
    end
  endtask

  // A quarter period after the start edge: start and the loads fall (their hold time).
  task lower_start;
    begin
      #(T / 4);
      pin27_start = 0;
      {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b0000;
    end
  endtask

  // A start still high at the edge that ends pass 1, with another cos λ on pin 17: the
  // sequencer ignores it (docs/rtl.md).
  task start_in_pass1_ignored;
    real first;
    begin
      first = first_edge_after_quarter($realtime);
      #(first - T / 4 - $realtime);
      pin17_cos = 17'h00123;
      pin27_start = 1;
      #(T / 2);               // T/4 after the start edge: another cos, start still high
      pin17_cos = 17'h04567;
      #(T);                   // T/4 after the edge that ends pass 1
      pin27_start = 0;
      #(0.74 * T);            // just before the next edge: settled at gate level too
      if (obs_reg1_q !== 17'h00123 || obs_select36 !== 1'b1 || obs_pass1 !== 1'b0)
        $fatal(1, "specular_device_sync_tb: a start in pass 1 was not ignored: register 1 %h, 36=%b pass1=%b at %0t",
               obs_reg1_q, obs_select36, obs_pass1, $realtime);
      #(T);
      if (pin35_done !== 1'b1) $fatal(1, "specular_device_sync_tb: 35 not high 2 T after the start at %0t", $realtime);
      expect_idle("after a start in pass 1:");
      #(2 * T);
      expect_idle("after a start in pass 1:");
    end
  endtask

  initial begin
    read_vectors;
    first_reset;
    start_in_pass1_ignored;
    run_operations;
    report_pulses;
    $display("specular_device_sync_tb: PASS %0d operations (%0d back to back at 2 T), %0d resets mid-operation, %0d values checked, %0s",
             count, back_to_back, resets, checks, VECTORS);
    $finish;
  end
endmodule

`default_nettype wire
