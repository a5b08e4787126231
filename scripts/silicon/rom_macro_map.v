// Yosys techmap for scripts/silicon.sh: the two ROM memories of rtl/ become the memory
// macros ROM5_MACRO and ROM38_MACRO (Liberty models written by rom_model.py), never
// gates. Any other memory fails the map (the flow then stops: rtl/ has no other).
(* techmap_celltype = "$mem_v2" *)
module rom_macro_map (RD_CLK, RD_EN, RD_ARST, RD_SRST, RD_ADDR, RD_DATA,
                      WR_CLK, WR_EN, WR_ADDR, WR_DATA);
  parameter MEMID = "";
  parameter signed SIZE = 4;
  parameter signed OFFSET = 0;
  parameter signed ABITS = 2;
  parameter signed WIDTH = 8;
  parameter signed INIT = 1'bx;
  parameter signed RD_PORTS = 1;
  parameter RD_CLK_ENABLE = 1'b1;
  parameter RD_CLK_POLARITY = 1'b1;
  parameter RD_TRANSPARENCY_MASK = 1'b0;
  parameter RD_COLLISION_X_MASK = 1'b0;
  parameter RD_WIDE_CONTINUATION = 1'b0;
  parameter RD_CE_OVER_SRST = 1'b0;
  parameter RD_ARST_VALUE = 1'b0;
  parameter RD_SRST_VALUE = 1'b0;
  parameter RD_INIT_VALUE = 1'b0;
  parameter signed WR_PORTS = 1;
  parameter WR_CLK_ENABLE = 1'b1;
  parameter WR_CLK_POLARITY = 1'b1;
  parameter WR_PRIORITY_MASK = 1'b0;
  parameter WR_WIDE_CONTINUATION = 1'b0;

  input [RD_PORTS-1:0] RD_CLK, RD_EN, RD_ARST, RD_SRST;
  input [RD_PORTS*ABITS-1:0] RD_ADDR;
  output [RD_PORTS*WIDTH-1:0] RD_DATA;
  input [WR_PORTS-1:0] WR_CLK;
  input [WR_PORTS*WIDTH-1:0] WR_EN;
  input [WR_PORTS*ABITS-1:0] WR_ADDR;
  input [WR_PORTS*WIDTH-1:0] WR_DATA;

  // Asynchronous single-port read-only memories at the default widths only.
  localparam ROM5 = RD_PORTS == 1 && WR_PORTS == 0 && RD_CLK_ENABLE == 0 &&
                    SIZE == 32768 && WIDTH == 22;
  localparam ROM38 = RD_PORTS == 1 && WR_PORTS == 0 && RD_CLK_ENABLE == 0 &&
                     SIZE == 16384 && WIDTH == 25;
  generate
    if (ROM5)
      ROM5_MACRO macro (.A(RD_ADDR[14:0]), .Q(RD_DATA));
    else if (ROM38)
      ROM38_MACRO macro (.A(RD_ADDR[13:0]), .Q(RD_DATA));
    else begin
      wire _TECHMAP_FAIL_ = 1'b1;
    end
  endgenerate
endmodule
