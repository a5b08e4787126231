#!/usr/bin/env python3
"""qflow's blif2Verilog netlist as Icarus reads it (scripts/layout.sh, postlayout/).

  verilog_bus_pins.py IN_V OUT_V

blif2Verilog connects a macro's bus pins bit by bit, `.A[0](n0), .A[1](n1)`, which is no
Verilog (Icarus: "Syntax error in instance port expression"). Each such pin becomes one
connection of its bits, highest first: `.A({n1, n0})`. A bus whose bits are not all
there (0..max) is refused (exit 1), naming the instance and pin. The fill cells router.sh's
annotation added (FILL, no pin, no Liberty entry: energy.py refused them) are left out.
"""
import re
import sys


def fix(line):
    bits = re.findall(r"\.(\w+)\[(\d+)\]\(([^()]*)\)", line)
    if not bits:
        return line
    buses = {}
    for pin, i, net in bits:
        buses.setdefault(pin, {})[int(i)] = net.strip()
    for pin, b in buses.items():
        if sorted(b) != list(range(max(b) + 1)):
            raise SystemExit(f"verilog_bus_pins.py: pin {pin} of '{line[:60]}' has bits {sorted(b)}, not 0..{max(b)}")
    first = {}
    def repl(m):
        pin = m.group(1)
        if pin in first:
            return ""
        first[pin] = True
        b = buses[pin]
        return f".{pin}({{{', '.join(b[i] for i in range(max(b), -1, -1))}}})"
    line = re.sub(r"\.(\w+)\[(\d+)\]\([^()]*\)", repl, line)
    return re.sub(r",\s*(?=,|\))", "", line)


def main():
    if len(sys.argv) != 3:
        sys.stderr.write("usage: verilog_bus_pins.py IN_V OUT_V\n")
        return 2
    text = open(sys.argv[1]).read()
    out = [fix(l) for l in text.split(";") if not re.match(r"\s*FILL\s", l)]
    open(sys.argv[2], "w").write(";".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
