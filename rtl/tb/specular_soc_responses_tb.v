// Directed tests of every AXI4-Lite response of specular_soc with the IP at a non-zero
// base (docs/rtl_ip.md, "Placing the IP in an SoC"), through the in-order master of
// axi_lite_master.vh (STALL = 1: random stalls on every channel):
//   - OKAY: ID and VERSION at IP_BASE, the RAM written and read back with byte strobes
//     (its first and last word);
//   - SLVERR from the IP: N = 1001 and a write to read-only ID, with STATUS.CAUSE and
//     ERROR_ADDRESS read back (the offset in the map, never IP_BASE + offset);
//   - DECERR from the IP: holes inside its window (0x1C, 0x7FFC), cause address;
//   - DECERR from the interconnect: addresses no slave has (just above the IP's window,
//     above the RAM's, 0x2000_0000), RDATA 0, and the IP's STATUS untouched;
//   - operations at the base: COS, N, R, G, B, START, then OUT_R/G/B compared with
//     `specular_tb --format csv` (VECTORS: Core's bits), done_irq high until DONE's W1C.
// The AXI4-Lite rules are checked each edge (specular_ip_axi_props.v) on the SoC's port
// and on the IP's. Stops with $fatal on the first mismatch.
`default_nettype none
`timescale 1ns / 1ps

module specular_soc_responses_tb;
  parameter VECTORS = "vectors.csv";
  parameter MAX_VECTORS = 64;
  parameter STALL = 1;

  localparam SOC_OPEN_WRITES = 2, SOC_OPEN_READS = 1;  // specular_soc_dut.vh's soc_port
  `include "specular_soc_dut.vh"  // SEED, the master (axi_lite_master.vh), the SoC
  localparam TB_NAME = "specular_soc_responses_tb";
  localparam VECTOR_COS_W = 32, VECTOR_REG9_W = 37, VECTOR_OUT_W = 32;  // the bus words
  `include "specular_vectors.vh"

  // The rules on the IP's port too (the SoC's: specular_soc_dut.vh).
  `include "specular_soc_ip_port.vh"

  // The IP's registers (docs/tlm.md's map), as offsets
  localparam [31:0] ID = 32'h000, VERSION = 32'h004, STATUS = 32'h00C, CONTROL = 32'h010;
  localparam [31:0] ERROR_ADDRESS = 32'h018, COS = 32'h020, N = 32'h024, R = 32'h028;
  localparam [31:0] G = 32'h02C, B = 32'h030, OUT_R = 32'h040, OUT_G = 32'h044, OUT_B = 32'h048;

  // A refusal by the IP: STATUS holds ERROR (bit 2) and CAUSE, ERROR_ADDRESS the offset;
  // then ERROR cleared (W1C) and both read 0.
  task expect_refusal;
    input [7:0] cause;
    input [31:0] offset;
    begin
      expect_read(IP_BASE + STATUS, 32'h4 | ({24'd0, cause} << 8), OKAY);
      expect_read(IP_BASE + ERROR_ADDRESS, offset, OKAY);
      write(IP_BASE + STATUS, 32'h4, OKAY);
      expect_read(IP_BASE + STATUS, 32'h0, OKAY);
      expect_read(IP_BASE + ERROR_ADDRESS, 32'h0, OKAY);
    end
  endtask

  // An address no slave has: DECERR from the interconnect, RDATA 0, the IP untouched.
  task expect_interconnect_decerr;
    input [31:0] address;
    reg [31:0] data;
    reg [1:0] response;
    begin
      read_raw(address, data, response);
      if (response !== DECERR || data !== 32'd0)
        $fatal(1, "MISMATCH read 0x%08h: 0x%08h response %b, expected 0 DECERR from the interconnect",
               address, data, response);
      write(address, 32'hFFFF_FFFF, DECERR);
      expect_read(IP_BASE + STATUS, 32'h0, OKAY);
      expect_read(IP_BASE + ERROR_ADDRESS, 32'h0, OKAY);
    end
  endtask

  task check_okay;
    begin
      expect_read(IP_BASE + ID, 32'h00059965, OKAY);
      expect_read(IP_BASE + VERSION, 32'h00010001, OKAY);
      expect_read(IP_BASE + N, 32'h1, OKAY);          // N's reset
      write(RAM_BASE + 32'h10, 32'h1234_5678, OKAY);
      expect_read(RAM_BASE + 32'h10, 32'h1234_5678, OKAY);
      write_strobed(RAM_BASE + 32'h10, 32'hAABB_CCDD, 4'b0101, OKAY);
      expect_read(RAM_BASE + 32'h10, 32'h12BB_56DD, OKAY);
      write_strobed(RAM_BASE + 32'h12, 32'hEEFF_0000, 4'b1100, OKAY);
      expect_read(RAM_BASE + 32'h10, 32'hEEFF_56DD, OKAY);
      write_strobed(RAM_BASE + 32'h10, 32'h0000_0000, 4'b0000, OKAY);  // no lane: nothing
      expect_read(RAM_BASE + 32'h10, 32'hEEFF_56DD, OKAY);
      write(RAM_BASE, 32'hCAFE_0000, OKAY);
      write(RAM_BASE + RAM_BYTES - 4, 32'h0000_F00D, OKAY);
      expect_read(RAM_BASE, 32'hCAFE_0000, OKAY);
      expect_read(RAM_BASE + RAM_BYTES - 4, 32'h0000_F00D, OKAY);
      expect_read(RAM_BASE + 32'h10, 32'hEEFF_56DD, OKAY);
    end
  endtask

  task check_slverr;
    begin
      write(IP_BASE + N, 32'd1001, SLVERR);
      expect_refusal(8'd2, N);                        // cause value_n, ERROR_ADDRESS 0x24
      expect_read(IP_BASE + N, 32'h1, OKAY);          // kept
      write(IP_BASE + ID, 32'd1, SLVERR);
      expect_refusal(8'd4, ID);                       // cause read_only
      write_strobed(IP_BASE + N, 32'd5, 4'b0101, SLVERR);
      expect_refusal(8'd9, N);                        // cause byte_enable
    end
  endtask

  task check_decerr;
    begin
      // holes inside the IP's window: the IP's own DECERR, cause address (7)
      expect_read(IP_BASE + 32'h1C, 32'd0, DECERR);
      expect_refusal(8'd7, 32'h1C);
      write(IP_BASE + 32'h1C, 32'd1, DECERR);
      expect_refusal(8'd7, 32'h1C);
      expect_read(IP_BASE + 32'h7FFC, 32'd0, DECERR);
      expect_refusal(8'd7, 32'h7FFC);
      // no slave: the interconnect's DECERR, the IP sees nothing
      expect_interconnect_decerr(IP_BASE + 32'h8000);  // the ID's alias one window up
      expect_interconnect_decerr(IP_BASE - 4);
      expect_interconnect_decerr(RAM_BASE + RAM_BYTES);
      expect_interconnect_decerr(32'h2000_0000);
      expect_interconnect_decerr(32'hFFFF_FFFC);
    end
  endtask

  task run_vector;
    input integer i;
    begin
      write(IP_BASE + COS, v_reg1[i], OKAY);
      write(IP_BASE + N, v_n[i], OKAY);
      write(IP_BASE + R, v_r[i], OKAY);
      write(IP_BASE + G, v_g[i], OKAY);
      write(IP_BASE + B, v_b[i], OKAY);
      write(IP_BASE + CONTROL, 32'h1, OKAY);          // START: its B comes with the results
      if (done_irq !== 1'b1) $fatal(1, "MISMATCH done_irq low after the START's response");
      expect_read(IP_BASE + STATUS, 32'h2, OKAY);     // DONE
      expect_read(IP_BASE + OUT_R, v_out24[i], OKAY);
      expect_read(IP_BASE + OUT_G, v_out25[i], OKAY);
      expect_read(IP_BASE + OUT_B, v_out26[i], OKAY);
      write(IP_BASE + STATUS, 32'h2, OKAY);           // W1C of DONE: done_irq falls
      @(posedge aclk);
      #1 if (done_irq !== 1'b0) $fatal(1, "MISMATCH done_irq still high after W1C of DONE");
    end
  endtask

  initial begin : watchdog
    repeat (200000) @(posedge aclk);
    $fatal(1, "MISMATCH no end within 200000 cycles: a channel hangs");
  end

  integer i;
  initial begin
    read_vectors;
    reset_release;
    check_okay;
    check_slverr;
    check_decerr;
    for (i = 0; i < count; i = i + 1) run_vector(i);
    $display("specular_soc_responses_tb: PASS (IP_BASE 0x%08h, RAM_BASE 0x%08h, %0d operations, STALL %0d)",
             IP_BASE, RAM_BASE, count, STALL);
    $finish;
  end
endmodule

`default_nettype wire
