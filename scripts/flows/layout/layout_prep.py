#!/usr/bin/env python3
"""The mapped netlist as qflow's placement wants it (scripts/flows/layout/layout.sh).

  layout_prep.py RAW_BLIF OUT_BLIF INSTANCES_TSV

RAW_BLIF is Yosys's `write_blif -cname` of the flattened mapped netlist. qflow's tools
name every instance by its cell and a count (blif2cel: NAND2X1_1, NAND2X1_2, ... in the
order of the .gate lines), so the hierarchical names (mul6._123_, the block of Fig. 1
before the dot) would be lost: INSTANCES_TSV keeps them, one line per instance, the
layout's name and the netlist's. Constants become a BUFX2 from gnd or vdd (the OSU
library has no tie cells; qflow's synthesis does the same). Backslashes go (qflow's
synthesis removes them too). Exit 1 when the netlist holds something else than .gate
lines and their names (a .names or .latch: logic Yosys did not map).
"""
import sys


def main():
    if len(sys.argv) != 4:
        sys.stderr.write("usage: layout_prep.py RAW_BLIF OUT_BLIF INSTANCES_TSV\n")
        return 2
    raw, out_blif, out_tsv = sys.argv[1:]
    lines = open(raw).read().replace("\\\n", " ").splitlines()
    out, names, counts = [], [], {}
    skip_cover = False
    for line in lines:
        s = line.strip()
        if skip_cover:
            skip_cover = False
            if s == "1":
                continue
        if s in (".names $false", ".names $true", ".names $undef"):
            skip_cover = True   # Yosys's constant nets, written whether used or not
            continue
        if s.startswith(".cname"):
            names[-1] = (names[-1][0], s.split(None, 1)[1])
            continue
        if s.startswith((".gate", ".subckt")):
            parts = s.split()
            if any(p.split("=")[-1] in ("$false", "$true", "$undef") for p in parts[2:]):
                sys.stderr.write(f"layout_prep.py: a constant on a pin Yosys's hilomap left: {s[:80]}\n")
                return 1
            cell = parts[1]
            if cell in ("LOGIC0", "LOGIC1"):
                supply = "gnd" if cell == "LOGIC0" else "vdd"
                parts = [".gate", "BUFX2", f"A={supply}"] + [p.replace("O=", "Y=") for p in parts[2:]]
                cell = "BUFX2"
            n = counts.get(cell, 0) + 1   # blif2cel counts from 1
            counts[cell] = n
            names.append((f"{cell}_{n}", ""))
            out.append(".gate " + " ".join([cell] + parts[2:]).replace("\\", ""))
            continue
        if s.startswith((".names", ".latch", ".subckt")):
            sys.stderr.write(f"layout_prep.py: unmapped logic in the netlist: {s[:80]}\n")
            return 1
        out.append(s.replace("\\", ""))
    open(out_blif, "w").write("\n".join(out) + "\n")
    with open(out_tsv, "w") as f:
        f.write("layout_name\tnetlist_name\n")
        for lay, net in names:
            f.write(f"{lay}\t{net.lstrip(chr(92))}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
