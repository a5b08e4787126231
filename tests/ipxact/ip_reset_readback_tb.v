// Reads CONFIG, PIN19_H and PIN20_A of specular_ip_axi after reset, elaborated with the
// parameters the test sets (iverilog -P), and prints them for ip_description_check.py
// ("resets"), which evaluates specular_ip_axi.xml's reset expressions with the same
// values. One read at a time, READY held high: the protocol is the other benches' job.
`default_nettype none
`timescale 1ns / 1ps

module ip_reset_readback_tb;
  parameter [31:0] CONFIG_VALUE = 32'h080D1000;
  parameter [31:0] PIN19_H_VALUE = 32'h80;
  parameter [31:0] PIN20_A_VALUE = 32'h400000;
  parameter ADDR_WIDTH = 15;
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";

  reg aclk = 1'b0, aresetn = 1'b0;
  always #5 aclk = ~aclk;
  reg arvalid = 1'b0;
  reg [ADDR_WIDTH-1:0] araddr = {ADDR_WIDTH{1'b0}};
  wire arready, rvalid, awready, wready, bvalid, done_irq;
  wire [1:0] rresp, bresp;
  wire [31:0] rdata;

  specular_ip_axi #(.CONFIG_VALUE(CONFIG_VALUE), .PIN19_H_VALUE(PIN19_H_VALUE),
                    .PIN20_A_VALUE(PIN20_A_VALUE), .ADDR_WIDTH(ADDR_WIDTH),
                    .ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axi_awvalid(1'b0), .s_axi_awready(awready), .s_axi_awaddr({ADDR_WIDTH{1'b0}}),
    .s_axi_awprot(3'd0), .s_axi_wvalid(1'b0), .s_axi_wready(wready), .s_axi_wdata(32'd0),
    .s_axi_wstrb(4'd0), .s_axi_bvalid(bvalid), .s_axi_bready(1'b1), .s_axi_bresp(bresp),
    .s_axi_arvalid(arvalid), .s_axi_arready(arready), .s_axi_araddr(araddr), .s_axi_arprot(3'd0),
    .s_axi_rvalid(rvalid), .s_axi_rready(1'b1), .s_axi_rdata(rdata), .s_axi_rresp(rresp),
    .done_irq(done_irq));

  task read_word;
    input [8*8-1:0] name;
    input [31:0] address;
    begin
      araddr = address[ADDR_WIDTH-1:0];
      arvalid = 1'b1;
      @(posedge aclk);
      while (!arready) @(posedge aclk);
      #1 arvalid = 1'b0;
      while (!rvalid) @(posedge aclk);
      $display("READ %0s 0x%08h resp %0d", name, rdata, rresp);
      @(posedge aclk);
    end
  endtask

  initial begin
    repeat (3) @(posedge aclk);
    #1 aresetn = 1'b1;
    @(posedge aclk);
    read_word("CONFIG", 32'h008);
    read_word("PIN19_H", 32'h06C);
    read_word("PIN20_A", 32'h070);
    $display("ip_reset_readback_tb: done");
    $finish;
  end

  wire unused = &{1'b0, awready, wready, bvalid, bresp, done_irq};
endmodule

`default_nettype wire
