#!/usr/bin/env python3
"""qflow's blif2Verilog netlist as Icarus reads it (scripts/flows/layout/layout.sh, postlayout/).

  verilog_bus_pins.py IN_V OUT_V

blif2Verilog connects a macro's bus pins bit by bit, `.A[0](n0), .A[1](n1)`, which is no
Verilog (Icarus: "Syntax error in instance port expression"). Each such pin becomes one
connection of its bits, highest first: `.A({n1, n0})`. A bus whose bits are not all
there (0..max) is refused (exit 1), naming the instance and pin. The fill cells router.sh's
annotation added (FILL, no pin, no Liberty entry: energy.py refused them) are left out.

A net name that is no Verilog identifier becomes an escaped one (`\\name `, the same name
to every reader): blif2Verilog keeps a `/` that qflow's spelling did not turn into `_`
(us5739820: a function's variable `count_ones$func$/work/.../us5739820_base.v:52$259.bits`,
which Icarus read as a division and energy.py refused).
"""
import re
import sys


# a connection's bits: a name, a bit select of one, a constant; braces and commas between
_TOKEN = re.compile(r"[^\s(){},]+")
_PLAIN = re.compile(r"[A-Za-z_][A-Za-z0-9_$]*(\[\d+\])?$|\d+('[sS]?[bhdoBHDO][0-9a-fA-FxXzZ_]+)?$")


def escape_names(line):
    """Each connection's net that is no Verilog identifier, escaped."""
    def conn(m):
        inner = _TOKEN.sub(lambda t: t.group(0) if t.group(0).startswith("\\") or _PLAIN.match(t.group(0))
                           else "\\" + t.group(0) + " ", m.group(2))
        return f".{m.group(1)}({inner})"
    return re.sub(r"\.(\w+(?:\[\d+\])?)\(([^()]*)\)", conn, line)


def fix(line):
    line = escape_names(line)
    bits = re.findall(r"\.(\w+)\[(\d+)\]\(([^()]*)\)", line)
    if not bits:
        return line
    buses = {}
    for pin, i, net in bits:
        net = net.strip()
        buses.setdefault(pin, {})[int(i)] = net + " " if net.startswith("\\") else net  # an escape ends in a space
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
