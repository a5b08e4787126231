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
  parameter VECTORS = "vectors.csv";
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";
  parameter PINS_IMAGE = "pins.hex";  // pins 19, 20 per constants policy (specular_romgen)
  parameter LITERAL = 0;        // 1: Saturation::literal
  parameter CONSTANTS = 0;      // Constants enum value: pins 19, 20 and ROM 38's bank
  parameter NORMALISATION = 0;  // Normalisation enum value: ROM 38's bank
  parameter real T = 10.0;      // clock period (ns)
  parameter RESET_EVERY = 17;
  parameter MAX_VECTORS = 8192;
  // Gate level (scripts/gatesim.sh, `define GATE_LEVEL): 35's edges come a gate delay
  // after the clock's, so their time is checked to EDGE_TOLERANCE periods (0: exactly),
  // and the control unit is checked idle IDLE_WAIT periods after reset moves.
  parameter real EDGE_TOLERANCE = 0.0;
  parameter real IDLE_WAIT = 0.01;
  // Data of pins 18, 21-23 LOAD_SETUP periods before their strobes 30-33 rise (0: with
  // them, as the zero-delay models allow; a flip-flop with setup time needs more).
  parameter real LOAD_SETUP = 0.0;
  // +START_OFFSET=x (-0.5 <= x < 0.5, default 0): start (27) and its data come x periods
  // after the rising clock edge the operation is timed from (negative: before it);
  // scripts/gatesim.sh --hazards sweeps it across a whole period.
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

  // ---- device ----
  reg  [COS_W-1:0]            pin17_cos = 0;
  reg  [N_BITS-1:0]           pin18_n = 0;
  // Pins 19 (h) and 20 (a): wired constants of the constants policy, as the harness
  // ties them (codes written by specular_romgen from constants.cpp).
  reg  [63:0]                 pin_codes [0:5];
  initial $readmemh(PINS_IMAGE, pin_codes);
  wire [MUX4_W-1:0]           pin19_h = pin_codes[2 * CONSTANTS][MUX4_W-1:0];
  wire [REG9_W-1:0]           pin20_a = pin_codes[2 * CONSTANTS + 1][REG9_W-1:0];
  reg  [RGB_BITS-1:0]         pin21_r = 0, pin22_g = 0, pin23_b = 0;
  wire [OUT_W-1:0]            pin24_r, pin25_g, pin26_b;
  reg  pin27_start = 0, pin28_clk = 0, pin29_reset_n = 0;
  reg  pin30_load_n = 0, pin31_load_r = 0, pin32_load_g = 0, pin33_load_b = 0;
  wire pin34_carry = 1'b1;
  wire pin35_done;
  wire obs_select36, obs_write37, obs_q41, obs_q42, obs_nand45;
  wire [COS_W-1:0]   obs_reg1_q;
  wire [REG9_W-1:0]  obs_reg9_q;
  wire [ROM38_W-1:0] obs_rom38_k;
  wire [NORM_W-1:0]  obs_mul39_norm;
  wire               cfg_literal = LITERAL;
  wire [ROM38_BANK_BITS-1:0] cfg_rom38_bank = 4 * CONSTANTS + NORMALISATION;

`ifdef GATE_LEVEL
  // The mapped netlist (scripts/silicon.sh, default widths) with the SDF delays; its ROM
  // macros read their images themselves (scripts/silicon/rom_model.py).
  initial $sdf_annotate(`SDF_FILE, dut);
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
    .pin17_cos(pin17_cos), .pin18_n(pin18_n), .pin19_h(pin19_h), .pin20_a(pin20_a),
    .pin21_r(pin21_r), .pin22_g(pin22_g), .pin23_b(pin23_b),
    .pin24_r(pin24_r), .pin25_g(pin25_g), .pin26_b(pin26_b),
    .pin27_start(pin27_start), .pin28_clk(pin28_clk), .pin29_reset_n(pin29_reset_n),
    .pin30_load_n(pin30_load_n), .pin31_load_r(pin31_load_r), .pin32_load_g(pin32_load_g),
    .pin33_load_b(pin33_load_b), .pin34_carry(pin34_carry), .pin35_done(pin35_done),
    .cfg_literal(cfg_literal), .cfg_rom38_bank(cfg_rom38_bank),
    .obs_select36(obs_select36), .obs_write37(obs_write37), .obs_q41(obs_q41),
    .obs_q42(obs_q42), .obs_nand45(obs_nand45), .obs_reg1_q(obs_reg1_q),
    .obs_reg9_q(obs_reg9_q), .obs_rom38_k(obs_rom38_k), .obs_mul39_norm(obs_mul39_norm));

  // Pin 28: rising edges at T/2 + k T.
  always #(T / 2) pin28_clk = ~pin28_clk;

  // ---- vectors ----
  real              v_cos [0:MAX_VECTORS-1];
  integer           v_n [0:MAX_VECTORS-1], v_r [0:MAX_VECTORS-1], v_g [0:MAX_VECTORS-1],
                    v_b [0:MAX_VECTORS-1];
  reg [COS_W-1:0]   v_reg1 [0:MAX_VECTORS-1];
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
      if (fd == 0) $fatal(1, "specular_device_tb: cannot read %0s", VECTORS);
      fields = $fgets(header, fd);
      count = 0;
      fields = 25;
      while (!$feof(fd) && fields == 25) begin
        fields = $fscanf(fd, {"%f,%d,%d,%d,%d,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,",
                              "0x%h,0x%h,0x%h,0x%h,0x%h,0x%h,%d\n"},
                         cos, n, r, g, b, skip, skip, skip, skip, skip, skip, skip, skip, skip,
                         skip, skip, skip, skip, h1, h2, h3, h4, h5, h6, pass);
        if (fields == 25) begin
          if (count == MAX_VECTORS) $fatal(1, "specular_device_tb: more than %0d vectors", MAX_VECTORS);
          v_cos[count] = cos;
          v_n[count] = n; v_r[count] = r; v_g[count] = g; v_b[count] = b;
          v_reg1[count] = h1[COS_W-1:0];
          v_pass1[count] = h2[REG9_W-1:0];
          v_pass2[count] = h3[REG9_W-1:0];
          v_out24[count] = h4[OUT_W-1:0];
          v_out25[count] = h5[OUT_W-1:0];
          v_out26[count] = h6[OUT_W-1:0];
          count = count + 1;
        end else if (fields > 0) begin
          $fatal(1, "specular_device_tb: %0s line %0d: %0d of 25 fields", VECTORS, count + 2, fields);
        end
      end
      $fclose(fd);
      if (count == 0) $fatal(1, "specular_device_tb: no vectors in %0s", VECTORS);
    end
  endtask

  // ---- monitors: results as the harness samples them ----
  reg     monitoring = 0;   // off during an aborted operation
  integer started = 0, pass1_seen = 0, done_seen = 0, fall_seen = 0, checks = 0;
  real     start_time [0:MAX_VECTORS-1];

  task mismatch(input integer index, input [8*24-1:0] what, input [63:0] got, input [63:0] want);
    $fatal(1, "specular_device_tb: MISMATCH vector %0d (cos %f n %0d RGB %0d,%0d,%0d) %0s: got %h, want %h at %0t",
           index, v_cos[index], v_n[index], v_r[index], v_g[index], v_b[index], what, got,
           want, $realtime);
  endtask

  always @(posedge obs_select36) if (monitoring) begin
    if (pass1_seen >= started) $fatal(1, "specular_device_tb: select 36 rose with no operation at %0t", $realtime);
    if (obs_reg1_q !== v_reg1[pass1_seen]) mismatch(pass1_seen, "register 1", obs_reg1_q, v_reg1[pass1_seen]);
    if (obs_reg9_q !== v_pass1[pass1_seen]) mismatch(pass1_seen, "register 9 pass 1", obs_reg9_q, v_pass1[pass1_seen]);
    checks = checks + 2;
    pass1_seen = pass1_seen + 1;
  end

  // An edge `elapsed` after start is not `periods` periods after it (to EDGE_TOLERANCE).
  function off_time(input real elapsed, input real periods);
    off_time = elapsed < periods * T || elapsed > (periods + EDGE_TOLERANCE) * T;
  endfunction

  always @(negedge pin35_done) if (monitoring) begin
    if (off_time($realtime - start_time[fall_seen], 2.0))
      $fatal(1, "specular_device_tb: 35 fell %f periods after start %0d (want 2)",
             ($realtime - start_time[fall_seen]) / T, fall_seen);
    fall_seen = fall_seen + 1;
  end

  always @(posedge pin35_done) if (monitoring) begin
    if (done_seen >= started) $fatal(1, "specular_device_tb: 35 rose with no operation at %0t", $realtime);
    if (off_time($realtime - start_time[done_seen], 2.5))
      $fatal(1, "specular_device_tb: 35 rose %f periods after start %0d (want 2.5)",
             ($realtime - start_time[done_seen]) / T, done_seen);
    if (obs_reg9_q !== v_pass2[done_seen]) mismatch(done_seen, "register 9 pass 2", obs_reg9_q, v_pass2[done_seen]);
    if (pin24_r !== v_out24[done_seen]) mismatch(done_seen, "pin 24", pin24_r, v_out24[done_seen]);
    if (pin25_g !== v_out25[done_seen]) mismatch(done_seen, "pin 25", pin25_g, v_out25[done_seen]);
    if (pin26_b !== v_out26[done_seen]) mismatch(done_seen, "pin 26", pin26_b, v_out26[done_seen]);
    checks = checks + 5;
    done_seen = done_seen + 1;
  end

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
  real     next_start, prev_start;
  integer  i, resets = 0, back_to_back = 0;
  reg      loaded;
  integer  loaded_n, loaded_r, loaded_g, loaded_b;

  // The first rising clock edge at least a quarter period from now.
  function real first_edge_after_quarter(input real now);
    real rising;
    begin
      rising = T / 2;
      while (rising < now + T / 4 + LOAD_SETUP * T - (start_offset < 0.0 ? start_offset * T : 0.0))
        rising = rising + T;
      first_edge_after_quarter = rising;
    end
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
      reload = !loaded || v_n[index] != loaded_n || v_r[index] != loaded_r ||
               v_g[index] != loaded_g || v_b[index] != loaded_b;
      #(at + start_offset * T - T / 4 - LOAD_SETUP * T - $realtime);
      if (reload) begin
        pin18_n = v_n[index];
        pin21_r = v_r[index]; pin22_g = v_g[index]; pin23_b = v_b[index];
      end
      #(LOAD_SETUP * T);
      pin17_cos = cos_code;
      if (reload) begin
        {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b1111;
        loaded = 1;
        loaded_n = v_n[index]; loaded_r = v_r[index]; loaded_g = v_g[index]; loaded_b = v_b[index];
      end
      #(T / 4);
      {pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b} = 4'b0000;
      pin27_start = 1;
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
        begin
          #(T / 2);
          pin27_start = 0;
        end
        begin
          #(phase * T / 4);
          pin29_reset_n = 0;
          #(IDLE_WAIT * T);
          expect_idle("during");
          #(T - IDLE_WAIT * T);
          pin29_reset_n = 1;
          #(IDLE_WAIT * T);
          expect_idle("after");
        end
      join
      resets = resets + 1;
      prev_start = -10 * T;
      monitoring = 1;
    end
  endtask

  // The widths derived above are the device's. (A mapped netlist has no parameters
  // left: scripts/silicon.sh maps the default widths, which the defaults above are.)
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
    loaded = 0;
    // Reset first: the device is defined from reset on (no initial values).
    #(T / 4);
    pin29_reset_n = 0;
    #(T);
    pin29_reset_n = 1;
    #(IDLE_WAIT * T);
    expect_idle("after");
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
      #(T / 2);
      pin27_start = 0;
    end
    #(3 * T);
    if (done_seen != count || pass1_seen != count || fall_seen != count)
      $fatal(1, "specular_device_tb: %0d operations, %0d pass-1 writes, %0d results",
             count, pass1_seen, done_seen);
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

  initial begin : watchdog
    #(T * (4 * MAX_VECTORS + 100));
    $fatal(1, "specular_device_tb: watchdog: no end after %0d periods", 4 * MAX_VECTORS + 100);
  end
endmodule

`default_nettype wire
