// Design variant us5739820 (docs/variants/us5739820.md): cos^n as in US 5,739,820,
// (1 - (1 - cos)*n/2^k)^(2^k) with k = round(log2 n), behind the common ports
// (docs/design_space.md). The start's clock loads the base, exact on U1.30 and clamped
// at 0; one squarer then squares it k times, a clock each; the clock after the last
// squaring writes K(n)*y (ROM 38, multiplier 39) and pins 24-26 (multipliers 13-15)
// and may take the next start: k + 1 clocks per result (1 for n = 1, 11 for n >= 725).
// Same bits as specular::variants::Us5739820.
`default_nettype none

module specular_us5739820 #(
  // ROM 5 is not used (no logarithm here); the parameter is kept so that every
  // variant takes the same image overrides.
  /* verilator lint_off UNUSEDPARAM */
  parameter ROM5_IMAGE = "rom5.hex",
  /* verilator lint_on UNUSEDPARAM */
  parameter ROM38_IMAGE = "rom38.hex"
) (
  input  wire               clk,
  input  wire               reset_n,   // synchronous, active low
  input  wire               start,     // operands valid; taken at the rising edge when ready
  output wire               ready,
  input  wire [16:0]        cos,       // register 1's code, U1.16
  input  wire [9:0]         n,
  input  wire [7:0]         r, g, b,
  output reg                valid,     // one clock: lobe and out_* hold a start's result
  output reg  signed [30:0] lobe,      // K(n)*cos^n, multiplier 39's format S10.20
  output reg  signed [31:0] out_r, out_g, out_b  // pins 24-26, S18.13
);
  localparam COS_FRAC = 16;
  localparam FRAC = 30;       // the squarer's U1.30: the base is exact on it (16 + k <= 26)
  localparam K_MAX = 10;      // round(log2 n) <= 10 for n <= 1023
  localparam REG9_FRAC = 22;  // multiplier 39's operand: register 9's format S14.22
  localparam ROM38_W = 25;    // U9.16
  localparam ROM38_BANK_BITS = 4;  // the image's banks (rom38_banks.h); bank 0: patent

  // ---- k = round(log2 n): how many thresholds ceil(sqrt(2)*2^j) n reaches ----
  // The smallest t with t*t >= 2^(2j+1), by an integer square root (2^(2j+1) is never
  // a square, so that is floor(sqrt) + 1).
  function integer round_log2_threshold;
    input integer j;
    integer t, bit_index, trial;
    begin
      t = 0;
      for (bit_index = 10; bit_index >= 0; bit_index = bit_index - 1) begin
        trial = t | (1 << bit_index);
        if (trial * trial <= (1 << (2 * j + 1))) t = trial;
      end
      round_log2_threshold = t + 1;
    end
  endfunction

  wire [K_MAX-1:0] reaches;
  genvar j;
  generate
    for (j = 0; j < K_MAX; j = j + 1) begin : thresholds
      localparam integer T = round_log2_threshold(j);
      assign reaches[j] = {22'd0, n} >= T[31:0];
    end
  endgenerate

  // The thresholds rise with j, so reaches is a thermometer: k counts its ones.
  function [3:0] count_ones;
    input [K_MAX-1:0] bits;
    integer i;
    begin
      count_ones = 4'd0;
      for (i = 0; i < K_MAX; i = i + 1) count_ones = count_ones + {3'd0, bits[i]};
    end
  endfunction
  wire [3:0] k = count_ones(reaches);

  // ---- the base 1 - (1 - cos)*n*2^-k on U1.30, clamped at 0 ----
  wire [16:0] one_minus_cos = 17'd65536 - cos;              // U1.16 (cos <= 1)
  wire [26:0] step = one_minus_cos * {17'd0, n};            // (1 - cos)*n, 16 fraction bits
  localparam integer ALIGN_K0 = FRAC - COS_FRAC;              // 14: the shift when k = 0
  wire [3:0]  align = ALIGN_K0[3:0] - k;                          // 30 - 16 - k fraction bits
  wire [40:0] step_aligned = {14'd0, step} << align;        // on FRAC fraction bits
  localparam [40:0] ONE = 41'd1 << FRAC;
  wire [FRAC:0] base = step_aligned > ONE ? {(FRAC + 1){1'b0}} : ONE[FRAC:0] - step_aligned[FRAC:0];

  // ---- the squarer and its sequencer ----
  reg  [FRAC:0] y;            // the base, then its squares
  reg  [3:0]    squarings;    // squarings left
  reg           busy;         // an operation holds y
  reg  [9:0]    n_q;          // ROM 38's address
  reg  [7:0]    r_q, g_q, b_q;
  wire [FRAC:0] y_squared;
  squarer #(.FRAC(FRAC)) squarer (.y(y), .square(y_squared));

  wire finishing = busy & (squarings == 4'd0);   // y is cos^n: written at this edge
  assign ready = ~busy | finishing;
  wire take = start & ready;

  always @(posedge clk) begin
    if (!reset_n) begin
      busy <= 1'b0;
      squarings <= 4'd0;
      valid <= 1'b0;
    end else begin
      valid <= finishing;
      if (take) begin
        y <= base;
        squarings <= k;
        busy <= 1'b1;
        n_q <= n;
        r_q <= r;
        g_q <= g;
        b_q <= b;
      end else if (busy & ~finishing) begin
        y <= y_squared;
        squarings <= squarings - 4'd1;
      end else begin
        busy <= 1'b0;
      end
    end
  end

  // ---- the device's tail: y rounded to S14.22, x K(n), x R, G, B ----
  wire [REG9_FRAC:0] y_reg9 = y[FRAC:FRAC-REG9_FRAC] + {{REG9_FRAC{1'b0}}, y[FRAC-REG9_FRAC-1]};
  wire [ROM38_W-1:0] rom38_k;
  wire [30:0] lobe_d;
  wire [31:0] out_r_d, out_g_d, out_b_d;
  rom38 #(.N_BITS(10), .WORD_W(ROM38_W), .BANK_BITS(ROM38_BANK_BITS), .IMAGE(ROM38_IMAGE)) rom38 (
    .bank({ROM38_BANK_BITS{1'b0}}), .reg2(n_q), .k(rom38_k));   // Normalisation::patent
  multiplier39 #(.A_W(37), .K_W(ROM38_W), .OUT_W(31), .SHIFT(18)) mul39 (
    .reg9({14'd0, y_reg9}), .k(rom38_k), .norm(lobe_d));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul13 (
    .norm(lobe_d), .intensity(r_q), .out(out_r_d));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul14 (
    .norm(lobe_d), .intensity(g_q), .out(out_g_d));
  multiplier_rgb #(.NORM_W(31), .RGB_BITS(8), .OUT_W(32), .SHIFT(7)) mul15 (
    .norm(lobe_d), .intensity(b_q), .out(out_b_d));

  always @(posedge clk)
    if (finishing) begin
      lobe <= lobe_d;
      out_r <= out_r_d;
      out_g <= out_g_d;
      out_b <= out_b_d;
    end

  wire unused_ok = &{1'b0, step_aligned[40:FRAC+1]};
endmodule

`default_nettype wire
