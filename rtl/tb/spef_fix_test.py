#!/usr/bin/env python3
"""layout_spef_fix: scripts/flows/layout/spef_fix.py on a SPEF written by hand in rc2dly's
dialect (issue 48, docs/silicon/layout.md "Layout: placed, routed, DRC and LVS checked"), against a flat netlist as qflow's
blif2Verilog writes it. Every expectation is spelled here, from the two dialects:

- dff41.d (a BLIF net through a block) becomes dff41_d, the netlist's spelling;
- mul6.b[0] (a block's bus bit) becomes mul6_b_0_, the netlist's spelling;
- cos[3] (a top-level bus bit the netlist has as it is) stays cos[3];
- a node N_K in *CAP/*RES becomes *N:K; *C_UNIT 1 FF becomes 1 PF;
- a macro's bus pin without its closing bracket (*2:Q[11) is closed;
- WIRE_CAP_OUT: one line per net, its *D_NET total, in the netlist's spelling.

  spef_fix_test.py SPEF_FIX_PY SCRATCH
"""
import os
import subprocess
import sys

NETLIST = """module top (cos, y);
input [3:0] cos; output y;
INVX1 INVX1_1 ( .A(cos[3]), .Y(dff41_d) );
INVX1 INVX1_2 ( .A(dff41_d), .Y(mul6_b_0_) );
ROM ROM_1 ( .A(mul6_b_0_), .Q(y) );
endmodule
"""

SPEF = """*SPEF "IEEE 1481.1999"
*DIVIDER /
*DELIMITER :
*BUS_DELIMITER <>
*T_UNIT 1 PS
*C_UNIT 1 FF
*R_UNIT 1 OHM

*NAME_MAP
*1 dff41.d
*2 mul6.b[0]
*3 cos<3>

*D_NET *1 0.0044
*CONN
*I *4:Y O
*I *5:A I
*CAP
1 1_1 0.0022
2 1_2 0.0022
*RES
1 *4:Y 1_1 0.5
2 1_1 1_2 0.5
*END

*D_NET *2 0.0031
*CONN
*I *5:Y O
*I *6:Q[11 I
*CAP
1 2_1 0.0031
*END

*D_NET *3 0.001
*CONN
*P *3 I
*CAP
1 3_1 0.001
*END
"""


def main():
    script, scratch = sys.argv[1:3]
    os.makedirs(scratch, exist_ok=True)
    net, spef = os.path.join(scratch, "top.v"), os.path.join(scratch, "in.spef")
    out, caps = os.path.join(scratch, "out.spef"), os.path.join(scratch, "wire_cap.txt")
    open(net, "w").write(NETLIST)
    open(spef, "w").write(SPEF)
    subprocess.run(["/usr/bin/python3", script, spef, net, out, caps], check=True)
    text = open(out).read().splitlines()
    want = ["*C_UNIT 1 PF", "*1 dff41_d", "*2 mul6_b_0_", "*3 cos<3>", "1 *1:1 0.0022",
            "2 *1:1 *1:2 0.5", "*I *6:Q[11] I"]
    failed = [w for w in want if w not in text]
    wires = dict(line.split() for line in open(caps))
    want_wires = {"dff41_d": "0.0044", "mul6_b_0_": "0.0031", "cos[3]": "0.001"}
    if wires != want_wires:
        failed.append(f"wire_cap.txt {wires}, want {want_wires}")
    for f in failed:
        print(f"FAIL: missing or wrong: {f}")
    if failed:
        return 1
    print("PASS spef_fix: block nets, block bus bits, top bus bits, nodes, units, macro pins")
    return 0


if __name__ == "__main__":
    sys.exit(main())
