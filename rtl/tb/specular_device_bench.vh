// specular_device_bench.vh: what the two device benches (specular_device_tb.v, the drawn
// device; specular_device_sync_tb.v, the synchronous variant) share: the pins, the clock,
// the vectors, the monitors that check every result, and the driver's schedule. `include
// it inside the bench module, after
//   - its parameters (specular_policy_parameters.vh's and T, RESET_EVERY, MAX_VECTORS,
//     EDGE_TOLERANCE);
//   - its localparams TB_NAME (its messages begin with it), the widths COS_FRAC, N_BITS,
//     RGB_BITS, COS_W, MUX4_W, REG9_W, ROM38_W, NORM_W, OUT_W, ROM38_BANK_BITS, and its
//     protocol's timing in periods after the start edge: SELECT36_AT (select 36 rises;
//     0: not checked), FALL35_AT, RISE35_AT (35 falls, rises), SAMPLE_AT_NEXT_EDGE (1:
//     results read at the rising clock edge after 36 or 35 rose, as a synchronous
//     consumer reads them; 0: at the rise), and the reset's checks in ns: the control
//     unit is checked idle RESET_CHECK_DURING after reset falls, reset rises RESET_REST
//     later, and the unit is checked idle again RESET_CHECK_AFTER after that.
// The bench itself instantiates the device as `dut` (specular_device_ports.vh: the
// connections) and writes the protocol's own parts: the tasks expect_idle(when),
// raise_start(at, cos_code, index) (returns at the start edge), lower_start, and the
// function earliest_start(now) (the earliest time a start's data may be set up for).
// Stops with $fatal (non-zero exit) on the first mismatch.

  // ---- device: pins 17-35 and what both variants let the bench observe ----
  reg  [COS_W-1:0]            pin17_cos = 0;
  reg  [N_BITS-1:0]           pin18_n = 0;
  // Pins 19 (h) and 20 (a): wired constants of the constants policy, as the harness
  // ties them (codes written by specular_romgen from constants.cpp).
  reg  [63:0]                 pin_codes [0:5];
  initial $readmemh(PINS_IMAGE, pin_codes);
`ifdef GATE_LEVEL
  initial $sdf_annotate(`SDF_FILE, dut);  // the mapped netlist's delays
`endif
  wire [MUX4_W-1:0]           pin19_h = pin_codes[2 * CONSTANTS][MUX4_W-1:0];
  wire [REG9_W-1:0]           pin20_a = pin_codes[2 * CONSTANTS + 1][REG9_W-1:0];
  reg  [RGB_BITS-1:0]         pin21_r = 0, pin22_g = 0, pin23_b = 0;
  wire [OUT_W-1:0]            pin24_r, pin25_g, pin26_b;
  reg  pin27_start = 0, pin28_clk = 0, pin29_reset_n = 0;
  reg  pin30_load_n = 0, pin31_load_r = 0, pin32_load_g = 0, pin33_load_b = 0;
  wire pin34_carry = 1'b1;
  wire pin35_done;
  wire obs_select36, obs_write37;
  wire [COS_W-1:0]   obs_reg1_q;
  wire [REG9_W-1:0]  obs_reg9_q;
  wire [ROM38_W-1:0] obs_rom38_k;
  wire [NORM_W-1:0]  obs_mul39_norm;
  wire               cfg_literal = LITERAL;
  wire [ROM38_BANK_BITS-1:0] cfg_rom38_bank = 4 * CONSTANTS + NORMALISATION;

  // Pin 28: rising edges at T/2 + k T.
  always #(T / 2) pin28_clk = ~pin28_clk;

  // ---- vectors ----
  localparam VECTOR_COS_W = COS_W, VECTOR_REG9_W = REG9_W, VECTOR_OUT_W = OUT_W;
  `include "specular_vectors.vh"

  // ---- monitors: results as the harness samples them ----
  reg     monitoring = 0;   // off during an aborted operation
  integer started = 0, pass1_seen = 0, done_seen = 0, fall_seen = 0, checks = 0;
  real     start_time [0:MAX_VECTORS-1];

  task mismatch(input integer index, input [8*24-1:0] what, input [63:0] got, input [63:0] want);
    $fatal(1, "%0s: MISMATCH vector %0d (cos %f n %0d RGB %0d,%0d,%0d) %0s: got %h, want %h at %0t",
           TB_NAME, index, v_cos[index], v_n[index], v_r[index], v_g[index], v_b[index], what, got,
           want, $realtime);
  endtask

  // An edge `elapsed` after start is not `periods` periods after it (to EDGE_TOLERANCE).
  function off_time(input real elapsed, input real periods);
    off_time = elapsed < periods * T || elapsed > (periods + EDGE_TOLERANCE) * T;
  endfunction

  always @(posedge obs_select36) if (monitoring) begin
    if (pass1_seen >= started) $fatal(1, "%0s: select 36 rose with no operation at %0t", TB_NAME, $realtime);
    if (SELECT36_AT > 0.0 && off_time($realtime - start_time[pass1_seen], SELECT36_AT))
      $fatal(1, "%0s: select 36 rose %f periods after start %0d (want %g)",
             TB_NAME, ($realtime - start_time[pass1_seen]) / T, pass1_seen, SELECT36_AT);
    if (SAMPLE_AT_NEXT_EDGE) @(posedge pin28_clk);
    if (obs_reg1_q !== v_reg1[pass1_seen]) mismatch(pass1_seen, "register 1", obs_reg1_q, v_reg1[pass1_seen]);
    if (obs_reg9_q !== v_pass1[pass1_seen][REG9_W-1:0])
      mismatch(pass1_seen, "register 9 pass 1", obs_reg9_q, v_pass1[pass1_seen][REG9_W-1:0]);
    checks = checks + 2;
    pass1_seen = pass1_seen + 1;
  end

  always @(negedge pin35_done) if (monitoring) begin
    if (off_time($realtime - start_time[fall_seen], FALL35_AT))
      $fatal(1, "%0s: 35 fell %f periods after start %0d (want %g)",
             TB_NAME, ($realtime - start_time[fall_seen]) / T, fall_seen, FALL35_AT);
    fall_seen = fall_seen + 1;
  end

  always @(posedge pin35_done) if (monitoring) begin
    if (done_seen >= started) $fatal(1, "%0s: 35 rose with no operation at %0t", TB_NAME, $realtime);
    if (off_time($realtime - start_time[done_seen], RISE35_AT))
      $fatal(1, "%0s: 35 rose %f periods after start %0d (want %g)",
             TB_NAME, ($realtime - start_time[done_seen]) / T, done_seen, RISE35_AT);
    if (SAMPLE_AT_NEXT_EDGE) @(posedge pin28_clk);
    if (obs_reg9_q !== v_pass2[done_seen][REG9_W-1:0])
      mismatch(done_seen, "register 9 pass 2", obs_reg9_q, v_pass2[done_seen][REG9_W-1:0]);
    if (pin24_r !== v_out24[done_seen]) mismatch(done_seen, "pin 24", pin24_r, v_out24[done_seen]);
    if (pin25_g !== v_out25[done_seen]) mismatch(done_seen, "pin 25", pin25_g, v_out25[done_seen]);
    if (pin26_b !== v_out26[done_seen]) mismatch(done_seen, "pin 26", pin26_b, v_out26[done_seen]);
    checks = checks + 5;
    done_seen = done_seen + 1;
  end

  // ---- driver ----
  real     next_start, prev_start;
  integer  i, resets = 0, back_to_back = 0;
  reg      loaded;
  integer  loaded_n, loaded_r, loaded_g, loaded_b;

  // The first rising clock edge whose start's data can be set up from now on.
  function real first_edge_after_quarter(input real now);
    real rising;
    begin
      rising = T / 2;
      while (rising < earliest_start(now)) rising = rising + T;
      first_edge_after_quarter = rising;
    end
  endfunction

  // Vector `index` has the operands on pins 18, 21-23 now (no load needed).
  function same_operands(input integer index);
    same_operands = loaded && v_n[index] == loaded_n && v_r[index] == loaded_r &&
                    v_g[index] == loaded_g && v_b[index] == loaded_b;
  endfunction
  task note_loaded(input integer index);
    begin
      loaded = 1;
      loaded_n = v_n[index]; loaded_r = v_r[index]; loaded_g = v_g[index]; loaded_b = v_b[index];
    end
  endtask

  // Reset first: the device is defined from reset on (no initial values).
  task first_reset;
    begin
      loaded = 0;
      #(T / 4);
      pin29_reset_n = 0;
      #(T);
      pin29_reset_n = 1;
      #(RESET_CHECK_AFTER);
      expect_idle("after");
    end
  endtask

  // An operation aborted by reset `phase` quarter periods after its start edge.
  task aborted_operation(input integer index, input integer phase);
    real at;
    begin
      wait (done_seen == started);  // the operations before it are complete
      monitoring = 0;
      at = first_edge_after_quarter($realtime);
      if (at < prev_start + 3 * T) at = prev_start + 3 * T;
      raise_start(at, ~v_reg1[index] & {1'b0, {COS_FRAC{1'b1}}}, index);
      fork
        lower_start;
        begin
          #(phase * T / 4);
          pin29_reset_n = 0;
          #(RESET_CHECK_DURING);
          expect_idle("during");
          #(RESET_REST);
          pin29_reset_n = 1;
          #(RESET_CHECK_AFTER);
          expect_idle("after");
        end
      join
      resets = resets + 1;
      prev_start = -10 * T;
      monitoring = 1;
    end
  endtask

  // Every vector, back to back every 2 T while n, R, G, B are unchanged, 3 T when they
  // change; every RESET_EVERY-th preceded by one aborted by reset.
  task run_operations;
    begin
      monitoring = 1;
      prev_start = -10 * T;
      for (i = 0; i < count; i = i + 1) begin
        if (i % RESET_EVERY == RESET_EVERY - 1)
          aborted_operation(i, 1 + 2 * ((i / RESET_EVERY) % 5));  // 0.25, 0.75 ... 2.25 T
        next_start = first_edge_after_quarter($realtime);
        if (same_operands(i)) begin
          if (next_start < prev_start + 2 * T) next_start = prev_start + 2 * T;
          if (next_start == prev_start + 2 * T) back_to_back = back_to_back + 1;
        end else if (next_start < prev_start + 3 * T) begin
          next_start = prev_start + 3 * T;
        end
        start_time[i] = next_start;
        started = started + 1;
        prev_start = next_start;
        raise_start(next_start, $rtoi(v_cos[i] * (1 << COS_FRAC) + 0.5), i);
        lower_start;
      end
      #(3 * T);
      if (done_seen != count || pass1_seen != count || fall_seen != count)
        $fatal(1, "%0s: %0d operations, %0d pass-1 writes, %0d results",
               TB_NAME, count, pass1_seen, done_seen);
    end
  endtask

  initial begin : watchdog
    #(T * (4 * MAX_VECTORS + 100));
    $fatal(1, "%0s: watchdog: no end after %0d periods", TB_NAME, 4 * MAX_VECTORS + 100);
  end
