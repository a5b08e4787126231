// ROM 38: the normalisation coefficient K(n), addressed by register 2. The image holds
// one bank of 2^N_BITS words per normalisation policy (bank b = the Normalisation enum
// value b, written by specular_romgen from arith::Rom38Table); cfg_bank picks the bank,
// a configuration input tied off by whoever instantiates the device. Same bits as
// arith::Rom38Table::k.
`default_nettype none

module rom38 #(
  parameter N_BITS = 10,
  parameter WORD_W = 24,      // ROM38_INT + ROM38_FRAC, unsigned
  parameter BANK_BITS = 2,
  parameter IMAGE = "rom38.hex"
) (
  input  wire [BANK_BITS-1:0] bank,
  input  wire [N_BITS-1:0]    reg2,
  output wire [WORD_W-1:0]    k
);
  localparam WORDS = 1 << (BANK_BITS + N_BITS);

  reg [WORD_W-1:0] k_rom [0:WORDS-1];
  // A host that writes the words itself (the verilated twin: twin/rom_words.vlt) defines
  // SPECULAR_ROM_WORDS_FROM_HOST and the model reads no file.
`ifndef SPECULAR_ROM_WORDS_FROM_HOST
  initial $readmemh(IMAGE, k_rom);
`endif

  assign k = k_rom[{bank, reg2}];
endmodule

`default_nettype wire
