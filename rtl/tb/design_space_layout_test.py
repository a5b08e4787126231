#!/usr/bin/env python3
"""design_space_layout: scripts/flows/design_space/design_space.py --layout-dir on made-up designs (issue 48):
the fronts are drawn from each design's figure after layout where it has one, its
estimate otherwise, and a layout that is not clean is no figure.

  a  estimate 1.0 mm², error 0.1; laid out: 3.0 mm², T_sta 20 ns (1 clock per result)
  b  estimate 2.0 mm², error 0.1; not laid out
  c  estimate 2.5 mm², error 0.01; laid out: 2.6 mm²
  d  estimate 0.5 mm², error 0.2; laid out with a DRC error: left out

Before layout a dominates b on the area plane; after it b dominates a (2.0 < 3.0 at the
same error), so b, not a, is on the area front. d stays an estimate and, at 0.5 mm², on
the area front; on the energy plane a (1 200 pJ, 0.1) and c (2 100 pJ, 0.01) are the
front. a's results/s per mm²
after layout is 1e9 / (20 ns · 1) / 3.0 mm², computed here. A layout of a design the runs
do not hold is an error naming it.

  design_space_layout_test.py DESIGN_SPACE_PY SCRATCH
Exit 0 pass, 1 fail.
"""
import json
import os
import shutil
import subprocess
import sys

# name: (estimate mm², error, results/s per mm² before, layout: (die mm², T_sta ns, clean) or None)
DESIGNS = {
    "a": (1.0, 0.1, 10e6, (3.0, 20.0, True)),
    "b": (2.0, 0.1, 5e6, None),
    "c": (2.5, 0.01, 4e6, (2.6, 25.0, True)),
    "d": (0.5, 0.2, 2e6, (0.7, 30.0, False)),
}
ENERGY = {"a": (1000.0, 1200.0), "c": (2000.0, 2100.0)}  # before, after layout (pJ)


def energy_json(pj):
    return {"results": 318, "clocks_per_result": 1, "internal_pj": pj * 0.4, "switching_pj": pj * 0.4,
            "rom_pj": pj * 0.2, "leakage_pj_at_period": 0.1, "total_pj_at_period": pj,
            "rom_reads_per_result": {"rom5": 1.0}, "random_results": 300, "random_dynamic_sem_rel": 0.005,
            "random_total_pj_at_period": pj, "settled_1pct": True}


def write(path, obj):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(obj, f)


def run(script, runs, layouts, scratch):
    table = os.path.join(scratch, "layout_table.md")
    svg = os.path.join(scratch, "svg")
    r = subprocess.run(["/usr/bin/python3", script, runs, "--table", os.path.join(scratch, "table.md"),
                        "--layout-dir", layouts, "--layout-table", table, "--svg-dir", svg],
                       capture_output=True, text=True)
    return r, table, svg


def main():
    script, scratch = sys.argv[1:3]
    shutil.rmtree(scratch, ignore_errors=True)
    runs, layouts = os.path.join(scratch, "runs"), os.path.join(scratch, "layout")
    for name, (die, err, tput, lay) in DESIGNS.items():
        write(os.path.join(runs, name, "silicon_summary.json"),
              {"top": "specular_" + name, "area_logic_um2": 1e5, "area_macros_um2": 1e5,
               "area_total_um2": die * 0.8e6, "area_total_one_rom38_bank_um2": die * 0.7e6,
               "die_area_estimate_mm2": die, "flip_flops": 10, "t_sta_ns": 10.0,
               "clocks_per_result_streamed": 1, "results_per_second_streamed_at_t_sta": tput * die,
               "results_per_second_per_mm2_streamed": tput})
        write(os.path.join(runs, name, "error.json"), {"lobe_max_abs": err})
        if name in ENERGY:
            write(os.path.join(runs, name, "energy.json"), energy_json(ENERGY[name][0]))
            write(os.path.join(layouts, name, "energy", "energy.json"), energy_json(ENERGY[name][1]))
        if lay:
            write(os.path.join(layouts, name, "layout_summary.json"),
                  {"top": "specular_" + name, "die_area_mm2": lay[0], "t_sta_ns": lay[1],
                   "unrouted_nets": 0, "drc_errors": 0 if lay[2] else 1, "lvs_match": True})
    fails = []
    r, table, svg = run(script, runs, layouts, scratch)
    if r.returncode != 0:
        print(f"FAIL: design_space.py exit {r.returncode}: {r.stderr}")
        return 1
    rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")]
            for line in open(table) if line.startswith("| ") and line.split("|")[1].strip() in DESIGNS}
    want = {  # laid out, Pareto column (area, throughput/mm², energy–error from the mixed figures)
        "a": ("yes", "throughput/mm², energy–error"),
        "b": ("no (estimate)", "area"),
        "c": ("yes", "area, throughput/mm², energy–error"),
        "d": ("no (estimate)", "area"),
    }
    for name, (laid, front) in want.items():
        cells = rows.get(name)
        if not cells:
            fails.append(f"no row for {name}")
            continue
        if cells[2] != laid:
            fails.append(f"{name}: after layout '{cells[2]}', want '{laid}'")
        if cells[-2] != front:
            fails.append(f"{name}: Pareto '{cells[-2]}', want '{front}'")
    a_tput = 1e9 / (20.0 * 1) / 3.0 / 1e6
    if rows.get("a") and rows["a"][3] != "1.000 → **3.000**":
        fails.append(f"a: die '{rows['a'][3]}', want '1.000 → **3.000**'")
    if rows.get("a") and rows["a"][5] != f"10.00 → **{a_tput:.2f}**":
        fails.append(f"a: results/s per mm² '{rows['a'][5]}', want '10.00 → **{a_tput:.2f}**'")
    if rows.get("a") and rows["a"][6] != "1000 → **1200**":
        fails.append(f"a: energy '{rows['a'][6]}', want '1000 → **1200**'")
    if rows.get("d") and rows["d"][3] != "0.500":
        fails.append(f"d (not clean) took a layout figure: '{rows['d'][3]}'")
    if "drc_errors 1" not in r.stderr or os.path.join("layout", "d") not in r.stderr:
        fails.append(f"d's unclean layout not named on stderr: {r.stderr!r}")
    for plane in ("area_vs_error", "throughput_vs_error", "energy_vs_error"):
        path = os.path.join(svg, plane + "_layout.svg")
        if not os.path.isfile(path) or "estimate (not laid out)" not in open(path).read():
            fails.append(f"{path}: missing or without the estimate's legend")
    # a layout of a design the runs do not hold
    write(os.path.join(layouts, "e", "layout_summary.json"),
          {"top": "specular_e", "die_area_mm2": 1.0, "t_sta_ns": 10.0, "unrouted_nets": 0,
           "drc_errors": 0, "lvs_match": True})
    r, _, _ = run(script, runs, layouts, scratch)
    if r.returncode != 1 or "laid out but not in" not in r.stderr or " e" not in r.stderr:
        fails.append(f"a layout of unknown design e: exit {r.returncode}, stderr {r.stderr!r}")
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print("PASS: fronts from the figures after layout where laid out; b dominates a after layout; "
              "d's unclean layout left out and named; an unknown design refused")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
