// The device of Fig. 1 (UA 59965 U) behind pins 17-35: the RTL twin of
// modules/src/device.cpp. Instances are named by reference number, nets after the block
// that drives them, as in the SystemC model, so a waveform of either reads the same.
// Widths are parameters whose defaults are the formats of docs/design.md.
`default_nettype none

module specular_device #(
  parameter COS_FRAC = 16, N_BITS = 10, RGB_BITS = 8,
  parameter ROM5_ADDR_BITS = 15, ROM5_WORD_BITS = 22,
  parameter REG9_INT = 14, REG9_FRAC = 22,
  parameter MUX4_FRAC = 8,
  parameter ROM38_INT = 9, ROM38_FRAC = 16, ROM38_BANK_BITS = 4,
  parameter NORM_INT = 10, NORM_FRAC = 20,
  parameter OUT_INT = 18, OUT_FRAC = 13,
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex",
  // A configuration fixed when the device is built (docs/rtl/sync.md, "Specialised
  // verilation"): FIXED_CONFIG = 1 ties pins 19, 20, 34 and the configuration inputs off
  // inside the device to these values, so a simulator folds them into the datapath (the
  // pins stay and are not read). FIXED_CONFIG = 0 (default): the pins and inputs are read.
  parameter FIXED_CONFIG = 0,
  parameter [N_BITS+MUX4_FRAC-1:0] FIXED_H19 = 0,
  parameter [REG9_INT+REG9_FRAC:0] FIXED_A20 = 0,
  parameter FIXED_CARRY34 = 1, FIXED_LITERAL = 0,
  parameter [ROM38_BANK_BITS-1:0] FIXED_ROM38_BANK = 0
) (
  input  wire [COS_FRAC:0]                    pin17_cos,    // U1.COS_FRAC
  input  wire [N_BITS-1:0]                    pin18_n,
  input  wire [N_BITS+MUX4_FRAC-1:0]          pin19_h,      // h: 1/2 under the patent's constants
  input  wire signed [REG9_INT+REG9_FRAC:0]   pin20_a,      // a: 1.0 under the patent's constants
  input  wire [RGB_BITS-1:0]                  pin21_r, pin22_g, pin23_b,
  output wire signed [OUT_INT+OUT_FRAC:0]     pin24_r, pin25_g, pin26_b,
  input  wire pin27_start, pin28_clk, pin29_reset_n,
  input  wire pin30_load_n, pin31_load_r, pin32_load_g, pin33_load_b, pin34_carry,
  output wire pin35_done,
  // configuration inputs (not pins of the patent): tied off by whoever instantiates it
  input  wire cfg_literal,                          // 1: Saturation::literal, 0: clamp
  input  wire [ROM38_BANK_BITS-1:0] cfg_rom38_bank, // ROM 38 image: Normalisation enum order
  // observation outputs (for harnesses and checkers)
  output wire obs_select36, obs_write37, obs_q41, obs_q42, obs_nand45,
  output wire [COS_FRAC:0]                    obs_reg1_q,
  output wire signed [REG9_INT+REG9_FRAC:0]   obs_reg9_q,
  output wire [ROM38_INT+ROM38_FRAC-1:0]      obs_rom38_k,
  output wire signed [NORM_INT+NORM_FRAC:0]   obs_mul39_norm
);
  // ---- derived widths (format.cpp) ----
  localparam COS_W = 1 + COS_FRAC;
  localparam MUX4_W = N_BITS + MUX4_FRAC;
  // bits_for(max(REG9_FRAC, REG9_INT)): integer bits that hold that magnitude.
  localparam LOG2_INT = $clog2((REG9_FRAC > REG9_INT ? REG9_FRAC : REG9_INT) + 1);
  localparam LOG2_W = 1 + LOG2_INT + ROM5_WORD_BITS;
  localparam REG9_W = 1 + REG9_INT + REG9_FRAC;
  localparam ROM38_W = ROM38_INT + ROM38_FRAC;
  localparam NORM_W = 1 + NORM_INT + NORM_FRAC;
  localparam OUT_W = 1 + OUT_INT + OUT_FRAC;
  localparam MUL6_SHIFT = ROM5_WORD_BITS + MUX4_FRAC - REG9_FRAC;
  localparam MUL39_SHIFT = REG9_FRAC + ROM38_FRAC - NORM_FRAC;
  localparam RGB_SHIFT = NORM_FRAC - OUT_FRAC;

  // ---- nets of Fig. 1, named after the block that drives them ----
  wire [COS_W-1:0]    reg1_q;
  wire [N_BITS-1:0]   reg2_q;
  wire [REG9_W-1:0]   mux3_address;
  wire [LOG2_W-1:0]   rom5_log2;
  wire [MUX4_W-1:0]   mux4_operand;
  wire [REG9_W-1:0]   mul6_product;
  wire [REG9_W-1:0]   inv7_inverted;
  wire [REG9_W-1:0]   adder8_sum;
  wire [REG9_W-1:0]   reg9_q;
  wire [RGB_BITS-1:0] reg10_q, reg11_q, reg12_q;
  wire [ROM38_W-1:0]  rom38_k;
  wire [NORM_W-1:0]   mul39_norm;
  wire select36, write37;

  // Pins 19, 20, 34 and the configuration inputs, or their values fixed at build time.
  wire [MUX4_W-1:0]          h19 = FIXED_CONFIG != 0 ? FIXED_H19 : pin19_h;
  wire [REG9_W-1:0]          a20 = FIXED_CONFIG != 0 ? FIXED_A20 : pin20_a;
  wire                       carry34 = FIXED_CONFIG != 0 ? FIXED_CARRY34 != 0 : pin34_carry;
  wire                       literal = FIXED_CONFIG != 0 ? FIXED_LITERAL != 0 : cfg_literal;
  wire [ROM38_BANK_BITS-1:0] rom38_bank = FIXED_CONFIG != 0 ? FIXED_ROM38_BANK : cfg_rom38_bank;

  // Input registers: 1 is written by the start pin itself (spec section 2).
  register #(.W(COS_W))    reg1  (.load(pin27_start),  .d(pin17_cos), .q(reg1_q));
  register #(.W(N_BITS))   reg2  (.load(pin30_load_n), .d(pin18_n),   .q(reg2_q));
  register #(.W(RGB_BITS)) reg10 (.load(pin31_load_r), .d(pin21_r),   .q(reg10_q));
  register #(.W(RGB_BITS)) reg11 (.load(pin32_load_g), .d(pin22_g),   .q(reg11_q));
  register #(.W(RGB_BITS)) reg12 (.load(pin33_load_b), .d(pin23_b),   .q(reg12_q));

  // The two-pass loop: multiplexers -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8
  // -> register 9.
  multiplexer3 #(.COS_W(COS_W), .REG9_W(REG9_W), .ALIGN(REG9_FRAC - COS_FRAC)) mux3 (
    .select36(select36), .reg1(reg1_q), .reg9(reg9_q), .address(mux3_address));
  multiplexer4 #(.N_BITS(N_BITS), .FRAC(MUX4_FRAC)) mux4 (
    .select36(select36), .reg2(reg2_q), .h19(h19), .operand(mux4_operand));
  rom5 #(.ADDR_BITS(ROM5_ADDR_BITS), .WORD_BITS(ROM5_WORD_BITS), .BUS_W(REG9_W),
         .BUS_FRAC(REG9_FRAC), .COS_FRAC(COS_FRAC), .LOG2_W(LOG2_W),
         .IMAGE(ROM5_IMAGE)) rom5 (
    .bus(mux3_address), .log2(rom5_log2));
  multiplier6 #(.LOG2_W(LOG2_W), .OPERAND_W(MUX4_W), .OUT_W(REG9_W),
                .SHIFT(MUL6_SHIFT)) mul6 (
    .log2(rom5_log2), .operand(mux4_operand), .product(mul6_product));
  inverter7 #(.W(REG9_W)) inv7 (.product(mul6_product), .inverted(inv7_inverted));
  adder8 #(.W(REG9_W)) adder8 (
    .literal(literal), .a20(a20), .inverted(inv7_inverted),
    .carry34(carry34), .sum(adder8_sum));
  register #(.W(REG9_W)) reg9 (.load(write37), .d(adder8_sum), .q(reg9_q));

  // Normalisation and colour: ROM 38 -> multiplier 39 -> multipliers 13-15 -> pins 24-26.
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(ROM38_BANK_BITS),
          .IMAGE(ROM38_IMAGE)) rom38 (
    .bank(rom38_bank), .reg2(reg2_q), .k(rom38_k));
  multiplier39 #(.A_W(REG9_W), .K_W(ROM38_W), .OUT_W(NORM_W), .SHIFT(MUL39_SHIFT)) mul39 (
    .reg9(reg9_q), .k(rom38_k), .norm(mul39_norm));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul13 (
    .norm(mul39_norm), .intensity(reg10_q), .out(pin24_r));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul14 (
    .norm(mul39_norm), .intensity(reg11_q), .out(pin25_g));
  multiplier_rgb #(.NORM_W(NORM_W), .RGB_BITS(RGB_BITS), .OUT_W(OUT_W),
                   .SHIFT(RGB_SHIFT)) mul15 (
    .norm(mul39_norm), .intensity(reg12_q), .out(pin26_b));

  control_unit16 cu16 (
    .start(pin27_start), .clk(pin28_clk), .reset_n(pin29_reset_n),
    .select36(select36), .write37(write37), .done35(pin35_done),
    .obs_q41(obs_q41), .obs_q42(obs_q42), .obs_nand45(obs_nand45));

  assign obs_select36 = select36;
  assign obs_write37 = write37;
  assign obs_reg1_q = reg1_q;
  assign obs_reg9_q = reg9_q;
  assign obs_rom38_k = rom38_k;
  assign obs_mul39_norm = mul39_norm;
endmodule

`default_nettype wire
