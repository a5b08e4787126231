#!/usr/bin/env bash
# Energy of the whole IP, specular_ip_axi, per kind of bus access (issue 46,
# docs/silicon/ip_tests.md "The whole IP (specular_ip_axi)"): energy.sh's method (the mapped netlist replayed by
# Icarus with the SDF, its toggles weighted by the OSU Liberty's internal-power tables and
# 1/2 C V^2 of the pin loads, the ROM macros' reads by rom_model.py's energy per read;
# scripts/flows/energy/energy.py) on three replays of rtl/tb/specular_ip_axi_gate_tb.v, one per
# kind, each counted from the testbench's PHASE_BEGIN_NS to its end:
#   operation: N, R, G, B, COS written, START written (its response comes with the
#              results), OUT_R, OUT_G, OUT_B read; one result per done_irq rise. The
#              operands are energy.sh's common stream (specular_variant_vectors patent
#              --count 18+N --seed 1, the expected values specular_tb's through gatesim.sh
#              --stimulus), counted from the first random one: the figure is the mean over
#              the N random operands, as the device's in docs/design_space.md;
#   read:      register reads (ID and the five operands in turn); one per RVALID rise;
#   write:     register writes (COS, N, R, G, B in turn); one per BVALID rise;
#   idle:      clocks with the bus idle; one per rising edge of aclk (the clock's own
#              cost, which every access above pays per clock it takes).
# Each figure is the replay's energy over its count: dynamic (logic + ROM) and the
# leakage over the replay's span (the clock runs through every access: its flip-flops'
# clock pins are in the figure).
#
#   scripts/flows/energy/energy_ip.sh [options] OUT_DIR [ROM_DIR]
#
#   --netlist-dir DIR   silicon.sh --top specular_ip_axi's output folder; default: run
#                       silicon.sh --no-gatesim into OUT_DIR/silicon first
#   --period NS         the replays' clock period (default 50, energy.sh's common clock)
#   --operations N      random operations after the stream's 18 edge cases (1-5000,
#                       default 300, the synchronous device's row of energy_streams.tsv)
#   --accesses N        register reads and register writes (1-5000, default 120)
#   --specular-tb PATH, --vectors-tool PATH, --counter PATH  as energy.sh
#   --keep-vcd          keep the VCDs
#
# OUT_DIR gets energy_ip.json, energy_ip.md and per kind its replay folder and
# energy_<kind>.json. Exit status: 0 written, 1 a tool or a replay failed, 2 bad arguments.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"
usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'; }
fail_args() { echo "energy_ip.sh: $1 (see --help)" >&2; exit 2; }

top=specular_ip_axi
netlist_dir=""
period=50
operations=300
accesses=120
specular_tb="$root/build/testbench/specular_tb"
vectors_tool="$root/build/tools/variant_vectors/specular_variant_vectors"
counter="$root/build/tools/vcd_activity/specular_vcd_activity"
keep_vcd=0
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --keep-vcd) keep_vcd=1; shift ;;
    --netlist-dir|--period|--operations|--accesses|--specular-tb|--vectors-tool|--counter)
      [[ $# -ge 2 ]] || fail_args "$1 needs a value"
      case "$1" in
        --netlist-dir) netlist_dir="$2" ;; --period) period="$2" ;;
        --operations) operations="$2" ;; --accesses) accesses="$2" ;;
        --specular-tb) specular_tb="$2" ;; --counter) counter="$2" ;;
        --vectors-tool) vectors_tool="$2" ;;
      esac
      shift 2 ;;
    -*) fail_args "unknown option '$1'" ;;
    *) args+=("$1"); shift ;;
  esac
done
[[ ${#args[@]} -ge 1 && ${#args[@]} -le 2 ]] || fail_args "usage: energy_ip.sh [options] OUT_DIR [ROM_DIR]"
number='^[0-9]+([.][0-9]+)?$'
[[ "$period" =~ $number ]] && (( $(echo "$period >= 1 && $period <= 1000" | bc) )) \
  || fail_args "--period '$period' is not a period in ns from 1 to 1000"
[[ "$operations" =~ ^[0-9]{1,4}$ ]] && (( 10#$operations >= 1 && 10#$operations <= 5000 )) \
  || fail_args "--operations '$operations' is not a count from 1 to 5000"
[[ "$accesses" =~ ^[0-9]{1,4}$ ]] && (( 10#$accesses >= 1 && 10#$accesses <= 5000 )) \
  || fail_args "--accesses '$accesses' is not a count from 1 to 5000"
operations=$((10#$operations)); accesses=$((10#$accesses))
out="${args[0]}"
rom_dir="${args[1]:-$root/build/rtl/rom/default}"
top_dir="$flows/designs/$top"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
if [[ -z "$netlist_dir" ]]; then
  netlist_dir="$out/silicon"
  bash "$flows/synthesis/silicon.sh" --top "$top" --no-gatesim "$netlist_dir" "$rom_dir" > "$out/silicon.log" 2>&1 \
    || { echo "energy_ip.sh: silicon.sh failed (see $out/silicon.log)" >&2; exit 1; }
fi
netlist_dir="$(cd "$netlist_dir" && pwd)"
for f in mapped.v device.sdf rom_macros.lib rom_model.json; do
  [[ -f "$netlist_dir/$f" ]] || fail_args "'$netlist_dir/$f' not found: run scripts/flows/synthesis/silicon.sh --top $top first"
done
source "$top_dir/gatesim.conf"   # TB_TOP
[[ -x "$vectors_tool" ]] || fail_args "specular_variant_vectors not found at '$vectors_tool' (cmake --build build --target specular_variant_vectors, or --vectors-tool PATH)"
# energy.sh's common stream: 18 edge cases, then the random operands
"$vectors_tool" patent --count $((18 + operations)) --seed 1 --out "$out/stream.txt" > "$out/stream.log" 2>&1 \
  || { echo "energy_ip.sh: writing the common stream failed; see $out/stream.log" >&2; exit 1; }

# ---- slews: OpenSTA at the period, the top's own SDC (as energy.sh) -----------------
/usr/bin/python3 "$flows/energy/energy.py" sta-slews "$out/slews_dump.tcl" "$out/slews.txt"
{
  echo "read_liberty {$OSU018/osu018_stdcells.lib}"
  echo "read_liberty {$netlist_dir/rom_macros.lib}"
  echo "read_verilog {$netlist_dir/mapped.v}"
  echo "link_design $top"
  echo "source {$top_dir/constraints.tcl}"
  echo "constrain $period"
  echo "source {$out/slews_dump.tcl}"
} > "$out/slews.tcl"
sta -no_splash -exit "$out/slews.tcl" > "$out/slews.log" 2>&1 && [[ -s "$out/slews.txt" ]] \
  && ! grep -q '^Error' "$out/slews.log" \
  || { echo "energy_ip.sh: OpenSTA's slews failed; see $out/slews.log" >&2; exit 1; }

counter_opts=()
[[ ! -x "$counter" ]] || counter_opts=(--counter "$counter")
# kind, testbench MODE, strobe (one rise per access), the count the strobe must reach
kinds=("operation 0 done_irq $operations" "read 1 s_axi_rvalid $accesses" "write 2 s_axi_bvalid $accesses"
       "idle 4 aclk $accesses")
for spec in "${kinds[@]}"; do
  read -r kind mode strobe expected <<< "$spec"
  started=$SECONDS
  if ! bash "$flows/gatelevel/gatesim.sh" --top "$top" --netlist-dir "$netlist_dir" --quiet \
       --specular-tb "$specular_tb" --stimulus "$out/stream.txt" \
       --tb-param "MODE=$mode" --tb-param "ACCESSES=$accesses" --tb-param MEASURE_FROM=18 \
       --vcd "$out/$kind/activity.vcd" "$period" "$out/$kind" "$rom_dir" > "$out/$kind.log" 2>&1; then
    echo "energy_ip.sh: the $kind replay failed at $period ns; see $out/$kind.log" >&2
    exit 1
  fi
  log=$(ls "$out/$kind"/T*/*.log | grep -v compile.log | head -1)
  begin=$(awk '/^PHASE_BEGIN_NS/ {print $2; exit}' "$log")
  clocks=$(awk -v k="clocks_per_$kind" '$1 == k {print $2; exit}' "$log")
  [[ -n "$begin" && -n "$clocks" ]] || { echo "energy_ip.sh: no PHASE_BEGIN_NS or clocks_per_$kind in $log" >&2; exit 1; }
  echo "sim_s $((SECONDS - started))" > "$out/$kind/time.txt"
  started=$SECONDS
  /usr/bin/python3 "$flows/energy/energy.py" compute --lib "$OSU018/osu018_stdcells.lib" \
    --lib "$netlist_dir/rom_macros.lib" --netlist "$netlist_dir/mapped.v" --top "$top" \
    --tb-top "$TB_TOP" --vcd "$out/$kind/activity.vcd" --slews "$out/slews.txt" \
    --rom-model "$netlist_dir/rom_model.json" --results-strobe "$strobe" --results-mode rise \
    --t-begin "$begin" "${counter_opts[@]}" --toggles-out "$out/toggles_$kind.txt" --out "$out/energy_$kind.json" \
    || { echo "energy_ip.sh: counting the $kind activity failed" >&2; exit 1; }
  echo "count_s $((SECONDS - started))" >> "$out/$kind/time.txt"
  echo "clocks_per_access $clocks" >> "$out/$kind/time.txt"
  echo "expected $expected" >> "$out/$kind/time.txt"
  [[ $keep_vcd -eq 1 ]] || rm -f "$out/$kind/activity.vcd"
done

# ---- the figures: per access, dynamic and leakage over the replay's span -----------
/usr/bin/python3 - "$out" "$period" <<'EOF'
import json, sys
out, period = sys.argv[1], float(sys.argv[2])
rows = {}
for kind in ("operation", "read", "write", "idle"):
    e = json.load(open(f"{out}/energy_{kind}.json"))
    t = dict(line.split() for line in open(f"{out}/{kind}/time.txt"))
    n = e["results"]
    if n != int(t["expected"]):
        raise SystemExit(f"energy_ip.sh: the {kind} replay counted {n} strobes, not {t['expected']}")
    dyn = (e["internal_pj"] + e["switching_pj"] + e["rom_pj"]) / n
    leak = e["leakage_nw"] * e["span_ns"] * 1e-6 / n   # nW x ns = 1e-6 pJ
    rows[kind] = {"count": n, "span_ns": round(e["span_ns"], 3),
                  "clocks_per_access": float(t["clocks_per_access"]),
                  "internal_pj": e["internal_pj"] / n, "switching_pj": e["switching_pj"] / n,
                  "internal_sequential_pj": e["internal_sequential_pj"] / n,
                  "rom_pj": e["rom_pj"] / n, "dynamic_pj": dyn, "leakage_pj": leak,
                  "total_pj": dyn + leak, "toggles": e["toggles"] / n,
                  "sim_s": int(t["sim_s"]), "count_s": int(t["count_s"])}
# beyond the idle clock: what an access costs over the clocks it takes with the bus idle
idle = rows["idle"]["total_pj"]
for k, r in rows.items():
    r["beyond_idle_clocks_pj"] = r["total_pj"] - r["clocks_per_access"] * idle
res = {"top": "specular_ip_axi", "period_ns": period, "leakage_nw": e["leakage_nw"],
       "cells": e["cells"], "per_access": rows}
json.dump(res, open(f"{out}/energy_ip.json", "w"), indent=1)
f = lambda x: f"{x:.1f}" if x >= 10 else f"{x:.2f}"
lines = ["# Energy per access: specular_ip_axi (scripts/flows/energy/energy_ip.sh)", "",
         f"Gate-level replays at {period:g} ns with the SDF delays; pJ per access, counted from "
         "each replay's PHASE_BEGIN_NS to its end; leakage over the replay's span.", "",
         "| access | count | clocks each | internal | switching | ROM | dynamic | leakage | **total** | beyond its clocks idle | toggles each |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for k, r in rows.items():
    lines.append(f"| {k} | {r['count']} | {r['clocks_per_access']:g} | {f(r['internal_pj'])} | "
                 f"{f(r['switching_pj'])} | {f(r['rom_pj'])} | {f(r['dynamic_pj'])} | "
                 f"{f(r['leakage_pj'])} | **{f(r['total_pj'])}** | {f(r['beyond_idle_clocks_pj'])} | {r['toggles']:.0f} |")
lines += ["", "An operation (the mean over the common stream's random operands, after its 18 edge cases): five operand writes, START (its response comes with the results) and "
          "three result reads. A read: ID or an operand register. A write: an operand register. "
          "Idle: one clock with the bus idle. Beyond its clocks idle: the access's total less its "
          "clocks times the idle clock's."]
open(f"{out}/energy_ip.md", "w").write("\n".join(lines) + "\n")
EOF
echo "energy_ip.sh: $out/energy_ip.md, $out/energy_ip.json"
