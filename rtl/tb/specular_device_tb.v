// Self-checking Icarus testbench of the RTL device: replays the vectors that
// `specular_tb --format csv` wrote (the hex columns: register 1, register 9 after each
// pass, pins 24-26) through pins 17-35 with the protocol of spec section 3 and
// modules/include/specular/device_harness.h:
//   - data (pin 17, and pins 18, 21-23 with their strobes 30-33 when n, R, G, B change)
//     a quarter period before the start edge; strobes fall at the start edge;
//   - start (27) rises with a rising clock edge, falls half a period later;
//   - starts back to back every 2 T while n, R, G, B are unchanged, 3 T when they change;
//   - register 1 and register 9's pass 1 are checked at the rising edge of select 36,
//     register 9's pass 2 and pins 24-26 at the rising edge of 35, which must come
//     2.5 T after start (35 falls at 2 T), and strobe 37 must rise at T and 2 T (RTL);
//   - every RESET_EVERY-th operation is preceded by one aborted by reset (29) at a
//     quarter-period phase cycling through the whole operation; 35 must be high and
//     the control unit idle (Q41 = Q42 = select 36 = write 37 = 0, NAND 45 = 1) during
//     and after the reset, and the next operation correct.
// Stops with $fatal (non-zero exit) on the first mismatch. The policy reaches the
// device as the twin's wrapper ties it: pins 19, 20 (CONSTANTS) and the configuration
// inputs cfg_rom38_bank (4 * CONSTANTS + NORMALISATION) and cfg_literal (LITERAL).
// Widths: the device's own width parameters, under the same names, passed to it
// whole; a width set other than the default is given on the command line
// (-Pspecular_device_tb.REG9_FRAC=16 ..., rtl/CMakeLists.txt's RTL_PARAMS_<set>), and
// every width below follows. At time 0 the widths derived here are checked against the
// device's own (hierarchical references), so the two derivations cannot drift.
`default_nettype none
`timescale 1ns / 1ps

module specular_device_tb;
  `include "specular_device_parameters.vh"  // VECTORS, ROM images, the policy, T, ...
  // Gate level: 35's edges come a gate delay after the clock's (EDGE_TOLERANCE), and the
  // control unit is checked idle IDLE_WAIT periods after reset moves.
  parameter real IDLE_WAIT = 0.01;
  // Data of pins 18, 21-23 LOAD_SETUP periods before their strobes 30-33 rise (0: with
  // them, as the zero-delay models allow; a flip-flop with setup time needs more).
  parameter real LOAD_SETUP = 0.0;
  // +START_OFFSET=x (-0.5 <= x < 0.5, default 0): start (27) and its data come x periods
  // after the rising clock edge the operation is timed from (negative: before it);
  // scripts/flows/gatelevel/gatesim.sh --hazards sweeps it across a whole period.
  real start_offset = 0.0;
  initial if ($value$plusargs("START_OFFSET=%f", start_offset) &&
              (start_offset < -0.5 || start_offset >= 0.5))
    $fatal(1, "specular_device_tb: START_OFFSET %f is outside [-0.5, 0.5) periods", start_offset);

  // The device's width parameters (rtl/device/specular_device.v; defaults: docs/design.md's
  // formats, as specular_tb uses them without --width).
  parameter COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8;
  parameter ROM5_ADDR_BITS = 15, ROM5_WORD_BITS = 22;
  parameter REG9_INT = 14, REG9_FRAC = 22;
  parameter MUX4_FRAC = 8;
  parameter ROM38_INT = 9, ROM38_FRAC = 16, ROM38_BANK_BITS = 4;  // bank = 4 * constants + normalisation
  parameter NORM_INT = 10, NORM_FRAC = 20;
  parameter OUT_INT = 18, OUT_FRAC = 13;
  // Bus widths, derived as the device derives them (checked against it at time 0).
  localparam COS_W = 1 + COS_FRAC;
  localparam MUX4_W = N_BITS + MUX4_FRAC;
  localparam REG9_W = 1 + REG9_INT + REG9_FRAC;
  localparam ROM38_W = ROM38_INT + ROM38_FRAC;
  localparam NORM_W = 1 + NORM_INT + NORM_FRAC;
  localparam OUT_W = 1 + OUT_INT + OUT_FRAC;
  // The protocol's timing (specular_device_bench.vh): 35 falls at 2 T and rises at 2.5 T,
  // read as it rises; the control unit checked idle IDLE_WAIT periods after reset moves.
  localparam TB_NAME = "specular_device_tb";
  localparam real SELECT36_AT = 0.0, FALL35_AT = 2.0, RISE35_AT = 2.5;
  localparam SAMPLE_AT_NEXT_EDGE = 0;
  localparam real RESET_CHECK_DURING = IDLE_WAIT * T, RESET_REST = T - IDLE_WAIT * T,
                  RESET_CHECK_AFTER = IDLE_WAIT * T;

  `include "specular_device_bench.vh"  // pins, clock, vectors, monitors, schedule
  wire obs_q41, obs_q42, obs_nand45;

`ifdef GATE_LEVEL
  // The mapped netlist (scripts/flows/synthesis/silicon.sh, default widths) with the SDF delays; its ROM
  // macros read their images themselves (scripts/flows/synthesis/rom_model.py).
  specular_device dut (
`else
  specular_device #(
    .COS_FRAC(COS_FRAC), .N_BITS(N_BITS), .RGB_BITS(RGB_BITS),
    .ROM5_ADDR_BITS(ROM5_ADDR_BITS), .ROM5_WORD_BITS(ROM5_WORD_BITS),
    .REG9_INT(REG9_INT), .REG9_FRAC(REG9_FRAC), .MUX4_FRAC(MUX4_FRAC),
    .ROM38_INT(ROM38_INT), .ROM38_FRAC(ROM38_FRAC), .ROM38_BANK_BITS(ROM38_BANK_BITS),
    .NORM_INT(NORM_INT), .NORM_FRAC(NORM_FRAC), .OUT_INT(OUT_INT), .OUT_FRAC(OUT_FRAC),
    .ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
`endif
    .obs_q41(obs_q41), .obs_q42(obs_q42), .obs_nand45(obs_nand45),
    `include "specular_device_ports.vh"
  );

`ifndef GATE_LEVEL
  // Strobe 37 rises at T (pass 1) and at 2T (pass 2) after the start edge, register 9's
  // two writes (spec section 3's timing table); checked at RTL, where no glitch can add
  // an edge (gate level: the pulse monitors below).
  integer rise37_seen = 0;
  always @(posedge obs_write37) if (monitoring) begin
    if (rise37_seen / 2 >= started) $fatal(1, "specular_device_tb: 37 rose with no operation at %0t", $realtime);
    if (off_time($realtime - start_time[rise37_seen / 2], 1.0 + rise37_seen % 2))
      $fatal(1, "specular_device_tb: 37 rose %f periods after start %0d (want %0d)",
             ($realtime - start_time[rise37_seen / 2]) / T, rise37_seen / 2, 1 + rise37_seen % 2);
    rise37_seen = rise37_seen + 1;
  end
`endif

`ifdef GATE_LEVEL
  // Fig. 2's strobes with real delays (docs/silicon.md, hazards): pulses of strobe 37
  // (high) and pin 35 (low) and the narrowest of each, against the DFFPOSX1's minimum
  // pulse width that register 9 needs.
  real    rise37 = -1.0, fall35 = -1.0, narrowest37 = 1.0e9, narrowest35 = 1.0e9;
  integer pulses37 = 0, pulses35 = 0;
  always @(posedge obs_write37) rise37 = $realtime;
  always @(negedge obs_write37) if (rise37 >= 0) begin
    pulses37 = pulses37 + 1;
    if ($realtime - rise37 < narrowest37) narrowest37 = $realtime - rise37;
  end
  always @(negedge pin35_done) fall35 = $realtime;
  always @(posedge pin35_done) if (fall35 >= 0) begin
    pulses35 = pulses35 + 1;
    if ($realtime - fall35 < narrowest35) narrowest35 = $realtime - fall35;
  end
`endif

  // ---- driver ----
  // A start's data come a quarter period (and LOAD_SETUP periods) before its edge, and
  // START_OFFSET periods before that when it is negative.
  function real earliest_start(input real now);
    earliest_start = now + T / 4 + LOAD_SETUP * T - (start_offset < 0.0 ? start_offset * T : 0.0);
  endfunction

  task expect_idle(input [8*16-1:0] when);
    if (pin35_done !== 1'b1 || obs_q41 !== 1'b0 || obs_q42 !== 1'b0 || obs_select36 !== 1'b0 ||
        obs_write37 !== 1'b0 || obs_nand45 !== 1'b1)
      $fatal(1, "specular_device_tb: control unit not idle %0s reset at %0t: 35=%b Q41=%b Q42=%b 36=%b 37=%b nand45=%b",
             when, $realtime, pin35_done, obs_q41, obs_q42, obs_select36, obs_write37, obs_nand45);
  endtask

  // Start an operation at `at` (a rising clock edge; START_OFFSET periods later when
  // set), data a quarter period before;
  // returns with start high, at the start edge (the caller lowers it T/2 later).
  task raise_start(input real at, input [COS_W-1:0] cos_code, input integer index);
    reg reload;
    begin
      reload = !same_operands(index);
      #(at + start_offset * T - T / 4 - LOAD_SETUP * T - $realtime);
      if (reload) begin
        pin18_n = v_n[index];
        pin21_r = v_r[index]; pin22_g = v_g[index]; pin23_b = v_b[index];
      end
      #(LOAD_SETUP * T);
      pin17_cos = cos_code;
      if (reload) begin
        {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b1111;
        note_loaded(index);
      end
      #(T / 4);
      {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b0000;
      pin27_start = 1;
    end
  endtask

  // Start falls half a period after its edge.
  task lower_start;
    begin
      #(T / 2);
      pin27_start = 0;
    end
  endtask

  // The widths derived above are the device's. (A mapped netlist has no parameters
  // left: scripts/flows/synthesis/silicon.sh maps the default widths, which the defaults above are.)
  task check_widths;
  begin  // (a Verilog-2005 task may not be empty, as it is at gate level)
`ifndef GATE_LEVEL
    if (COS_W != dut.COS_W || MUX4_W != dut.MUX4_W || REG9_W != dut.REG9_W ||
        ROM38_W != dut.ROM38_W || NORM_W != dut.NORM_W || OUT_W != dut.OUT_W)
      $fatal(1, "specular_device_tb: widths derived differently from the device's: COS %0d/%0d MUX4 %0d/%0d REG9 %0d/%0d ROM38 %0d/%0d NORM %0d/%0d OUT %0d/%0d",
             COS_W, dut.COS_W, MUX4_W, dut.MUX4_W, REG9_W, dut.REG9_W, ROM38_W, dut.ROM38_W,
             NORM_W, dut.NORM_W, OUT_W, dut.OUT_W);
`endif
  end
  endtask

  initial begin
    check_widths;
    read_vectors;
    first_reset;
    run_operations;
`ifndef GATE_LEVEL
    if (rise37_seen != 2 * count)
      $fatal(1, "specular_device_tb: %0d operations, %0d rising edges of 37 (want 2 each)", count, rise37_seen);
`endif
    $display("specular_device_tb: PASS %0d operations (%0d back to back at 2 T), %0d resets mid-operation, %0d values checked, %0s; widths COS U1.%0d, register 9 S%0d.%0d, ROM 5 word %0d bits",
             count, back_to_back, resets, checks, VECTORS, COS_FRAC, REG9_INT, REG9_FRAC,
             ROM5_WORD_BITS);
`ifdef GATE_LEVEL
    $display("specular_device_tb: strobes: 37 %0d pulses (narrowest %.3f ns), 35 %0d pulses (narrowest %.3f ns) for %0d operations and %0d aborted",
             pulses37, narrowest37, pulses35, narrowest35, count, resets);
`endif
    $finish;
  end
endmodule

`default_nettype wire
