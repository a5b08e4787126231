// axi_lite_slave_ports.vh: the connections of an AXI4-Lite slave port s_axi_* (the IP's
// specular_ip_axi, the SoC's specular_soc) and its done_irq to the master's signals of the
// same names (axi_lite_master.vh's, or the bench's own). `include it inside the bench's
// instance of the slave, as its whole port list.
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(awvalid), .s_axi_awready(awready), .s_axi_awaddr(awaddr), .s_axi_awprot(3'd0),
    .s_axi_wvalid(wvalid), .s_axi_wready(wready), .s_axi_wdata(wdata), .s_axi_wstrb(wstrb),
    .s_axi_bvalid(bvalid), .s_axi_bready(bready), .s_axi_bresp(bresp),
    .s_axi_arvalid(arvalid), .s_axi_arready(arready), .s_axi_araddr(araddr), .s_axi_arprot(3'd0),
    .s_axi_rvalid(rvalid), .s_axi_rready(rready), .s_axi_rdata(rdata), .s_axi_rresp(rresp),
    .done_irq(done_irq)
