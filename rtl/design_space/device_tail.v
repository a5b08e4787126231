// The device's tail behind a variant's cos^n: ROM 38's K(n) (bank 0, the patent's
// normalisation), multiplier 39 (register 9's S14.22 code x K(n) -> the lobe, S10.20)
// and multipliers 13-15 (lobe x R, G, B -> pins 24-26, S18.13), the device's own blocks
// at the default widths. Combinational. Same bits as arith::Rom38Table::k, arith::mul39
// and arith::mul_rgb.
`default_nettype none

module device_tail #(
  parameter ROM38_IMAGE = "rom38.hex"
) (
  input  wire [36:0]        reg9,     // cos^n on register 9's format S14.22
  input  wire [9:0]         n,        // ROM 38's address
  input  wire [7:0]         r, g, b,
  output wire signed [30:0] lobe,     // K(n)*cos^n, S10.20
  output wire signed [31:0] out_r, out_g, out_b  // pins 24-26, S18.13
);
  localparam ROM38_W = 25;          // U9.16
  localparam ROM38_BANK_BITS = 4;   // the image's banks (rom38_banks.h); bank 0: patent

  wire [ROM38_W-1:0] rom38_k;
  rom38 #(.N_BITS(10), .WORD_W(ROM38_W), .BANK_BITS(ROM38_BANK_BITS), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank({ROM38_BANK_BITS{1'b0}}), .reg2(n), .k(rom38_k));
  multiplier39 #(.A_W(37), .K_W(ROM38_W), .OUT_W(31), .SHIFT(18)) mul39 (
    .reg9(reg9), .k(rom38_k), .norm(lobe));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul13 (
    .norm(lobe), .intensity(r), .out(out_r));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul14 (
    .norm(lobe), .intensity(g), .out(out_g));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul15 (
    .norm(lobe), .intensity(b), .out(out_b));
endmodule

`default_nettype wire
