// Replays a trace of bus accesses into specular_soc and compares every response and read
// value with the recording (docs/rtl_ip.md, "Placing the IP in an SoC"). The trace is the
// contract with the recorder: one access per line, five whitespace-separated hex fields,
// no comments,
//     <op> <offset> <data> <strb> <resp>
// op 0 a read (data: the value the recording read; strb f), 1 a write (data and strb as
// written); offset from the IP's base (the bench adds IP_BASE); resp 0 OKAY, 2 SLVERR,
// 3 DECERR. A read's data is compared when the recording's response is OKAY (a refused
// read's data is no part of the contract). The master is axi_lite_master.vh's, in order
// (STALL, SEED: random stalls on every channel). Every mismatch is printed; the summary
// line counts accesses replayed, reads compared and mismatches; PASS only with none.
// A malformed line stops the replay naming the line and the allowed values.
`default_nettype none
`timescale 1ns / 1ps

module specular_soc_replay_tb;
  parameter TRACE = "trace.txt";
  parameter STALL = 0;
  parameter SHOWN = 20;  // mismatches printed in full

  localparam SOC_OPEN_WRITES = 2, SOC_OPEN_READS = 1;  // specular_soc_dut.vh's soc_port
  `include "specular_soc_dut.vh"  // SEED, the master (axi_lite_master.vh), the SoC


  integer accesses = 0, reads_compared = 0, mismatches = 0;
  task mismatch;
    input integer line;
    input [31:0] offset;
    input [8*5-1:0] what;
    input [31:0] got_data;
    input [1:0] got_resp;
    input [31:0] want_data;
    input [1:0] want_resp;
    begin
      mismatches = mismatches + 1;
      if (mismatches <= SHOWN)
        $display("MISMATCH line %0d: %0s offset 0x%08h: 0x%08h resp %0d, recorded 0x%08h resp %0d",
                 line, what, offset, got_data, got_resp, want_data, want_resp);
    end
  endtask

  reg [8*1024-1:0] text;
  integer fd, fields, line;
  reg [31:0] op, offset, data, strb, resp, extra, got_data;
  // A line of nothing but blanks (the last may end the file)
  function blank;
    input [8*1024-1:0] t;
    integer k;
    begin
      blank = 1'b1;
      for (k = 0; k < 1024; k = k + 1)
        if (t[8*k +: 8] != 8'h00 && t[8*k +: 8] != " " && t[8*k +: 8] != 8'h09 &&
            t[8*k +: 8] != 8'h0A && t[8*k +: 8] != 8'h0D)
          blank = 1'b0;
    end
  endfunction
  reg [1:0] got_resp, got_bresp;
  initial begin : replay
    fd = $fopen(TRACE, "r");
    if (fd == 0) $fatal(1, "specular_soc_replay_tb: cannot read the trace %0s", TRACE);
    reset_release;
    line = 0;
    while (!$feof(fd)) begin
      text = 0;
      fields = $fgets(text, fd);
      if (fields > 0) begin
        line = line + 1;
        op = 0; offset = 0; data = 0; strb = 0; resp = 0;
        fields = $sscanf(text, "%h %h %h %h %h %h", op, offset, data, strb, resp, extra);
        // A well-formed line first: blank() walks all 1 024 characters, which for every
        // line was 94 % of the replay's time in Icarus (a tenth of the driver's trace:
        // 28.1 CPU-s before, 1.6 after).
        if (fields != 5 || ^{op, offset, data, strb, resp} === 1'bx) begin
          if (blank(text)) begin
            // nothing to replay
          end else if (fields != 5) begin
            $fatal(1, "specular_soc_replay_tb: %0s line %0d: %0d fields, allowed 5 hex (<op> <offset> <data> <strb> <resp>)",
                   TRACE, line, fields < 0 ? 0 : fields);
          end else begin
            $fatal(1, "specular_soc_replay_tb: %0s line %0d: a field with x or z, allowed hex digits 0-9 a-f",
                   TRACE, line);
          end
        end else begin
          if (op > 1)
            $fatal(1, "specular_soc_replay_tb: %0s line %0d: op %0h (allowed: 0 read, 1 write)", TRACE, line, op);
          if (strb > 32'hF)
            $fatal(1, "specular_soc_replay_tb: %0s line %0d: strb %0h (allowed: 0 to f)", TRACE, line, strb);
          if (resp != 0 && resp != 2 && resp != 3)
            $fatal(1, "specular_soc_replay_tb: %0s line %0d: resp %0h (allowed: 0 OKAY, 2 SLVERR, 3 DECERR)",
                   TRACE, line, resp);
          accesses = accesses + 1;
          if (op == 0) begin
            read_raw(IP_BASE + offset, got_data, got_resp);
            if (got_resp !== resp[1:0])
              mismatch(line, offset, "read", got_data, got_resp, data, resp[1:0]);
            else if (resp == 0) begin
              reads_compared = reads_compared + 1;
              if (got_data !== data) mismatch(line, offset, "read", got_data, got_resp, data, resp[1:0]);
            end
          end else begin
            fork
              send_aw(IP_BASE + offset);
              send_w(data, strb[3:0]);
              take_b(got_bresp);
            join
            if (got_bresp !== resp[1:0]) mismatch(line, offset, "write", data, got_bresp, data, resp[1:0]);
          end
        end
      end
    end
    $fclose(fd);
    $display("specular_soc_replay_tb: %0d accesses replayed, %0d reads compared, %0d mismatches (%0s, IP_BASE 0x%08h, STALL %0d)",
             accesses, reads_compared, mismatches, TRACE, IP_BASE, STALL);
    if (accesses == 0) $fatal(1, "specular_soc_replay_tb: no access in %0s", TRACE);
    if (mismatches != 0) $fatal(1, "specular_soc_replay_tb: FAIL (%0d mismatches)", mismatches);
    $display("specular_soc_replay_tb: PASS");
    $finish;
  end
endmodule

`default_nettype wire
