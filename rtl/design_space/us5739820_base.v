// What both us5739820 tops (sequential and pipelined) compute from their operands
// before squaring: k = round(log2 n), as the thermometer `squares` (bit j set when
// n >= ceil(sqrt(2)*2^j), so bits 0..k-1 are set) and its count, and the base
// max(0, 1 - (1 - cos)*n/2^k) on U1.FRAC, exact (16 + k <= FRAC fraction bits).
// Same bits as Us5739820::squarings and Us5739820::base.
`default_nettype none

module us5739820_base #(
  parameter FRAC = 30
) (
  input  wire [16:0]   cos,      // register 1's code, U1.16
  input  wire [9:0]    n,
  output wire [9:0]    squares,  // thermometer: squaring j+1 of k is done when bit j is set
  output wire [3:0]    k,
  output wire [FRAC:0] base      // U1.FRAC
);
  localparam COS_FRAC = 16;
  localparam K_MAX = 10;      // round(log2 n) <= 10 for n <= 1023

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

  genvar j;
  generate
    for (j = 0; j < K_MAX; j = j + 1) begin : thresholds
      localparam integer T = round_log2_threshold(j);
      assign squares[j] = {22'd0, n} >= T[31:0];
    end
  endgenerate

  // The thresholds rise with j, so squares is a thermometer: k counts its ones.
  function [3:0] count_ones;
    input [K_MAX-1:0] bits;
    integer i;
    begin
      count_ones = 4'd0;
      for (i = 0; i < K_MAX; i = i + 1) count_ones = count_ones + {3'd0, bits[i]};
    end
  endfunction
  assign k = count_ones(squares);

  // 2^FRAC - (1 - cos)*n << (FRAC - 16 - k), clamped at 0.
  wire [16:0] one_minus_cos = 17'd65536 - cos;              // U1.16 (cos <= 1)
  wire [26:0] step = one_minus_cos * {17'd0, n};            // (1 - cos)*n, 16 fraction bits
  localparam integer ALIGN_K0 = FRAC - COS_FRAC;              // the shift when k = 0
  wire [3:0]  align = ALIGN_K0[3:0] - k;                      // FRAC - 16 - k fraction bits
  wire [FRAC+10:0] step_aligned = {{(FRAC - COS_FRAC){1'b0}}, step} << align;  // on FRAC bits
  localparam [FRAC+10:0] ONE = {{10{1'b0}}, 1'b1, {FRAC{1'b0}}};
  assign base = step_aligned > ONE ? {(FRAC + 1){1'b0}} : ONE[FRAC:0] - step_aligned[FRAC:0];
  wire unused_ok = &{1'b0, step_aligned[FRAC+10:FRAC+1]};
endmodule

`default_nettype wire
