#!/usr/bin/env bash
# layout_whole_device (long, nightly): scripts/flows/layout/layout.sh lays out the synchronous device
# whole (issue 48): silicon.sh's mapping, placement, routing, DRC, LVS, extraction and
# post-layout STA. Passes when layout.sh exits 0 (no unrouted net, 0 DRC errors, LVS
# match) and its summary holds both ROM macros, the mapped netlist's cell count (read here
# from silicon.sh's stat.txt) and a post-layout T_sta.
#   layout_whole_test.sh PROJECT_ROOT ROM_DIR SCRATCH
set -euo pipefail
root="$1"; rom_dir="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
nice -n 10 bash "$root/scripts/flows/layout/layout.sh" --top specular_device_sync --rom-dir "$rom_dir" "$scratch/layout"
/usr/bin/python3 - "$scratch/layout" <<'PY'
import json, re, sys
out = sys.argv[1]
s = json.load(open(f"{out}/layout_summary.json"))
stat = open(f"{out}/silicon/stat.txt").read()
cells = int(re.search(r"Number of cells:\s+(\d+)", stat.split("=== design hierarchy ===")[-1]).group(1))
macros = sum(int(n) for n in re.findall(r"ROM\S*_MACRO\s+(\d+)", stat.split("=== design hierarchy ===")[-1]))
problems = []
if s["unrouted_nets"] != 0 or s["drc_errors"] != 0 or not s["lvs_match"]:
    problems.append(f"unrouted {s['unrouted_nets']} DRC {s['drc_errors']} LVS {s['lvs_match']}")
if len(s["macros"]) != 2 or macros != 2:
    problems.append(f"macros in the layout {len(s['macros'])}, in the netlist {macros}")
if s["standard_cells"] + len(s["macros"]) < cells:
    problems.append(f"{s['standard_cells']} cells + macros laid out, {cells} mapped")
if not s["t_sta_ns"]:
    problems.append("no post-layout T_sta")
if problems:
    print("FAIL: " + "; ".join(problems)); sys.exit(1)
print(f"PASS: die {s['die_area_mm2']} mm^2, T_sta {s['t_sta_ns']} ns")
PY
