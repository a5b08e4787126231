#!/usr/bin/env python3
"""silicon_netlist_assigns: scripts/flows/synthesis/netlist_assigns.py on netlists written here.

Yosys's concatenated alias assignments, as OpenSTA cannot read them, each become one
assignment per bit, the highest first (a concatenation lists its most significant item
first; the expected lines are written here from that rule):
  - plain names with bit and range selects (specular_ip_axi's register block);
  - escaped identifiers, whose select follows a space (`\\mul.biased [64:61]`, the
    netlist of us5739820 that stopped silicon.sh): the space stays, or the select would
    become part of the name;
  - a netlist without such a line is left byte for byte;
  - an item it cannot split (a whole bus without a select) and sides of different widths
    exit 1 naming the line.

  netlist_assigns_test.py NETLIST_ASSIGNS_PY SCRATCH
Exit 0 pass, 1 fail.
"""
import os
import shutil
import subprocess
import sys

SPLIT_IN = r"""module t;
  assign { \mul.biased [64:61], \mul.biased [0] } = { 2'h0, \mul.above [1:0], y[0] };
  assign {q[7], q[5:4]} = {q[6], q[6], q[6]};
  assign z = a;
endmodule
"""
SPLIT_OUT = r"""module t;
  assign \mul.biased [64] = 1'b0;
  assign \mul.biased [63] = 1'b0;
  assign \mul.biased [62] = \mul.above [1];
  assign \mul.biased [61] = \mul.above [0];
  assign \mul.biased [0] = y[0];
  assign q[7] = q[6];
  assign q[5] = q[6];
  assign q[4] = q[6];
  assign z = a;
endmodule
"""
UNTOUCHED = "module u;\n  assign a = b;  \n  assign c[3:0] = d[3:0];\nendmodule"
BAD = {  # name: (netlist, what stderr must name)
    "whole bus": ("module b;\n  assign { q, r[0] } = { s[1:0] };\nendmodule\n", "'q'"),
    "widths": ("module w;\n  assign { q[2:0] } = { s[1:0] };\nendmodule\n", "3 bits on the left, 2 on the right"),
}


def run(script, path):
    return subprocess.run([sys.executable, script, path], capture_output=True, text=True)


def main():
    script, scratch = sys.argv[1:3]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    fails = []
    path = os.path.join(scratch, "split.v")
    open(path, "w").write(SPLIT_IN)
    r = run(script, path)
    got = open(path).read()
    if r.returncode != 0 or got != SPLIT_OUT:
        fails.append(f"split: exit {r.returncode} {r.stderr.strip()}\n--- got\n{got}--- want\n{SPLIT_OUT}")
    path = os.path.join(scratch, "untouched.v")
    open(path, "w").write(UNTOUCHED)
    r = run(script, path)
    if r.returncode != 0 or open(path).read() != UNTOUCHED:
        fails.append(f"a netlist without a concatenated assign changed (exit {r.returncode})")
    for name, (text, named) in BAD.items():
        path = os.path.join(scratch, name.replace(" ", "_") + ".v")
        open(path, "w").write(text)
        r = run(script, path)
        if r.returncode != 1 or named not in r.stderr + r.stdout or "assign" not in r.stderr + r.stdout:
            fails.append(f"{name}: exit {r.returncode}, output {(r.stderr + r.stdout).strip()!r}: "
                         f"want exit 1 naming {named} and the line")
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print("PASS: bits split highest first, escaped names keep their space, other netlists untouched, "
              "bad items and widths refused by name")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
