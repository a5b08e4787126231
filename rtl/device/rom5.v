// ROM 5: log2 of the multiplexer-3 bus, the usual hardware log2 unit (spec section 4):
// a leading-one detector finds the exponent, the ADDR_BITS bits just below the leading
// one address a mantissa ROM of round(log2(1 + a/2^ADDR_BITS) * 2^WORD_BITS), and the
// exponent is added back. A bus <= 0 reads as log2 of the smallest cos code, -COS_FRAC
// (spec, Decision "log2 0"). Same bits as arith::Rom5Table::lookup; the image is written
// by specular_romgen from that table (rtl/romgen).
`default_nettype none

module rom5 #(
  parameter ADDR_BITS = 15,
  parameter WORD_BITS = 22,
  parameter BUS_W = 37,       // multiplexer-3 bus (1 + REG9_INT + REG9_FRAC), signed
  parameter BUS_FRAC = 22,    // its fraction bits
  parameter COS_FRAC = 16,    // log2 0 := -COS_FRAC
  parameter LOG2_W = 28,      // output width (1 + LOG2_INT + WORD_BITS), signed
  parameter IMAGE = "rom5.hex"
) (
  input  wire [BUS_W-1:0]  bus,
  output wire [LOG2_W-1:0] log2
);
  localparam WORDS = 1 << ADDR_BITS;
  localparam EXP_W = LOG2_W - WORD_BITS;  // signed exponent: 1 + LOG2_INT bits
  localparam POS_W = $clog2(BUS_W);       // a bit index of the bus
  localparam NORM_W = BUS_W + ADDR_BITS;  // bus with ADDR_BITS zeros appended

  reg [WORD_BITS-1:0] mantissa_rom [0:WORDS-1];
  // A host that writes the words itself (the verilated twin: twin/rom_words.vlt) defines
  // SPECULAR_ROM_WORDS_FROM_HOST and the model reads no file.
`ifndef SPECULAR_ROM_WORDS_FROM_HOST
  initial $readmemh(IMAGE, mantissa_rom);
`endif

  // Leading-one detector: index of the highest one below the sign bit. Its own loop, not
  // the shared rtl/primitives/leading_one_normaliser.v (Schlick's variant): with that block ROM 5
  // mapped 11 645 um^2 larger and its device's T_sta 2.87 ns longer on OSU 0.18 um
  // (docs/design_space.md); arith::leading_one is the one C++ model of both.
  reg [POS_W-1:0] msb;
  integer i;
  always @* begin
    msb = {POS_W{1'b0}};
    for (i = 0; i < BUS_W - 1; i = i + 1)
      if (bus[i]) msb = i[POS_W-1:0];
  end

  // Normaliser: the leading one moves to the top bit and out; the next ADDR_BITS bits
  // are the address (zero-filled when fewer bits follow the leading one).
  localparam integer TOP = BUS_W - 1;
  wire [POS_W-1:0]  left = TOP[POS_W-1:0] - msb;
  wire [NORM_W-1:0] normalised = {bus, {ADDR_BITS{1'b0}}} << left;
  wire [ADDR_BITS-1:0] address = normalised[NORM_W-2 -: ADDR_BITS];
  wire [WORD_BITS-1:0] word = mantissa_rom[address];

  // Exponent msb - BUS_FRAC and the result exponent * 2^WORD_BITS + word, modulo the
  // output width (the exact value always fits: format.cpp sizes LOG2_INT for it).
  localparam CALC_W = (POS_W > EXP_W ? POS_W : EXP_W) + 1;
  localparam integer ZERO_EXP = -COS_FRAC;
  wire [CALC_W-1:0] exponent = {{(CALC_W-POS_W){1'b0}}, msb} - BUS_FRAC[CALC_W-1:0];
  wire [LOG2_W-1:0] scaled = {exponent[EXP_W-1:0], {WORD_BITS{1'b0}}};
  wire [LOG2_W-1:0] positive = scaled + {{EXP_W{1'b0}}, word};
  wire [LOG2_W-1:0] zero_log2 = {ZERO_EXP[EXP_W-1:0], {WORD_BITS{1'b0}}};
  wire non_positive = bus[BUS_W-1] || (bus == {BUS_W{1'b0}});
  assign log2 = non_positive ? zero_log2 : positive;

  // Bits a log2 unit reads but does not need: the normaliser's leading one and the
  // bits below the address, the exponent's spare top bits.
  wire unused_ok = &{1'b0, normalised[NORM_W-1], normalised[NORM_W-ADDR_BITS-2:0],
                     exponent[CALC_W-1:EXP_W]};
endmodule

`default_nettype wire
