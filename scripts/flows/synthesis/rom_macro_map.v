// Yosys techmap template for scripts/flows/synthesis/silicon.sh: rom_model.py writes one copy per ROM
// macro (MACRO_NAME, MACRO_WORDS, MACRO_WIDTH, MACRO_ABITS filled in) and silicon.sh
// applies it to that macro's memories only (module/cell selections, rom_macro_map.ys):
// the read-only memories of a top (ROMs 5 and 38, a variant's tables) become the memory
// macros of rom_macros.lib, never gates. A memory of another shape fails the map.
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

  // Asynchronous single-port read-only memory of the macro's size only.
  localparam FITS = RD_PORTS == 1 && WR_PORTS == 0 && RD_CLK_ENABLE == 0 &&
                    SIZE == MACRO_WORDS && WIDTH == MACRO_WIDTH && ABITS >= MACRO_ABITS;
  generate
    if (FITS)
      MACRO_NAME macro (.A(RD_ADDR[MACRO_ABITS-1:0]), .Q(RD_DATA));
    else begin
      wire _TECHMAP_FAIL_ = 1'b1;
    end
  endgenerate
endmodule
