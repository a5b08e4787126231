#!/usr/bin/env bash
# Energy per result of one design from its gate-level activity (issue 36,
# docs/design_space/energy_per_result.md "Energy per result"): the mapped netlist of scripts/flows/synthesis/silicon.sh replayed by
# Icarus twice over the same vectors, with the SDF (glitches count) and with zero delay,
# each replay's value changes of the netlist's own scopes to a VCD, its toggles weighted
# by the OSU Liberty's internal-power tables and 1/2 C V^2, the ROM macros' reads by
# scripts/flows/synthesis/rom_model.py's energy per read (scripts/flows/energy/energy.py).
#
#   scripts/flows/energy/energy.sh [options] OUT_DIR [ROM_DIR]
#
#   --top NAME          the top (default specular_device), as silicon.sh takes it
#   --netlist-dir DIR   silicon.sh's output folder (mapped.v, device.sdf, rom_model.json),
#                       or scripts/flows/layout/layout.sh's OUT/postlayout (its wire_cap.txt: each net
#                       weighed by its pins and its routed wire);
#                       default: run silicon.sh --no-gatesim into OUT_DIR/silicon first
#   --period NS         the replays' clock period, the common clock (default 50)
#   --t-sim NS          the design's own T_sim (default: t_sim_ns of DIR's
#                       silicon_summary.json, else the top's row of energy_streams.tsv):
#                       leakage also given at T_sim
#   --clocks-per-result C  for the figure at T_sim (default: the summary's streamed value)
#   --random N          random operations of the common stream after its 18 edge cases
#                       (0-5000; default: the top's row of scripts/flows/energy/energy_streams.tsv,
#                       long enough for a 1 % standard error, else 262). Every design
#                       replays the same operands: specular_variant_vectors NAME --count
#                       18+N --seed 1 (a device top through its own testbench, gatesim.sh
#                       --stimulus, with the patent's policy and no reset mid-operation)
#   --vectors-tool PATH, --specular-tb PATH  as gatesim.sh
#   --counter PATH      the toggle counter (default build/tools/vcd_activity/
#                       specular_vcd_activity; without it energy.py's own reader, the
#                       reference, counts: the same figures, 10-20 times slower)
#   --keep-vcd          keep the two VCDs (deleted after counting by default: up to GBs)
#   --no-zero-delay     skip the zero-delay replay (no glitch share)
#   --stimulus FILE     (a device top) replay these operations instead of the common
#                       stream (gatesim.sh --stimulus's format: hex cos n r g b per line);
#                       the report's "random operands" are then all of them
#   --per-result        also OUT_DIR/per_result.tsv: each operation's energy (energy.py
#                       report --per-result-out), line k the stimulus's k-th operation,
#                       a result counted by the top's ENERGY_PER_RESULT strobe where its
#                       gatesim.conf names one (the synchronous device: 35's rise, the end
#                       of the operation, so that an interval is one operation's own clocks)
#
# OUT_DIR gets energy.json (the figures), energy.md (the table), sdf/ and zero/ (the
# replays, energy_sdf.json, energy_zero.json, toggles_*.txt; after layout also
# wire_switching_*.txt: each wired net's wire, toggles and the wire's own 1/2 C V^2 energy,
# the largest first, and energy_*.json's wire_switching_pj) and slews.txt.
# Exit status: 0 written, 1 a tool or a replay failed, 2 bad arguments.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"
usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'; }
fail_args() { echo "energy.sh: $1 (see --help)" >&2; exit 2; }

top=specular_device
netlist_dir=""
period=50
t_sim=""
cpr=""
random=""
vectors_tool="$root/build/tools/variant_vectors/specular_variant_vectors"
specular_tb="$root/build/testbench/specular_tb"
counter="$root/build/tools/vcd_activity/specular_vcd_activity"
keep_vcd=0
zero=1
stimulus=""
per_result=0
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --keep-vcd) keep_vcd=1; shift ;;
    --no-zero-delay) zero=0; shift ;;
    --per-result) per_result=1; shift ;;
    --stimulus|--top|--netlist-dir|--period|--t-sim|--clocks-per-result|--random|--vectors-tool|--specular-tb|--counter)
      [[ $# -ge 2 ]] || fail_args "$1 needs a value"
      case "$1" in
        --top) top="$2" ;; --netlist-dir) netlist_dir="$2" ;; --period) period="$2" ;;
        --t-sim) t_sim="$2" ;; --clocks-per-result) cpr="$2" ;;
        --random) random="$2" ;; --vectors-tool) vectors_tool="$2" ;; --specular-tb) specular_tb="$2" ;;
        --counter) counter="$2" ;;
        --stimulus) stimulus="$2" ;;
      esac
      shift 2 ;;
    -*) fail_args "unknown option '$1'" ;;
    *) args+=("$1"); shift ;;
  esac
done
[[ ${#args[@]} -ge 1 && ${#args[@]} -le 2 ]] || fail_args "usage: energy.sh [options] OUT_DIR [ROM_DIR]"
number='^[0-9]+([.][0-9]+)?$'
[[ "$period" =~ $number ]] && (( $(echo "$period >= 1 && $period <= 1000" | bc) )) \
  || fail_args "--period '$period' is not a period in ns from 1 to 1000"
[[ -z "$t_sim" ]] || { [[ "$t_sim" =~ $number ]] && (( $(echo "$t_sim > 0 && $t_sim <= 1000" | bc) )); } \
  || fail_args "--t-sim '$t_sim' is not a period in ns above 0 and at most 1000"
[[ -z "$random" || ( "$random" =~ ^[0-9]{1,4}$ && 10#$random -le 5000 ) ]] || fail_args "--random '$random' is not a count from 0 to 5000"
[[ -z "$stimulus" || -f "$stimulus" ]] || fail_args "--stimulus '$stimulus' is no file"
[[ -z "$stimulus" ]] || stimulus="$(cd "$(dirname "$stimulus")" && pwd)/$(basename "$stimulus")"
out="${args[0]}"
rom_dir="${args[1]:-$root/build/rtl/rom/default}"
top_dir="$flows/designs/$top"
variant=0
if [[ ! -d "$top_dir" && "$top" == specular_* && -f "$root/rtl/design_space/$top.v" ]]; then
  top_dir="$flows/designs/variant"; variant=1
fi
[[ -f "$top_dir/constraints.tcl" ]] || fail_args "top '$top' has no flow pieces (scripts/flows/designs/$top/) and is no design variant"
[[ -x "$vectors_tool" ]] || fail_args "specular_variant_vectors not found at '$vectors_tool' (cmake --build build --target specular_variant_vectors, or --vectors-tool PATH)"
# the top's stream length and T_sim (scripts/flows/energy/energy_streams.tsv)
read -r stream_random stream_t_sim < <(awk -v t="$top" '$1 == t { print $2, $3 }' "$flows/energy/energy_streams.tsv") || true
[[ -n "$random" ]] || random=${stream_random:-262}
mkdir -p "$out"
out="$(cd "$out" && pwd)"
if [[ -z "$netlist_dir" ]]; then
  netlist_dir="$out/silicon"
  bash "$flows/synthesis/silicon.sh" --top "$top" --no-gatesim --vectors-tool "$vectors_tool" "$netlist_dir" "$rom_dir" > "$out/silicon.log" 2>&1 \
    || { echo "energy.sh: silicon.sh failed (see $out/silicon.log)" >&2; exit 1; }
fi
netlist_dir="$(cd "$netlist_dir" && pwd)"
for f in mapped.v device.sdf rom_macros.lib rom_model.json; do
  [[ -f "$netlist_dir/$f" ]] || fail_args "'$netlist_dir/$f' not found: run scripts/flows/synthesis/silicon.sh first"
done
summary="$netlist_dir/silicon_summary.json"
if [[ -z "$t_sim" && -f "$summary" ]]; then
  t_sim=$(/usr/bin/python3 -c "import json,sys; v=json.load(open(sys.argv[1])).get('t_sim_ns'); print(v if v else '')" "$summary")
fi
[[ -n "$t_sim" ]] || t_sim=${stream_t_sim:-}
if [[ -z "$cpr" && -f "$summary" ]]; then
  cpr=$(/usr/bin/python3 -c "import json,sys; v=json.load(open(sys.argv[1])).get('clocks_per_result_streamed'); print(v if v else '')" "$summary")
fi

# ---- the vectors and the result strobe of the top -----------------------------------
# One stream for every design: 18 edge cases and RANDOM random operands. A device top
# takes its operands as a stimulus (its testbench's own expected values, the patent's
# policy), with no operation aborted by reset (RESET_EVERY), so that every operation is
# a result, as in a variant's testbench.
ENERGY_RESULTS=()
ENERGY_LEAD_RESULTS=0
ENERGY_INSTEAD=""
ENERGY_PER_RESULT=()
source "$top_dir/gatesim.conf"   # ENERGY_RESULTS: how a result shows (per top); results before the stream's
random_from=$((18 + ENERGY_LEAD_RESULTS))
[[ ${#ENERGY_RESULTS[@]} -gt 0 ]] || fail_args "top '$top' names no result strobe (ENERGY_RESULTS in its gatesim.conf)${ENERGY_INSTEAD:+; $ENERGY_INSTEAD}"
strobe=("${ENERGY_RESULTS[@]}")
[[ $per_result -eq 0 || ${#ENERGY_PER_RESULT[@]} -eq 0 ]] || strobe=("${ENERGY_PER_RESULT[@]}")
[[ $variant -eq 0 || -z "$stimulus" ]] || fail_args "--stimulus is for a device top; a variant replays its model's vectors"
if [[ $variant -eq 1 ]]; then
  vec_opts=(--random "$random")
  [[ -n "$cpr" ]] || cpr=1
else
  if [[ -n "$stimulus" ]]; then
    [[ "$stimulus" -ef "$out/stream.txt" ]] || cp "$stimulus" "$out/stream.txt"
    random_from=$ENERGY_LEAD_RESULTS
  else
    "$vectors_tool" patent --count $((18 + random)) --seed 1 --out "$out/stream.txt" > "$out/stream.log" 2>&1 \
      || { echo "energy.sh: writing the common stream failed; see $out/stream.log" >&2; exit 1; }
  fi
  vec_opts=(--stimulus "$out/stream.txt" --tb-param RESET_EVERY=1000000)
  [[ -n "$cpr" ]] || cpr=2
fi

# ---- slews: OpenSTA at the period, the top's own SDC -------------------------------
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
  || { echo "energy.sh: OpenSTA's slews failed; see $out/slews.log" >&2; exit 1; }

# ---- the replays and their toggles -------------------------------------------------
counter_opts=()
if [[ -x "$counter" ]]; then
  counter_opts=(--counter "$counter")
else
  echo "energy.sh: no toggle counter at '$counter' (cmake --build build --target specular_vcd_activity): energy.py's own reader counts, 10-20 times slower" >&2
fi
# after layout (scripts/flows/layout/layout.sh's postlayout/): each net's routed wire capacitance too
wire_opts=()
[[ ! -f "$netlist_dir/wire_cap.txt" ]] || wire_opts=(--wire-cap "$netlist_dir/wire_cap.txt")
modes=(sdf)
[[ $zero -eq 0 ]] || modes+=(zero)
for mode in "${modes[@]}"; do
  extra=()
  [[ $mode == sdf ]] || extra=(--zero-delay)
  started=$SECONDS
  if ! bash "$flows/gatelevel/gatesim.sh" --top "$top" --netlist-dir "$netlist_dir" --quiet \
       --vectors-tool "$vectors_tool" --specular-tb "$specular_tb" "${vec_opts[@]}" "${extra[@]}" \
       --vcd "$out/$mode/activity.vcd" "$period" "$out/$mode" "$rom_dir" > "$out/$mode.log" 2>&1; then
    echo "energy.sh: the $mode replay failed at $period ns; see $out/$mode.log" >&2
    exit 1
  fi
  echo "sim_s $((SECONDS - started))" > "$out/$mode/time.txt"
  started=$SECONDS
  /usr/bin/python3 "$flows/energy/energy.py" compute --lib "$OSU018/osu018_stdcells.lib" \
    --lib "$netlist_dir/rom_macros.lib" --netlist "$netlist_dir/mapped.v" --top "$top" \
    --tb-top "$TB_TOP" --vcd "$out/$mode/activity.vcd" --slews "$out/slews.txt" \
    --rom-model "$netlist_dir/rom_model.json" "${strobe[@]}" \
    "${counter_opts[@]}" "${wire_opts[@]}" ${wire_opts:+--wire-out "$out/wire_switching_$mode.txt"} --toggles-out "$out/toggles_$mode.txt" --out "$out/energy_$mode.json" \
    || { echo "energy.sh: counting the $mode activity failed" >&2; exit 1; }
  echo "count_s $((SECONDS - started))" >> "$out/$mode/time.txt"
  echo "vcd_bytes $(stat -c %s "$out/$mode/activity.vcd")" >> "$out/$mode/time.txt"
  [[ $keep_vcd -eq 1 ]] || rm -f "$out/$mode/activity.vcd"
done
per_opts=()
[[ $per_result -eq 0 ]] || per_opts=(--per-result-out "$out/per_result.tsv")
/usr/bin/python3 "$flows/energy/energy.py" report --top "$top" --dir "$out" --period "$period" \
  ${t_sim:+--t-sim "$t_sim"} --clocks-per-result "$cpr" --random-from "$random_from" \
  --lead-results "$ENERGY_LEAD_RESULTS" "${per_opts[@]}" \
  || { echo "energy.sh: the report failed" >&2; exit 1; }
echo "energy.sh: $out/energy.md, $out/energy.json"
