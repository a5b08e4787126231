#!/usr/bin/env python3
"""layout_verilog_bus_pins: scripts/flows/layout/verilog_bus_pins.py on a netlist written here in
blif2Verilog's dialect, then compiled and run by Icarus.

The netlist plants what qflow 1.3.17 wrote on the laid-out designs:
  - a macro's bus pins bit by bit (`.A[1](n), .A[0](a)`), which Icarus refuses;
  - a net whose name kept a `/` (us5739820's `count_ones$func$/work/...` variable), which
    Icarus reads as a division;
  - a FILL cell with no pin (router.sh's annotation).
With behavioural cells written here (BUFX2, NAND2X1, a 2-bit-address ROM holding 1 at
address 01 only), the outputs are worked out by hand: the BUFX2 drives the odd net from
gnd, so y[0] = !(0 & a) = 1 and y[1] = ROM[{0, a}] = a. A bus with a missing bit is
refused with exit 1, naming the pin.

  verilog_bus_pins_test.py VERILOG_BUS_PINS_PY SCRATCH
Exit 0 pass, 1 fail.
"""
import os
import shutil
import subprocess
import sys

NETLIST = """module t (a, y);
input a;
output [1:0] y;
wire vdd = 1'b1;
wire gnd = 1'b0;
BUFX2 BUFX2_1 ( .A(gnd), .Y(k_count_ones_func_/work/x/f_v_52_259_bits_9_) );
NAND2X1 NAND2X1_1 ( .A(k_count_ones_func_/work/x/f_v_52_259_bits_9_), .B(a), .Y(y[0]) );
ROM2 ROM2_1 ( .A[1](k_count_ones_func_/work/x/f_v_52_259_bits_9_), .A[0](a), .Q[0](y[1]) );
FILL FILL_1 ( );
endmodule
"""
CELLS = """module BUFX2 (input A, output Y); assign Y = A; endmodule
module NAND2X1 (input A, input B, output Y); assign Y = !(A & B); endmodule
module ROM2 (input [1:0] A, output [0:0] Q); assign Q = (A == 2'b01); endmodule
module tb;
  reg a; wire [1:0] y;
  t dut (.a(a), .y(y));
  initial begin
    a = 0; #1 $display("a=0 y=%b", y);
    a = 1; #1 $display("a=1 y=%b", y);
    $finish;
  end
endmodule
"""


def main():
    script, scratch = sys.argv[1:3]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    src, out = os.path.join(scratch, "rtl.v"), os.path.join(scratch, "mapped.v")
    open(src, "w").write(NETLIST)
    fails = []
    r = subprocess.run(["/usr/bin/python3", script, src, out], capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        return 1
    text = open(out).read()
    if "FILL" in text:
        fails.append("the FILL cell was kept")
    cells = os.path.join(scratch, "cells.v")
    open(cells, "w").write(CELLS)
    sim = os.path.join(scratch, "sim.vvp")
    r = subprocess.run(["iverilog", "-o", sim, out, cells], capture_output=True, text=True)
    if r.returncode != 0:
        fails.append("Icarus did not compile the output:\n" + r.stdout + r.stderr)
    else:
        got = subprocess.run(["vvp", "-n", sim], capture_output=True, text=True).stdout
        for want in ("a=0 y=01", "a=1 y=11"):   # y[1] = a, y[0] = 1 (worked out above)
            if want not in got:
                fails.append(f"simulation: want '{want}', got:\n{got}")
    # a bus missing bit 0: refused, the pin named
    open(src, "w").write(NETLIST.replace(".A[0](a), ", ""))
    r = subprocess.run(["/usr/bin/python3", script, src, out], capture_output=True, text=True)
    if r.returncode != 1 or "pin A" not in r.stdout + r.stderr:
        fails.append(f"a bus without bit 0: want exit 1 naming pin A, got {r.returncode}: {r.stdout + r.stderr}")
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print("layout_verilog_bus_pins: PASS")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
