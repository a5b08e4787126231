// Restoring divider, one quotient bit per clock (variant schlick_divider,
// docs/variants/schlick.md): quotient = floor(a * 2^(Q_BITS-1) / d) for 0 <= a <= d,
// d > 0. Each step compares the partial remainder with d, subtracts it when not
// smaller (a quotient bit of 1) and doubles the rest: one D_W+2-bit subtractor, a
// remainder, divisor and quotient register. The step at the `load` edge takes a and d
// from the inputs; Q_BITS-1 more follow while `busy`; in the clock where `last` is high
// `quotient` holds all Q_BITS bits (its final bit combinational) for the caller's edge.
`default_nettype none

module restoring_divider #(
  parameter D_W = 26,
  parameter Q_BITS = 24,
  parameter COUNT_W = $clog2(Q_BITS)   // derived; leave at its default
) (
  input  wire              clk,
  input  wire              reset_n,   // synchronous, active low
  input  wire              load,      // a and d taken (only when not busy)
  input  wire [D_W-1:0]    a,         // dividend, a <= d
  input  wire [D_W-1:0]    d,         // divisor, > 0
  output reg               busy,
  output wire              last,      // this clock's edge takes the last step
  output wire [Q_BITS-1:0] quotient
);
  reg [COUNT_W-1:0] count_q;
  reg [D_W:0]       remainder_q;      // < 2d
  reg [D_W-1:0]     divisor_q;
  reg [Q_BITS-2:0]  bits_q;

  wire [D_W:0]   remainder = busy ? remainder_q : {1'b0, a};
  wire [D_W-1:0] divisor = busy ? divisor_q : d;
  wire [D_W+1:0] difference = {1'b0, remainder} - {2'b00, divisor};
  wire           quotient_bit = ~difference[D_W+1];            // remainder >= divisor
  wire [D_W:0]   rest = quotient_bit ? difference[D_W:0] : remainder;  // < divisor

  localparam [COUNT_W-1:0] LAST = Q_BITS - 1;
  assign last = busy & (count_q == LAST);
  assign quotient = {bits_q, quotient_bit};

  always @(posedge clk) begin
    if (!reset_n) begin
      busy <= 1'b0;
      count_q <= {COUNT_W{1'b0}};
    end else if (load) begin
      busy <= 1'b1;
      count_q <= {{(COUNT_W-1){1'b0}}, 1'b1};
    end else if (busy) begin
      busy <= ~last;
      count_q <= count_q + 1'b1;
    end
    if (load | busy) begin
      remainder_q <= {rest[D_W-1:0], 1'b0};
      divisor_q <= divisor;
      bits_q <= {bits_q[Q_BITS-3:0], quotient_bit};
    end
  end

  // The rest is below the divisor: its top bit is always 0.
  wire unused_ok = &{1'b0, rest[D_W]};
endmodule

`default_nettype wire
