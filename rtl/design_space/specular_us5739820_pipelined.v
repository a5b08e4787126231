// Design variant us5739820_pipelined (docs/variants/us5739820.md): the same cos^n as
// us5739820, (1 - (1 - cos)*n/2^k)^(2^k) with k = round(log2 n), unrolled: the start's
// clock registers the base, ten stages of one squarer each follow (stage j squares when
// j <= k, else passes y on), and the tail (ROM 38, multiplier 39, multipliers 13-15)
// writes the outputs. A start every clock, the result 11 clocks after it (valid high
// for one clock). Same bits as us5739820 and specular::variants::Us5739820.
`default_nettype none

module specular_us5739820_pipelined #(
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
  localparam FRAC = 30;       // the squarers' U1.30, as in us5739820
  localparam YW = FRAC + 1;
  localparam STAGES = 10;     // k <= 10
  localparam REG9_FRAC = 22;  // multiplier 39's operand: register 9's format S14.22
  localparam OPW = 10 + 24;   // n and R, G, B, carried along to the tail

  assign ready = 1'b1;

  wire [9:0]    squares;      // bit j: stage j + 1 squares
  wire [3:0]    unused_k;
  wire [FRAC:0] base;
  us5739820_base #(.FRAC(FRAC)) base_k (.cos(cos), .n(n), .squares(squares), .k(unused_k), .base(base));

  // Stage s (0 = the base, 1..STAGES = after s squarings or passes) at slice s of each
  // vector: y, the squarings still to decide, the operands, and its valid bit.
  reg [(STAGES+1)*YW-1:0]      y_q;
  reg [(STAGES+1)*STAGES-1:0]  squares_q;
  reg [(STAGES+1)*OPW-1:0]     operands_q;
  reg [STAGES:0]               valid_q;
  wire [STAGES*YW-1:0]         squared;

  genvar s;
  generate
    for (s = 1; s <= STAGES; s = s + 1) begin : stage
      squarer #(.FRAC(FRAC)) squarer (.y(y_q[(s-1)*YW +: YW]), .square(squared[(s-1)*YW +: YW]));
    end
  endgenerate

  integer i;
  always @(posedge clk) begin
    y_q[0 +: YW] <= base;
    squares_q[0 +: STAGES] <= squares;
    operands_q[0 +: OPW] <= {n, r, g, b};
    for (i = 1; i <= STAGES; i = i + 1) begin
      y_q[i*YW +: YW] <= squares_q[(i-1)*STAGES + (i-1)] ? squared[(i-1)*YW +: YW]
                                                         : y_q[(i-1)*YW +: YW];
      squares_q[i*STAGES +: STAGES] <= squares_q[(i-1)*STAGES +: STAGES];
      operands_q[i*OPW +: OPW] <= operands_q[(i-1)*OPW +: OPW];
    end
    if (!reset_n) begin
      valid_q <= {(STAGES+1){1'b0}};
      valid_out <= 1'b0;
    end else begin
      valid_q <= {valid_q[STAGES-1:0], start};
      valid_out <= valid_q[STAGES];
    end
  end

  // ---- the device's tail: y rounded to S14.22, x K(n), x R, G, B ----
  wire [FRAC:0] y_last = y_q[STAGES*YW +: YW];
  wire [OPW-1:0] operands_last = operands_q[STAGES*OPW +: OPW];
  wire [REG9_FRAC:0] y_reg9 = y_last[FRAC:FRAC-REG9_FRAC] + {{REG9_FRAC{1'b0}}, y_last[FRAC-REG9_FRAC-1]};
  wire signed [30:0] lobe_d;
  wire signed [31:0] out_r_d, out_g_d, out_b_d;
  device_tail #(.ROM38_IMAGE(ROM38_IMAGE)) tail (
    .reg9({14'd0, y_reg9}), .n(operands_last[33:24]), .r(operands_last[23:16]),
    .g(operands_last[15:8]), .b(operands_last[7:0]),
    .lobe(lobe_d), .out_r(out_r_d), .out_g(out_g_d), .out_b(out_b_d));

  always @(posedge clk)
    if (valid_q[STAGES]) begin
      lobe_out <= lobe_d;
      out_r_out <= out_r_d;
      out_g_out <= out_g_d;
      out_b_out <= out_b_d;
    end

  wire unused_ok = &{1'b0, unused_k, squares_q[STAGES*STAGES +: STAGES]};
endmodule

`default_nettype wire
