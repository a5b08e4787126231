#!/usr/bin/env python3
"""silicon_ip_constraints: the SDC of the whole IP (scripts/flows/designs/specular_ip_axi/
constraints.tcl) is read by OpenSTA without an error or a warning, at a period, on a
netlist with the ports of the RTL top (read from rtl/ip/specular_ip_axi.v, not from a
mapped netlist: quick, no Yosys), and leaves no port out: check_setup names no input
without an input delay, no output without an output delay, nothing unclocked; the one
clock is aclk.

  silicon_ip_constraints_test.py ROOT SCRATCH

The stand-in netlist: each input bit into the D of a DFFPOSX1 on aclk, each output bit
from the Q of one that holds it (Q back to D: so every port and pin is on a timed path). A misspelt port in the SDC shows
as OpenSTA's warning, a port left out as check_setup's line.
"""
import os
import re
import subprocess
import sys

LIB = "/usr/share/qflow/tech/osu018/osu018_stdcells.lib"


def ports(rtl):
    """The top's ports (direction, name, width) at its parameters' integer defaults: a
    range may be an expression of them (`[ADDR_WIDTH-1:0]`)."""
    text = re.sub(r"//.*", "", open(rtl).read())
    module = text[text.index("module specular_ip_axi"):]
    defaults = {m.group(1): int(m.group(2))
                for m in re.finditer(r"\b(\w+)\s*=\s*(\d+)\b", module[:module.index(") (")])}
    header = module[module.index(") (") + 3:module.index(");")]

    def value(expression):
        if not re.fullmatch(r"[\w\s+\-*()]+", expression):
            raise ValueError(f"a port range this test cannot read: {expression}")
        return int(eval(expression, {"__builtins__": {}}, dict(defaults)))

    found = []
    for m in re.finditer(r"\b(input|output)\s+(?:wire|reg)?\s*(?:\[([^:\]]+):([^\]]+)\])?\s*(\w+)", header):
        width = value(m.group(2)) - value(m.group(3)) + 1 if m.group(2) else 1
        found.append((m.group(1), m.group(4), width))
    return found


def main():
    root, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    plist = ports(f"{root}/rtl/ip/specular_ip_axi.v")
    if len(plist) < 20 or ("input", "aclk", 1) not in plist:
        print(f"FAIL: ports read from the RTL look wrong: {plist}")
        return 1
    decl, cells, k = [], [], 0
    for direction, name, width in plist:
        decl.append(f"  {direction} {'[%d:0] ' % (width - 1) if width > 1 else ''}{name};")
        if name == "aclk":
            continue
        for b in range(width):
            bit = f"{name}[{b}]" if width > 1 else name
            pins = f".D({bit})" if direction == "input" else f".D({bit}), .Q({bit})"
            cells.append(f"  DFFPOSX1 ff{k} (.CLK(aclk), {pins});")
            k += 1
    netlist = f"{scratch}/ports.v"
    with open(netlist, "w") as f:
        f.write("module specular_ip_axi (" + ", ".join(n for _, n, _ in plist) + ");\n")
        f.write("\n".join(decl + cells) + "\nendmodule\n")
    tcl = f"{scratch}/read_sdc.tcl"
    with open(tcl, "w") as f:
        f.write(f"read_liberty {LIB}\nread_verilog {netlist}\nlink_design specular_ip_axi\n"
                f"source {root}/scripts/flows/designs/specular_ip_axi/constraints.tcl\n"
                "constrain 20.0\n"
                "puts \"clocks: [get_full_name [all_clocks]]\"\n"
                "check_setup -verbose -unconstrained_endpoints -no_clock -no_input_delay "
                "-no_output_delay -multiple_clock -loops -generated_clocks\n"
                "puts \"worst slack: [sta::worst_slack -max]\"\n")
    r = subprocess.run(["sta", "-no_splash", "-exit", tcl], capture_output=True, text=True, timeout=120)
    log = r.stdout + r.stderr
    open(f"{scratch}/sta.log", "w").write(log)
    bad = [line for line in log.splitlines()
           if re.match(r"(Error|Warning)", line) or re.search(r"There (is|are) \d+", line)]
    if r.returncode != 0 or bad:
        print(f"FAIL: OpenSTA (exit {r.returncode}) on the SDC:\n" + "\n".join(bad or log.splitlines()[-20:]))
        return 1
    if "clocks: aclk" not in log or "worst slack:" not in log:
        print(f"FAIL: want the one clock aclk and a slack:\n{log}")
        return 1
    print(f"PASS: {len(plist)} ports, {k} port bits on aclk, every one constrained; {log.strip().splitlines()[-1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
