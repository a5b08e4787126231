#!/usr/bin/env python3
"""The SDF and ROM models Icarus reads (scripts/flows/gatelevel/gatesim.sh).

  gatesim_sdf.py NETLIST_DIR OUT_DIR

Icarus 11's SDF reader refuses IOPATHs between bus bits (`A[13] Q[24]`), which OpenSTA
writes for the ROM macros; the macros are behavioural models anyway. So OUT_DIR/icarus.sdf
is device.sdf without the macros' CELL entries, with every (min::max) triple given a
typical value Icarus selects (and OUT_DIR/mapped_icarus.v the netlist with dots in
escaped names replaced), and OUT_DIR/rom_macros_gatesim.v is
rom_macros_sim.v with each macro's ACCESS set to the largest IOPATH delay OpenSTA
computed for it (its Liberty access time at the load it drives).
"""
import re
import sys


def main():
    src, out = sys.argv[1], sys.argv[2]
    sdf = open(f"{src}/device.sdf").read()
    # Split into CELL entries (each starts with a line " (CELL").
    parts = re.split(r"(?m)^(?= \(CELL\s*$)", sdf)
    kept, access = [], {}
    for part in parts:
        m = re.search(r'\(CELLTYPE "(\w+_MACRO)"\)', part)
        if not m:
            kept.append(part)
            continue
        delays = [float(x) for x in re.findall(r"\(([\d.]+)::[\d.]+\)", part)]
        access[m.group(1)] = max(access.get(m.group(1), 0.0), max(delays) if delays else 0.0)
    text = "".join(kept)
    # The last kept entry may have lost the closing parenthesis of DELAYFILE if a macro
    # came last: count and repair.
    text = text.rstrip() + "\n"
    while text.count("(") > text.count(")"):
        text += ")\n"
    # Icarus cannot match an escaped instance name with a dot (`cu16/dff41\\.cell` from
    # flatten, `k_rom.genblk1.macro` from techmap): dots become double underscores, here and in
    # the netlist copy Icarus reads (OpenSTA reads the original).
    text = text.replace("\\.", "__")
    # OpenSTA writes one corner as (min::max) with the typical value left empty; Icarus 11
    # selects the typical value and, finding none, silently keeps the cell model's own
    # unloaded specify delay (docs/silicon/timing.md, "Why T_sim was below T_sta"). Fill the
    # typical value with the maximum, the slower of the two (they differ by < 1 ps).
    text, filled = re.subn(r"\((-?[\d.]+)::(-?[\d.]+)\)", r"(\1:\2:\2)", text)
    open(f"{out}/icarus.sdf", "w").write(text)
    netlist = open(f"{src}/mapped.v").read()
    netlist = re.sub(r"\\(\S+)", lambda m: "\\" + m.group(1).replace(".", "__"), netlist)
    open(f"{out}/mapped_icarus.v", "w").write(netlist)
    models = open(f"{src}/rom_macros_sim.v").read()
    for name, t in access.items():
        models = re.sub(rf"(module {name} .*?parameter real ACCESS = )[\d.]+",
                        lambda m: m.group(1) + f"{t:.4f}", models, flags=re.S)
    open(f"{out}/rom_macros_gatesim.v", "w").write(models)
    print(f"{filled} delay triples (min::max) given their typical value (max)")
    for name, t in sorted(access.items()):
        print(f"{name} access {t:.4f} ns (largest SDF IOPATH)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
