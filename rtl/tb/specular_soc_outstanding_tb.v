// specular_soc with several reads and several writes in flight (docs/rtl_ip.md, "Placing
// the IP in an SoC"), as AXI4-Lite allows and CPUs with store buffers do. The master
// issues AW, W and AR without waiting for responses, up to MAX_IN_FLIGHT requests per
// direction beyond the last response taken, each channel on its own: every VALID rises
// 0-3 cycles late at random (so a W often comes before its AW), BREADY and RREADY are low
// in bursts of 1-12 cycles, each begun in a cycle with STALL_PERCENT % chance
// (seeded: SEED).
// The program: PHASES phases, each a few writes and a few reads mixing the RAM, the IP's
// operands (values in range, and refused ones: SLVERR, nothing written), its constants
// (ID, VERSION, CONFIG, PIN19_H, PIN20_A: a write is SLVERR), START, holes in the IP's
// window (its DECERR) and addresses no slave has (the interconnect's DECERR). AXI4-Lite
// does not order reads against writes, so within a phase no read touches a word that the
// phase writes; a phase starts when every response of the one before has come. The
// scoreboard computes every response and read value itself (the RAM and the operands
// mirrored, the constants from docs/tlm.md's map) and checks each one in order as it
// comes. The AXI4-Lite rules are checked each edge (specular_ip_axi_props.v) on the
// SoC's port, the RAM's and the IP's. Stops with $fatal on the first mismatch.
`default_nettype none
`timescale 1ns / 1ps

module specular_soc_outstanding_tb;
  parameter PHASES = 120;
  parameter MAX_IN_FLIGHT = 6;     // the interconnect takes 4 per direction: more wait
  parameter STALL_PERCENT = 15;
  parameter STALL = 1;             // (axi_lite_master.vh's; unused here)
  localparam MAX_PER_PHASE = 8;
  localparam RAM_LOCS = 24;        // 16 words at the RAM's start, 8 at its end
  localparam MAX_OPS = PHASES * MAX_PER_PHASE + RAM_LOCS;  // phase 0 writes every RAM word

  localparam SOC_OPEN_WRITES = 4, SOC_OPEN_READS = 4;  // specular_soc_dut.vh's soc_port
  `include "specular_soc_dut.vh"  // SEED, the master (axi_lite_master.vh), the SoC

  // The rules on the RAM's port (it queues 4 responses, as the interconnect keeps 4 in
  // flight on the SoC's port) and on the IP's (its own holding registers: the defaults).
  specular_ip_axi_props #(.MAX_OPEN_WRITES(4), .MAX_OPEN_READS(4)) ram_port (
    .aclk(aclk), .aresetn(aresetn),
    .awvalid(dut.awvalid[0]), .awready(dut.awready[0]), .awaddr(dut.awaddr[31:0]),
    .wvalid(dut.wvalid[0]), .wready(dut.wready[0]), .wdata(dut.wdata[31:0]), .wstrb(dut.wstrb[3:0]),
    .bvalid(dut.bvalid[0]), .bready(dut.bready[0]), .bresp(dut.bresp[1:0]),
    .arvalid(dut.arvalid[0]), .arready(dut.arready[0]), .araddr(dut.araddr[31:0]),
    .rvalid(dut.rvalid[0]), .rready(dut.rready[0]), .rdata(dut.rdata[31:0]), .rresp(dut.rresp[1:0]));
  `include "specular_soc_ip_port.vh"

  // ---- the locations the program touches ----
  localparam K_RAM = 0, K_OPERAND = 1, K_CONST = 2, K_HOLE = 3, K_NONE = 4, K_CONTROL = 5;
  localparam LOCS = RAM_LOCS + 5 + 5 + 3 + 3 + 1;
  reg [31:0] loc_addr [0:LOCS-1];
  integer    loc_kind [0:LOCS-1];
  reg [31:0] loc_value [0:LOCS-1];  // the mirror
  reg        loc_known [0:LOCS-1];  // written in full once (the RAM has no reset)
  reg        loc_busy [0:LOCS-1];   // written in the phase being built
  integer    loc_operand [0:LOCS-1];  // 0..4: COS, N, R, G, B

  task add_loc;
    input integer i;
    input [31:0] address;
    input integer kind;
    input [31:0] value;
    input integer known;
    begin
      loc_addr[i] = address; loc_kind[i] = kind; loc_value[i] = value;
      loc_known[i] = known != 0; loc_busy[i] = 1'b0; loc_operand[i] = 0;
    end
  endtask
  integer i, j;
  task build_locations;
    begin
      for (i = 0; i < 16; i = i + 1) add_loc(i, RAM_BASE + 4 * i, K_RAM, 32'd0, 0);
      for (i = 0; i < 8; i = i + 1) add_loc(16 + i, RAM_BASE + RAM_BYTES - 4 - 4 * i, K_RAM, 32'd0, 0);
      // the IP's operands with their resets (COS, N, R, G, B)
      for (i = 0; i < 5; i = i + 1) begin
        add_loc(RAM_LOCS + i, IP_BASE + 32'h20 + 4 * i, K_OPERAND, i == 1 ? 32'd1 : 32'd0, 1);
        loc_operand[RAM_LOCS + i] = i;
      end
      add_loc(RAM_LOCS + 5, IP_BASE + 32'h000, K_CONST, 32'h00059965, 1);  // ID
      add_loc(RAM_LOCS + 6, IP_BASE + 32'h004, K_CONST, 32'h00010001, 1);  // VERSION
      add_loc(RAM_LOCS + 7, IP_BASE + 32'h008, K_CONST, 32'h080D1000, 1);  // CONFIG's reset
      add_loc(RAM_LOCS + 8, IP_BASE + 32'h06C, K_CONST, 32'h00000080, 1);  // PIN19_H
      add_loc(RAM_LOCS + 9, IP_BASE + 32'h070, K_CONST, 32'h00400000, 1);  // PIN20_A
      add_loc(RAM_LOCS + 10, IP_BASE + 32'h01C, K_HOLE, 32'd0, 1);
      add_loc(RAM_LOCS + 11, IP_BASE + 32'h034, K_HOLE, 32'd0, 1);
      add_loc(RAM_LOCS + 12, IP_BASE + 32'h7FFC, K_HOLE, 32'd0, 1);
      add_loc(RAM_LOCS + 13, IP_BASE + 32'h8000, K_NONE, 32'd0, 1);
      add_loc(RAM_LOCS + 14, RAM_BASE + RAM_BYTES, K_NONE, 32'd0, 1);
      add_loc(RAM_LOCS + 15, 32'h2000_0000, K_NONE, 32'd0, 1);
      add_loc(RAM_LOCS + 16, IP_BASE + 32'h010, K_CONTROL, 32'd0, 1);      // START (never read)
    end
  endtask

  // ---- the program, with each response expected ----
  reg [31:0] wr_addr [0:MAX_OPS-1], wr_data [0:MAX_OPS-1];
  reg [3:0]  wr_strb [0:MAX_OPS-1];
  reg [1:0]  wr_resp [0:MAX_OPS-1];
  reg [31:0] rd_addr [0:MAX_OPS-1], rd_data [0:MAX_OPS-1];
  reg [1:0]  rd_resp [0:MAX_OPS-1];
  integer    ph_wr_end [0:PHASES-1], ph_rd_end [0:PHASES-1];
  integer    wr_total = 0, rd_total = 0;
  integer    gen_seed = SEED * 7919 + 13;

  function integer pick;  // 0..range-1
    input integer range;
    begin
      pick = {$random(gen_seed)} % range;
    end
  endfunction

  // One location, RAM-only in some phases so that long runs to one slave happen
  function integer pick_location;
    input integer ram_only;
    begin
      pick_location = ram_only ? pick(RAM_LOCS) : (pick(2) == 0 ? pick(RAM_LOCS) : RAM_LOCS + pick(LOCS - RAM_LOCS));
    end
  endfunction

  task add_write;
    input integer l;
    reg [31:0] value;
    reg [3:0] strobes;
    integer o;
    begin
      value = $random(gen_seed);
      strobes = 4'hF;
      wr_resp[wr_total] = OKAY;
      case (loc_kind[l])
        K_RAM: begin
          if (loc_known[l] && pick(2) == 0) strobes = pick(16);
          for (o = 0; o < 4; o = o + 1)
            if (strobes[o]) loc_value[l][8*o +: 8] = value[8*o +: 8];
          loc_known[l] = 1'b1;
        end
        K_OPERAND: begin
          o = loc_operand[l];
          case (pick(6))
            0: begin  // out of range: refused, nothing written
              value = o == 0 ? 32'd65537 + pick(100000) : o == 1 ? (pick(2) ? 32'd0 : 32'd1001 + pick(5000))
                      : 32'd256 + pick(1000);
              wr_resp[wr_total] = SLVERR;
            end
            1: begin  // strobes the IP refuses (two bytes apart)
              strobes = 4'b0101;
              value = 32'd1;
              wr_resp[wr_total] = SLVERR;
            end
            default: begin
              value = o == 0 ? pick(65537) : o == 1 ? 1 + pick(1000) : pick(256);
              loc_value[l] = value;
            end
          endcase
        end
        K_CONST: wr_resp[wr_total] = SLVERR;
        K_HOLE, K_NONE: wr_resp[wr_total] = DECERR;
        default: value = 32'd1;  // K_CONTROL: START, OKAY (its B with the results)
      endcase
      wr_addr[wr_total] = loc_addr[l];
      wr_data[wr_total] = value;
      wr_strb[wr_total] = strobes;
      loc_busy[l] = 1'b1;
      wr_total = wr_total + 1;
    end
  endtask

  task add_read;
    input integer l;
    begin
      rd_addr[rd_total] = loc_addr[l];
      rd_data[rd_total] = loc_value[l];
      rd_resp[rd_total] = (loc_kind[l] == K_HOLE || loc_kind[l] == K_NONE) ? DECERR : OKAY;
      rd_total = rd_total + 1;
    end
  endtask

  task build_program;
    integer p, n, l, ram_only, tries;
    begin
      for (p = 0; p < PHASES; p = p + 1) begin
        for (l = 0; l < LOCS; l = l + 1) loc_busy[l] = 1'b0;
        ram_only = pick(4) == 0;
        // the writes first (the RAM's words are all written in phase 0)
        n = p == 0 ? RAM_LOCS : 1 + pick(MAX_PER_PHASE);
        for (i = 0; i < n; i = i + 1)
          add_write(p == 0 ? i : pick_location(ram_only));
        // then reads of words this phase leaves alone (known before it)
        n = 1 + pick(MAX_PER_PHASE);
        for (i = 0; i < n; i = i + 1) begin
          tries = 0;
          l = pick_location(ram_only);
          while ((loc_busy[l] || !loc_known[l] || loc_kind[l] == K_CONTROL) && tries < 100) begin
            l = pick_location(ram_only);
            tries = tries + 1;
          end
          if (tries < 100) add_read(l);
        end
        ph_wr_end[p] = wr_total;
        ph_rd_end[p] = rd_total;
      end
    end
  endtask

  // ---- the master: five processes, one per channel ----
  integer phase = 0;                         // the phase being issued
  integer aw_next = 0, w_next = 0, b_done = 0, ar_next = 0, r_done = 0;
  integer aw_shown = 0;                      // AWs made valid (for "W before its AW")
  integer aw_switch_waits = 0, ar_switch_waits = 0;
  integer w_first = 0, max_writes = 0, max_reads = 0, b_stalled = 0, r_stalled = 0;
  integer valid_seed = SEED * 31 + 1, ready_seed = SEED * 131 + 7;
  reg started = 1'b0;

  function integer delay;                    // 0..3 cycles before a VALID (none half the time)
    input integer dummy;
    begin
      delay = {$random(valid_seed)} % 2 == 0 ? 0 : 1 + {$random(valid_seed)} % 3;
    end
  endfunction
  // READY low in bursts of 1..12 cycles, each begun in a cycle with STALL_PERCENT % chance
  integer b_hold = 0, r_hold = 0;
  function integer hold;
    input integer dummy;
    begin
      hold = {$random(ready_seed)} % 100 < STALL_PERCENT ? 1 + {$random(ready_seed)} % 12 : 0;
    end
  endfunction

  // One channel's requests in order (0 AW, 1 W, 2 AR; a process each): a request waits
  // for its phase and for fewer than MAX_IN_FLIGHT unanswered before it, its VALID rises
  // delay(0) cycles late and is held until READY. The counts aw_next, w_next, ar_next
  // (requests taken) are the scoreboard's.
  task automatic issue(input integer ch);
    integer next;
    begin
      wait (started);
      next = 0;
      while (next < (ch == 2 ? rd_total : wr_total)) begin
        while (next >= (ch == 2 ? ph_rd_end[phase] : ph_wr_end[phase]) ||
               next - (ch == 2 ? r_done : b_done) >= MAX_IN_FLIGHT) @(posedge aclk);
        #1 repeat (delay(0)) @(posedge aclk);
        #1 case (ch)
          0: begin awaddr = wr_addr[next]; awvalid = 1'b1; aw_shown = next + 1; end
          1: begin
            wdata = wr_data[next]; wstrb = wr_strb[next]; wvalid = 1'b1;
            if (aw_shown <= next) w_first = w_first + 1;
          end
          default: begin araddr = rd_addr[next]; arvalid = 1'b1; end
        endcase
        @(posedge aclk);
        while (!(ch == 0 ? awready : ch == 1 ? wready : arready)) @(posedge aclk);
        next = next + 1;
        case (ch)
          0: aw_next = next;
          1: w_next = next;
          default: ar_next = next;
        endcase
        #1 case (ch)
          0: begin awvalid = 1'b0; awaddr = 32'hDEAD_BEEF; end
          1: begin wvalid = 1'b0; wdata = 32'hDEAD_BEEF; end
          default: begin arvalid = 1'b0; araddr = 32'hDEAD_BEEF; end
        endcase
      end
    end
  endtask
  initial issue(0);
  initial issue(1);
  initial issue(2);
  // B and R: READY low at random; each response checked, in order, as it is taken
  always @(posedge aclk) begin
    if (started && bvalid && bready) begin
      if (b_done >= aw_next)
        $fatal(1, "MISMATCH a B before its AW was taken (write %0d)", b_done);
      if (bresp !== wr_resp[b_done])
        $fatal(1, "MISMATCH write %0d at 0x%08h of 0x%08h (strobes %b): BRESP %b, expected %b",
               b_done, wr_addr[b_done], wr_data[b_done], wr_strb[b_done], bresp, wr_resp[b_done]);
      b_done = b_done + 1;
    end
    if (started && rvalid && rready) begin
      if (r_done >= ar_next)
        $fatal(1, "MISMATCH an R before its AR was taken (read %0d)", r_done);
      if (rresp !== rd_resp[r_done] || (rresp == OKAY && rdata !== rd_data[r_done]))
        $fatal(1, "MISMATCH read %0d at 0x%08h: 0x%08h RRESP %b, expected 0x%08h RRESP %b",
               r_done, rd_addr[r_done], rdata, rresp, rd_data[r_done], rd_resp[r_done]);
      r_done = r_done + 1;
    end
    if (started && bvalid && !bready) b_stalled = b_stalled + 1;
    if (started && rvalid && !rready) r_stalled = r_stalled + 1;
    // a request held back because responses of another slave are still to come
    if (started && awvalid && dut.bus.wr_out != 0 && dut.bus.aw_decode != dut.bus.wr_target)
      aw_switch_waits = aw_switch_waits + 1;
    if (started && arvalid && dut.bus.rd_out != 0 && dut.bus.ar_decode != dut.bus.rd_target)
      ar_switch_waits = ar_switch_waits + 1;
    if (aw_next - b_done > max_writes) max_writes = aw_next - b_done;
    if (ar_next - r_done > max_reads) max_reads = ar_next - r_done;
    b_hold = b_hold > 0 ? b_hold - 1 : hold(0);
    r_hold = r_hold > 0 ? r_hold - 1 : hold(0);
    #1 bready = started && b_hold == 0;
    rready = started && r_hold == 0;
  end

  initial begin : watchdog
    wait (started);
    repeat (400 * PHASES + 1000) @(posedge aclk);
    $fatal(1, "MISMATCH no end within %0d cycles (phase %0d; writes issued %0d, answered %0d; reads %0d, %0d)",
           400 * PHASES + 1000, phase, aw_next, b_done, ar_next, r_done);
  end

  initial begin
    build_locations;
    build_program;
    reset_release;
    started = 1'b1;
    while (phase < PHASES) begin
      @(posedge aclk);
      if (b_done == ph_wr_end[phase] && r_done == ph_rd_end[phase]) phase = phase + 1;
    end
    $display("specular_soc_outstanding_tb: PASS (%0d phases: %0d writes, %0d reads; in flight at most %0d writes, %0d reads; W before its AW %0d times; AW and AR held back for another slave's responses %0d and %0d cycles; B held by BREADY %0d cycles, R by RREADY %0d; SEED %0d)",
             PHASES, wr_total, rd_total, max_writes, max_reads, w_first, aw_switch_waits, ar_switch_waits,
             b_stalled, r_stalled, SEED);
    $finish;
  end
endmodule

`default_nettype wire
