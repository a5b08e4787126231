// Gate-level testbench of the whole IP, specular_ip_axi (scripts/flows/synthesis/silicon.sh --top
// specular_ip_axi, scripts/flows/gatelevel/gatesim.sh, scripts/flows/energy/energy_ip.sh; docs/silicon.md): an
// AXI4-Lite master on a clock of period T that drives the mapped netlist with the SDF
// (`define GATE_LEVEL) or the RTL, and checks every response. Its own file, beside
// specular_ip_axi_tb.v (the RTL tests' master, with random stalls and a fixed clock):
// here the master keeps the bus's timing of the top's SDC
// (scripts/flows/designs/specular_ip_axi/constraints.tcl):
//   - inputs change at the falling edge of aclk, half a period before the rising edge that
//     takes them (the SDC's input delay T/2);
//   - outputs are read just before the next rising edge (T/64 before it: the SDC's output
//     delay 0, one period);
//   - READY for B and R is held high, AW and W go together: the bus's quickest master.
// MODE picks what it runs, for the T_sim bisection (3) and for the energy of each kind of
// access (scripts/flows/energy/energy_ip.sh, 0-2, 4); `PHASE_BEGIN_NS` in the log is when the measured
// part starts (in MODE 0 before operation MEASURE_FROM: energy_ip.sh skips the stream's
// edge cases), and the run ends as its last access ends:
//   0 operations: per vector of VECTORS (specular_tb --format csv: Core's bits) N, R, G,
//     B, COS written, START written (its response comes with the results), OUT_R, OUT_G,
//     OUT_B read and compared;
//   1 register reads: ACCESSES reads of ID, COS, N, R, G, B in turn after one write of
//     each operand (ID the map's constant 0x00059965, the operands as written);
//   2 register writes: ACCESSES writes of COS, N, R, G, B in turn (operands of the
//     vectors, in range: each response OKAY);
//   3 all: the operations with REG1 and REG9's two passes read too, then the reads, then
//     the writes, each operand read back after its last write;
//   4 idle: ACCESSES clocks with the bus idle after one write of each operand (what the
//     clock alone costs: no clock gating in the IP).
// The netlist's CONFIG is fixed at the default (patent constants and normalisation,
// clamp), so the only policy is patent/patent/clamp (CONSTANTS = NORMALISATION =
// LITERAL = 0). Stops with $fatal (non-zero exit) on the first mismatch.
`default_nettype none
`timescale 1ns / 1ps

module specular_ip_axi_gate_tb;
  `include "specular_policy_parameters.vh"  // PINS_IMAGE unused; the policy 0/0/0 only
  parameter real T = 20.0;            // clock period (ns)
  parameter MODE = 3;
  parameter ACCESSES = 60;
  parameter MEASURE_FROM = 0;         // MODE 0: the operation PHASE_BEGIN_NS is printed before
  parameter RESET_EVERY = 0;          // gatesim.sh and energy.sh set it for the device: unused
  parameter MAX_VECTORS = 8192;

  localparam [1:0] OKAY = 2'b00;
  localparam [31:0] ID = 32'h000, CONTROL = 32'h010;
  localparam [31:0] COS = 32'h020, N = 32'h024, R = 32'h028, G = 32'h02C, B = 32'h030;
  localparam [31:0] OUT_R = 32'h040, REG1 = 32'h050, REG9_PASS1_LO = 32'h054;
  localparam [31:0] ID_VALUE = 32'h00059965;   // docs/tlm.md's register table

  reg aclk = 1'b0, aresetn = 1'b0;
  always #(T / 2) aclk = ~aclk;   // rising edges at T/2 + k T, falling at k T

  reg         awvalid = 1'b0, wvalid = 1'b0, bready = 1'b0, arvalid = 1'b0, rready = 1'b0;
  reg  [31:0] wdata = 32'd0;
  reg  [14:0] awaddr = 15'd0, araddr = 15'd0;   // the IP's default ADDR_WIDTH: offsets in the map
  reg  [3:0]  wstrb = 4'd0;
  wire        awready, wready, bvalid, arready, rvalid, done_irq;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;

`ifdef GATE_LEVEL
  initial $sdf_annotate(`SDF_FILE, dut);
  specular_ip_axi dut (
`else
  specular_ip_axi #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
`endif
    `include "axi_lite_slave_ports.vh"
  );

  // ---- the master: one access at a time, on the SDC's timing ----
  // sample: the outputs just before the rising edge (the caller is at a falling edge)
  task sample;
    #(T / 2 - T / 64);
  endtask

  // end_period: to the falling edge that ends the access's period (the caller then
  // lowers what was taken); an access not done in 50 periods is a failure, not a hang
  integer periods;
  task end_period;
    input [8*5-1:0] kind;
    input [31:0] address;
    input [8*8-1:0] awaited;
    begin
      @(negedge aclk);
      periods = periods + 1;
      if (periods > 50)
        $fatal(1, "specular_ip_axi_gate_tb: MISMATCH %0s 0x%08h: no %0s in 50 periods", kind, address, awaited);
    end
  endtask

  task write;
    input [31:0] address;
    input [31:0] data;
    reg aw_done, w_done, b_done;
    begin
      awaddr = address; awvalid = 1'b1;
      wdata = data; wstrb = 4'b1111; wvalid = 1'b1;
      bready = 1'b1;
      aw_done = 1'b0; w_done = 1'b0; b_done = 1'b0;
      periods = 0;
      while (!b_done) begin
        sample;
        if (awvalid && awready === 1'b1) aw_done = 1'b1;
        if (wvalid && wready === 1'b1) w_done = 1'b1;
        if (bvalid === 1'b1) begin
          b_done = 1'b1;
          if (!aw_done || !w_done)
            $fatal(1, "specular_ip_axi_gate_tb: MISMATCH write 0x%08h: B before AW and W were taken at %0t",
                   address, $realtime);
          if (bresp !== OKAY)
            $fatal(1, "specular_ip_axi_gate_tb: MISMATCH write 0x%08h of 0x%08h: response %b, expected OKAY at %0t",
                   address, data, bresp, $realtime);
        end
        end_period("write", address, "response");
        if (aw_done) awvalid = 1'b0;
        if (w_done) wvalid = 1'b0;
      end
      bready = 1'b0;
    end
  endtask

  task read;
    input [31:0] address;
    input [31:0] expected;
    input [8*16-1:0] what;
    reg ar_done, r_done;
    begin
      araddr = address; arvalid = 1'b1;
      rready = 1'b1;
      ar_done = 1'b0; r_done = 1'b0;
      periods = 0;
      while (!r_done) begin
        sample;
        if (arvalid && arready === 1'b1) ar_done = 1'b1;
        if (rvalid === 1'b1 && ar_done) begin
          r_done = 1'b1;
          if (rresp !== OKAY || rdata !== expected)
            $fatal(1, "specular_ip_axi_gate_tb: MISMATCH read 0x%08h (%0s): 0x%08h response %b, expected 0x%08h OKAY at %0t",
                   address, what, rdata, rresp, expected, $realtime);
        end
        end_period("read", address, "data");
        if (ar_done) arvalid = 1'b0;
      end
      rready = 1'b0;
    end
  endtask

  // ---- vectors (specular_tb --format csv: Core's bits, as specular_ip_axi_tb.v reads them) ----
  localparam TB_NAME = "specular_ip_axi_gate_tb";
  localparam VECTOR_COS_W = 32, VECTOR_REG9_W = 37, VECTOR_OUT_W = 32;  // the bus words
  `include "specular_vectors.vh"  // read_vectors: VECTORS into v_*[0:count-1]

  // ---- the three kinds of access ----
  // N, R, G, B of vector i, in that order (an operation writes COS after them)
  task write_nrgb;
    input integer i;
    begin
      write(N, v_n[i]);
      write(R, v_r[i]);
      write(G, v_g[i]);
      write(B, v_b[i]);
    end
  endtask
  task operation;
    input integer i;
    input integer all_reads;
    begin
      write_nrgb(i);
      write(COS, v_reg1[i]);
      write(CONTROL, 32'h1);   // START: its response comes with the results
      if (done_irq !== 1'b1) $fatal(1, "specular_ip_axi_gate_tb: MISMATCH vector %0d: done_irq low after START's response", i);
      read(OUT_R, v_out24[i], "OUT_R");
      read(OUT_R + 4, v_out25[i], "OUT_G");
      read(OUT_R + 8, v_out26[i], "OUT_B");
      if (all_reads) begin
        read(REG1, v_reg1[i], "REG1");
        read(REG9_PASS1_LO, v_pass1[i][31:0], "REG9_PASS1_LO");
        read(REG9_PASS1_LO + 4, v_pass1[i][63:32], "REG9_PASS1_HI");
        read(REG9_PASS1_LO + 8, v_pass2[i][31:0], "REG9_PASS2_LO");
        read(REG9_PASS1_LO + 12, v_pass2[i][63:32], "REG9_PASS2_HI");
      end
    end
  endtask

  // register reads: ID and the five operands in turn (the operands of vector 0, written first)
  task register_reads;
    integer k;
    begin
      for (k = 0; k < ACCESSES; k = k + 1)
        case (k % 6)
          0: read(ID, ID_VALUE, "ID");
          1: read(COS, v_reg1[0], "COS");
          2: read(N, v_n[0], "N");
          3: read(R, v_r[0], "R");
          4: read(G, v_g[0], "G");
          default: read(B, v_b[0], "B");
        endcase
    end
  endtask
  task write_operands;
    input integer i;
    begin
      write(COS, v_reg1[i]);
      write_nrgb(i);
    end
  endtask

  // register writes: COS, N, R, G, B in turn, the operands of vector k / 5
  integer last_write [0:4];
  task register_writes;
    integer k, i;
    begin
      for (k = 0; k < ACCESSES; k = k + 1) begin
        i = (k / 5) % count;
        case (k % 5)
          0: begin write(COS, v_reg1[i]); last_write[0] = v_reg1[i]; end
          1: begin write(N, v_n[i]); last_write[1] = v_n[i]; end
          2: begin write(R, v_r[i]); last_write[2] = v_r[i]; end
          3: begin write(G, v_g[i]); last_write[3] = v_g[i]; end
          default: begin write(B, v_b[i]); last_write[4] = v_b[i]; end
        endcase
      end
    end
  endtask

  task phase_begins;
    input [8*12-1:0] what;
    $display("PHASE_BEGIN_NS %0.3f %0s", $realtime, what);
  endtask

  // rising edges of aclk, for the clocks an operation, a read and a write take
  integer edges = 0;
  always @(posedge aclk) edges = edges + 1;
  integer first_edge;
  task clocks_per;
    input [8*12-1:0] what;
    input integer accesses;
    $display("clocks_per_%0s %0.2f", what, (edges - first_edge) * 1.0 / accesses);
  endtask

  integer i, k;
  initial begin
    if (CONSTANTS != 0 || NORMALISATION != 0 || LITERAL != 0)
      $fatal(1, "specular_ip_axi_gate_tb: policy %0d/%0d/%0d: the mapped IP's CONFIG is fixed at patent/patent/clamp (0/0/0)",
             CONSTANTS, NORMALISATION, LITERAL);
    if (MODE < 0 || MODE > 4) $fatal(1, "specular_ip_axi_gate_tb: MODE %0d is not 0-4", MODE);
    if (ACCESSES < 1) $fatal(1, "specular_ip_axi_gate_tb: ACCESSES %0d is not at least 1", ACCESSES);
    read_vectors;
    // reset: held low three periods, released at a falling edge
    for (k = 0; k < 3; k = k + 1) @(negedge aclk);
    aresetn = 1'b1;
    @(negedge aclk);
    if (MODE == 0 || MODE == 3) begin
      if (MEASURE_FROM >= count)
        $fatal(1, "specular_ip_axi_gate_tb: MEASURE_FROM %0d is not below the %0d vectors", MEASURE_FROM, count);
      for (i = 0; i < count; i = i + 1) begin
        if (i == MEASURE_FROM) begin
          if (MODE == 0) phase_begins("operations");
          first_edge = edges;
        end
        operation(i, MODE == 3);
      end
      clocks_per("operation", count - MEASURE_FROM);
    end
    if (MODE == 1 || MODE == 3) begin
      write_operands(0);
      if (MODE == 1) phase_begins("reads");
      first_edge = edges;
      register_reads;
      clocks_per("read", ACCESSES);
    end
    if (MODE == 2 || MODE == 3) begin
      if (MODE == 2) phase_begins("writes");
      first_edge = edges;
      register_writes;
      clocks_per("write", ACCESSES);
      if (MODE == 3) begin
        read(COS, last_write[0], "COS");
        read(N, last_write[1], "N");
        read(R, last_write[2], "R");
        read(G, last_write[3], "G");
        read(B, last_write[4], "B");
      end
    end
    if (MODE == 4) begin
      write_operands(0);
      phase_begins("idle");
      first_edge = edges;
      for (k = 0; k < ACCESSES; k = k + 1) @(negedge aclk);
      clocks_per("idle", ACCESSES);
    end
    $display("specular_ip_axi_gate_tb: PASS (MODE %0d: %0d operations, %0d reads, %0d writes at T = %0.3f ns)",
             MODE, (MODE == 0 || MODE == 3) ? count : 0, (MODE == 1 || MODE == 3) ? ACCESSES : 0,
             (MODE == 2 || MODE == 3) ? ACCESSES : 0, T);
    $finish;
  end

  initial begin
    #(T * (60 * MAX_VECTORS + 200 * ACCESSES + 100));
    $fatal(1, "specular_ip_axi_gate_tb: watchdog: no end");
  end
endmodule

`default_nettype wire
