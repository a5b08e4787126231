// The exp2 unit: 2^x for x <= 0, the usual hardware exp2 (Tang 1989; Oberman and Siu,
// ARITH-17, 2005; docs/variants/exp2.md). x's integer part becomes a right
// shift; the top ADDR_BITS bits of its fraction f address a table of 2^(i/2^ADDR_BITS)
// (VALUE_FRAC fraction bits, the leading one implied) beside the difference to the next
// word (DELTA_W bits), and the other bits of f interpolate linearly between the two.
// x >= 0 reads as 0 (result 1.0). The result is rounded half up to OUT_FRAC fraction bits.
// Same bits as specular::variants::Exp2Table::pow2; the image is written by
// specular_romgen from that table.
`default_nettype none

module exp2_unit #(
  parameter X_W = 37,          // x, signed (register 9's S14.22)
  parameter X_FRAC = 22,
  parameter ADDR_BITS = 9,     // table words: 2^ADDR_BITS
  parameter VALUE_FRAC = 24,   // a table value's fraction bits
  parameter DELTA_W = 16,      // a table difference's bits
  parameter OUT_W = 37,        // the result, signed, value in [0, 1]
  parameter OUT_FRAC = 22,
  parameter IMAGE = "exp2.hex"
) (
  input  wire [X_W-1:0]   x,
  output wire [OUT_W-1:0] pow2
);
  localparam WORDS = 1 << ADDR_BITS;
  localparam WORD_W = VALUE_FRAC + DELTA_W;
  localparam LOW = X_FRAC - ADDR_BITS;           // interpolation fraction bits
  localparam INT_W = X_W - X_FRAC;               // x's integer part, signed
  localparam integer ALIGN = VALUE_FRAC - OUT_FRAC;      // the shift when floor(x) = 0
  localparam integer MAX_SHIFT = VALUE_FRAC + 2;         // any longer shift also leaves 0
  localparam SHIFT_W = $clog2(MAX_SHIFT + 1);
  localparam M_W = VALUE_FRAC + 2;               // 2^f on VALUE_FRAC bits, one spare
  localparam PROD_W = DELTA_W + LOW;

  reg [WORD_W-1:0] exp2_rom [0:WORDS-1];
  initial $readmemh(IMAGE, exp2_rom);

  // The domain is x <= 0: a positive x reads as 0.
  wire [X_W-1:0] x_domain = x[X_W-1] ? x : {X_W{1'b0}};

  // Integer part: k = -floor(x) >= 0, as a saturated shift amount k + ALIGN.
  wire [INT_W-1:0] k = {INT_W{1'b0}} - x_domain[X_W-1:X_FRAC];
  localparam integer K_LIMIT = MAX_SHIFT - ALIGN;
  wire [SHIFT_W-1:0] shift = (k >= K_LIMIT[INT_W-1:0]) ? MAX_SHIFT[SHIFT_W-1:0]
                                            : k[SHIFT_W-1:0] + ALIGN[SHIFT_W-1:0];

  // Fraction: table word and linear interpolation, rounded half up.
  wire [ADDR_BITS-1:0] address = x_domain[X_FRAC-1 -: ADDR_BITS];
  wire [LOW-1:0]       t = x_domain[LOW-1:0];
  wire [WORD_W-1:0]    word = exp2_rom[address];
  wire [DELTA_W-1:0]   delta = word[DELTA_W-1:0];
  wire [PROD_W-1:0]    product = delta * t;
  localparam [PROD_W:0] HALF = {{PROD_W{1'b0}}, 1'b1} << (LOW - 1);
  wire [PROD_W:0]      biased = {1'b0, product} + HALF;
  wire [M_W-1:0]       step = {{(M_W-DELTA_W-1){1'b0}}, biased[PROD_W:LOW]};
  wire [M_W-1:0]       mantissa = {2'b01, word[WORD_W-1:DELTA_W]} + step;

  // Integer part: shift right by SHIFT rounding half up, floor((m >> (SHIFT-1) + 1) / 2).
  wire [M_W-1:0] shifted = mantissa >> (shift - 1'b1);
  wire [M_W-1:0] rounded = shifted + {{(M_W-1){1'b0}}, 1'b1};
  assign pow2 = {{(OUT_W-M_W+1){1'b0}}, rounded[M_W-1:1]};

  wire unused_ok = &{1'b0, rounded[0], biased[LOW-1:0], k[INT_W-1:SHIFT_W]};
endmodule

`default_nettype wire
