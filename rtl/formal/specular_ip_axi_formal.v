// The proof's top (rtl/formal/axi_lite_bmc.cmake): specular_ip_axi with every master
// input free, and its AXI4-Lite rules (specular_ip_axi_props.v, read with FORMAL:
// the slave's asserted, the master's assumed). The IP at its default ADDR_WIDTH (15): the
// checker sees the offsets zero-extended.
`default_nettype none

module specular_ip_axi_formal (
  input wire        aclk,
  input wire        aresetn,
  input wire        awvalid,
  input wire [14:0] awaddr,
  input wire [2:0]  awprot,
  input wire        wvalid,
  input wire [31:0] wdata,
  input wire [3:0]  wstrb,
  input wire        bready,
  input wire        arvalid,
  input wire [14:0] araddr,
  input wire [2:0]  arprot,
  input wire        rready
);
  wire awready, wready, bvalid, arready, rvalid, done_irq;
  wire [1:0] bresp, rresp;
  wire [31:0] rdata;

  specular_ip_axi dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(awvalid), .s_axi_awready(awready), .s_axi_awaddr(awaddr), .s_axi_awprot(awprot),
    .s_axi_wvalid(wvalid), .s_axi_wready(wready), .s_axi_wdata(wdata), .s_axi_wstrb(wstrb),
    .s_axi_bvalid(bvalid), .s_axi_bready(bready), .s_axi_bresp(bresp),
    .s_axi_arvalid(arvalid), .s_axi_arready(arready), .s_axi_araddr(araddr), .s_axi_arprot(arprot),
    .s_axi_rvalid(rvalid), .s_axi_rready(rready), .s_axi_rdata(rdata), .s_axi_rresp(rresp),
    .done_irq(done_irq));

  specular_ip_axi_props props (
    .aclk(aclk), .aresetn(aresetn),
    .awvalid(awvalid), .awready(awready), .awaddr({17'd0, awaddr}),
    .wvalid(wvalid), .wready(wready), .wdata(wdata), .wstrb(wstrb),
    .bvalid(bvalid), .bready(bready), .bresp(bresp),
    .arvalid(arvalid), .arready(arready), .araddr({17'd0, araddr}),
    .rvalid(rvalid), .rready(rready), .rdata(rdata), .rresp(rresp));

  // done_irq is STATUS.DONE: not an AXI signal, not checked here.
  wire unused = done_irq;
endmodule

`default_nettype wire
