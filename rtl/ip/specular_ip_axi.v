// specular_ip_axi: the whole IP in Verilog (docs/rtl_ip.md). An AMBA AXI4-Lite slave
// (32-bit data, byte strobes) with the register block generated from the register map
// (specular_reg_block.v) around the synchronous device (rtl/device/specular_device_sync.v),
// and done_irq, a level that follows STATUS.DONE as docs/tlm.md defines it.
//   - Write: AW and W are taken in any order or together into one holding register
//     each; the write is done when both are held and no response waits. A refusal is
//     SLVERR, a hole DECERR (STATUS, CAUSE and ERROR_ADDRESS as the TLM target sets them).
//   - A write that starts an operation (START, START in OPERANDS word 5) gets its
//     response with the results, at the 4th clock edge after the write, as the TLM target's
//     b_transport returns after the operation: no other write is done in between, so
//     no operand changes under the device and cause "busy" never arises.
//   - Read: one at a time, its response the cycle after the address; served at any
//     time, also while an operation runs (STATUS.BUSY then reads 1) and in the same
//     cycle as a write. The master may hold READY low on B and R for as long as it likes.
//   - Partial strobes: one byte or an aligned half-word, the TLM target's sub-word rules;
//     any other pattern is refused (cause byte_enable). AWPROT and ARPROT are ignored.
// The device runs at the bus clock; its configuration is fixed by the parameters
// (CONFIG_VALUE at the device's default widths, PIN19_H_VALUE, PIN20_A_VALUE).
// Addresses: AWADDR and ARADDR are ADDR_WIDTH bits wide, the low bits of whatever address
// the interconnect carries, so the IP answers at any base aligned to 2**ADDR_WIDTH (the
// interconnect selects the IP by the bits above). 15 (the default) covers the map's
// 0x8000 bytes; 16 to 32 make the holes above 0x8000 visible too, answered DECERR as on
// the TLM targets (the `axi` TLM target uses 32, the whole TLM address space). Below 15
// the map does not fit: elaboration stops (ADDR_WIDTH_OUT_OF_RANGE). ERROR_ADDRESS holds
// the offset the IP saw, zero-extended.
`default_nettype none

module specular_ip_axi #(
  parameter [31:0] CONFIG_VALUE = 135073792,     // 0x080D1000: patent constants and normalisation, clamp
  parameter [31:0] PIN19_H_VALUE = 128,          // 0x80: h = 1/2
  parameter [31:0] PIN20_A_VALUE = 4194304,      // 0x400000: a = 1.0
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex",
  parameter ADDR_WIDTH = 15                      // 15..32: the offset bits decoded
) (
  input  wire        aclk,
  input  wire        aresetn,
  // write address
  input  wire        s_axi_awvalid,
  output wire        s_axi_awready,
  input  wire [ADDR_WIDTH-1:0] s_axi_awaddr,
  input  wire [2:0]  s_axi_awprot,
  // write data
  input  wire        s_axi_wvalid,
  output wire        s_axi_wready,
  input  wire [31:0] s_axi_wdata,
  input  wire [3:0]  s_axi_wstrb,
  // write response
  output reg         s_axi_bvalid,
  input  wire        s_axi_bready,
  output reg  [1:0]  s_axi_bresp,
  // read address
  input  wire        s_axi_arvalid,
  output wire        s_axi_arready,
  input  wire [ADDR_WIDTH-1:0] s_axi_araddr,
  input  wire [2:0]  s_axi_arprot,
  // read data
  output reg         s_axi_rvalid,
  input  wire        s_axi_rready,
  output reg  [31:0] s_axi_rdata,
  output reg  [1:0]  s_axi_rresp,
  // interrupt: high while STATUS.DONE is set
  output wire        done_irq
);
  // ---- write channel: one holding register for AW, one for W ----
  reg        aw_held, w_held;
  reg [ADDR_WIDTH-1:0] aw_addr;
  reg [31:0] w_data;
  reg [3:0]  w_strb;
  reg        op_running;       // an operation is in flight: its START's response waits
  reg [1:0]  op_resp;          // that response
  assign s_axi_awready = ~aw_held;
  assign s_axi_wready = ~w_held;
  wire do_write = aw_held && w_held && !s_axi_bvalid && !op_running;
  wire [1:0] wr_resp;
  wire wr_starts;

  // ---- read channel: the address goes straight to the register block ----
  assign s_axi_arready = ~s_axi_rvalid;
  wire do_read = s_axi_arvalid && s_axi_arready;
  wire [31:0] rd_data;
  wire [1:0] rd_resp;

  // ---- the offsets in the map, zero-extended to the register block's 32 bits ----
  wire [31:0] wr_offset, rd_offset;
  generate
    if (ADDR_WIDTH < 15 || ADDR_WIDTH > 32) begin : ADDR_WIDTH_OUT_OF_RANGE
      // Not a module: every tool stops here naming this block (allowed: 15 to 32).
      specular_ip_axi_ADDR_WIDTH_must_be_15_to_32 refused ();
    end else if (ADDR_WIDTH == 32) begin : offset_full
      assign wr_offset = aw_addr;
      assign rd_offset = s_axi_araddr;
    end else begin : offset_low
      assign wr_offset = {{(32 - ADDR_WIDTH){1'b0}}, aw_addr};
      assign rd_offset = {{(32 - ADDR_WIDTH){1'b0}}, s_axi_araddr};
    end
  endgenerate

  // ---- the operation (control_unit_sync): the device takes the start at edge 0 and
  // runs pass 1 (op_pass1); register 9 holds pass 1 after edge 1 (op_pass2, taken into
  // REG1 and REG9_PASS1 at edge 2); the results are there after edge 2 (op_result,
  // taken into OUT_*, REG9_PASS2, ROM38_K, NORM39 at edge 3, when DONE rises) ----
  wire start_pulse;
  reg  op_pass1, op_pass2, op_result;
  wire [31:0] cos_q, n_q, r_q, g_q, b_q;
  wire signed [31:0] pin24_r, pin25_g, pin26_b;
  wire pin35_done;
  wire obs_select36, obs_write37, obs_pass1;
  wire [16:0] obs_reg1_q;
  wire signed [36:0] obs_reg9_q;
  wire [24:0] obs_rom38_k;
  wire signed [30:0] obs_mul39_norm;

  always @(posedge aclk)
    if (!aresetn) begin
      aw_held <= 1'b0;
      w_held <= 1'b0;
      aw_addr <= {ADDR_WIDTH{1'b0}};
      w_data <= 32'd0;
      w_strb <= 4'd0;
      s_axi_bvalid <= 1'b0;
      s_axi_bresp <= 2'b00;
      s_axi_rvalid <= 1'b0;
      s_axi_rdata <= 32'd0;
      s_axi_rresp <= 2'b00;
      op_running <= 1'b0;
      op_resp <= 2'b00;
      op_pass1 <= 1'b0;
      op_pass2 <= 1'b0;
      op_result <= 1'b0;
    end else begin
      if (s_axi_awvalid && s_axi_awready) begin
        aw_held <= 1'b1;
        aw_addr <= s_axi_awaddr;
      end else if (do_write) begin
        aw_held <= 1'b0;
      end
      if (s_axi_wvalid && s_axi_wready) begin
        w_held <= 1'b1;
        w_data <= s_axi_wdata;
        w_strb <= s_axi_wstrb;
      end else if (do_write) begin
        w_held <= 1'b0;
      end
      // B: at once, or for a START when the results are in
      if (do_write && !wr_starts) begin
        s_axi_bvalid <= 1'b1;
        s_axi_bresp <= wr_resp;
      end else if (op_result) begin
        s_axi_bvalid <= 1'b1;
        s_axi_bresp <= op_resp;
      end else if (s_axi_bvalid && s_axi_bready) begin
        s_axi_bvalid <= 1'b0;
      end
      if (do_write && wr_starts) begin
        op_running <= 1'b1;
        op_resp <= wr_resp;
      end else if (op_result) begin
        op_running <= 1'b0;
      end
      // R
      if (do_read) begin
        s_axi_rvalid <= 1'b1;
        s_axi_rdata <= rd_data;
        s_axi_rresp <= rd_resp;
      end else if (s_axi_rvalid && s_axi_rready) begin
        s_axi_rvalid <= 1'b0;
      end
      op_pass1 <= start_pulse;
      op_pass2 <= op_pass1;
      op_result <= op_pass2;
    end

  specular_reg_block #(
    .CONFIG_VALUE(CONFIG_VALUE), .BATCH_CAPACITY_VALUE(32'd0),
    .PIN19_H_VALUE(PIN19_H_VALUE), .PIN20_A_VALUE(PIN20_A_VALUE)
  ) regs (
    .clk(aclk), .rst_n(aresetn),
    .wr_valid(do_write), .wr_addr(wr_offset), .wr_data(w_data), .wr_strb(w_strb),
    .wr_resp(wr_resp), .wr_starts(wr_starts),
    .rd_valid(do_read), .rd_addr(rd_offset), .rd_data(rd_data), .rd_resp(rd_resp),
    .hw_busy(op_running), .hw_done(op_result),
    // register 1 and register 9 after pass 1: there while select 36 is high
    .hw_reg1_we(op_pass2), .hw_reg1_d({15'd0, obs_reg1_q}),
    .hw_reg9_pass1_lo_we(op_pass2), .hw_reg9_pass1_lo_d(obs_reg9_q[31:0]),
    .hw_reg9_pass1_hi_we(op_pass2), .hw_reg9_pass1_hi_d({{27{obs_reg9_q[36]}}, obs_reg9_q[36:32]}),
    // the results and what made them: there once pin 35 has risen again
    .hw_out_r_we(op_result), .hw_out_r_d(pin24_r),
    .hw_out_g_we(op_result), .hw_out_g_d(pin25_g),
    .hw_out_b_we(op_result), .hw_out_b_d(pin26_b),
    .hw_reg9_pass2_lo_we(op_result), .hw_reg9_pass2_lo_d(obs_reg9_q[31:0]),
    .hw_reg9_pass2_hi_we(op_result), .hw_reg9_pass2_hi_d({{27{obs_reg9_q[36]}}, obs_reg9_q[36:32]}),
    .hw_rom38_k_we(op_result), .hw_rom38_k_d({7'd0, obs_rom38_k}),
    .hw_norm39_we(op_result), .hw_norm39_d({obs_mul39_norm[30], obs_mul39_norm}),
    .cos_q(cos_q), .n_q(n_q), .r_q(r_q), .g_q(g_q), .b_q(b_q),
    .start_pulse(start_pulse), .done_irq(done_irq));

  // The device: the operands go in with the start (the loads reload N, R, G, B each
  // time), ROM 38's bank and adder 8's saturation come from CONFIG.
  specular_device_sync #(.ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) device (
    .pin17_cos(cos_q[16:0]), .pin18_n(n_q[9:0]),
    .pin19_h(PIN19_H_VALUE[17:0]), .pin20_a({{5{PIN20_A_VALUE[31]}}, PIN20_A_VALUE}),
    .pin21_r(r_q[7:0]), .pin22_g(g_q[7:0]), .pin23_b(b_q[7:0]),
    .pin24_r(pin24_r), .pin25_g(pin25_g), .pin26_b(pin26_b),
    .pin27_start(start_pulse), .pin28_clk(aclk), .pin29_reset_n(aresetn),
    .pin30_load_n(start_pulse), .pin31_load_r(start_pulse), .pin32_load_g(start_pulse),
    .pin33_load_b(start_pulse), .pin34_carry(1'b1),
    .pin35_done(pin35_done),
    .cfg_literal(CONFIG_VALUE[4]), .cfg_rom38_bank({CONFIG_VALUE[6:5], CONFIG_VALUE[1:0]}),
    .obs_select36(obs_select36), .obs_write37(obs_write37), .obs_pass1(obs_pass1),
    .obs_reg1_q(obs_reg1_q), .obs_reg9_q(obs_reg9_q), .obs_rom38_k(obs_rom38_k),
    .obs_mul39_norm(obs_mul39_norm));

  // Read only by the assertions (specular_ip_axi_props.v) and the unused-signal lint.
  wire unused = &{1'b0, s_axi_awprot, s_axi_arprot, cos_q[31:17], n_q[31:10], r_q[31:8],
                  g_q[31:8], b_q[31:8], pin35_done, obs_select36, obs_write37, obs_pass1,
                  PIN19_H_VALUE[31:18]};
endmodule

`default_nettype wire
