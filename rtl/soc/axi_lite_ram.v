// axi_lite_ram: an AXI4-Lite RAM slave for the SoC example (docs/rtl_ip.md, "Placing the
// IP in an SoC"): BYTES bytes (a power of two, 8 to 2^30) of 32-bit words, byte strobes.
//   - The address is the full one an interconnect passes; the RAM reads the word index
//     from bits [log2(BYTES)-1:2] and ignores the rest (the interconnect selects it by the
//     bits above; bits 1:0 are the strobes' business, as AXI4-Lite has it).
//   - Write: AW and W are taken in any order into one holding register each; the write is
//     done when both are held, every strobed byte lane written (no strobe: nothing
//     written), and its B (always OKAY) is queued.
//   - Read: the word is read when the AR is taken and its R queued.
//   - Up to DEPTH (a power of two, 2 to 16) responses queue in each direction while the
//     master holds BREADY or RREADY low, so that several requests can be in flight (what
//     the interconnect's outstanding rule is there for). A write is never answered
//     before it is done, a read returns the word as it was when its AR was taken.
// The memory has no reset and no initial contents: a word never written reads X in
// simulation, as a real RAM reads what it powered up with.
`default_nettype none

module axi_lite_ram #(
  parameter BYTES = 65536,
  parameter DEPTH = 4
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
  output wire [1:0]  s_axi_rresp
);
  localparam WORDS = BYTES / 4;
  localparam IW = $clog2(WORDS);        // word index bits
  localparam PW = $clog2(DEPTH);        // a queue position
  localparam CW = PW + 1;               // a queue's fill, 0..DEPTH
  localparam [CW-1:0] FULL = DEPTH[CW-1:0];

  generate
    if (BYTES < 8 || BYTES > 32'h4000_0000 || (BYTES & (BYTES - 1)) != 0) begin : BYTES_MUST_BE_A_POWER_OF_TWO_8_TO_2_30
      axi_lite_ram_BYTES_must_be_a_power_of_two_8_to_2_30 refused ();
    end
    if (DEPTH < 2 || DEPTH > 16 || (DEPTH & (DEPTH - 1)) != 0) begin : DEPTH_MUST_BE_A_POWER_OF_TWO_2_TO_16
      axi_lite_ram_DEPTH_must_be_a_power_of_two_2_to_16 refused ();
    end
  endgenerate

  reg [31:0] mem [0:WORDS-1];

  // ---- writes ----
  reg          aw_held, w_held;
  reg [IW-1:0] aw_word;
  reg [31:0]   w_data;
  reg [3:0]    w_strb;
  reg [CW-1:0] b_count;               // B queued (all OKAY: a count is the queue)
  wire do_write = aw_held && w_held && b_count != FULL;
  wire b_go = s_axi_bvalid && s_axi_bready;
  assign s_axi_awready = ~aw_held;
  assign s_axi_wready = ~w_held;
  assign s_axi_bvalid = b_count != {CW{1'b0}};
  assign s_axi_bresp = 2'b00;

  // ---- reads ----
  reg [31:0]   r_queue [0:DEPTH-1];
  reg [PW-1:0] r_head, r_tail;
  reg [CW-1:0] r_count;
  assign s_axi_arready = r_count != FULL;
  wire ar_go = s_axi_arvalid && s_axi_arready;
  wire r_go = s_axi_rvalid && s_axi_rready;
  assign s_axi_rvalid = r_count != {CW{1'b0}};
  assign s_axi_rdata = r_queue[r_head];
  assign s_axi_rresp = 2'b00;

  always @(posedge aclk)
    if (!aresetn) begin
      aw_held <= 1'b0;
      w_held <= 1'b0;
      aw_word <= {IW{1'b0}};
      w_data <= 32'd0;
      w_strb <= 4'd0;
      b_count <= {CW{1'b0}};
      r_head <= {PW{1'b0}};
      r_tail <= {PW{1'b0}};
      r_count <= {CW{1'b0}};
    end else begin
      if (s_axi_awvalid && s_axi_awready) begin
        aw_held <= 1'b1;
        aw_word <= s_axi_awaddr[IW+1:2];
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
      b_count <= b_count + {{PW{1'b0}}, do_write} - {{PW{1'b0}}, b_go};
      if (ar_go) r_tail <= r_tail + 1'b1;
      if (r_go) r_head <= r_head + 1'b1;
      r_count <= r_count + {{PW{1'b0}}, ar_go} - {{PW{1'b0}}, r_go};
    end

  // The memory and the read queue: no reset (a RAM block's words have none).
  always @(posedge aclk) begin
    if (do_write) begin
      if (w_strb[0]) mem[aw_word][7:0] <= w_data[7:0];
      if (w_strb[1]) mem[aw_word][15:8] <= w_data[15:8];
      if (w_strb[2]) mem[aw_word][23:16] <= w_data[23:16];
      if (w_strb[3]) mem[aw_word][31:24] <= w_data[31:24];
    end
    if (aresetn && ar_go) r_queue[r_tail] <= mem[s_axi_araddr[IW+1:2]];
  end

  // Read only by the unused-signal lint.
  wire unused = &{1'b0, s_axi_awaddr[31:IW+2], s_axi_awaddr[1:0], s_axi_araddr[31:IW+2],
                  s_axi_araddr[1:0], s_axi_awprot, s_axi_arprot};
endmodule

`default_nettype wire
