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
  parameter VECTORS = "vectors.csv";
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";
  parameter PINS_IMAGE = "pins.hex";  // pins 19, 20 per constants policy (specular_romgen)
  parameter LITERAL = 0;        // 1: Saturation::literal
  parameter CONSTANTS = 0;      // Constants enum value: pins 19, 20 and ROM 38's bank
  parameter NORMALISATION = 0;  // Normalisation enum value: ROM 38's bank
  parameter real T = 10.0;      // clock period (ns)
  parameter RESET_EVERY = 17;
  parameter MAX_VECTORS = 8192;
  // Gate level (scripts/gatesim.sh, `define GATE_LEVEL): select 36 and 35 change a
  // clock-to-Q delay after the clock edge, so their time is checked to EDGE_TOLERANCE
  // periods (0: exactly).
  parameter real EDGE_TOLERANCE = 0.0;

  // Default widths (docs/design.md), as specular_tb uses them.
  localparam COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8, MUX4_FRAC = 8;
  localparam REG9_W = 37, REG9_FRAC = 22, OUT_W = 32, ROM38_W = 25, NORM_W = 31;
  localparam BANK_BITS = 4;     // bank = 4 * constants + normalisation (twin/rom38_banks.h)

  // ---- device ----
  reg  [COS_FRAC:0]           pin17_cos = 0;
  reg  [N_BITS-1:0]           pin18_n = 0;
  // Pins 19 (h) and 20 (a): wired constants of the constants policy, as the harness
  // ties them (codes written by specular_romgen from constants.cpp).
  reg  [63:0]                 pin_codes [0:5];
  initial $readmemh(PINS_IMAGE, pin_codes);
  wire [N_BITS+MUX4_FRAC-1:0] pin19_h = pin_codes[2 * CONSTANTS][N_BITS+MUX4_FRAC-1:0];
  wire [REG9_W-1:0]           pin20_a = pin_codes[2 * CONSTANTS + 1][REG9_W-1:0];
  reg  [RGB_BITS-1:0]         pin21_r = 0, pin22_g = 0, pin23_b = 0;
  wire [OUT_W-1:0]            pin24_r, pin25_g, pin26_b;
  reg  pin27_start = 0, pin28_clk = 0, pin29_reset_n = 0;
  reg  pin30_load_n = 0, pin31_load_r = 0, pin32_load_g = 0, pin33_load_b = 0;
  wire pin34_carry = 1'b1;
  wire pin35_done;
  wire obs_select36, obs_write37, obs_pass1;
  wire [COS_FRAC:0]  obs_reg1_q;
  wire [REG9_W-1:0]  obs_reg9_q;
  wire [ROM38_W-1:0] obs_rom38_k;
  wire [NORM_W-1:0]  obs_mul39_norm;
  wire               cfg_literal = LITERAL;
  wire [BANK_BITS-1:0] cfg_rom38_bank = 4 * CONSTANTS + NORMALISATION;

`ifdef GATE_LEVEL
  // The mapped netlist (scripts/silicon.sh --top specular_device_sync) with the SDF
  // delays; its ROM macros read their images themselves.
  initial $sdf_annotate(`SDF_FILE, dut);
  specular_device_sync dut (
`else
  specular_device_sync #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
`endif
    .pin17_cos(pin17_cos), .pin18_n(pin18_n), .pin19_h(pin19_h), .pin20_a(pin20_a),
    .pin21_r(pin21_r), .pin22_g(pin22_g), .pin23_b(pin23_b),
    .pin24_r(pin24_r), .pin25_g(pin25_g), .pin26_b(pin26_b),
    .pin27_start(pin27_start), .pin28_clk(pin28_clk), .pin29_reset_n(pin29_reset_n),
    .pin30_load_n(pin30_load_n), .pin31_load_r(pin31_load_r), .pin32_load_g(pin32_load_g),
    .pin33_load_b(pin33_load_b), .pin34_carry(pin34_carry), .pin35_done(pin35_done),
    .cfg_literal(cfg_literal), .cfg_rom38_bank(cfg_rom38_bank),
    .obs_select36(obs_select36), .obs_write37(obs_write37), .obs_pass1(obs_pass1),
    .obs_reg1_q(obs_reg1_q),
    .obs_reg9_q(obs_reg9_q), .obs_rom38_k(obs_rom38_k), .obs_mul39_norm(obs_mul39_norm));

  // Pin 28: rising edges at T/2 + k T.
  always #(T / 2) pin28_clk = ~pin28_clk;

  // ---- vectors ----
  real              v_cos [0:MAX_VECTORS-1];
  integer           v_n [0:MAX_VECTORS-1], v_r [0:MAX_VECTORS-1], v_g [0:MAX_VECTORS-1],
                    v_b [0:MAX_VECTORS-1];
  reg [COS_FRAC:0]  v_reg1 [0:MAX_VECTORS-1];
  reg [REG9_W-1:0]  v_pass1 [0:MAX_VECTORS-1], v_pass2 [0:MAX_VECTORS-1];
  reg [OUT_W-1:0]   v_out24 [0:MAX_VECTORS-1], v_out25 [0:MAX_VECTORS-1],
                    v_out26 [0:MAX_VECTORS-1];
  integer count;

  task read_vectors;
    integer fd, fields, n, r, g, b, pass;
    real cos, skip;
    reg [63:0] h1, h2, h3, h4, h5, h6;
    reg [8*2048-1:0] header;
    begin
      fd = $fopen(VECTORS, "r");
      if (fd == 0) $fatal(1, "specular_device_sync_tb: cannot read %0s", VECTORS);
      fields = $fgets(header, fd);
      count = 0;
      fields = 25;
      while (!$feof(fd) && fields == 25) begin
        fields = $fscanf(fd, {"%f,%d,%d,%d,%d,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,",
                              "0x%h,0x%h,0x%h,0x%h,0x%h,0x%h,%d\n"},
                         cos, n, r, g, b, skip, skip, skip, skip, skip, skip, skip, skip, skip,
                         skip, skip, skip, skip, h1, h2, h3, h4, h5, h6, pass);
        if (fields == 25) begin
          if (count == MAX_VECTORS) $fatal(1, "specular_device_sync_tb: more than %0d vectors", MAX_VECTORS);
          v_cos[count] = cos;
          v_n[count] = n; v_r[count] = r; v_g[count] = g; v_b[count] = b;
          v_reg1[count] = h1[COS_FRAC:0];
          v_pass1[count] = h2[REG9_W-1:0];
          v_pass2[count] = h3[REG9_W-1:0];
          v_out24[count] = h4[OUT_W-1:0];
          v_out25[count] = h5[OUT_W-1:0];
          v_out26[count] = h6[OUT_W-1:0];
          count = count + 1;
        end else if (fields > 0) begin
          $fatal(1, "specular_device_sync_tb: %0s line %0d: %0d of 25 fields", VECTORS, count + 2, fields);
        end
      end
      $fclose(fd);
      if (count == 0) $fatal(1, "specular_device_sync_tb: no vectors in %0s", VECTORS);
    end
  endtask

  // ---- monitors: results as the harness samples them ----
  reg     monitoring = 0;   // off during an aborted operation
  integer started = 0, pass1_seen = 0, done_seen = 0, fall_seen = 0, checks = 0;
  real     start_time [0:MAX_VECTORS-1];

  task mismatch(input integer index, input [8*24-1:0] what, input [63:0] got, input [63:0] want);
    $fatal(1, "specular_device_sync_tb: MISMATCH vector %0d (cos %f n %0d RGB %0d,%0d,%0d) %0s: got %h, want %h at %0t",
           index, v_cos[index], v_n[index], v_r[index], v_g[index], v_b[index], what, got,
           want, $realtime);
  endtask

  // An edge `elapsed` after start is not `periods` periods after it (to EDGE_TOLERANCE).
  function off_time(input real elapsed, input real periods);
    off_time = elapsed < periods * T || elapsed > (periods + EDGE_TOLERANCE) * T;
  endfunction

  // Register 1, register 9 and pins 24-26 change at the clock edge that raises select
  // 36 or 35 (all registered) and settle within the period: they are read as a
  // synchronous consumer reads them, at the next rising clock edge (before it acts).
  always @(posedge obs_select36) if (monitoring) begin
    if (pass1_seen >= started) $fatal(1, "specular_device_sync_tb: select 36 rose with no operation at %0t", $realtime);
    if (off_time($realtime - start_time[pass1_seen], 1.0))
      $fatal(1, "specular_device_sync_tb: select 36 rose %f periods after start %0d (want 1)",
             ($realtime - start_time[pass1_seen]) / T, pass1_seen);
    @(posedge pin28_clk);
    if (obs_reg1_q !== v_reg1[pass1_seen]) mismatch(pass1_seen, "register 1", obs_reg1_q, v_reg1[pass1_seen]);
    if (obs_reg9_q !== v_pass1[pass1_seen]) mismatch(pass1_seen, "register 9 pass 1", obs_reg9_q, v_pass1[pass1_seen]);
    checks = checks + 2;
    pass1_seen = pass1_seen + 1;
  end

  always @(negedge pin35_done) if (monitoring) begin
    if (off_time($realtime - start_time[fall_seen], 1.0))
      $fatal(1, "specular_device_sync_tb: 35 fell %f periods after start %0d (want 1)",
             ($realtime - start_time[fall_seen]) / T, fall_seen);
    fall_seen = fall_seen + 1;
  end

  always @(posedge pin35_done) if (monitoring) begin
    if (done_seen >= started) $fatal(1, "specular_device_sync_tb: 35 rose with no operation at %0t", $realtime);
    if (off_time($realtime - start_time[done_seen], 2.0))
      $fatal(1, "specular_device_sync_tb: 35 rose %f periods after start %0d (want 2)",
             ($realtime - start_time[done_seen]) / T, done_seen);
    @(posedge pin28_clk);
    if (obs_reg9_q !== v_pass2[done_seen]) mismatch(done_seen, "register 9 pass 2", obs_reg9_q, v_pass2[done_seen]);
    if (pin24_r !== v_out24[done_seen]) mismatch(done_seen, "pin 24", pin24_r, v_out24[done_seen]);
    if (pin25_g !== v_out25[done_seen]) mismatch(done_seen, "pin 25", pin25_g, v_out25[done_seen]);
    if (pin26_b !== v_out26[done_seen]) mismatch(done_seen, "pin 26", pin26_b, v_out26[done_seen]);
    checks = checks + 5;
    done_seen = done_seen + 1;
  end

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
  real     next_start, prev_start;
  integer  i, resets = 0, back_to_back = 0;
  reg      loaded;
  integer  loaded_n, loaded_r, loaded_g, loaded_b;

  // The first rising clock edge at least a quarter period from now.
  function real first_edge_after_quarter(input real now);
    real rising;
    begin
      rising = T / 2;
      while (rising < now + T / 4) rising = rising + T;
      first_edge_after_quarter = rising;
    end
  endfunction

  task expect_idle(input [8*16-1:0] when);
    if (pin35_done !== 1'b1 || obs_pass1 !== 1'b0 || obs_select36 !== 1'b0 || obs_write37 !== 1'b0)
      $fatal(1, "specular_device_sync_tb: sequencer not idle %0s reset at %0t: 35=%b pass1=%b 36=%b 37=%b",
             when, $realtime, pin35_done, obs_pass1, obs_select36, obs_write37);
  endtask

  // Start an operation at `at` (a rising clock edge): start, data and loads a quarter
  // period before; returns at the start edge (the caller lowers start and the loads
  // a quarter period later).
  task raise_start(input real at, input [COS_FRAC:0] cos_code, input integer index);
    reg reload;
    begin
      reload = !loaded || v_n[index] != loaded_n || v_r[index] != loaded_r ||
               v_g[index] != loaded_g || v_b[index] != loaded_b;
      #(at - T / 4 - $realtime);
      pin17_cos = cos_code;
      if (reload) begin
        pin18_n = v_n[index];
        pin21_r = v_r[index]; pin22_g = v_g[index]; pin23_b = v_b[index];
        {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b1111;
        loaded = 1;
        loaded_n = v_n[index]; loaded_r = v_r[index]; loaded_g = v_g[index]; loaded_b = v_b[index];
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
          #(T - T / 100);  // past the one clock edge inside the reset
          expect_idle("during");
          #(T / 100);
          pin29_reset_n = 1;
          #(T / 100);
          expect_idle("after");
        end
      join
      resets = resets + 1;
      prev_start = -10 * T;
      monitoring = 1;
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
    loaded = 0;
    // Reset first: the device is defined from reset on (no initial values).
    #(T / 4);
    pin29_reset_n = 0;
    #(T);
    pin29_reset_n = 1;
    #(T / 100);
    expect_idle("after");
    start_in_pass1_ignored;
    monitoring = 1;
    prev_start = -10 * T;
    for (i = 0; i < count; i = i + 1) begin
      if (i % RESET_EVERY == RESET_EVERY - 1)
        aborted_operation(i, 1 + 2 * ((i / RESET_EVERY) % 5));  // 0.25, 0.75 ... 2.25 T
      next_start = first_edge_after_quarter($realtime);
      if (loaded && v_n[i] == loaded_n && v_r[i] == loaded_r && v_g[i] == loaded_g &&
          v_b[i] == loaded_b) begin
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
      $fatal(1, "specular_device_sync_tb: %0d operations, %0d pass-1 writes, %0d results",
             count, pass1_seen, done_seen);
    report_pulses;
    $display("specular_device_sync_tb: PASS %0d operations (%0d back to back at 2 T), %0d resets mid-operation, %0d values checked, %0s",
             count, back_to_back, resets, checks, VECTORS);
    $finish;
  end

  initial begin : watchdog
    #(T * (4 * MAX_VECTORS + 100));
    $fatal(1, "specular_device_sync_tb: watchdog: no end after %0d periods", 4 * MAX_VECTORS + 100);
  end
endmodule

`default_nettype wire
