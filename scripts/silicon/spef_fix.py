#!/usr/bin/env python3
"""qrouter's SPEF (qflow's rc2dly) as OpenSTA reads it (scripts/layout.sh).

  spef_fix.py IN_SPEF NETLIST_V OUT_SPEF

Two things OpenSTA (Debian 12's) refuses in rc2dly's output, both checked by hand on the
control unit's layout: a net's internal nodes are written N_K, where SPEF names them
*N:K (net N's node K: OpenSTA warns "pin N_K not found" and drops the resistor); and the
name map keeps the BLIF's net names (dff41.d) where blif2Verilog's netlist, which OpenSTA
reads, has dff41_d. Nodes become *N:K; a mapped name absent from the netlist that is
present with its dots as underscores takes that spelling.
"""
import re
import sys


def main():
    if len(sys.argv) != 4:
        sys.stderr.write("usage: spef_fix.py IN_SPEF NETLIST_V OUT_SPEF\n")
        return 2
    spef, netlist, out = sys.argv[1:]
    words = set(re.findall(r"[A-Za-z_][\w.$\[\]]*", open(netlist).read()))
    lines = open(spef).read().splitlines()
    fixed, section = [], None
    renamed = 0
    for line in lines:
        s = line.strip()
        if s.startswith("*"):
            section = s.split()[0] if s.split()[0] in ("*NAME_MAP", "*CAP", "*RES", "*CONN", "*D_NET", "*END", "*PORTS") else section
        if section == "*NAME_MAP":
            m = re.match(r"^(\*\d+)\s+(\S+)$", s)
            if m:
                name = m.group(2)
                base = re.sub(r"<(\d+)>$", r"[\1]", name)
                alt = base.replace(".", "_")
                if base not in words and alt in words:
                    name = alt.replace("[", "<").replace("]", ">") if "<" in m.group(2) else alt
                    renamed += 1
                line = f"{m.group(1)} {name}"
        elif section in ("*CAP", "*RES"):
            line = re.sub(r"(?<![\w*:])(\d+)_(\d+)(?![\w:])", r"*\1:\2", line)
            # the first field is the element's index, not a node
        fixed.append(line)
    open(out, "w").write("\n".join(fixed) + "\n")
    print(f"spef_fix.py: {renamed} names respelt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
