// Reciprocal unit (variant schlick, docs/variants/schlick.md): y1 ~ 1/m for a divisor
// normalised to m in [1, 2) (leading one at the mantissa's top bit). A table of
// 2^ADDR_BITS words y0 = round(2^WORD_BITS / (1 + (a + 1/2)/2^ADDR_BITS)), read at m's
// first fraction bits, then one Newton-Raphson step y1 = y0 + y0*(1 - m*y0) + BIAS,
// which squares the table's error; BIAS (2^-23) centres the step's one-sided error.
// Combinational. Same bits as specular::variants::ReciprocalNr; the image (recip.hex)
// is written by specular_romgen from that table.
`default_nettype none

module reciprocal_nr #(
  parameter MANT_W = 26,      // the mantissa m, U1.(MANT_W-1)
  parameter ADDR_BITS = 10,
  parameter WORD_BITS = 13,   // y0, U0.WORD_BITS
  parameter ERROR_FRAC = 28,  // e0 = 1 - m*y0 kept to 2^-ERROR_FRAC (floor)
  parameter ERROR_W = 19,     // |e0| < 2^-10: 18 magnitude bits and a sign at 2^-28
  parameter FRAC = 26,        // y1, U0.FRAC
  parameter BIAS = 8,         // added to y1, in 2^-FRAC units
  parameter IMAGE = "recip.hex"
) (
  input  wire [MANT_W-1:0] mantissa,
  output wire [FRAC-1:0]   y1
);
  localparam WORDS = 1 << ADDR_BITS;
  reg [WORD_BITS-1:0] y0_rom [0:WORDS-1];
  initial $readmemh(IMAGE, y0_rom);

  wire [ADDR_BITS-1:0] address = mantissa[MANT_W-2 -: ADDR_BITS];
  wire [WORD_BITS-1:0] y0 = y0_rom[address];

  // e0 = 1 - m*y0, exact at 2^-(MANT_W-1+WORD_BITS), then floored to ERROR_FRAC bits:
  // its top bits are copies of the sign (|e0| < 2^-10), so ERROR_W bits keep it all.
  localparam PROD_W = MANT_W + WORD_BITS + 1;    // one bit more: a signed difference
  localparam DROP = MANT_W - 1 + WORD_BITS - ERROR_FRAC;
  wire [PROD_W-1:0] m_y0 = {{(WORD_BITS+1){1'b0}}, mantissa} * {{(MANT_W+1){1'b0}}, y0};
  wire [PROD_W-1:0] one = {2'b01, {(PROD_W-2){1'b0}}};
  wire [PROD_W-1:0] e0 = one - m_y0;
  wire signed [ERROR_W-1:0] e0_kept = e0[DROP +: ERROR_W];

  // y0*e0 rounded half up to 2^-FRAC: a WORD_BITS x ERROR_W multiplier.
  localparam CORR_W = WORD_BITS + 1 + ERROR_W;   // the signed product
  localparam SHIFT = WORD_BITS + ERROR_FRAC - FRAC;
  wire signed [WORD_BITS:0] y0_signed = {1'b0, y0};
  wire signed [CORR_W-1:0] y0_e0 = {{(ERROR_W){y0_signed[WORD_BITS]}}, y0_signed} *
                                   {{(WORD_BITS+1){e0_kept[ERROR_W-1]}}, e0_kept};
  wire [CORR_W-1:0] half = {{(CORR_W-SHIFT){1'b0}}, 1'b1, {(SHIFT-1){1'b0}}};
  wire [CORR_W-1:0] y0_e0_rounded = y0_e0 + half;
  wire [CORR_W-SHIFT-1:0] correction = y0_e0_rounded[CORR_W-1:SHIFT];
  wire [FRAC-1:0] correction_wide = {{(FRAC-CORR_W+SHIFT){correction[CORR_W-SHIFT-1]}}, correction};
  wire [FRAC-1:0] bias = BIAS;
  assign y1 = {y0, {(FRAC-WORD_BITS){1'b0}}} + correction_wide + bias;

  // e0's sign copies and dropped bits, the rounding's dropped bits are not needed.
  wire unused_ok = &{1'b0, e0[PROD_W-1:DROP+ERROR_W], e0[DROP-1:0],
                     y0_e0_rounded[SHIFT-1:0]};
endmodule

`default_nettype wire
