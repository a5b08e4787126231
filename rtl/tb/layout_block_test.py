#!/usr/bin/env python3
"""layout_block: scripts/flows/layout/layout.sh lays out Fig. 2's control unit end to end (issue 48).

  layout_block_test.py PROJECT_ROOT SCRATCH [PLANT|resume|no-cleanup]

Maps control_unit16 onto the OSU 0.18 um cells with Yosys as scripts/flows/synthesis/silicon.sh does
(Fig. 2's gates kept as the library cells of scripts/flows/synthesis/fig2_cells.v), then runs
scripts/flows/layout/layout.sh on it.
  - Without PLANT: layout.sh exits 0 and its summary says no unrouted net, 0 DRC errors,
    LVS match; the layout holds the 10 cells of Fig. 2 (inverter 44, AND 40, NANDs 45-47,
    flip-flops 41-43, the two /Q inverters: written here from the figure, docs/silicon.md)
    and a BUFX2 from vdd per constant (the library has no tie cell), and a die no smaller
    than their area (from the LEF, read here); some wire is routed; times.txt gives each
    step's CPU time beside its wall time, not zero for placement and routing; qrouter ran
    its stage 3 (route log and router_stage3 in the summary).
  - no-cleanup: the same with layout.sh --no-cleanup: as clean, and qrouter's log says
    stage 3 was bypassed and never ran (router_stage3 false).
  - PLANT = drc, lvs or unrouted: layout.sh --plant PLANT must exit 1 and name that
    fault on standard error (the checks can fail).
  - resume (no fault): after the layout above, the placed DEF and the netlists as
    placement left them are put back, qrouter routes by hand (qrouter -s TOP.cfg, as the
    whole device was routed), and layout.sh --resume must go on from that routing: exit
    0, no placement or routing step run again, routing_before_resume_s in times.txt,
    DRC 0 and LVS match (the fill cells annotated into the netlists as router.sh does).
Exit 0 pass, 1 fail.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time

FIG2_CELLS = {"INVX1": 3, "AND2X1": 1, "NAND3X1": 2, "NAND2X1": 1, "DFFSR": 3}
FAULT_WORDS = {"drc": "DRC errors", "lvs": "LVS mismatch", "unrouted": "nets unrouted"}
QFLOW_BIN = "/usr/lib/qflow/bin"
OSU018 = "/usr/share/qflow/tech/osu018"


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def main():
    if len(sys.argv) not in (3, 4):
        print("usage: layout_block_test.py PROJECT_ROOT SCRATCH [drc|lvs|unrouted|resume|no-cleanup]")
        return 2
    root, scratch = sys.argv[1], sys.argv[2]
    plant = sys.argv[3] if len(sys.argv) == 4 else ""
    resume, no_cleanup = plant == "resume", plant == "no-cleanup"
    if resume or no_cleanup:
        plant = ""
    if plant and plant not in FAULT_WORDS:
        print(f"layout_block_test.py: '{plant}' is not one of drc, lvs, unrouted, resume, no-cleanup")
        return 2
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    lib = f"{OSU018}/osu018_stdcells.lib"
    netlist = f"{scratch}/control_unit16.v"
    prims = " ".join(f"{root}/rtl/primitives/{f}" for f in sorted(os.listdir(f"{root}/rtl/primitives")))
    script = (f"read_liberty -lib {lib}; read_verilog {prims} {root}/rtl/device/control_unit16.v; "
              f"read_verilog -overwrite {root}/scripts/flows/synthesis/fig2_cells.v; "
              "hierarchy -check -top control_unit16; flatten; proc; opt; techmap; opt; "
              f"dfflibmap -liberty {lib}; abc -fast -liberty {lib}; opt_clean; "
              f"write_verilog -noattr {netlist}")
    r = subprocess.run(["yosys", "-q", "-p", script], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"yosys could not map control_unit16: {r.stderr[-500:]}")
    cmd = ["bash", f"{root}/scripts/flows/layout/layout.sh", "--netlist", netlist, "--top", "control_unit16"]
    if plant:
        cmd += ["--plant", plant]
    if no_cleanup:
        cmd += ["--no-cleanup"]
    out = f"{scratch}/layout"
    r = subprocess.run(cmd + [out], capture_output=True, text=True)
    print(r.stdout[-2000:], r.stderr[-2000:])
    if plant:
        if r.returncode != 1:
            fail(f"layout.sh --plant {plant} exited {r.returncode}, not 1")
        if FAULT_WORDS[plant] not in r.stderr:
            fail(f"layout.sh --plant {plant} did not say '{FAULT_WORDS[plant]}'")
        print(f"PASS: the planted {plant} fault fails the layout")
        return 0
    if r.returncode != 0:
        fail(f"layout.sh exited {r.returncode}")
    s = json.load(open(f"{out}/layout_summary.json"))
    if s["unrouted_nets"] != 0 or s["drc_errors"] != 0 or not s["lvs_match"]:
        fail(f"unrouted {s['unrouted_nets']}, DRC {s['drc_errors']}, LVS {s['lvs_match']}")
    # the cells in the layout's DEF, counted here by cell name: Fig. 2's and one BUFX2
    # from vdd or gnd per constant the mapped netlist uses (the library has no tie cell)
    text = open(netlist).read()
    expected = dict(FIG2_CELLS)
    ties = int(bool(re.search(r"1'[bh]1", text))) + int(bool(re.search(r"1'[bh]0", text)))
    if ties:
        expected["BUFX2"] = ties
    placed = {}
    for m in re.finditer(r"^-\s+\S+\s+(\S+)\s+\+\s+PLACED", open(f"{out}/qflow/control_unit16_route.def").read(), re.M):
        if m.group(1) != "FILL":
            placed[m.group(1)] = placed.get(m.group(1), 0) + 1
    if placed != expected:
        fail(f"placed cells {placed}, Fig. 2 and the ties: {expected}")
    sizes, name = {}, None
    for line in open(f"{OSU018}/osu018_stdcells.lef"):
        if line.startswith("MACRO "):
            name = line.split()[1]
        m = re.match(r"\s*SIZE\s+([\d.]+)\s+BY\s+([\d.]+)", line)
        if m and name:
            sizes[name] = float(m.group(1)) * float(m.group(2))
    cell_area = sum(sizes[c] * n for c, n in expected.items())
    if s["die_area_mm2"] * 1e6 < cell_area:
        fail(f"die {s['die_area_mm2']} mm^2 smaller than the cells' {cell_area} um^2")
    if abs(s["standard_cell_area_um2"] - cell_area) > 0.5:
        fail(f"cell area {s['standard_cell_area_um2']} um^2, the LEF gives {cell_area}")
    if s["wire_length_total_um"] <= 0:
        fail("no wire routed")
    # qrouter's stage 3, as its own log tells (the control unit routes in stage 1, after
    # which standard_route runs stage 3 unless told not to)
    log = open(f"{out}/qflow/log/route.log").read()
    ran, bypassed = "Running stage3" in log, "Cleanup stage (stage3) bypassed" in log
    if (ran, bypassed) != ((False, True) if no_cleanup else (True, False)):
        fail(f"qrouter's stage 3 {'ran' if ran else 'did not run'}, bypassed: {bypassed} "
             f"(--no-cleanup {'given' if no_cleanup else 'not given'})")
    if s["router_stage3"] is not (not no_cleanup):
        fail(f"layout_summary.json router_stage3 {s['router_stage3']}, qrouter's log: stage 3 ran {ran}")
    # each step's wall and CPU time (the farm's model of a design's cost); graywolf and
    # qrouter are child processes that ran, so their steps' CPU cannot be zero
    times = dict(line.split() for line in open(f"{out}/times.txt"))
    steps = [k[:-2] for k in times if k.endswith("_s") and not k.endswith("_cpu_s")]
    missing = [k for k in steps if f"{k}_cpu_s" not in times]
    if missing or not all(float(times.get(f"{k}_cpu_s", 0)) > 0 for k in ("placement", "routing")):
        fail(f"times.txt without each step's CPU time, or none for placement and routing: {times}")
    print(f"PASS: control unit laid out: die {s['die_area_mm2']} mm^2, {sum(placed.values())} cells, "
          f"wire {s['wire_length_total_um']} um, DRC 0, LVS match, none unrouted")
    return check_resume(root, netlist, out) if resume else 0


def check_resume(root, netlist, out):
    """The routing done by hand on the placed project, then layout.sh --resume."""
    top, proj = "control_unit16", f"{out}/qflow"
    shutil.copy(f"{proj}/{top}_unroute.def", f"{proj}/{top}.def")
    for f in (f"{top}_route.def", f"{top}.rc", "antenna.out"):
        if os.path.exists(f"{proj}/{f}"):
            os.remove(f"{proj}/{f}")
    # the netlists without router.sh's annotation, as blif2Verilog and blif2BSpice write them
    with open(f"{proj}/{top}.rtlnopwr.v", "w") as f:
        subprocess.run([f"{QFLOW_BIN}/blif2Verilog", "-c", "-p", "-v", "vdd", "-g", "gnd", f"{top}_full.blif"],
                       cwd=proj, stdout=f, check=True)
    with open(f"{proj}/{top}.spc", "w") as f:
        subprocess.run([f"{QFLOW_BIN}/blif2BSpice", "-i", "-p", "vdd", "-g", "gnd", "-l", f"{proj}/cells.sp",
                        f"{top}_full.blif"], cwd=proj, stdout=f, check=True)
    if "FILL" in open(f"{proj}/{top}.spc").read():
        fail("the netlist put back already holds the fill cells")
    time.sleep(1.1)   # the routing strictly newer than the placement, whatever the clock's grain
    with open(f"{proj}/log/route.log", "w") as f:
        subprocess.run(["qrouter", "-nog", "-s", f"{top}.cfg"], cwd=proj, stdout=f, stderr=subprocess.STDOUT)
    if not os.path.exists(f"{proj}/{top}_route.def") or not os.path.exists(f"{proj}/{top}_route.rc"):
        fail("qrouter by hand wrote no TOP_route.def and TOP_route.rc")
    r = subprocess.run(["bash", f"{root}/scripts/flows/layout/layout.sh", "--resume", "--netlist", netlist, "--top", top, out],
                       capture_output=True, text=True)
    print(r.stdout[-2000:], r.stderr[-2000:])
    if r.returncode != 0:
        fail(f"layout.sh --resume after the routing by hand exited {r.returncode}")
    if "holds a finished routing" not in r.stdout:
        fail("layout.sh --resume did not say it found the routing")
    times = dict(line.split() for line in open(f"{out}/times.txt"))
    if "routing_before_resume_s" not in times or {"prepare_s", "placement_s"} & set(times):
        fail(f"times.txt after --resume: {sorted(times)}: not the routing by hand alone before DRC")
    s = json.load(open(f"{out}/layout_summary.json"))
    if s["unrouted_nets"] != 0 or s["drc_errors"] != 0 or not s["lvs_match"]:
        fail(f"after --resume: unrouted {s['unrouted_nets']}, DRC {s['drc_errors']}, LVS {s['lvs_match']}")
    if "FILL" not in open(f"{proj}/{top}.spc").read():
        fail("after --resume the LVS netlist holds no fill cell (not annotated)")
    print("PASS: layout.sh --resume went on from the routing by hand: DRC 0, LVS match")
    return 0


if __name__ == "__main__":
    sys.exit(main())
