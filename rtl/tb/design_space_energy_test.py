#!/usr/bin/env python3
"""design_space_energy: scripts/flows/design_space/design_space.py --energy-table on four made-up designs
(issue 36). A design's energy per result is its random operands' mean, not the whole
stream's: design d, cheapest over its whole stream (500 pJ) but dearest over its random
operands (3 000 pJ), is on no front; a (1 000 pJ, error 0.1, 2.0 mm²) and b (2 000 pJ,
0.01, 1.0 mm²) are on both fronts; c (2 500 pJ, 0.2, 2.5 mm²) is dominated by a on both.
A stream whose standard error is above 1 % says "no" in the settled column.

  design_space_energy_test.py DESIGN_SPACE_PY SCRATCH
Exit 0 pass, 1 fail.
"""
import json
import os
import subprocess
import sys

DESIGNS = {  # name: (random operands' pJ, whole stream's pJ, lobe max |error|, die mm², s.e., settled)
    "a": (1000.0, 900.0, 0.1, 2.0, 0.005, True),
    "b": (2000.0, 1900.0, 0.01, 1.0, 0.008, True),
    "c": (2500.0, 2400.0, 0.2, 2.5, 0.009, True),
    "d": (3000.0, 500.0, 0.3, 3.0, 0.012, False),
}


def main():
    script, scratch = sys.argv[1:3]
    runs = os.path.join(scratch, "runs")
    for name, (rnd, whole, err, die, sem, settled) in DESIGNS.items():
        d = os.path.join(runs, name)
        os.makedirs(d, exist_ok=True)
        json.dump({"top": "specular_" + name, "area_total_um2": die * 0.8e6, "die_area_estimate_mm2": die,
                   "results_per_second_per_mm2_streamed": 1e6}, open(os.path.join(d, "silicon_summary.json"), "w"))
        json.dump({"lobe_max_abs": err}, open(os.path.join(d, "error.json"), "w"))
        json.dump({"results": 318, "clocks_per_result": 1, "internal_pj": whole * 0.4, "switching_pj": whole * 0.4,
                   "rom_pj": whole * 0.2, "leakage_pj_at_period": 0.1, "total_pj_at_period": whole,
                   "rom_reads_per_result": {"rom5": 1.0}, "random_results": 300, "random_dynamic_pj": rnd - 0.1,
                   "random_dynamic_sem_rel": sem, "random_total_pj_at_period": rnd, "settled_1pct": settled},
                  open(os.path.join(d, "energy.json"), "w"))
    table = os.path.join(scratch, "energy_table.md")
    r = subprocess.run(["/usr/bin/python3", script, runs, "--energy-table", table, "--energy-only"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAIL: design_space.py exit {r.returncode}: {r.stderr}")
        return 1
    rows = {line.split("|")[1].strip(): line for line in open(table) if line.startswith("| ") and
            line.split("|")[1].strip() in DESIGNS}
    want_front = {"a": "energy–error, energy–area", "b": "energy–error, energy–area", "c": "", "d": ""}
    fails = []
    for name, (rnd, whole, err, die, sem, settled) in DESIGNS.items():
        cells = [c.strip() for c in rows.get(name, "").split("|")]
        if len(cells) < 3:
            fails.append(f"no row for design {name}")
            continue
        if cells[-2] != want_front[name]:
            fails.append(f"{name}: Pareto '{cells[-2]}', want '{want_front[name]}'")
        if f"**{rnd:.0f}** ± {100 * sem:.1f} %" not in cells:
            fails.append(f"{name}: the figure is not the random operands' {rnd:.0f} ± {100 * sem:.1f} %: {cells}")
        if ("yes" if settled else "**no**") not in cells:
            fails.append(f"{name}: settled column does not say {'yes' if settled else 'no'}")
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print("PASS: the figure is the random operands' mean; fronts {a, b}; d's unsettled stream says no")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
