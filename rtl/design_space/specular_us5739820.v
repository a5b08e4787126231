// Design variant us5739820 (docs/variants/us5739820.md): cos^n as in US 5,739,820,
// (1 - (1 - cos)*n/2^k)^(2^k) with k = round(log2 n), behind the common ports
// (docs/design_space.md). The start's clock loads the base, exact on U1.30 and clamped
// at 0; one squarer then squares it k times, a clock each; the clock after the last
// squaring writes K(n)*y (ROM 38, multiplier 39) and pins 24-26 (multipliers 13-15)
// and may take the next start: k + 1 clocks per result (1 for n = 1, 11 for n >= 725).
// Same bits as specular::variants::Us5739820.
`default_nettype none

module specular_us5739820 #(
  parameter ROM38_IMAGE = "rom38.hex"
) (
`include "variant_ports.vh"
);
  // The outputs an always block drives (the common ports are wires).
  reg valid_out;
  reg signed [30:0] lobe_out;
  reg signed [31:0] out_r_out, out_g_out, out_b_out;
  assign valid = valid_out;
  assign lobe = lobe_out;
  assign out_r = out_r_out;
  assign out_g = out_g_out;
  assign out_b = out_b_out;
  localparam FRAC = 30;       // the squarer's U1.30: the base is exact on it (16 + k <= 26)
  localparam REG9_FRAC = 22;  // multiplier 39's operand: register 9's format S14.22

  // ---- k = round(log2 n) and the base max(0, 1 - (1 - cos)*n/2^k), exact on U1.30 ----
  wire [9:0]    unused_squares;
  wire [3:0]    k;
  wire [FRAC:0] base;
  us5739820_base #(.FRAC(FRAC)) base_k (.cos(cos), .n(n), .squares(unused_squares), .k(k), .base(base));

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
      valid_out <= 1'b0;
    end else begin
      valid_out <= finishing;
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
  wire signed [30:0] lobe_d;
  wire signed [31:0] out_r_d, out_g_d, out_b_d;
  device_tail #(.ROM38_IMAGE(ROM38_IMAGE)) tail (
    .reg9({14'd0, y_reg9}), .n(n_q), .r(r_q), .g(g_q), .b(b_q),
    .lobe(lobe_d), .out_r(out_r_d), .out_g(out_g_d), .out_b(out_b_d));

  always @(posedge clk)
    if (finishing) begin
      lobe_out <= lobe_d;
      out_r_out <= out_r_d;
      out_g_out <= out_g_d;
      out_b_out <= out_b_d;
    end

  wire unused_ok = &{1'b0, unused_squares};
endmodule

`default_nettype wire
