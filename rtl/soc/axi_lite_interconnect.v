// axi_lite_interconnect: one AXI4-Lite master port (s_axi_*) to N slave ports (m_axi_*,
// flattened: slave i's signals are bits [i], [32*i +: 32], ...), for the SoC example
// (docs/rtl_ip.md, "Placing the IP in an SoC").
//   - Decode: slave i owns SLAVE_SIZE[32*i +: 32] bytes (a power of two, 4 to 2^31) at
//     SLAVE_BASE[32*i +: 32] (aligned to its size); the windows may not overlap.
//     Elaboration stops on a parameter that breaks this (the generate blocks named
//     *_MUST_*, which instantiate modules no tool finds).
//   - Every slave gets the FULL 32-bit address, as AXI interconnects pass it; a slave
//     takes the low bits its map needs.
//   - An address no slave owns is answered by the interconnect itself, DECERR (RDATA 0),
//     after its W for a write: its own error slave, index N.
//   - Outstanding transactions: AXI4-Lite has no IDs, so responses must return in the
//     order of the requests. Each direction keeps up to MAX_OUTSTANDING requests in
//     flight, but only while they go to the same slave: a request for another slave
//     waits until every response of the previous one has returned. Each slave answers in
//     order, so the responses come back in order without a reorder buffer or a queue of
//     targets; the cost is a pipeline drain where the master changes slave. Reads and
//     writes are independent, as AXI makes them.
//   - AW and W may come in any order: a W waits (WREADY low) until its AW has gone to a
//     slave, and then goes to the same slave (AXI lets a slave wait for AW before WREADY).
//   - No register on the paths: AW, AR and the responses pass through in the cycle they
//     come (the handshakes are the slave's, so VALID and payloads hold as the slave
//     holds them). AWPROT and ARPROT are passed on unchanged.
`default_nettype none

module axi_lite_interconnect #(
  parameter N = 2,                                        // slaves, 1 to 15
  parameter [32*N-1:0] SLAVE_BASE = {32'h4000_0000, 32'h0000_0000},
  parameter [32*N-1:0] SLAVE_SIZE = {32'h0000_8000, 32'h0001_0000},
  parameter MAX_OUTSTANDING = 4                           // per direction, 1 to 255
) (
  input  wire            aclk,
  input  wire            aresetn,
  // the master's port
  input  wire            s_axi_awvalid,
  output wire            s_axi_awready,
  input  wire [31:0]     s_axi_awaddr,
  input  wire [2:0]      s_axi_awprot,
  input  wire            s_axi_wvalid,
  output wire            s_axi_wready,
  input  wire [31:0]     s_axi_wdata,
  input  wire [3:0]      s_axi_wstrb,
  output wire            s_axi_bvalid,
  input  wire            s_axi_bready,
  output wire [1:0]      s_axi_bresp,
  input  wire            s_axi_arvalid,
  output wire            s_axi_arready,
  input  wire [31:0]     s_axi_araddr,
  input  wire [2:0]      s_axi_arprot,
  output wire            s_axi_rvalid,
  input  wire            s_axi_rready,
  output wire [31:0]     s_axi_rdata,
  output wire [1:0]      s_axi_rresp,
  // the slaves' ports
  output wire [N-1:0]    m_axi_awvalid,
  input  wire [N-1:0]    m_axi_awready,
  output wire [32*N-1:0] m_axi_awaddr,
  output wire [3*N-1:0]  m_axi_awprot,
  output wire [N-1:0]    m_axi_wvalid,
  input  wire [N-1:0]    m_axi_wready,
  output wire [32*N-1:0] m_axi_wdata,
  output wire [4*N-1:0]  m_axi_wstrb,
  input  wire [N-1:0]    m_axi_bvalid,
  output wire [N-1:0]    m_axi_bready,
  input  wire [2*N-1:0]  m_axi_bresp,
  output wire [N-1:0]    m_axi_arvalid,
  input  wire [N-1:0]    m_axi_arready,
  output wire [32*N-1:0] m_axi_araddr,
  output wire [3*N-1:0]  m_axi_arprot,
  input  wire [N-1:0]    m_axi_rvalid,
  output wire [N-1:0]    m_axi_rready,
  input  wire [32*N-1:0] m_axi_rdata,
  input  wire [2*N-1:0]  m_axi_rresp
);
  localparam TW = $clog2(N + 1);                 // a target: slave 0..N-1, or N (error)
  localparam CW = $clog2(MAX_OUTSTANDING + 1) + 1;  // a count in flight (a spare bit: CW >= 2)
  localparam [TW-1:0] ERROR_SLAVE = N[TW-1:0];
  localparam [CW-1:0] MAX_COUNT = MAX_OUTSTANDING[CW-1:0];
  localparam [1:0] DECERR = 2'b11;

  // ---- parameters checked at elaboration ----
  genvar gi, gj;
  generate
    if (N < 1 || N > 15) begin : N_MUST_BE_1_TO_15
      axi_lite_interconnect_N_must_be_1_to_15 refused ();
    end
    if (MAX_OUTSTANDING < 1 || MAX_OUTSTANDING > 255) begin : MAX_OUTSTANDING_MUST_BE_1_TO_255
      axi_lite_interconnect_MAX_OUTSTANDING_must_be_1_to_255 refused ();
    end
    for (gi = 0; gi < N; gi = gi + 1) begin : check_window
      localparam [31:0] BASE = SLAVE_BASE[32*gi +: 32];
      localparam [31:0] SIZE = SLAVE_SIZE[32*gi +: 32];
      if (SIZE < 4 || SIZE > 32'h8000_0000 || (SIZE & (SIZE - 1)) != 0) begin : SIZE_MUST_BE_A_POWER_OF_TWO_4_TO_2_31
        axi_lite_interconnect_SLAVE_SIZE_must_be_a_power_of_two_4_to_2_31 refused ();
      end
      if ((BASE & (SIZE - 1)) != 0) begin : BASE_MUST_BE_ALIGNED_TO_SIZE
        axi_lite_interconnect_SLAVE_BASE_must_be_aligned_to_SLAVE_SIZE refused ();
      end
      for (gj = 0; gj < gi; gj = gj + 1) begin : check_pair
        localparam [31:0] BASE_J = SLAVE_BASE[32*gj +: 32];
        localparam [31:0] SIZE_J = SLAVE_SIZE[32*gj +: 32];
        // Two aligned power-of-two windows overlap when one holds the other's base.
        if ((BASE & ~(SIZE_J - 1)) == BASE_J || (BASE_J & ~(SIZE - 1)) == BASE) begin : WINDOWS_MUST_NOT_OVERLAP
          axi_lite_interconnect_windows_must_not_overlap refused ();
        end
      end
    end
  endgenerate

  // The slave that owns an address, ERROR_SLAVE if none does.
  function [TW-1:0] decode;
    input [31:0] address;
    integer i;
    begin
      decode = ERROR_SLAVE;
      for (i = 0; i < N; i = i + 1)
        if ((address & ~(SLAVE_SIZE[32*i +: 32] - 32'd1)) == SLAVE_BASE[32*i +: 32])
          decode = i[TW-1:0];
    end
  endfunction
  // One bit per target (the error slave's at N), set for target t.
  function [N:0] one_hot;
    input [TW-1:0] t;
    integer i;
    begin
      for (i = 0; i <= N; i = i + 1)
        one_hot[i] = (t == i[TW-1:0]);
    end
  endfunction

  // ---- writes ----
  reg  [TW-1:0] wr_target;   // the slave of the writes in flight
  reg  [CW-1:0] wr_out;      // AWs passed on whose B has not returned
  reg  [CW-1:0] w_owed;      // AWs passed on whose W has not
  reg  [CW-1:0] err_b;       // the error slave's B owed (its W taken)
  wire [TW-1:0] aw_decode = decode(s_axi_awaddr);
  wire          wr_allowed = (wr_out == {CW{1'b0}} || aw_decode == wr_target) && wr_out != MAX_COUNT;
  wire [N:0]    aw_sel = one_hot(aw_decode);
  wire [N:0]    w_sel = (w_owed != {CW{1'b0}}) ? one_hot(wr_target) : {(N + 1){1'b0}};
  wire [N:0]    b_sel = (wr_out != {CW{1'b0}}) ? one_hot(wr_target) : {(N + 1){1'b0}};
  wire          err_bvalid = err_b != {CW{1'b0}};

  assign m_axi_awvalid = {N{s_axi_awvalid && wr_allowed}} & aw_sel[N-1:0];
  assign s_axi_awready = wr_allowed && |({1'b1, m_axi_awready} & aw_sel);
  assign m_axi_awaddr = {N{s_axi_awaddr}};
  assign m_axi_awprot = {N{s_axi_awprot}};
  assign m_axi_wvalid = {N{s_axi_wvalid}} & w_sel[N-1:0];
  assign s_axi_wready = |({1'b1, m_axi_wready} & w_sel);
  assign m_axi_wdata = {N{s_axi_wdata}};
  assign m_axi_wstrb = {N{s_axi_wstrb}};
  assign s_axi_bvalid = |({err_bvalid, m_axi_bvalid} & b_sel);
  assign m_axi_bready = {N{s_axi_bready}} & b_sel[N-1:0];

  wire aw_go = s_axi_awvalid && s_axi_awready;
  wire w_go = s_axi_wvalid && s_axi_wready;
  wire b_go = s_axi_bvalid && s_axi_bready;

  // ---- reads ----
  reg  [TW-1:0] rd_target;
  reg  [CW-1:0] rd_out;      // ARs passed on whose R has not returned
  reg  [CW-1:0] err_r;       // the error slave's R owed
  wire [TW-1:0] ar_decode = decode(s_axi_araddr);
  wire          rd_allowed = (rd_out == {CW{1'b0}} || ar_decode == rd_target) && rd_out != MAX_COUNT;
  wire [N:0]    ar_sel = one_hot(ar_decode);
  wire [N:0]    r_sel = (rd_out != {CW{1'b0}}) ? one_hot(rd_target) : {(N + 1){1'b0}};
  wire          err_rvalid = err_r != {CW{1'b0}};

  assign m_axi_arvalid = {N{s_axi_arvalid && rd_allowed}} & ar_sel[N-1:0];
  assign s_axi_arready = rd_allowed && |({1'b1, m_axi_arready} & ar_sel);
  assign m_axi_araddr = {N{s_axi_araddr}};
  assign m_axi_arprot = {N{s_axi_arprot}};
  assign s_axi_rvalid = |({err_rvalid, m_axi_rvalid} & r_sel);
  assign m_axi_rready = {N{s_axi_rready}} & r_sel[N-1:0];

  wire ar_go = s_axi_arvalid && s_axi_arready;
  wire r_go = s_axi_rvalid && s_axi_rready;

  // ---- the response payloads of the selected slave (the error slave's: DECERR, 0) ----
  reg [1:0]  bresp, rresp;
  reg [31:0] rdata;
  integer k;
  always @* begin
    bresp = b_sel[N] ? DECERR : 2'b00;
    rresp = r_sel[N] ? DECERR : 2'b00;
    rdata = 32'd0;
    for (k = 0; k < N; k = k + 1) begin
      bresp = bresp | ({2{b_sel[k]}} & m_axi_bresp[2*k +: 2]);
      rresp = rresp | ({2{r_sel[k]}} & m_axi_rresp[2*k +: 2]);
      rdata = rdata | ({32{r_sel[k]}} & m_axi_rdata[32*k +: 32]);
    end
  end
  assign s_axi_bresp = bresp;
  assign s_axi_rresp = rresp;
  assign s_axi_rdata = rdata;

  always @(posedge aclk)
    if (!aresetn) begin
      wr_target <= {TW{1'b0}};
      wr_out <= {CW{1'b0}};
      w_owed <= {CW{1'b0}};
      err_b <= {CW{1'b0}};
      rd_target <= {TW{1'b0}};
      rd_out <= {CW{1'b0}};
      err_r <= {CW{1'b0}};
    end else begin
      // (a new target only when nothing is in flight: then the assignment changes it,
      // otherwise it keeps the value it has)
      if (aw_go) wr_target <= aw_decode;
      wr_out <= wr_out + {{(CW - 1){1'b0}}, aw_go} - {{(CW - 1){1'b0}}, b_go};
      w_owed <= w_owed + {{(CW - 1){1'b0}}, aw_go} - {{(CW - 1){1'b0}}, w_go};
      err_b <= err_b + {{(CW - 1){1'b0}}, w_go && w_sel[N]} - {{(CW - 1){1'b0}}, b_go && b_sel[N]};
      if (ar_go) rd_target <= ar_decode;
      rd_out <= rd_out + {{(CW - 1){1'b0}}, ar_go} - {{(CW - 1){1'b0}}, r_go};
      err_r <= err_r + {{(CW - 1){1'b0}}, ar_go && ar_sel[N]} - {{(CW - 1){1'b0}}, r_go && r_sel[N]};
    end
endmodule

`default_nettype wire
