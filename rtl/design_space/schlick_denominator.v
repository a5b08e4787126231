// Schlick's denominator d = n - (n-1)*x for x = cos/2^16 (docs/variants/schlick.md):
// n*2^16 - (n-1)*cos as U10.16, exact (a 10 x 17-bit multiplier and a subtractor;
// d >= 1 for n >= 1, so x/d <= 1). Shared by variants schlick and schlick_divider.
// Same bits as specular::variants::Schlick::denominator.
`default_nettype none

module schlick_denominator #(
  parameter COS_FRAC = 16,
  parameter N_BITS = 10,
  parameter D_W = N_BITS + COS_FRAC   // derived; leave at its default
) (
  input  wire [COS_FRAC:0]   cos,     // U1.16
  input  wire [N_BITS-1:0]   n,       // 1 .. 2^N_BITS - 1
  output wire [D_W-1:0]      d
);
  wire [N_BITS-1:0] n_minus_1 = n - 1'b1;
  wire [D_W-1:0] n_cos = {{(D_W-N_BITS){1'b0}}, n_minus_1} * {{(D_W-COS_FRAC-1){1'b0}}, cos};
  assign d = {n, {COS_FRAC{1'b0}}} - n_cos;
endmodule

`default_nettype wire
