#!/usr/bin/env python3
"""qrouter's SPEF (qflow's rc2dly) as OpenSTA reads it (scripts/flows/layout/layout.sh).

  spef_fix.py IN_SPEF NETLIST_V OUT_SPEF [WIRE_CAP_OUT]

Two things OpenSTA (Debian 12's) refuses in rc2dly's output, both checked by hand on the
control unit's layout: a net's internal nodes are written N_K, where SPEF names them
*N:K (net N's node K: OpenSTA warns "pin N_K not found" and drops the resistor); and the
name map keeps the BLIF's net names (dff41.d) where blif2Verilog's netlist, which OpenSTA
reads, has dff41_d, and a block's bus bit mul6.b[0] where the netlist has mul6_b_0_.
Nodes become *N:K; a mapped name absent from the netlist that is present with its dots
as underscores (and a block's bus bit with its brackets as _K_) takes that spelling. And its header says
*C_UNIT 1 FF where its figures are pF (the pins' *L loads are the Liberty's pF, and a net
of some 60 um of metal2 and metal3 comes out 0.0044: 4.4 fF, not 0.0044 fF): *C_UNIT 1 PF.
WIRE_CAP_OUT: each net's wire capacitance (its *D_NET total, pF), "NET PF" lines for
energy.py --wire-cap.
"""
import re
import sys


def main():
    if len(sys.argv) not in (4, 5):
        sys.stderr.write("usage: spef_fix.py IN_SPEF NETLIST_V OUT_SPEF [WIRE_CAP_OUT]\n")
        return 2
    spef, netlist, out = sys.argv[1:4]
    names, totals = {}, []
    words = set(re.findall(r"[A-Za-z_][\w.$\[\]]*", open(netlist).read()))
    lines = open(spef).read().splitlines()
    fixed, section = [], None
    renamed = 0
    for line in lines:
        s = line.strip()
        if s.startswith("*"):
            section = s.split()[0] if s.split()[0] in ("*NAME_MAP", "*CAP", "*RES", "*CONN", "*D_NET", "*END", "*PORTS") else section
        if s.startswith("*C_UNIT"):
            line = "*C_UNIT 1 PF"
        m = re.match(r"^\*D_NET\s+(\*\d+)\s+(\S+)", s)
        if m:
            totals.append((m.group(1), float(m.group(2))))
        if section == "*NAME_MAP":
            m = re.match(r"^(\*\d+)\s+(\S+)$", s)
            if m:
                name = m.group(2)
                base = re.sub(r"<(\d+)>$", r"[\1]", name)
                alt = base.replace(".", "_")
                # a block's bus bit (mul6.b[0]): blif2Verilog flattens it to mul6_b_0_
                flat = re.sub(r"\[(\d+)\]$", r"_\1_", alt)
                if base not in words and alt in words:
                    name = alt.replace("[", "<").replace("]", ">") if "<" in m.group(2) else alt
                    renamed += 1
                elif base not in words and flat in words:
                    name = flat
                    renamed += 1
                line = f"{m.group(1)} {name}"
                names[m.group(1)] = name
        # a macro's bus pin comes without its closing bracket (*I *N:Q[11 O): OpenSTA stopped
        # reading the whole device's SPEF there (syntax error), two thirds of the way in
        line = re.sub(r"(\*\d+:\w+\[\d+)(?=\s|$)", r"\1]", line)
        if section in ("*CAP", "*RES"):
            line = re.sub(r"(?<![\w*:])(\d+)_(\d+)(?![\w:])", r"*\1:\2", line)
            # the first field is the element's index, not a node
        fixed.append(line)
    open(out, "w").write("\n".join(fixed) + "\n")
    if len(sys.argv) == 5:
        with open(sys.argv[4], "w") as f:
            for ref, pf in totals:
                name = re.sub(r"<(\d+)>$", r"[\1]", names.get(ref, ref))
                f.write(f"{name} {pf}\n")
    print(f"spef_fix.py: {renamed} names respelt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
