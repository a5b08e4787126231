// specular_soc_ip_port.vh: the AXI4-Lite rules checked each edge on the port between the
// SoC's interconnect and the IP (slave 1 of specular_soc `dut`, its own holding registers:
// the checker's defaults). `include it inside an SoC bench, after specular_soc_dut.vh.
  specular_ip_axi_props ip_port (
    .aclk(aclk), .aresetn(aresetn),
    .awvalid(dut.awvalid[1]), .awready(dut.awready[1]), .awaddr({17'd0, dut.awaddr[46:32]}),
    .wvalid(dut.wvalid[1]), .wready(dut.wready[1]), .wdata(dut.wdata[63:32]), .wstrb(dut.wstrb[7:4]),
    .bvalid(dut.bvalid[1]), .bready(dut.bready[1]), .bresp(dut.bresp[3:2]),
    .arvalid(dut.arvalid[1]), .arready(dut.arready[1]), .araddr({17'd0, dut.araddr[46:32]}),
    .rvalid(dut.rvalid[1]), .rready(dut.rready[1]), .rdata(dut.rdata[63:32]), .rresp(dut.rresp[3:2]));
