// specular_soc: the integrator's example (docs/rtl_ip.md, "Placing the IP in an SoC").
// A CPU-facing AXI4-Lite slave port, an interconnect that passes the full 32-bit address
// (axi_lite_interconnect.v), a RAM at RAM_BASE (axi_lite_ram.v) and the whole IP,
// specular_ip_axi, at IP_BASE:
//
//   CPU --AXI4-Lite--> axi_lite_interconnect --+--> [0] axi_lite_ram     RAM_BASE, RAM_BYTES
//                      (no slave: DECERR)      +--> [1] specular_ip_axi  IP_BASE, 0x8000 bytes --> done_irq
//
// The IP keeps its default ADDR_WIDTH, 15 (its map's 0x8000 bytes): it gets the low 15
// bits of the address and the interconnect selects it by the 17 above, so IP_BASE must
// be a multiple of 0x8000. RAM_BYTES is a power of two and RAM_BASE a multiple of it;
// the two windows may not overlap (the interconnect stops elaboration otherwise).
// done_irq is the IP's: a level, active high, high while STATUS.DONE is set.
`default_nettype none

module specular_soc #(
  parameter [31:0] IP_BASE = 32'h4000_0000,
  parameter [31:0] RAM_BASE = 32'h0000_0000,
  parameter RAM_BYTES = 65536,
  parameter ROM5_IMAGE = "rom5.hex",
  parameter ROM38_IMAGE = "rom38.hex"
) (
  input  wire        aclk,
  input  wire        aresetn,
  input  wire        s_axi_awvalid,
  output wire        s_axi_awready,
  input  wire [31:0] s_axi_awaddr,
  input  wire [2:0]  s_axi_awprot,
  input  wire        s_axi_wvalid,
  output wire        s_axi_wready,
  input  wire [31:0] s_axi_wdata,
  input  wire [3:0]  s_axi_wstrb,
  output wire        s_axi_bvalid,
  input  wire        s_axi_bready,
  output wire [1:0]  s_axi_bresp,
  input  wire        s_axi_arvalid,
  output wire        s_axi_arready,
  input  wire [31:0] s_axi_araddr,
  input  wire [2:0]  s_axi_arprot,
  output wire        s_axi_rvalid,
  input  wire        s_axi_rready,
  output wire [31:0] s_axi_rdata,
  output wire [1:0]  s_axi_rresp,
  output wire        done_irq
);
  localparam IP_ADDR_WIDTH = 15;                       // specular_ip_axi's default
  localparam [31:0] IP_BYTES = 32'd1 << IP_ADDR_WIDTH;
  localparam [31:0] RAM_SIZE = 32'd0 + RAM_BYTES;  // sized (Verilator: no unsized value in a concatenation)

  // The interconnect's slave side, flattened: [0] the RAM, [1] the IP.
  wire [1:0]  awvalid, awready, wvalid, wready, bvalid, bready, arvalid, arready, rvalid, rready;
  wire [63:0] awaddr, wdata, araddr, rdata;
  wire [5:0]  awprot, arprot;
  wire [7:0]  wstrb;
  wire [3:0]  bresp, rresp;

  axi_lite_interconnect #(
    .N(2), .SLAVE_BASE({IP_BASE, RAM_BASE}), .SLAVE_SIZE({IP_BYTES, RAM_SIZE})
  ) bus (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(s_axi_awvalid), .s_axi_awready(s_axi_awready), .s_axi_awaddr(s_axi_awaddr),
    .s_axi_awprot(s_axi_awprot),
    .s_axi_wvalid(s_axi_wvalid), .s_axi_wready(s_axi_wready), .s_axi_wdata(s_axi_wdata),
    .s_axi_wstrb(s_axi_wstrb),
    .s_axi_bvalid(s_axi_bvalid), .s_axi_bready(s_axi_bready), .s_axi_bresp(s_axi_bresp),
    .s_axi_arvalid(s_axi_arvalid), .s_axi_arready(s_axi_arready), .s_axi_araddr(s_axi_araddr),
    .s_axi_arprot(s_axi_arprot),
    .s_axi_rvalid(s_axi_rvalid), .s_axi_rready(s_axi_rready), .s_axi_rdata(s_axi_rdata),
    .s_axi_rresp(s_axi_rresp),
    .m_axi_awvalid(awvalid), .m_axi_awready(awready), .m_axi_awaddr(awaddr), .m_axi_awprot(awprot),
    .m_axi_wvalid(wvalid), .m_axi_wready(wready), .m_axi_wdata(wdata), .m_axi_wstrb(wstrb),
    .m_axi_bvalid(bvalid), .m_axi_bready(bready), .m_axi_bresp(bresp),
    .m_axi_arvalid(arvalid), .m_axi_arready(arready), .m_axi_araddr(araddr), .m_axi_arprot(arprot),
    .m_axi_rvalid(rvalid), .m_axi_rready(rready), .m_axi_rdata(rdata), .m_axi_rresp(rresp));

  axi_lite_ram #(.BYTES(RAM_BYTES)) ram (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(awvalid[0]), .s_axi_awready(awready[0]), .s_axi_awaddr(awaddr[31:0]),
    .s_axi_awprot(awprot[2:0]),
    .s_axi_wvalid(wvalid[0]), .s_axi_wready(wready[0]), .s_axi_wdata(wdata[31:0]),
    .s_axi_wstrb(wstrb[3:0]),
    .s_axi_bvalid(bvalid[0]), .s_axi_bready(bready[0]), .s_axi_bresp(bresp[1:0]),
    .s_axi_arvalid(arvalid[0]), .s_axi_arready(arready[0]), .s_axi_araddr(araddr[31:0]),
    .s_axi_arprot(arprot[2:0]),
    .s_axi_rvalid(rvalid[0]), .s_axi_rready(rready[0]), .s_axi_rdata(rdata[31:0]),
    .s_axi_rresp(rresp[1:0]));

  // The IP gets the low IP_ADDR_WIDTH bits: its offset in the map.
  specular_ip_axi #(
    .ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE), .ADDR_WIDTH(IP_ADDR_WIDTH)
  ) ip (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(awvalid[1]), .s_axi_awready(awready[1]),
    .s_axi_awaddr(awaddr[32+IP_ADDR_WIDTH-1:32]), .s_axi_awprot(awprot[5:3]),
    .s_axi_wvalid(wvalid[1]), .s_axi_wready(wready[1]), .s_axi_wdata(wdata[63:32]),
    .s_axi_wstrb(wstrb[7:4]),
    .s_axi_bvalid(bvalid[1]), .s_axi_bready(bready[1]), .s_axi_bresp(bresp[3:2]),
    .s_axi_arvalid(arvalid[1]), .s_axi_arready(arready[1]),
    .s_axi_araddr(araddr[32+IP_ADDR_WIDTH-1:32]), .s_axi_arprot(arprot[5:3]),
    .s_axi_rvalid(rvalid[1]), .s_axi_rready(rready[1]), .s_axi_rdata(rdata[63:32]),
    .s_axi_rresp(rresp[3:2]),
    .done_irq(done_irq));

  // The address bits above the IP's window: the interconnect's decode, not the IP's.
  wire unused = &{1'b0, awaddr[63:32+IP_ADDR_WIDTH], araddr[63:32+IP_ADDR_WIDTH]};
endmodule

`default_nettype wire
