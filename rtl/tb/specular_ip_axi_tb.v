// Self-checking Icarus testbench of the whole IP, specular_ip_axi (docs/rtl_ip.md): an
// AXI4-Lite master that stalls every channel at random (STALL = 1; SEED) drives
//   - the reset values of every word of the map (docs/tlm.md's table, written out here);
//   - the operations of `specular_tb --format csv` (VECTORS: Core's bits), each through
//     COS, N, R, G, B and START or through the OPERANDS window, waited for by done_irq,
//     then OUT_R/G/B, REG1, REG9_PASS1 and REG9_PASS2 read and compared;
//   - misuse: every refusal of the register block (hole DECERR, the batch windows left
//     out, read-only, byte strobes, sub-word writes to a window, the range checks,
//     CONTROL's reserved bits) with STATUS.CAUSE and ERROR_ADDRESS, the operands kept,
//     W1C and sub-word merges;
//   - corner operations at cos code 1 (n = 1..10, 1000): REG9_PASS1 = 1 + 16n, ROM38_K;
//   - a read and a write issued together, and STATUS.BUSY read while an operation runs;
//     a read issued while the previous R waits.
// The AXI4-Lite rules are checked on every edge (specular_ip_axi_props.v). Stops with
// $fatal on the first mismatch. The master's tasks are axi_lite_master.vh's, the vectors'
// reader specular_vectors.vh's (both in this folder: iverilog -I).
`default_nettype none
`timescale 1ns / 1ps

module specular_ip_axi_tb;
  parameter VECTORS = "vectors.csv";
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";
  parameter STALL = 1;
  parameter SEED = 1;
  parameter MAX_VECTORS = 4096;

  `include "axi_lite_master.vh"  // aclk, aresetn, the master's signals and tasks
  wire done_irq;

  // ADDR_WIDTH 32, as the TLM `axi` target verilates it: the refusals above the map
  // (0x8000 and up, 0xDEADBEEF) reach the IP and are its to answer.
  specular_ip_axi #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE), .ADDR_WIDTH(32)) dut (
    `include "axi_lite_slave_ports.vh"
  );

  specular_ip_axi_props props (
    `include "axi_lite_check_ports.vh"
  );

  localparam [31:0] STATUS = 32'h00C, CONTROL = 32'h010, ERROR_ADDRESS = 32'h018;
  localparam [31:0] COS = 32'h020, N = 32'h024, R = 32'h028, G = 32'h02C, B = 32'h030;
  localparam [31:0] OUT_R = 32'h040, REG1 = 32'h050, REG9_PASS1_LO = 32'h054;
  localparam [31:0] ROM38_K = 32'h064, NORM39 = 32'h068;
  localparam [31:0] OPERANDS = 32'h080, RESULTS = 32'h0A0;

  // A refusal: STATUS reads error and CAUSE, ERROR_ADDRESS the offset; then cleared.
  task expect_refusal;
    input [7:0] cause;
    input [31:0] address;
    begin
      expect_read(STATUS, 32'h4 | ({24'd0, cause} << 8), OKAY);
      expect_read(ERROR_ADDRESS, address, OKAY);
      write_strobed(STATUS, 32'h0000_0400, 4'b0010, OKAY);  // a byte of 0x04: no bit of ERROR
      expect_read(STATUS, 32'h4 | ({24'd0, cause} << 8), OKAY);
      write(STATUS, 32'h4, OKAY);
      expect_read(STATUS, 32'h0, OKAY);
      expect_read(ERROR_ADDRESS, 32'h0, OKAY);
    end
  endtask

  localparam TB_NAME = "specular_ip_axi_tb";
  localparam VECTOR_COS_W = 32, VECTOR_REG9_W = 37, VECTOR_OUT_W = 32;  // the bus words
  `include "specular_vectors.vh"  // read_vectors: VECTORS into v_*[0:count-1]
  // ROM 38's table as specular_romgen writes it from the C++ tables (rtl_rom_contents
  // checks the image against them): ROM38_K after an operation is word n of bank 0
  // (CONFIG's default: patent constants and normalisation).
  reg [24:0] rom38_table [0:16383];
  initial $readmemh(ROM38_IMAGE, rom38_table);
  // ---- checks ----
  task check_reset_values;
    integer k;
    begin
      expect_read(32'h000, 32'h00059965, OKAY);  // ID
      expect_read(32'h004, 32'h00010001, OKAY);  // VERSION
      expect_read(32'h008, 32'h080D1000, OKAY);  // CONFIG (defaults)
      expect_read(STATUS, 32'h0, OKAY);
      expect_read(CONTROL, 32'h0, OKAY);
      expect_read(32'h014, 32'h0, OKAY);         // BATCH_CAPACITY: no batch window here
      expect_read(ERROR_ADDRESS, 32'h0, OKAY);
      expect_read(COS, 32'h0, OKAY);
      expect_read(N, 32'h1, OKAY);
      expect_read(R, 32'h0, OKAY);
      expect_read(G, 32'h0, OKAY);
      expect_read(B, 32'h0, OKAY);
      // the operands again, each a cycle later: reads come every 2 cycles, so a bit that
      // toggles each cycle would otherwise be seen on one phase only
      for (k = 0; k < 5; k = k + 1) begin
        cycles(1);
        expect_read(COS + 4 * k, k == 1 ? 32'h1 : 32'h0, OKAY);
      end
      for (k = 0; k < 11; k = k + 1)             // OUT_R .. NORM39 (0x040-0x068, holes DECERR)
        expect_read(OUT_R + 4 * k, 32'h0, (k == 3 || k == 19) ? DECERR : OKAY);
      write(STATUS, 32'h4, OKAY);                // the hole at 0x04C was read: clear the record
      expect_read(32'h068, 32'h0, OKAY);         // NORM39
      expect_read(32'h06C, 32'h80, OKAY);        // PIN19_H
      expect_read(32'h070, 32'h00400000, OKAY);  // PIN20_A
      expect_read(OPERANDS + 4, 32'h1, OKAY);    // N through the window
      expect_read(OPERANDS + 20, 32'h0, OKAY);   // CONTROL through the window
      if (done_irq !== 1'b0) $fatal(1, "MISMATCH done_irq high after reset");
    end
  endtask

  task wait_irq;
    integer k;
    begin
      k = 0;
      while (done_irq !== 1'b1) begin
        @(posedge aclk);
        #1 k = k + 1;
        if (k > 50) $fatal(1, "MISMATCH done_irq did not rise");
      end
    end
  endtask

  task run_vector;
    input integer i;
    input integer through_window;
    begin
      if (through_window) begin
        write(OPERANDS + 4, v_n[i], OKAY);
        write(OPERANDS + 8, v_r[i], OKAY);
        write(OPERANDS + 12, v_g[i], OKAY);
        write(OPERANDS + 16, v_b[i], OKAY);
        write(OPERANDS + 0, v_reg1[i], OKAY);
        write(OPERANDS + 20, 32'h1, OKAY);
      end else begin
        write(N, v_n[i], OKAY);
        write(R, v_r[i], OKAY);
        write(G, v_g[i], OKAY);
        write(B, v_b[i], OKAY);
        write(COS, v_reg1[i], OKAY);
        write(CONTROL, 32'h1, OKAY);
      end
      wait_irq;
      expect_read(STATUS, 32'h2, OKAY);
      expect_read(through_window ? RESULTS : OUT_R, v_out24[i], OKAY);
      expect_read((through_window ? RESULTS : OUT_R) + 4, v_out25[i], OKAY);
      expect_read((through_window ? RESULTS : OUT_R) + 8, v_out26[i], OKAY);
      expect_read(REG1, v_reg1[i], OKAY);
      expect_read(REG9_PASS1_LO, v_pass1[i][31:0], OKAY);
      expect_read(REG9_PASS1_LO + 4, v_pass1[i][63:32], OKAY);
      expect_read(REG9_PASS1_LO + 8, v_pass2[i][31:0], OKAY);
      expect_read(REG9_PASS1_LO + 12, v_pass2[i][63:32], OKAY);
      expect_read(ROM38_K, {7'd0, rom38_table[v_n[i]]}, OKAY);
      // multiplier 39's s·K·A (S10.20), from Core's real
      expect_read(NORM39, $rtoi(v_norm[i] * 1048576.0), OKAY);
      write(STATUS, 32'h2, OKAY);  // W1C: done_irq falls
      @(posedge aclk);
      #1 if (done_irq !== 1'b0) $fatal(1, "MISMATCH done_irq still high after W1C of DONE");
    end
  endtask

  // Corner operations the random draws almost never reach, each at cos code 1 = 2^-16:
  // log2 cos = -16 exactly, so register 9 after pass 1 = a - n*log2 cos = 1 + 16n (a = 1.0),
  // exact in S14.22. n = 1..10: ROM 38's largest words (bank 0 words 2 and 5..10 have
  // K's bit 15, 2^-1 in U9.16, set; the vectors draw n <= 10 once in 300); n = 1000:
  // register 9 = 16001, its bit 35 (2^13) set (the vectors' largest is below 2^13).
  task check_corners;
    integer k, n;
    reg [36:0] pass1;
    begin
      for (k = 1; k <= 11; k = k + 1) begin
        n = k == 11 ? 1000 : k;
        pass1 = (37'd1 + 37'd16 * n) << 22;
        write(N, n, OKAY);
        write(COS, 32'd1, OKAY);
        write(CONTROL, 32'h1, OKAY);
        wait_irq;
        expect_read(REG1, 32'd1, OKAY);
        expect_read(REG9_PASS1_LO, pass1[31:0], OKAY);
        expect_read(REG9_PASS1_LO + 4, {27'd0, pass1[36:32]}, OKAY);
        expect_read(ROM38_K, {7'd0, rom38_table[n]}, OKAY);
        write(STATUS, 32'h2, OKAY);
      end
    end
  endtask

  task check_misuse;
    reg [31:0] data;
    reg [1:0] response;
    integer k, j;
    begin
      write(N, 32'd36, OKAY);
      write(G, 32'd0, OKAY);
      write(N, 32'd0, SLVERR);            expect_refusal(8'd2, N);
      write(N, 32'd1001, SLVERR);         expect_refusal(8'd2, N);
      write(COS, 32'd65537, SLVERR);      expect_refusal(8'd1, COS);
      write(COS, 32'd65536, OKAY);
      write(G, 32'd256, SLVERR);          expect_refusal(8'd3, G);
      write(OPERANDS + 8, 32'd300, SLVERR); expect_refusal(8'd3, OPERANDS + 8);
      write(32'h000, 32'd1, SLVERR);      expect_refusal(8'd4, 32'h000);
      // every read-only word of docs/tlm.md's map: CONFIG, BATCH_CAPACITY, ERROR_ADDRESS,
      // OUT_R .. PIN20_A (0x04C is a hole), the RESULTS window (ID above, VERSION here)
      write(32'h004, 32'd1, SLVERR);      expect_refusal(8'd4, 32'h004);
      write(32'h008, 32'd1, SLVERR);      expect_refusal(8'd4, 32'h008);
      write(32'h014, 32'd1, SLVERR);      expect_refusal(8'd4, 32'h014);
      for (k = 0; k < 13; k = k + 1)
        if (k != 3) begin
          write(OUT_R + 4 * k, 32'd1, SLVERR); expect_refusal(8'd4, OUT_R + 4 * k);
        end
      for (k = 1; k < 3; k = k + 1) begin
        write(RESULTS + 4 * k, 32'd1, SLVERR); expect_refusal(8'd4, RESULTS + 4 * k);
      end
      // every bit above COS's 2^16 alone: out of range, whichever bit it is
      for (k = 17; k < 32; k = k + 1) begin
        write(COS, 32'd1 << k, SLVERR);   expect_refusal(8'd1, COS);
      end
      write(RESULTS, 32'd1, SLVERR);      expect_refusal(8'd4, RESULTS);
      write(ERROR_ADDRESS, 32'd1, SLVERR); expect_refusal(8'd4, ERROR_ADDRESS);
      write(CONTROL, 32'h2, SLVERR);      expect_refusal(8'd5, CONTROL);
      write(CONTROL, 32'h21, SLVERR);     expect_refusal(8'd5, CONTROL);
      write(CONTROL, 32'h8000_0001, SLVERR); expect_refusal(8'd5, CONTROL);
      // every address bit above the map's: a hole, whichever register its low bits name
      for (k = 15; k < 32; k = k + 1)
        for (j = 0; j < 43; j = j + 1) begin   // every word up to RESULTS' last
          expect_read(32'd1 << k | 4 * j, 32'd0, DECERR); expect_refusal(8'd7, 32'd1 << k | 4 * j);
        end
      for (k = 15; k < 32; k = k + 1)
        for (j = 0; j < 43; j = j + 1) begin   // and every write there, whatever it carries
          write(32'd1 << k | 4 * j, 32'd0, DECERR); expect_refusal(8'd7, 32'd1 << k | 4 * j);
        end
      write(32'h01C, 32'd1, DECERR);      expect_refusal(8'd7, 32'h01C);   // a hole
      expect_read(32'h034, 32'd0, DECERR); expect_refusal(8'd7, 32'h034);
      write(32'h1000, 32'd5, DECERR);     expect_refusal(8'd7, 32'h1000);  // BATCH_COS: left out
      expect_read(32'h4000, 32'd0, DECERR); expect_refusal(8'd7, 32'h4000); // BATCH_OUT: left out
      expect_read(32'h8000, 32'd0, DECERR); expect_refusal(8'd7, 32'h8000);
      write(32'hFFFF_FFFC, 32'd0, DECERR); expect_refusal(8'd7, 32'hFFFF_FFFC);
      write_strobed(N, 32'd5, 4'b0101, SLVERR); expect_refusal(8'd9, N);
      write_strobed(N, 32'd5, 4'b0000, SLVERR); expect_refusal(8'd9, N);
      write_strobed(N, 32'd5, 4'b0111, SLVERR); expect_refusal(8'd9, N);
      write_strobed(OPERANDS + 4, 32'd5, 4'b0001, SLVERR); expect_refusal(8'd8, OPERANDS + 4);
      write_strobed(32'h041, 32'h0000_0100, 4'b0010, SLVERR); expect_refusal(8'd4, 32'h041);
      // the operands kept their values through every refusal
      expect_read(N, 32'd36, OKAY);
      expect_read(COS, 32'd65536, OKAY);
      expect_read(G, 32'd0, OKAY);
      // sub-word writes merge into the operand registers, checked as a whole word
      write_strobed(N + 1, 32'h0000_0300, 4'b0010, OKAY);       // N = 0x324 = 804
      expect_read(N, 32'd804, OKAY);
      write_strobed(N + 2, 32'h0001_0000, 4'b1100, SLVERR);     // 0x10324: above 1000
      expect_refusal(8'd2, N + 2);
      expect_read(N, 32'd804, OKAY);
      write_strobed(R, 32'h0000_00FF, 4'b0001, OKAY);
      write_strobed(R + 1, 32'h0000_0100, 4'b0010, SLVERR);      // 0x1FF
      expect_refusal(8'd3, R + 1);
      expect_read(R, 32'd255, OKAY);
      write_strobed(R + 1, 32'h0000_0000, 4'b0010, OKAY);       // byte 1 = 0: R keeps 0xFF
      expect_read(R, 32'd255, OKAY);
      // a START by a byte write, the DONE flag cleared by a byte write
      write_strobed(CONTROL, 32'h0000_0001, 4'b0001, OKAY);
      wait_irq;
      expect_read(STATUS, 32'h2, OKAY);
      write(STATUS, 32'h4, OKAY);                // ERROR alone: DONE stays
      expect_read(STATUS, 32'h2, OKAY);
      write(STATUS, 32'hFFFF_FFF9, OKAY);        // every bit but DONE and ERROR: nothing
      expect_read(STATUS, 32'h2, OKAY);
      write_strobed(STATUS, 32'h0000_0002, 4'b0001, OKAY);
      expect_read(STATUS, 32'h0, OKAY);
      if (done_irq !== 1'b0) $fatal(1, "MISMATCH done_irq high after a byte W1C of DONE");
      // CONTROL written with 0 starts nothing and is accepted
      write(CONTROL, 32'h0, OKAY);
      cycles(8);
      if (done_irq !== 1'b0) $fatal(1, "MISMATCH CONTROL = 0 started an operation");
      // A refusal after an error replaces the record (cause, address)
      write(N, 32'd0, SLVERR);
      write(B, 32'd999, SLVERR);
      expect_refusal(8'd3, B);
      read_raw(STATUS, data, response);
    end
  endtask

  // Writes queued behind responses the master has not taken (AXI4-Lite lets it issue the
  // next AW and W meanwhile; the slave holds one of each and stalls the rest).
  // (The held-back B waits with `repeat`, not `cycles`: a task is static, and the other
  // branches' calls of `cycles` would overwrite its count.)
  task check_queued_writes;
    reg [1:0] r1, r2, r3;
    begin
      // a refusal's B taken late: BRESP stays SLVERR while it waits (props check it)
      fork
        send_aw(N);
        send_w(32'd0, 4'b1111);
        begin repeat (12) @(posedge aclk); #1 take_b(r1); end
      join
      if (r1 !== SLVERR) $fatal(1, "MISMATCH a late-taken refusal's B: %b, expected SLVERR", r1);
      expect_refusal(8'd2, N);
      // three writes, B held back 20 cycles: the third W must wait, not replace the second's data
      fork
        begin send_aw(R); send_aw(G); send_aw(B); end
        begin send_w(32'd1, 4'b1111); send_w(32'd2, 4'b1111); send_w(32'd3, 4'b1111); end
        begin repeat (20) @(posedge aclk); #1 take_b(r1); take_b(r2); take_b(r3); end
      join
      if (r1 !== OKAY || r2 !== OKAY || r3 !== OKAY)
        $fatal(1, "MISMATCH queued writes' responses %b %b %b, expected OKAY", r1, r2, r3);
      expect_read(R, 32'd1, OKAY);
      expect_read(G, 32'd2, OKAY);
      expect_read(B, 32'd3, OKAY);
      // a write issued while an operation runs is done after it: the START's B (OKAY, with
      // the results) comes first, then the write's (a refusal here)
      fork send_aw(CONTROL); send_w(32'h1, 4'b1111); join
      cycles(1);
      fork send_aw(N); send_w(32'd0, 4'b1111); join
      take_b(r1);
      take_b(r2);
      if (r1 !== OKAY || r2 !== SLVERR)
        $fatal(1, "MISMATCH a write during an operation: B %b then %b, expected OKAY then SLVERR", r1, r2);
      expect_read(STATUS, 32'h2 | 32'h4 | (32'd2 << 8), OKAY);
      write(STATUS, 32'h2, OKAY);
      expect_refusal(8'd2, N);
      // a byte-3 write whose other lanes carry data: those bits are not written
      write_strobed(N + 3, 32'h0020_0000, 4'b1000, OKAY);
      expect_read(N, 32'd804, OKAY);
    end
  endtask

  // A read with RREADY raised with ARVALID and no stall: returns at the edge that takes
  // R (RDATA and RRESP there), RREADY still high (the caller lowers it).
  task read_unstalled;
    input [31:0] address;
    begin
      araddr = address;
      arvalid = 1'b1;
      rready = 1'b1;
      @(posedge aclk);
      while (!arready) @(posedge aclk);
      #1 arvalid = 1'b0;
      @(posedge aclk);
      while (!rvalid) @(posedge aclk);
    end
  endtask

  // A write and a read issued in the same cycle; STATUS.BUSY seen during an operation.
  task check_concurrency;
    reg [31:0] data;
    integer busy_seen;
    reg [31:0] out_before [0:2];
    begin
      read_raw(OUT_R, out_before[0], data[1:0]);
      read_raw(OUT_R + 4, out_before[1], data[1:0]);
      read_raw(OUT_R + 8, out_before[2], data[1:0]);
      fork
        write(CONTROL, 32'h1, OKAY);
        begin
          // the START's response comes with the results: meanwhile reads are served
          // (without stalls here, 2 cycles each, so that one falls inside the operation)
          busy_seen = 0;
          data = 32'd0;
          while (data[1] !== 1'b1) begin
            read_unstalled(STATUS);
            data = rdata;
            if (rresp !== OKAY) $fatal(1, "MISMATCH STATUS read refused during an operation");
            if (data[0] === 1'b1) busy_seen = busy_seen + 1;
            if (data[0] === 1'b1 && busy_seen == 1) begin  // OUT_* hold the last results meanwhile
              #1 rready = 1'b0;
              read_unstalled(OUT_R + 4 * (busy_seen % 3));
              if (rdata !== out_before[busy_seen % 3])
                $fatal(1, "MISMATCH OUT word %0d changed during an operation", busy_seen % 3);
            end
            #1 rready = 1'b0;
          end
          if (busy_seen == 0) $fatal(1, "MISMATCH STATUS.BUSY never read 1 during an operation");
        end
      join
      expect_read(STATUS, 32'h2, OKAY);
      write(STATUS, 32'h2, OKAY);
      fork
        write(R, 32'd17, OKAY);
        expect_read(N, 32'd804, OKAY);
      join
      fork
        write(G, 32'd18, OKAY);
        expect_read(32'h01C, 32'd0, DECERR);
      join
      expect_refusal(8'd7, 32'h01C);
      expect_read(G, 32'd18, OKAY);
      check_queued_writes;
    end
  endtask

  // A read issued while the previous one's R waits (RREADY low): AXI4-Lite lets the master
  // present the next AR at once; the slave holds one read (ARREADY low while RVALID), so
  // the waiting R keeps the first read's data and the second read is taken after it.
  task check_read_behind_r;
    begin
      write(N, 32'd513, OKAY);
      write(R, 32'd200, OKAY);
      araddr = N;
      arvalid = 1'b1;
      @(posedge aclk);
      while (!arready) @(posedge aclk);
      #1 araddr = R;                        // the next AR at once: ARVALID stays high
      repeat (4) @(posedge aclk);           // the first R waits
      #1 if (rvalid !== 1'b1 || arready !== 1'b0 || rdata !== 32'd513 || rresp !== OKAY)
        $fatal(1, "MISMATCH a read behind a waiting R: RVALID %b ARREADY %b RDATA 0x%08h RRESP %b, expected 1 0 0x00000201 00",
               rvalid, arready, rdata, rresp);
      rready = 1'b1;
      @(posedge aclk);                      // the first R taken
      #1 rready = 1'b0;
      @(posedge aclk);
      while (!arready) @(posedge aclk);     // the second AR taken
      #1 arvalid = 1'b0;
      araddr = 32'hDEAD_BEEF;
      rready = 1'b1;
      @(posedge aclk);
      while (!rvalid) @(posedge aclk);
      if (rdata !== 32'd200 || rresp !== OKAY)
        $fatal(1, "MISMATCH the read behind a waiting R: 0x%08h response %b, expected 0x000000c8 00", rdata, rresp);
      #1 rready = 1'b0;
    end
  endtask

  // A channel that never answers is a failure, not a hang (a mutant's READY or VALID stuck
  // at 0): a run takes about 230 cycles per operation with stalls, misuse included; the
  // limit is several times that.
  reg vectors_read = 1'b0;
  initial begin : watchdog
    wait (vectors_read);
    repeat (1000 * (count + 100)) @(posedge aclk);
    $fatal(1, "MISMATCH no end within %0d cycles: a channel hangs", 1000 * (count + 100));
  end

  integer i;
  initial begin
    read_vectors;
    vectors_read = 1'b1;
    reset_release;
    check_reset_values;
    for (i = 0; i < count; i = i + 1) run_vector(i, i % 3 == 2);
    check_corners;
    check_misuse;
    check_concurrency;
    check_read_behind_r;
    $display("specular_ip_axi_tb: PASS (%0d operations, STALL %0d)", count, STALL);
    $finish;
  end
endmodule

`default_nettype wire
