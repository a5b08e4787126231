// The AXI4-Lite handshake rules (AMBA AXI and ACE Protocol Specification, IHI 0022,
// sections A3.1-A3.3 and B1) for the slave specular_ip_axi, written for this project
// (docs/rtl_ip.md, "The protocol proven"). One checker for both uses:
//   - `define FORMAL (yosys read_verilog -formal, proved by yosys-smtbmc): the slave's
//     rules are asserted, the master's assumed;
//   - otherwise (Icarus testbenches): every rule is checked each clock edge and a
//     broken one stops the simulation ($fatal) naming it.
// The slave's rules: after a clock edge in reset BVALID and RVALID are low; a
// response is held with its payload until READY; BRESP and RRESP are never EXOKAY
// (AXI4-Lite has no exclusive access); a response only for a request (an AW and a W
// taken, or an AR taken, not yet answered) and for each request a response within
// MAX_WAIT cycles of the slave's own (the master's READY held low does not count):
// exactly one per request. The master's rules: VALID low in reset and the cycle after
// it, then held with its payload until READY.
`default_nettype none

module specular_ip_axi_props #(
  parameter MAX_WAIT = 8,        // cycles from a complete request to its response, at most
  // requests taken and not yet answered, at most: the IP's one holding register each
  // (an AW or W waiting beside one answered); an interconnect's port takes more (1 to 6)
  parameter MAX_OPEN_WRITES = 2,
  parameter MAX_OPEN_READS = 1
) (
  input wire        aclk,
  input wire        aresetn,
  input wire        awvalid, awready,
  input wire [31:0] awaddr,
  input wire        wvalid, wready,
  input wire [31:0] wdata,
  input wire [3:0]  wstrb,
  input wire        bvalid, bready,
  input wire [1:0]  bresp,
  input wire        arvalid, arready,
  input wire [31:0] araddr,
  input wire        rvalid, rready,
  input wire [31:0] rdata,
  input wire [1:0]  rresp
);
`ifdef FORMAL
`define SPECULAR_AXI_SLAVE(rule, what) assert (rule);
`define SPECULAR_AXI_MASTER(rule, what) assume (rule);
`else
`define SPECULAR_AXI_SLAVE(rule, what) if (!(rule)) $fatal(1, "AXI4-Lite rule broken by the slave at %0t: %0s", $time, what);
`define SPECULAR_AXI_MASTER(rule, what) if (!(rule)) $fatal(1, "AXI4-Lite rule broken by the master at %0t: %0s", $time, what);
`endif
  localparam [1:0] EXOKAY = 2'b01;

  // The previous cycle's values (no $past: Icarus reads this file too).
  reg        past_valid = 1'b0;
  reg        p_aresetn, p_awvalid, p_awready, p_wvalid, p_wready, p_bvalid, p_bready;
  reg        p_arvalid, p_arready, p_rvalid, p_rready;
  reg [31:0] p_awaddr, p_wdata, p_araddr, p_rdata;
  reg [3:0]  p_wstrb;
  reg [1:0]  p_bresp, p_rresp;
  // Requests taken and not yet answered, and how long the slave has kept one waiting.
  reg [2:0] aw_open, w_open, ar_open;
  reg [4:0] b_wait, r_wait;

  wire aw_go = awvalid && awready, w_go = wvalid && wready, b_go = bvalid && bready;
  wire ar_go = arvalid && arready, r_go = rvalid && rready;
  wire in_reset = !aresetn || (past_valid && !p_aresetn);

  always @(posedge aclk) begin
    past_valid <= 1'b1;
    p_aresetn <= aresetn;
    p_awvalid <= awvalid; p_awready <= awready; p_awaddr <= awaddr;
    p_wvalid <= wvalid; p_wready <= wready; p_wdata <= wdata; p_wstrb <= wstrb;
    p_bvalid <= bvalid; p_bready <= bready; p_bresp <= bresp;
    p_arvalid <= arvalid; p_arready <= arready; p_araddr <= araddr;
    p_rvalid <= rvalid; p_rready <= rready; p_rdata <= rdata; p_rresp <= rresp;
    if (!aresetn) begin
      aw_open <= 3'd0; w_open <= 3'd0; ar_open <= 3'd0;
      b_wait <= 5'd0; r_wait <= 5'd0;
    end else begin
      aw_open <= aw_open + {2'd0, aw_go} - {2'd0, b_go};
      w_open <= w_open + {2'd0, w_go} - {2'd0, b_go};
      ar_open <= ar_open + {2'd0, ar_go} - {2'd0, r_go};
      b_wait <= (aw_open != 3'd0 && w_open != 3'd0 && !bvalid) ? b_wait + 5'd1 : 5'd0;
      r_wait <= (ar_open != 3'd0 && !rvalid) ? r_wait + 5'd1 : 5'd0;
    end

    // ---- the master (assumed when proving) ----
    `SPECULAR_AXI_MASTER(past_valid || !aresetn, "the first cycle is in reset")
    `SPECULAR_AXI_MASTER(!in_reset || (!awvalid && !wvalid && !arvalid),
                         "AWVALID, WVALID, ARVALID low in reset and the cycle after it")
    if (past_valid && p_aresetn && aresetn) begin
      `SPECULAR_AXI_MASTER(!(p_awvalid && !p_awready) || (awvalid && awaddr == p_awaddr),
                           "AWVALID and AWADDR held until AWREADY")
      `SPECULAR_AXI_MASTER(!(p_wvalid && !p_wready) || (wvalid && wdata == p_wdata && wstrb == p_wstrb),
                           "WVALID, WDATA and WSTRB held until WREADY")
      `SPECULAR_AXI_MASTER(!(p_arvalid && !p_arready) || (arvalid && araddr == p_araddr),
                           "ARVALID and ARADDR held until ARREADY")
    end

    // ---- the slave (proved) ----
    // (a synchronous reset: from the first clock edge with ARESETn low until one after it rose)
    `SPECULAR_AXI_SLAVE(!(past_valid && !p_aresetn) || (!bvalid && !rvalid),
                        "BVALID and RVALID low after a clock edge in reset")
    if (past_valid && p_aresetn && aresetn) begin
      `SPECULAR_AXI_SLAVE(!(p_bvalid && !p_bready) || (bvalid && bresp == p_bresp),
                          "BVALID and BRESP held until BREADY")
      `SPECULAR_AXI_SLAVE(!(p_rvalid && !p_rready) || (rvalid && rdata == p_rdata && rresp == p_rresp),
                          "RVALID, RDATA and RRESP held until RREADY")
    end
    if (aresetn) begin
      `SPECULAR_AXI_SLAVE(!bvalid || bresp != EXOKAY, "BRESP is OKAY, SLVERR or DECERR")
      `SPECULAR_AXI_SLAVE(!rvalid || rresp != EXOKAY, "RRESP is OKAY, SLVERR or DECERR")
      `SPECULAR_AXI_SLAVE(!bvalid || (aw_open != 3'd0 && w_open != 3'd0),
                          "a write response only for an AW and a W taken and not answered")
      `SPECULAR_AXI_SLAVE(!rvalid || ar_open != 3'd0, "a read response only for an AR taken and not answered")
      `SPECULAR_AXI_SLAVE(b_wait <= MAX_WAIT, "each write answered within MAX_WAIT cycles")
      `SPECULAR_AXI_SLAVE(r_wait <= MAX_WAIT, "each read answered within MAX_WAIT cycles")
      `SPECULAR_AXI_SLAVE({29'd0, aw_open} <= MAX_OPEN_WRITES && {29'd0, w_open} <= MAX_OPEN_WRITES &&
                          {29'd0, ar_open} <= MAX_OPEN_READS,
                          "at most MAX_OPEN_WRITES writes and MAX_OPEN_READS reads taken and not answered")
    end
  end
`undef SPECULAR_AXI_SLAVE
`undef SPECULAR_AXI_MASTER
endmodule

`default_nettype wire
