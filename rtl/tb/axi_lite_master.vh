// axi_lite_master.vh: the testbenches' AXI4-Lite master, in order, one access at a time
// (docs/rtl_ip.md, "Placing the IP in an SoC"). `include it inside the testbench module,
// after the module's parameters STALL (1: each VALID rises 0-3 cycles late and each
// BREADY/RREADY 0-3 cycles late, at random; 0: no stall) and SEED (the stalls' seed).
// It declares:
//   - aclk (10 ns period) and aresetn (low until reset_release);
//   - the master's signals, to connect to the slave: awvalid, awaddr, wvalid, wdata,
//     wstrb, bready, arvalid, araddr, rready (driven here) and awready, wready, bvalid,
//     bresp, arready, rvalid, rdata, rresp (wires the slave drives);
//   - OKAY, SLVERR, DECERR;
//   - the tasks: reset_release; cycles(k); send_aw, send_w, take_b (one channel each,
//     for benches that fork them); write_strobed, write (a write, its BRESP checked);
//     read_raw (a read, RDATA and RRESP returned); expect_read (RRESP checked, RDATA too
//     when OKAY). A mismatch stops the simulation: $fatal with a line "MISMATCH ...".
// The tasks are static (Verilog-2005): branches of a fork that call the same task share
// its variables, so a branch that must wait on its own counts with `repeat`.
// Signals are driven 1 ns after a rising edge and sampled at the edge.

  reg aclk = 1'b0, aresetn = 1'b0;
  always #5 aclk = ~aclk;

  reg         awvalid = 1'b0, wvalid = 1'b0, bready = 1'b0, arvalid = 1'b0, rready = 1'b0;
  reg  [31:0] awaddr = 32'd0, wdata = 32'd0, araddr = 32'd0;
  reg  [3:0]  wstrb = 4'd0;
  wire        awready, wready, bvalid, arready, rvalid;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;

  localparam [1:0] OKAY = 2'b00, SLVERR = 2'b10, DECERR = 2'b11;

  integer seed = SEED;
  // 0..3 cycles of stall when STALL is set
  function integer stall;
    input integer dummy;
    begin
      stall = STALL ? ({$random(seed)} % 4) : 0;
    end
  endfunction
  task cycles;
    input integer k;
    integer i;
    begin
      for (i = 0; i < k; i = i + 1) @(posedge aclk);
      #1;
    end
  endtask
  // Three edges in reset, then one after it (no VALID in that cycle: AXI's rule).
  task reset_release;
    begin
      cycles(3);
      aresetn = 1'b1;
      cycles(1);
    end
  endtask

  // ---- the master's channels, each with its own stalls ----
  task send_aw;
    input [31:0] address;
    begin
      cycles(stall(0));
      awaddr = address;
      awvalid = 1'b1;
      @(posedge aclk);
      while (!awready) @(posedge aclk);
      #1 awvalid = 1'b0;
      awaddr = 32'hDEAD_BEEF;
    end
  endtask
  task send_w;
    input [31:0] data;
    input [3:0] strobes;
    begin
      cycles(stall(0));
      wdata = data;
      wstrb = strobes;
      wvalid = 1'b1;
      @(posedge aclk);
      while (!wready) @(posedge aclk);
      #1 wvalid = 1'b0;
      wdata = 32'hDEAD_BEEF;
    end
  endtask
  task take_b;
    output [1:0] response;
    begin
      cycles(stall(0));
      bready = 1'b1;
      @(posedge aclk);
      while (!bvalid) @(posedge aclk);
      response = bresp;
      #1 bready = 1'b0;
    end
  endtask
  task write_strobed;
    input [31:0] address;
    input [31:0] data;
    input [3:0] strobes;
    input [1:0] expected;
    reg [1:0] response;
    begin
      fork
        send_aw(address);
        send_w(data, strobes);
        take_b(response);
      join
      if (response !== expected)
        $fatal(1, "MISMATCH write 0x%08h of 0x%08h (strobes %b): response %b, expected %b",
               address, data, strobes, response, expected);
    end
  endtask
  task write;
    input [31:0] address;
    input [31:0] data;
    input [1:0] expected;
    begin
      write_strobed(address, data, 4'b1111, expected);
    end
  endtask
  task read_raw;
    input [31:0] address;
    output [31:0] data;
    output [1:0] response;
    begin
      cycles(stall(0));
      araddr = address;
      arvalid = 1'b1;
      @(posedge aclk);
      while (!arready) @(posedge aclk);
      #1 arvalid = 1'b0;
      araddr = 32'hDEAD_BEEF;
      cycles(stall(0));
      rready = 1'b1;
      @(posedge aclk);
      while (!rvalid) @(posedge aclk);
      data = rdata;
      response = rresp;
      #1 rready = 1'b0;
    end
  endtask
  task expect_read;
    input [31:0] address;
    input [31:0] expected;
    input [1:0] expected_response;
    reg [31:0] data;
    reg [1:0] response;
    begin
      read_raw(address, data, response);
      if (response !== expected_response || (response == OKAY && data !== expected))
        $fatal(1, "MISMATCH read 0x%08h: 0x%08h response %b, expected 0x%08h response %b",
               address, data, response, expected, expected_response);
    end
  endtask
