#!/usr/bin/env bash
# Gate-level timing simulation of the mapped device (scripts/silicon.sh): Icarus runs the
# netlist with the OSU 0.18 um cells' Verilog models, the SDF OpenSTA wrote
# ($sdf_annotate) and the ROM macros as behavioural models with their Liberty access
# time, and replays the self-checking vectors of rtl/tb/specular_device_tb.v at a clock
# period. docs/silicon.md explains it.
#
#   scripts/gatesim.sh [options] PERIOD_NS OUT_DIR [ROM_DIR]
#   scripts/gatesim.sh [options] --bisect T_STA_NS OUT_DIR [ROM_DIR]
#
#   --top NAME          top module (default specular_device); its testbench settings are
#                       scripts/silicon/NAME/gatesim.conf
#   --netlist-dir DIR   the output folder of scripts/silicon.sh (mapped.v, device.sdf,
#                       rom_macros_sim.v); default: run silicon.sh --no-gatesim into
#                       OUT_DIR/silicon first
#   --policies LIST     constants/normalisation/saturation triples, comma separated, or
#                       `all` (every combination the device accepts); default
#                       patent/patent/clamp
#   --random N          random operations per policy after the edge-case groups (default 8)
#   --groups N          edge-case groups of 10 operations with n, R, G, B unchanged (back
#                       to back at 2 T), 1-8 (default 2)
#   --specular-tb PATH  the testbench that writes the expected values (default
#                       build/testbench/specular_tb)
#   --bisect T_STA      find T_sim: the smallest period (to 0.1 ns) at which every vector
#                       passes, searched from T_STA/4 to 2 T_STA; writes OUT_DIR/tsim.txt
# ROM_DIR holds rom5.hex, rom38.hex, pins.hex (default build/rtl/rom/default).
# Exit status: 0 every vector matches (--bisect: T_sim found), 1 the first mismatch (named
# with the vector, register or pin, got and want) or a tool failed, 2 bad arguments or a
# missing package.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"

usage() { sed -n '2,30p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
fail_args() { echo "gatesim.sh: $1 (see --help)" >&2; exit 2; }

top=specular_device
netlist_dir=""
policies="patent/patent/clamp"
random=8
groups=2
specular_tb="$root/build/testbench/specular_tb"
bisect=""
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --top|--netlist-dir|--policies|--random|--groups|--specular-tb|--bisect)
      [[ $# -ge 2 ]] || fail_args "$1 needs a value"
      case "$1" in
        --top) top="$2" ;; --netlist-dir) netlist_dir="$2" ;; --policies) policies="$2" ;;
        --random) random="$2" ;; --groups) groups="$2" ;; --specular-tb) specular_tb="$2" ;;
        --bisect) bisect="$2" ;;
      esac
      shift 2 ;;
    -*) fail_args "unknown option '$1'" ;;
    *) args+=("$1"); shift ;;
  esac
done
number='^[0-9]+([.][0-9]+)?$'
if [[ -n "$bisect" ]]; then
  [[ ${#args[@]} -ge 1 && ${#args[@]} -le 2 ]] || fail_args "usage: gatesim.sh [options] --bisect T_STA_NS OUT_DIR [ROM_DIR]"
  [[ "$bisect" =~ $number ]] && (( $(echo "$bisect > 0" | bc) )) || fail_args "T_STA '$bisect' is not a period in ns above 0"
  out="${args[0]}"; rom_dir="${args[1]:-$root/build/rtl/rom/default}"
else
  [[ ${#args[@]} -ge 2 && ${#args[@]} -le 3 ]] || fail_args "usage: gatesim.sh [options] PERIOD_NS OUT_DIR [ROM_DIR]"
  period="${args[0]}"
  [[ "$period" =~ $number ]] && (( $(echo "$period >= 0.1 && $period <= 1000" | bc) )) \
    || fail_args "PERIOD_NS '$period' is not a period in ns from 0.1 to 1000"
  out="${args[1]}"; rom_dir="${args[2]:-$root/build/rtl/rom/default}"
fi
[[ "$random" =~ ^[0-9]+$ && $random -le 2000 ]] || fail_args "--random '$random' is not a count from 0 to 2000"
[[ "$groups" =~ ^[1-8]$ ]] || fail_args "--groups '$groups' is not a count from 1 to 8"
conf="$here/silicon/$top/gatesim.conf"
[[ -f "$conf" ]] || fail_args "top '$top' has no gate-level settings (scripts/silicon/$top/gatesim.conf)"

need() {
  if [[ "$1" == /* ]]; then [[ -e "$1" ]] && return 0; else command -v "$1" >/dev/null && return 0; fi
  echo "gatesim.sh: $1 not found: sudo apt-get install $2 (or bash scripts/setup.sh)" >&2
  exit 2
}
need "$OSU018/osu018_stdcells.v" qflow-tech-osu018
need iverilog iverilog
need vvp iverilog
need bc bc
need /usr/bin/python3 python3
[[ -x "$specular_tb" ]] || fail_args "specular_tb not found at '$specular_tb' (cmake --build build --target specular_tb, or --specular-tb PATH)"
for image in rom5.hex rom38.hex pins.hex; do
  [[ -f "$rom_dir/$image" ]] || fail_args "'$rom_dir/$image' not found: build the ROM images (cmake --build build --target specular_rom_images) or name their folder"
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rom_dir="$(cd "$rom_dir" && pwd)"
if [[ -z "$netlist_dir" ]]; then
  netlist_dir="$out/silicon"
  bash "$here/silicon.sh" --top "$top" --no-gatesim "$netlist_dir" "$rom_dir" >/dev/null \
    || { echo "gatesim.sh: silicon.sh failed (see $netlist_dir)" >&2; exit 1; }
fi
netlist_dir="$(cd "$netlist_dir" && pwd)"
for f in mapped.v device.sdf rom_macros_sim.v; do
  [[ -f "$netlist_dir/$f" ]] || fail_args "'$netlist_dir/$f' not found: run scripts/silicon.sh first"
done
# shellcheck source=/dev/null
source "$conf"   # TB_FILE, TB_TOP, TB_PARAMS (per top)

# ---- the SDF Icarus can read, the ROM models at their SDF access time ---------------
/usr/bin/python3 "$here/silicon/gatesim_sdf.py" "$netlist_dir" "$out" > "$out/sdf.log" 2>&1 \
  || { echo "gatesim.sh: preparing the SDF failed; see $out/sdf.log" >&2; exit 1; }

# ---- vectors: specular_tb writes the expected values, one file per policy ----------
/usr/bin/python3 "$here/silicon/gatesim_vectors.py" "$specular_tb" "$out" "$policies" "$groups" "$random" \
  > "$out/vectors.log" 2>&1 || { echo "gatesim.sh: writing the vectors failed; see $out/vectors.log" >&2; exit 1; }

# run_at PERIOD: every policy's vectors at that period; 0 all pass, 1 a mismatch.
run_at() {
  local T="$1" dir="$out/T$1" status=0
  mkdir -p "$dir"
  while read -r name constants normalisation literal vectors; do
    if ! iverilog -g2005 -gspecify -o "$dir/$name.vvp" -s "$TB_TOP" -DGATE_LEVEL \
         "-DSDF_FILE=\"$out/icarus.sdf\"" \
         "-P$TB_TOP.T=$T" "-P$TB_TOP.VECTORS=\"$vectors\"" \
         "-P$TB_TOP.PINS_IMAGE=\"$rom_dir/pins.hex\"" \
         "-P$TB_TOP.LITERAL=$literal" "-P$TB_TOP.CONSTANTS=$constants" \
         "-P$TB_TOP.NORMALISATION=$normalisation" ${TB_PARAMS[@]/#/-P$TB_TOP.} \
         "$OSU018/osu018_stdcells.v" "$out/rom_macros_gatesim.v" "$out/mapped_icarus.v" \
         "$TB_FILE" > "$dir/$name.compile.log" 2>&1; then
      echo "gatesim.sh: iverilog failed; see $dir/$name.compile.log" >&2
      return 2
    fi
    if ! (cd "$rom_dir" && vvp -n "$dir/$name.vvp") > "$dir/$name.log" 2>&1 \
       || ! grep -q "PASS" "$dir/$name.log"; then
      echo "gatesim.sh: T = $T ns, policy $name: $(grep -m1 -E 'MISMATCH|fatal|FATAL|specular_device_tb:' "$dir/$name.log" || echo 'no result')"
      status=1
      break
    fi
    echo "gatesim.sh: T = $T ns, policy $name: $(grep -m1 PASS "$dir/$name.log")"
  done < "$out/policies.txt"
  return $status
}

if [[ -z "$bisect" ]]; then
  set +e
  run_at "$period"
  status=$?
  set -e
  [[ $status -le 1 ]] || exit 1
  exit $status
fi

# ---- T_sim: bisection to 0.1 ns between T_sta/4 (must fail) and 2 T_sta (must pass) ----
lo=$(printf '%.1f' "$(echo "$bisect / 4" | bc -l)")
hi=$(printf '%.1f' "$(echo "$bisect * 2" | bc -l)")
set +e
run_at "$hi"; s=$?
[[ $s -eq 0 ]] || { echo "gatesim.sh: fails even at 2 T_sta = $hi ns" >&2; exit 1; }
run_at "$lo"; s=$?
[[ $s -eq 1 ]] || { echo "gatesim.sh: passes at T_sta/4 = $lo ns: not sensitive to timing" >&2; exit 1; }
while (( $(echo "$hi - $lo > 0.1 + 0.0001" | bc) )); do
  mid=$(printf '%.1f' "$(echo "($lo + $hi) / 2" | bc -l)")
  run_at "$mid"; s=$?
  [[ $s -le 1 ]] || exit 1
  if [[ $s -eq 0 ]]; then hi=$mid; else lo=$mid; fi
done
set -e
{
  echo "t_sim_ns $hi"
  echo "fails_at_ns $lo"
  echo "first_failure $(grep -h -m1 -E 'MISMATCH|fatal' "$out/T$lo"/*.log | head -1)"
  echo "policies $policies"
  echo "vectors_per_policy $(( groups * 10 + random ))"
} > "$out/tsim.txt"
echo "gatesim.sh: T_sim = $hi ns (fails at $lo ns)"
