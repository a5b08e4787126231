// Self-checking testbench of any design variant's top behind the common ports
// (docs/design_space/flow.md, "Conventions (every variant follows them)"), in RTL (Icarus) and at gate level with the SDF
// (scripts/flows/gatelevel/gatesim.sh, `define GATE_LEVEL). One testbench for every variant: the top's
// module name is the macro VARIANT_TOP (-DVARIANT_TOP=specular_NAME).
//
// VECTORS: one operation per line, hex: cos n r g b lobe out_r out_g out_b (the expected
// lobe and pins 24-26 from the C++ model, tools/variant_vectors/specular_variant_vectors).
// Start is held high with the next operands while any remain; a start counts as taken
// at a rising edge where ready was 1 just before it, and the next operands then come
// 3T/4 after that edge (the SDC's input delay). Outputs are read just before each rising
// edge (output delay 0: settled by the next edge); each valid result must equal the
// next expected one, in order. Reported at the end:
//   clocks per result: (edge of the last valid - edge of the first) / (results - 1),
//                      starts streamed back to back;
//   latency: edges from the edge a start is taken to the edge that raises its valid
//            (the largest over the run; the first operation's too).
`timescale 1ns / 1ps
`ifndef VARIANT_TOP
`define VARIANT_TOP specular_patent
`endif

module specular_variant_tb;
  parameter VECTORS = "vectors.txt";
  parameter real T = 10.0;          // clock period (ns)
  parameter MAX_VECTORS = 8192;
  parameter TIMEOUT_CLOCKS = 4096;  // no valid for this long: fail
  // gatesim.sh passes the device testbench's policy parameters to every testbench;
  // the variants are built for the default configuration and ignore them.
  parameter PINS_IMAGE = "pins.hex";
  parameter LITERAL = 0, CONSTANTS = 0, NORMALISATION = 0;
  localparam real SAMPLE_BEFORE = 0.001;  // ns before the rising edge outputs are read

  reg clk = 1'b0, reset_n = 1'b0, start = 1'b0;
  reg [16:0] cos = 17'd0;
  reg [9:0] n = 10'd1;
  reg [7:0] r = 8'd0, g = 8'd0, b = 8'd0;
  wire ready, valid;
  wire signed [30:0] lobe;
  wire signed [31:0] out_r, out_g, out_b;

  `VARIANT_TOP dut (.clk(clk), .reset_n(reset_n), .start(start), .ready(ready),
                    .cos(cos), .n(n), .r(r), .g(g), .b(b), .valid(valid), .lobe(lobe),
                    .out_r(out_r), .out_g(out_g), .out_b(out_b));
`ifdef GATE_LEVEL
  initial $sdf_annotate(`SDF_FILE, dut);
`endif

  // The vectors.
  reg [16:0] v_cos [0:MAX_VECTORS-1];
  reg [9:0] v_n [0:MAX_VECTORS-1];
  reg [7:0] v_r [0:MAX_VECTORS-1], v_g [0:MAX_VECTORS-1], v_b [0:MAX_VECTORS-1];
  reg [30:0] v_lobe [0:MAX_VECTORS-1];
  reg [31:0] v_out [0:3*MAX_VECTORS-1];
  integer count, fd, got;
  reg [31:0] f0, f1, f2, f3, f4, f5, f6, f7, f8;
  initial begin
    count = 0;
    fd = $fopen(VECTORS, "r");
    if (fd == 0) begin
      $display("FATAL specular_variant_tb: cannot open %0s", VECTORS);
      $finish;
    end
    got = 9;
    while (got == 9 && count < MAX_VECTORS) begin
      got = $fscanf(fd, "%h %h %h %h %h %h %h %h %h\n", f0, f1, f2, f3, f4, f5, f6, f7, f8);
      if (got == 9) begin
        v_cos[count] = f0[16:0]; v_n[count] = f1[9:0];
        v_r[count] = f2[7:0]; v_g[count] = f3[7:0]; v_b[count] = f4[7:0];
        v_lobe[count] = f5[30:0];
        v_out[3*count] = f6; v_out[3*count+1] = f7; v_out[3*count+2] = f8;
        count = count + 1;
      end
    end
    $fclose(fd);
    if (count == 0) begin
      $display("FATAL specular_variant_tb: no vectors in %0s", VECTORS);
      $finish;
    end
  end

  always #(T / 2.0) clk = ~clk;

  // Edge k rises at k*T; the testbench acts at k*T - SAMPLE_BEFORE (read) and at
  // k*T + 3T/4 (drive).
  integer edge_k, taken, checked, last_valid_edge, first_valid_edge, latency, first_latency;
  integer idle;
  integer take_edge [0:MAX_VECTORS-1];
  reg fail;
  initial begin
    edge_k = 0; taken = 0; checked = 0; latency = 0; first_latency = -1;
    first_valid_edge = -1; last_valid_edge = -1; idle = 0; fail = 1'b0;
    #(0.75 * T);
    // Reset for two edges (synchronous), then streaming.
    reset_n = 1'b0;
    #(2.0 * T);
    reset_n = 1'b1;
    start = 1'b1;
    cos = v_cos[0]; n = v_n[0]; r = v_r[0]; g = v_g[0]; b = v_b[0];
    forever begin
      // just before the next rising edge: read
      #(0.25 * T - SAMPLE_BEFORE);
      edge_k = edge_k + 1;
      if (valid === 1'b1) begin
        check_result;
      end else if (valid !== 1'b0 && reset_n === 1'b1 && edge_k > 4) begin
        $display("MISMATCH vector %0d valid: got %b, want 0 or 1", checked, valid);
        finish_fail;
      end
      if (start && ready === 1'b1) begin
        take_edge[taken] = edge_k;
        taken = taken + 1;
      end
      idle = (valid === 1'b1) ? 0 : idle + 1;
      if (idle > TIMEOUT_CLOCKS) begin
        $display("FATAL specular_variant_tb: no valid for %0d clocks (%0d of %0d results)",
                 TIMEOUT_CLOCKS, checked, count);
        finish_fail;
      end
      // 3T/4 after the edge: the next operands, or start low when all are taken
      #(SAMPLE_BEFORE + 0.75 * T);
      if (taken < count) begin
        cos = v_cos[taken]; n = v_n[taken]; r = v_r[taken]; g = v_g[taken]; b = v_b[taken];
      end else begin
        start = 1'b0;
        cos = 17'bx; n = 10'bx; r = 8'bx; g = 8'bx; b = 8'bx;
      end
    end
  end

  // valid read just before edge_k: raised by edge_k - 1.
  task check_result;
    integer k, e;
    begin
      k = checked;
      e = edge_k - 1;
      if (k >= taken) begin
        $display("MISMATCH vector %0d valid: got 1 before its start was taken", k);
        finish_fail;
      end
      if (lobe !== v_lobe[k])
        report_mismatch(k, "lobe", {1'b0, lobe}, {1'b0, v_lobe[k]});
      if (out_r !== v_out[3*k]) report_mismatch(k, "pin 24 (out_r)", out_r, v_out[3*k]);
      if (out_g !== v_out[3*k+1]) report_mismatch(k, "pin 25 (out_g)", out_g, v_out[3*k+1]);
      if (out_b !== v_out[3*k+2]) report_mismatch(k, "pin 26 (out_b)", out_b, v_out[3*k+2]);
      if (e - take_edge[k] > latency) latency = e - take_edge[k];
      if (first_latency < 0) first_latency = e - take_edge[k];
      if (first_valid_edge < 0) first_valid_edge = e;
      last_valid_edge = e;
      checked = checked + 1;
      if (checked == count) begin
        if (count > 1)
          $display("PASS %0d vectors: clocks_per_result %0.3f latency_clocks %0d first_latency_clocks %0d at T = %0.3f ns",
                   count, (last_valid_edge - first_valid_edge) * 1.0 / (count - 1), latency,
                   first_latency, T);
        else
          $display("PASS %0d vectors: clocks_per_result na latency_clocks %0d first_latency_clocks %0d at T = %0.3f ns",
                   count, latency, first_latency, T);
        $finish;
      end
    end
  endtask

  task report_mismatch(input integer k, input [8*16-1:0] what, input [31:0] got_v,
                       input [31:0] want_v);
    begin
      $display("MISMATCH vector %0d (cos %05x n %0d RGB %0d,%0d,%0d) %0s: got %08x, want %08x",
               k, v_cos[k], v_n[k], v_r[k], v_g[k], v_b[k], what, got_v, want_v);
      finish_fail;
    end
  endtask

  task finish_fail;
    begin
      fail = 1'b1;
      $display("FAIL after %0d of %0d results", checked, count);
      $finish;
    end
  endtask
endmodule
