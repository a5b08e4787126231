// axi_lite_check_ports.vh: the connections of the AXI4-Lite rules checker
// (rtl/ip/specular_ip_axi_props.v) to the master's signals (axi_lite_master.vh's), the
// port between the bench's master and the slave it drives. `include it inside the
// bench's instance of specular_ip_axi_props, as its whole port list.
    .aclk(aclk), .aresetn(aresetn),
    .awvalid(awvalid), .awready(awready), .awaddr(awaddr),
    .wvalid(wvalid), .wready(wready), .wdata(wdata), .wstrb(wstrb),
    .bvalid(bvalid), .bready(bready), .bresp(bresp),
    .arvalid(arvalid), .arready(arready), .araddr(araddr),
    .rvalid(rvalid), .rready(rready), .rdata(rdata), .rresp(rresp)
