// Leading-one normaliser: the index of the highest one of a W-bit code x > 0 and x
// shifted left until that one sits at bit W-1: the design variants normalise a divisor
// with it (variant schlick: d into [1, 2) before the reciprocal table). ROM 5 keeps its
// own detector (rom5.v says why). Same bits as arith::leading_one. x = 0 gives msb 0 and
// x unchanged (callers never present it: ROM 5 reads a non-positive bus as log2 0).
`default_nettype none

module leading_one_normaliser #(
  parameter W = 26,
  parameter POS_W = $clog2(W)   // a bit index of x (derived; leave at its default)
) (
  input  wire [W-1:0]     x,
  output reg  [POS_W-1:0] msb,
  output wire [W-1:0]     normalised
);
  integer i;
  always @* begin
    msb = {POS_W{1'b0}};
    for (i = 0; i < W; i = i + 1)
      if (x[i]) msb = i[POS_W-1:0];
  end

  localparam integer TOP = W - 1;
  wire [POS_W-1:0] left = TOP[POS_W-1:0] - msb;
  assign normalised = x << left;
endmodule

`default_nettype wire
