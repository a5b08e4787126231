// The SoC benches' device under test (included inside the bench module, after
// axi_lite_master.vh, whose master signals it connects): specular_soc `dut` on the bench's
// IP_BASE, RAM_BASE, RAM_BYTES, ROM5_IMAGE, ROM38_IMAGE, and `soc_port`, the AXI4-Lite
// rules checked each edge on the SoC's port. The bench declares SOC_OPEN_WRITES and
// SOC_OPEN_READS first: the requests its master keeps in flight (the checker's defaults,
// 2 and 1, for an in-order master; 4 and 4, the interconnect's, for one that keeps more).
  wire done_irq;

  specular_soc #(.IP_BASE(IP_BASE), .RAM_BASE(RAM_BASE), .RAM_BYTES(RAM_BYTES),
                 .ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(awvalid), .s_axi_awready(awready), .s_axi_awaddr(awaddr), .s_axi_awprot(3'd0),
    .s_axi_wvalid(wvalid), .s_axi_wready(wready), .s_axi_wdata(wdata), .s_axi_wstrb(wstrb),
    .s_axi_bvalid(bvalid), .s_axi_bready(bready), .s_axi_bresp(bresp),
    .s_axi_arvalid(arvalid), .s_axi_arready(arready), .s_axi_araddr(araddr), .s_axi_arprot(3'd0),
    .s_axi_rvalid(rvalid), .s_axi_rready(rready), .s_axi_rdata(rdata), .s_axi_rresp(rresp),
    .done_irq(done_irq));

  specular_ip_axi_props #(.MAX_OPEN_WRITES(SOC_OPEN_WRITES), .MAX_OPEN_READS(SOC_OPEN_READS)) soc_port (
    .aclk(aclk), .aresetn(aresetn),
    .awvalid(awvalid), .awready(awready), .awaddr(awaddr),
    .wvalid(wvalid), .wready(wready), .wdata(wdata), .wstrb(wstrb),
    .bvalid(bvalid), .bready(bready), .bresp(bresp),
    .arvalid(arvalid), .arready(arready), .araddr(araddr),
    .rvalid(rvalid), .rready(rready), .rdata(rdata), .rresp(rresp));
