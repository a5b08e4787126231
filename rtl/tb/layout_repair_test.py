#!/usr/bin/env python3
"""layout_repair: scripts/flows/layout/layout_repair.py on a routed DEF written here.

Three NAND3X1 cells of the OSU 0.18 um LEF (3.2 x 10 um; pins A 0.2-0.6 x 4.9-5.7 um,
B 1.0-1.8 x 4.3-4.7 um, C 1.8-2.2 x 5.9-6.7 um, read off the LEF by hand), U3 flipped
(FS: its pins at 10 um - y). Each net plants one case, its expected result worked out
here from that geometry:
  - n_open: the metal2 wire runs over U3's C and its via lands 0.8 um beside it (qrouter's
    fault on the device): the via goes, a via M2_M1 comes on the pin where the wire
    crosses it, at (302.00, 4.00) um;
  - n_extra: both pins reached, one more via whose pad touches nothing: it goes, nothing
    is added;
  - n_lost: U3's B has no wire near it: left open, named, exit 1;
  - n_split: two pieces, U1's A up to a metal3 wire that ends at (200.40, 15.00) um on
    the metal2 rising from U2's A, with no via there (qrouter's fault on schlick_divider):
    a via M3_M2 comes at that point; U1's A to U2's B, joined on metal2 through vias at
    both ends, gets nothing.
Without n_lost the run exits 0; run again on its own output it changes nothing.

  layout_repair_test.py LAYOUT_REPAIR_PY OSU018_DIR SCRATCH
Exit 0 pass, 1 fail.
"""
import os
import shutil
import subprocess
import sys

HEAD = """VERSION 5.6 ;
DESIGN t ;
UNITS DISTANCE MICRONS 100 ;
DIEAREA ( 0 0 ) ( 40000 5000 ) ;
COMPONENTS 3 ;
- U1 NAND3X1 + PLACED ( 10000 0 ) N ;
- U2 NAND3X1 + PLACED ( 20000 0 ) N ;
- U3 NAND3X1 + PLACED ( 30000 0 ) FS ;
END COMPONENTS
"""
N_EXTRA = """- n_extra
  ( U1 A )
  ( U2 A )
+ ROUTED metal1 ( 10040 530 ) M2_M1
  NEW metal2 ( 10040 530 ) ( * 1500 ) ( 20040 * ) ( * 530 ) M2_M1
  NEW metal2 ( 15000 1500 ) ( * 2500 ) M2_M1 ;
"""
N_OPEN = """- n_open
  ( U1 C )
  ( U3 C )
+ ROUTED metal1 ( 10200 630 ) M2_M1
  NEW metal2 ( 10200 630 ) ( * 400 ) ( 30200 * ) ( 30120 * ) M2_M1 ;
"""
N_LOST = """- n_lost
  ( U1 B )
  ( U3 B )
+ ROUTED metal1 ( 10140 450 ) M2_M1
  NEW metal2 ( 10140 450 ) ( * 3000 ) ;
"""
N_SPLIT = """- n_split
  ( U1 A )
  ( U2 A )
+ ROUTED metal1 ( 10040 530 ) M2_M1
  NEW metal2 ( 10040 530 ) ( * 1500 ) M3_M2
  NEW metal3 ( 10040 1500 ) ( 20040 * )
  NEW metal1 ( 20040 530 ) M2_M1
  NEW metal2 ( 20040 530 ) ( * 2000 ) ;
"""
N_WHOLE = """- n_whole
  ( U1 A )
  ( U2 B )
+ ROUTED metal1 ( 10040 530 ) M2_M1
  NEW metal2 ( 10040 530 ) ( * 3500 ) M3_M2
  NEW metal3 ( 10040 3500 ) ( 20140 * ) M3_M2
  NEW metal2 ( 20140 3500 ) ( * 450 ) M2_M1 ;
"""


def write_def(path, nets):
    with open(path, "w") as f:
        f.write(HEAD + f"NETS {len(nets)} ;\n" + "".join(nets) + "END NETS\nEND DESIGN\n")


def main():
    tool, osu, scratch = sys.argv[1:4]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    lef = f"{osu}/osu018_stdcells.lef"
    fails = []

    def run(src, dst, report):
        r = subprocess.run(["/usr/bin/python3", tool, src, dst, report, lef], capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr, open(report).read() if os.path.exists(report) else ""

    write_def(f"{scratch}/all.def", [N_EXTRA, N_OPEN, N_LOST])
    rc, out, rep = run(f"{scratch}/all.def", f"{scratch}/all_out.def", f"{scratch}/all.txt")
    if rc != 1:
        fails.append(f"with U3/B unreachable: exit {rc}, expected 1\n{out}")
    if "n_lost: pin U3/B is open" not in rep:
        fails.append(f"the pin left open is not named:\n{rep}")

    write_def(f"{scratch}/fix.def", [N_EXTRA, N_OPEN, N_SPLIT, N_WHOLE])
    rc, out, rep = run(f"{scratch}/fix.def", f"{scratch}/fix_out.def", f"{scratch}/fix.txt")
    text = open(f"{scratch}/fix_out.def").read() if os.path.exists(f"{scratch}/fix_out.def") else ""
    if rc != 0:
        fails.append(f"mendable faults: exit {rc}, expected 0\n{out}")
    expect_lines = [
        "NEW metal2 ( 10200 630 ) ( * 400 ) ( 30200 * ) ( 30120 * )",   # its via taken out
        "NEW metal1 ( 30200 400 ) M2_M1 ;",                               # one on U3's C
        "NEW metal2 ( 10040 530 ) ( * 1500 ) ( 20040 * ) ( * 530 ) M2_M1",  # kept: on U2's A
        "+ ROUTED metal1 ( 10200 630 ) M2_M1",                            # kept: on U1's C
        "NEW metal2 ( 20040 1500 ) M3_M2 ;",                              # n_split's two pieces joined
        "NEW metal2 ( 20140 3500 ) ( * 450 ) M2_M1 ;",                    # n_whole: nothing added
    ]
    lines = [l.strip() for l in text.splitlines()]
    for e in expect_lines:
        if e not in lines:
            fails.append(f"expected line missing: {e!r}")
    if any("( 15000 1500 ) ( * 2500 ) M2_M1" in l for l in lines):
        fails.append("the via touching nothing at (150.00, 25.00) um is still there")
    if any("( 30200 * ) ( 30120 * ) M2_M1" in l for l in lines):
        fails.append("the via beside U3's C is still there")
    if not rep.startswith("repairs 4\nleft_open 0\n"):
        fails.append(f"report: expected 4 repairs (two vias out, one on a pin, one between metals), "
                     f"none left open:\n{rep}")
    if "n_split: its metal2 and metal3 meet at (200.40, 15.00) um" not in rep:
        fails.append(f"n_split's missing via is not named at (200.40, 15.00) um:\n{rep}")

    rc, out, rep = run(f"{scratch}/fix_out.def", f"{scratch}/again.def", f"{scratch}/again.txt")
    if rc != 0 or not rep.startswith("repairs 0\n") or open(f"{scratch}/again.def").read() != text:
        fails.append(f"a second pass on the mended DEF changed something (exit {rc}):\n{rep}")

    for f in fails:
        print("FAIL: " + f)
    print("layout_repair: " + ("PASS" if not fails else f"{len(fails)} failures"))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
