#!/usr/bin/env bash
# Gate-level timing simulation of the mapped device (scripts/flows/synthesis/silicon.sh): Icarus runs the
# netlist with the OSU 0.18 um cells' Verilog models, the SDF OpenSTA wrote
# ($sdf_annotate) and the ROM macros as behavioural models with their Liberty access
# time, and replays the self-checking vectors of rtl/tb/specular_device_tb.v at a clock
# period. docs/silicon.md explains it.
#
#   scripts/flows/gatelevel/gatesim.sh [options] PERIOD_NS OUT_DIR [ROM_DIR]
#   scripts/flows/gatelevel/gatesim.sh [options] --bisect T_STA_NS OUT_DIR [ROM_DIR]
#   scripts/flows/gatelevel/gatesim.sh [options] --hazards T_SIM_NS OUT_DIR [ROM_DIR]
#   scripts/flows/gatelevel/gatesim.sh --merge [--output F|DIR] [--partial F] PARTIAL...
#
#   --top NAME          top module (default specular_device); its testbench settings are
#                       scripts/flows/designs/NAME/gatesim.conf, or for a design variant's top
#                       without a folder (rtl/design_space/specular_NAME.v) scripts/flows/designs/variant/'s:
#                       rtl/tb/specular_variant_tb.v, vectors from the variant's C++ model
#                       (specular_variant_vectors NAME --count 18+R --seed 1, R = --random,
#                       here 10 by default: 28 operations; --policies and --groups unused)
#   --vectors-tool PATH specular_variant_vectors (default
#                       build/tools/variant_vectors/specular_variant_vectors), for a variant's top
#   --netlist-dir DIR   the output folder of scripts/flows/synthesis/silicon.sh (mapped.v, device.sdf,
#                       rom_macros_sim.v); default: run silicon.sh --no-gatesim into
#                       OUT_DIR/silicon first
#   --policies LIST     constants/normalisation/saturation triples, comma separated, or
#                       `all` (every combination the device accepts); default
#                       patent/patent/clamp
#   --random N          random operations per policy after the edge-case groups (default 8,
#                       at most 5000)
#   --groups N          edge-case groups of 10 operations with n, R, G, B unchanged (back
#                       to back at 2 T), 1-8 (default 2)
#   --stimulus FILE     (a device top) these operations instead of the groups and random
#                       ones: lines `cos n r g b` in hex, specular_variant_vectors' first
#                       five columns (scripts/flows/energy/energy.sh's common stream, issue 36)
#   --specular-tb PATH  the testbench that writes the expected values (default
#                       build/testbench/specular_tb)
#   --shard I/N         run shard I (0-based) of N only (issue 25, docs/farm.md): a period
#                       run and --bisect take the policies k with k mod N = I (in the
#                       order of OUT_DIR/policies_all.txt; each shard bisects its own),
#                       --hazards the units u (2 periods x 4 groups of 4 start offsets,
#                       u = 4 p + g) with u mod N = I
#   --partial FILE      write this run's partial result (JSON: settings and digests of
#                       netlist, SDF, ROMs and vectors, commit, shard, per policy verdict,
#                       vectors and first mismatch / T_sim / hazard sweep, timing)
#   --merge PARTIAL...  merge a complete set of shards' partials into the unsharded run's
#                       answer (exit 0 PASS, 1 FAIL; 2 and nothing written for a missing,
#                       repeated or mismatched shard, named); --output F writes the text
#                       (hazards: the folder of hazards.md/.json), --partial F the merged
#                       partial (scripts/flows/gatelevel/gatesim_partial.py)
#   --vcd FILE          (a period run, one policy) also write the netlist's own scopes'
#                       value changes into FILE (scripts/flows/energy/energy.py dumper): the
#                       activity of scripts/flows/energy/energy.sh (issue 36)
#   --zero-delay        no SDF, no cell delays (-gspecify off), ROM macros without their
#                       access time: the zero-delay replay of the same netlist, whose
#                       toggles the glitch share is measured against (scripts/flows/energy/energy.sh)
#   --tb-param NAME=V   one more testbench parameter after the top's (energy.sh:
#                       RESET_EVERY=1000000, no operation aborted by reset)
#   --quiet             no progress lines (drawn on standard error only when it is a
#                       terminal: periods tried or policies' vectors run, the total,
#                       rate and time left, by specular_progress beside specular_tb)
#   --bisect T_STA      find T_sim: the smallest period (to 0.1 ns) at which every vector
#                       passes, searched from T_STA/4 to 2 T_STA; writes OUT_DIR/tsim.txt
#   --hazards T_SIM     Fig. 2's hazards at T_SIM and 2 T_SIM: start (27) swept across a
#                       whole period (16 offsets from -T/2 to 7T/16 around its rising
#                       clock edge, and 0.499 T; each pass/fail boundary refined to
#                       0.1 ns), the reset pulse of flip-flop 41 against the DFFSR's
#                       recovery/removal, select 36's delay, register 9's settling;
#                       writes OUT_DIR/hazards.md and OUT_DIR/hazards.json (vectors
#                       here by default: --groups 1 --random 4, 14 operations; about
#                       10 minutes)
# ROM_DIR holds rom5.hex, rom38.hex, pins.hex (default build/rtl/rom/default).
# Exit status: 0 every vector matches (--bisect: T_sim found; --hazards: the tables
# written, whatever the sweep found), 1 the first mismatch (named
# with the vector, register or pin, got and want) or a tool failed, 2 bad arguments or a
# missing package.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"

if [[ ${1:-} == --merge ]]; then
  shift
  exec /usr/bin/python3 "$flows/gatelevel/gatesim_partial.py" merge "$@"
fi

usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'; }
fail_args() { echo "gatesim.sh: $1 (see --help)" >&2; exit 2; }

top=specular_device
netlist_dir=""
policies="patent/patent/clamp"
random=8
groups=2
specular_tb="$root/build/testbench/specular_tb"
vectors_tool="$root/build/tools/variant_vectors/specular_variant_vectors"
bisect=""
hazards=""
random_set=0
groups_set=0
quiet=0
vcd=""
stimulus=""
zero_delay=0
tb_params_extra=()
shard_index=0
shard_count=1
partial=""
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --quiet) quiet=1; shift ;;
    --zero-delay) zero_delay=1; shift ;;
    --top|--vcd|--tb-param|--netlist-dir|--policies|--random|--groups|--specular-tb|--bisect|--hazards|--shard|--partial|--vectors-tool|--stimulus)
      [[ $# -ge 2 ]] || fail_args "$1 needs a value"
      case "$1" in
        --top) top="$2" ;; --netlist-dir) netlist_dir="$2" ;; --policies) policies="$2" ;;
        --random) random="$2"; random_set=1 ;; --groups) groups="$2"; groups_set=1 ;;
        --specular-tb) specular_tb="$2" ;; --bisect) bisect="$2" ;; --hazards) hazards="$2" ;;
        --vectors-tool) vectors_tool="$2" ;;
        --partial) partial="$2" ;;
        --vcd) vcd="$2" ;;
        --stimulus) stimulus="$2" ;;
        --tb-param) [[ "$2" =~ ^[A-Z_][A-Z0-9_]*=[0-9.]+$ ]] || fail_args "--tb-param '$2': expected NAME=NUMBER"
                    tb_params_extra+=("$2") ;;
        --shard)
          [[ "$2" =~ ^([0-9]{1,4})/([0-9]{1,4})$ ]] && (( BASH_REMATCH[2] >= 1 && BASH_REMATCH[2] <= 1000 \
            && 10#${BASH_REMATCH[1]} < 10#${BASH_REMATCH[2]} )) \
            || fail_args "--shard '$2': expected I/N, integers with 0 <= I < N and 1 <= N <= 1000"
          shard_index=$((10#${BASH_REMATCH[1]})); shard_count=$((10#${BASH_REMATCH[2]})) ;;
      esac
      shift 2 ;;
    -*) fail_args "unknown option '$1'" ;;
    *) args+=("$1"); shift ;;
  esac
done
number='^[0-9]+([.][0-9]+)?$'
[[ -z "$bisect" || -z "$hazards" ]] || fail_args "--bisect and --hazards exclude each other"
if [[ -n "$hazards" ]]; then
  [[ ${#args[@]} -ge 1 && ${#args[@]} -le 2 ]] || fail_args "usage: gatesim.sh [options] --hazards T_SIM_NS OUT_DIR [ROM_DIR]"
  [[ "$hazards" =~ $number ]] && (( $(echo "$hazards >= 0.1 && $hazards <= 500" | bc) )) \
    || fail_args "T_SIM '$hazards' is not a period in ns from 0.1 to 500"
  out="${args[0]}"; rom_dir="${args[1]:-$root/build/rtl/rom/default}"
  [[ $random_set -eq 1 ]] || random=4
  [[ $groups_set -eq 1 ]] || groups=1
elif [[ -n "$bisect" ]]; then
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
[[ "$random" =~ ^[0-9]+$ && $random -le 5000 ]] || fail_args "--random '$random' is not a count from 0 to 5000"
[[ -z "$stimulus" || -f "$stimulus" ]] || fail_args "--stimulus '$stimulus' is no file"
[[ "$groups" =~ ^[1-8]$ ]] || fail_args "--groups '$groups' is not a count from 1 to 8"
conf="$flows/designs/$top/gatesim.conf"
if [[ ! -d "$flows/designs/$top" && "$top" == specular_* && -f "$root/rtl/design_space/$top.v" ]]; then
  conf="$flows/designs/variant/gatesim.conf"   # a design variant's top: the generic settings
fi
[[ -f "$conf" ]] || fail_args "top '$top' has no gate-level settings (scripts/flows/designs/$top/gatesim.conf)"

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
TB_DEFINES=()
VARIANT_VECTORS=0
# shellcheck source=/dev/null
source "$conf"   # TB_FILE, TB_TOP, TB_PARAMS, TB_DEFINES, VARIANT_VECTORS (per top)
TB_PARAMS+=("${tb_params_extra[@]}")
if [[ $VARIANT_VECTORS -eq 1 ]]; then
  [[ -z "$stimulus" ]] || fail_args "--stimulus is for a device top; a variant's top replays its model's vectors"
  [[ -x "$vectors_tool" ]] || fail_args "specular_variant_vectors not found at '$vectors_tool' (cmake --build build --target specular_variant_vectors, or --vectors-tool PATH)"
  [[ $random_set -eq 1 ]] || random=10
else
[[ -x "$specular_tb" ]] || fail_args "specular_tb not found at '$specular_tb' (cmake --build build --target specular_tb, or --specular-tb PATH)"
for image in rom5.hex rom38.hex; do
  [[ -f "$rom_dir/$image" ]] || fail_args "'$rom_dir/$image' not found: build the ROM images (cmake --build build --target specular_rom_images) or name their folder"
done
fi
# every top reads pins.hex; a variant's other images are its own (exp2.hex, recip.hex, ...)
[[ -f "$rom_dir/pins.hex" ]] || fail_args "ROM_DIR '$rom_dir' holds no pins.hex: build the ROM images (cmake --build build --target specular_rom_images) or name their folder"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rom_dir="$(cd "$rom_dir" && pwd)"
if [[ -z "$netlist_dir" ]]; then
  netlist_dir="$out/silicon"
  bash "$flows/synthesis/silicon.sh" --top "$top" --no-gatesim "$netlist_dir" "$rom_dir" >/dev/null \
    || { echo "gatesim.sh: silicon.sh failed (see $netlist_dir)" >&2; exit 1; }
fi
netlist_dir="$(cd "$netlist_dir" && pwd)"
for f in mapped.v device.sdf rom_macros_sim.v; do
  [[ -f "$netlist_dir/$f" ]] || fail_args "'$netlist_dir/$f' not found: run scripts/flows/synthesis/silicon.sh first"
done

# ---- the SDF Icarus can read, the ROM models at their SDF access time ---------------
/usr/bin/python3 "$flows/gatelevel/gatesim_sdf.py" "$netlist_dir" "$out" > "$out/sdf.log" 2>&1 \
  || { echo "gatesim.sh: preparing the SDF failed; see $out/sdf.log" >&2; exit 1; }
# ---- energy (scripts/flows/energy/energy.sh): the VCD of the netlist's scopes; the zero-delay models
extra_tops=()
if [[ -n "$vcd" ]]; then
  [[ -z "$bisect" && -z "$hazards" ]] || fail_args "--vcd is for a period run"
  mkdir -p "$(dirname "$vcd")"
  vcd="$(cd "$(dirname "$vcd")" && pwd)/$(basename "$vcd")"
  /usr/bin/python3 "$flows/energy/energy.py" dumper "$out/mapped_icarus.v" "$top" "$TB_TOP" "$vcd" \
    "$out/energy_dump.v" || { echo "gatesim.sh: writing the VCD dumper failed" >&2; exit 1; }
  extra_tops=(-s energy_dump "$out/energy_dump.v")
fi
specify=-gspecify
if [[ $zero_delay -eq 1 ]]; then
  specify=-gno-specify
  sed -E 's/(parameter real ACCESS = )[0-9.]+/\10.0/' "$out/rom_macros_gatesim.v" > "$out/rom_macros_zero.v"
  mv "$out/rom_macros_zero.v" "$out/rom_macros_gatesim.v"
fi

# ---- vectors: specular_tb writes the expected values, one file per policy ----------
if [[ $VARIANT_VECTORS -eq 1 ]]; then
  # a design variant: its C++ model's expected values, one file, no policy
  "$vectors_tool" "${top#specular_}" --count $((18 + random)) --seed 1 --out "$out/vectors.txt" \
    > "$out/vectors.log" 2>&1 || { echo "gatesim.sh: writing the vectors failed; see $out/vectors.log" >&2; exit 1; }
  echo "variant 0 0 0 $out/vectors.txt" > "$out/policies.txt"
else
stimulus_args=()
[[ -z "$stimulus" ]] || { stimulus_args=("$(cd "$(dirname "$stimulus")" && pwd)/$(basename "$stimulus")"); random=0; }
/usr/bin/python3 "$flows/gatelevel/gatesim_vectors.py" "$specular_tb" "$out" "$policies" "$groups" "$random" \
  "${stimulus_args[@]}" > "$out/vectors.log" 2>&1 || { echo "gatesim.sh: writing the vectors failed; see $out/vectors.log" >&2; exit 1; }
fi
# The shard's policies (a period run, --bisect): the k-th of the run's, k mod N = I.
cp "$out/policies.txt" "$out/policies_all.txt"
if [[ -z "$hazards" ]]; then
  awk -v i="$shard_index" -v n="$shard_count" 'NF && (NR - 1) % n == i' "$out/policies_all.txt" > "$out/policies.txt"
fi
: > "$out/results.tsv"
run_started=$SECONDS
# The commit of the run (a partial names it; read at the start: the code that ran).
run_commit=$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)
[[ -z $(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null) ]] || run_commit+=-dirty
mode=period; [[ -z "$bisect" ]] || mode=bisect; [[ -z "$hazards" ]] || mode=hazards
# write_partial: OUT_DIR/partial.json (and --partial FILE) from this run's results.
write_partial() {
  {
    echo "mode=$mode"; echo "top=$top"; echo "period=${period:-${bisect:-$hazards}}"
    echo "policies=$policies"; echo "groups=$groups"; echo "random=$random"
    echo "netlist_dir=$netlist_dir"; echo "rom_dir=$rom_dir"; echo "conf=$conf"; echo "root=$root"
    echo "shard_index=$shard_index"; echo "shard_count=$shard_count"; echo "commit=$run_commit"
    echo "wall_seconds=$((SECONDS - run_started))"; echo "hazard_units=${hazard_units:-}"
  } > "$out/partial_info.txt"
  times > "$out/times.txt"  # this shell's and its children's CPU (a builtin: not in a subshell)
  echo "cpu=$(tr '\n' ' ' < "$out/times.txt")" >> "$out/partial_info.txt"
  /usr/bin/python3 "$flows/gatelevel/gatesim_partial.py" write "$out" "$out/partial.json" \
    || { echo "gatesim.sh: writing the partial result failed" >&2; exit 1; }
  [[ -z "$partial" ]] || cp "$out/partial.json" "$partial"
}

# compile_tb T VVP LOG [PROBE_TOP PROBE_FILE]: the testbench at period T for the policy
# in $constants $normalisation $literal $vectors (the caller's), against the cell models,
# the ROM macros and the mapped netlist with the SDF; with the hazard probe if given.
compile_tb() {
  local T="$1" vvp="$2" log="$3" tops=(-s "$TB_TOP") files=()
  if [[ $# -ge 5 ]]; then tops+=(-s "$4"); files+=("$5"); fi
  if [[ ${#extra_tops[@]} -gt 0 ]]; then tops+=("${extra_tops[0]}" "${extra_tops[1]}"); files+=("${extra_tops[2]}"); fi
  iverilog -g2005 $specify -o "$vvp" "${tops[@]}" -DGATE_LEVEL ${TB_DEFINES[@]/#/-D} \
    -I "$(dirname "$TB_FILE")" \
    "-DSDF_FILE=\"$out/icarus.sdf\"" \
    "-P$TB_TOP.T=$T" "-P$TB_TOP.VECTORS=\"$vectors\"" \
    "-P$TB_TOP.PINS_IMAGE=\"$rom_dir/pins.hex\"" \
    "-P$TB_TOP.LITERAL=$literal" "-P$TB_TOP.CONSTANTS=$constants" \
    "-P$TB_TOP.NORMALISATION=$normalisation" ${TB_PARAMS[@]/#/-P$TB_TOP.} \
    "$OSU018/osu018_stdcells.v" "$out/rom_macros_gatesim.v" "$out/mapped_icarus.v" \
    "$TB_FILE" "${files[@]}" > "$log" 2>&1
}

# ---- progress (issue 27): specular_tb's progress line (run_support/progress.h) through
# the specular_progress tool beside it, one line per period tried or per policy's
# vectors, on standard error only when it is a terminal and --quiet is not given.
progress_tool="$(dirname "$specular_tb")/specular_progress"
progress_started=$SECONDS
progress() {  # DONE TOTAL UNIT
  [[ $quiet -eq 0 && -t 2 && -x "$progress_tool" ]] || return 0
  "$progress_tool" "$1" "$2" "$((SECONDS - progress_started))" "$3" gatesim >&2 || true
}
policy_count=$(wc -l < "$out/policies.txt")
policies_done=0

# run_at PERIOD: every policy's vectors at that period; 0 all pass, 1 a mismatch. A period
# run goes on after a mismatch (every policy's verdict in results.tsv); the bisection
# stops at the first (failed_policy names it).
failed_policy=""
run_at() {
  local T="$1" dir="$out/T$1" status=0 started
  mkdir -p "$dir"
  failed_policy=""
  while read -r name constants normalisation literal vectors; do
    started=$SECONDS
    if ! compile_tb "$T" "$dir/$name.vvp" "$dir/$name.compile.log"; then
      echo "gatesim.sh: iverilog failed; see $dir/$name.compile.log" >&2
      return 2
    fi
    if ! (cd "$rom_dir" && vvp -n "$dir/$name.vvp") > "$dir/$name.log" 2>&1 \
       || ! grep -q "PASS" "$dir/$name.log"; then
      first=$(grep -m1 -E 'MISMATCH|fatal|FATAL|specular_device_tb:' "$dir/$name.log" || echo 'no result')
      echo "gatesim.sh: T = $T ns, policy $name: $first"
      printf '%s\t%s\tFAIL\t%s\t%s\n' "$T" "$name" "$((SECONDS - started))" "$first" >> "$out/results.tsv"
      status=1
      failed_policy=$name
      [[ -n "$bisect" ]] || continue
      break
    fi
    echo "gatesim.sh: T = $T ns, policy $name: $(grep -m1 PASS "$dir/$name.log")"
    printf '%s\t%s\tPASS\t%s\t\n' "$T" "$name" "$((SECONDS - started))" >> "$out/results.tsv"
    policies_done=$((policies_done + 1))
    [[ -n "$bisect" ]] || progress "$policies_done" "$policy_count" "policies' vectors"
  done < "$out/policies.txt"
  return $status
}

# ---- Fig. 2's hazards: start swept across a period, the reset pulse of flip-flop 41 ----
# One compile per period (the testbench and the hazard probe of the top), one run per
# start offset (+START_OFFSET, in periods); the probe's last HAZARD line is kept.
# The work is 8 units, u = 4 p + g: period p (T_SIM, 2 T_SIM) and group g of the 16
# offsets (4 g .. 4 g + 3; the last group also 0.499); a unit refines the boundaries
# between its offsets and the one before them (which it runs first when the unit before
# it is another shard's). Units u mod N = I are this shard's; each unit's sweep, boundaries
# and logs go to hazards/unit<u>/, and the merge (gatesim_partial.py, also for the
# unsharded run) gathers them into hazards/T<period>/ and writes the tables.
if [[ -n "$hazards" ]]; then
  [[ -n "${TB_PROBE:-}" && -f "$TB_PROBE" ]] || fail_args "top '$top' has no hazard probe (TB_PROBE in $conf)"
  read -r name constants normalisation literal vectors < "$out/policies.txt"
  hz="$out/hazards"
  mkdir -p "$hz"
  # Offset runs: 17 per period and its boundaries' refinements, about 24 a period
  # (docs/silicon.md): the total is an estimate, raised as runs go past it.
  offsets_done=0; offsets_total=48
  # run_offset T X: 0 pass, 1 fail; the log is $ud/x<X>.log (the unit's folder)
  run_offset() {
    local log="$ud/x$2.log" status=0
    (cd "$rom_dir" && vvp -n "$hz/T$1/tb.vvp" "+START_OFFSET=$2") > "$log" 2>&1
    grep -q "PASS" "$log" || status=1
    offsets_done=$((offsets_done + 1))
    (( offsets_done < offsets_total )) || offsets_total=$((offsets_done + 1))
    progress "$offsets_done" "$offsets_total" "offset runs (total estimated)"
    return $status
  }
  # refine T A B A_OK: bisect the boundary between offsets A and B to 0.1 ns; A keeps its
  # status A_OK, B the other; both ends go to boundaries.txt.
  refine() {
    local T=$1 a=$2 b=$3 a_ok=$4 m m_ok
    while (( $(echo "($b - $a) * $T > 0.1" | bc -l) )); do
      m=$(echo "($a + $b) / 2" | bc -l | xargs printf '%.6f')
      if run_offset "$T" "$m"; then m_ok=1; else m_ok=0; fi
      echo "$m $m_ok" >> "$ud/sweep.txt"
      if [[ "$m_ok" == "$a_ok" ]]; then a=$m; else b=$m; fi
    done
    echo "boundary $a $b $a_ok" >> "$ud/boundaries.txt"
  }
  hazard_units=""
  p=0
  for T in "$hazards" "$(echo "$hazards * 2" | bc -l | xargs printf '%.2f')"; do
    prev_x=""; prev_ok=""; compiled=0
    for g in 0 1 2 3; do
      u=$((4 * p + g))
      if (( u % shard_count != shard_index )); then prev_x=""; prev_ok=""; continue; fi
      hazard_units+=" $u"
      ud="$hz/unit$u"
      mkdir -p "$ud" "$hz/T$T"
      echo "$T" > "$ud/period"
      : > "$ud/sweep.txt"
      if [[ $compiled -eq 0 ]]; then
        compile_tb "$T" "$hz/T$T/tb.vvp" "$hz/T$T/compile.log" "$TB_PROBE_TOP" "$TB_PROBE" \
          || { echo "gatesim.sh: iverilog failed; see $hz/T$T/compile.log" >&2; exit 1; }
        compiled=1
      fi
      if [[ $g -gt 0 && -z "$prev_ok" ]]; then  # the offset before the group: another shard's
        prev_x=$(echo "-0.5 + $((4 * g - 1)) / 16" | bc -l | xargs printf '%.6f')
        if run_offset "$T" "$prev_x"; then prev_ok=1; else prev_ok=0; fi
      fi
      for k in $(seq $((4 * g)) $((4 * g + 3))); do
        x=$(echo "-0.5 + $k / 16" | bc -l | xargs printf '%.6f')
        if run_offset "$T" "$x"; then ok=1; else ok=0; fi
        echo "$x $ok" >> "$ud/sweep.txt"
        echo "gatesim.sh: hazards T = $T ns, start offset $x T: $([[ $ok -eq 1 ]] && echo pass || grep -m1 -E 'MISMATCH|fatal|FATAL|specular_device_tb:' "$ud/x$x.log" || echo 'no result')"
        # A boundary between two offsets: refine it to 0.1 ns.
        [[ -z "$prev_ok" || "$ok" == "$prev_ok" ]] || refine "$T" "$prev_x" "$x" "$prev_ok"
        prev_x=$x; prev_ok=$ok
      done
      # Start just before the falling edge (x -> 0.5, the same phase as the first offset
      # -0.5 of the next edge): refine up to 0.5 when the last offset passes.
      if [[ $g -eq 3 && "$ok" == 1 ]]; then
        x=0.499000
        if run_offset "$T" "$x"; then ok=1; else ok=0; fi
        echo "$x $ok" >> "$ud/sweep.txt"
        [[ "$ok" == 1 ]] || refine "$T" "$prev_x" "$x" 1
      fi
    done
    p=$((p + 1))
  done
  write_partial
  if [[ $shard_count -eq 1 ]]; then
    /usr/bin/python3 "$flows/gatelevel/gatesim_partial.py" merge --output "$out" "$out/partial.json" > /dev/null \
      || { echo "gatesim.sh: the hazard report failed" >&2; exit 1; }
    echo "gatesim.sh: hazards written to $out/hazards.md, $out/hazards.json"
  else
    echo "gatesim.sh: hazard units$hazard_units of shard $shard_index/$shard_count done; merge the shards' partials (--merge --output DIR)"
  fi
  exit 0
fi

if [[ -z "$bisect" ]]; then
  set +e
  run_at "$period"
  status=$?
  set -e
  [[ $status -le 1 ]] || exit 1
  write_partial
  exit $status
fi

# ---- T_sim: bisection to 0.1 ns between T_sta/4 (must fail) and 2 T_sta (must pass) ----
# A shard bisects its own policies; T_sim of the run is the largest of the shards' (a
# period passes every policy when it passes each), which the merge takes.
lo=$(printf '%.1f' "$(echo "$bisect / 4" | bc -l)")
hi=$(printf '%.1f' "$(echo "$bisect * 2" | bc -l)")
: > "$out/tsim_shard.txt"
bisect_error() {  # MESSAGE: the shard's bisection failed
  echo "gatesim.sh: $1" >&2
  echo "error $1" >> "$out/tsim_shard.txt"
  write_partial
  exit 1
}
if [[ ! -s "$out/policies.txt" ]]; then
  echo "gatesim.sh: shard $shard_index/$shard_count has no policy to bisect"
  write_partial
  exit 0
fi
# Periods to try: both ends and the halvings of (hi - lo) down to 0.1 ns.
periods_total=$(echo "l(($hi - $lo) / 0.1) / l(2)" | bc -l | xargs printf '%.0f')
periods_total=$((periods_total + 2)); periods_done=0
declare -A failed_at
set +e
run_at "$hi"; s=$?
periods_done=1; progress "$periods_done" "$periods_total" "periods tried"
[[ $s -eq 0 ]] || bisect_error "fails even at 2 T_sta = $hi ns"
run_at "$lo"; s=$?
failed_at[$lo]=$failed_policy
periods_done=2; progress "$periods_done" "$periods_total" "periods tried"
[[ $s -eq 1 ]] || bisect_error "passes at T_sta/4 = $lo ns: not sensitive to timing"
while (( $(echo "$hi - $lo > 0.1 + 0.0001" | bc) )); do
  mid=$(printf '%.1f' "$(echo "($lo + $hi) / 2" | bc -l)")
  run_at "$mid"; s=$?
  failed_at[$mid]=$failed_policy
  periods_done=$((periods_done + 1))
  (( periods_done < periods_total )) || periods_total=$periods_done
  progress "$periods_done" "$periods_total" "periods tried"
  [[ $s -le 1 ]] || exit 1
  if [[ $s -eq 0 ]]; then hi=$mid; else lo=$mid; fi
done
set -e
# The first failure at lo: the first policy (in the run's order) that failed there.
first_policy=${failed_at[$lo]}
first_failure=$(grep -h -m1 -E 'MISMATCH|fatal' "$out/T$lo/$first_policy.log" | head -1)
{
  echo "t_sim_ns $hi"
  echo "fails_at_ns $lo"
  echo "first_failure $first_failure"
  if [[ $VARIANT_VECTORS -eq 1 ]]; then
    echo "policies default (a design variant)"
    echo "vectors_per_policy $(( 18 + random ))"
  else
    echo "policies $policies"
    if [[ -n "$stimulus" ]]; then echo "vectors_per_policy $(grep -c . "$stimulus")"
    else echo "vectors_per_policy $(( groups * 10 + random ))"; fi
  fi
} > "$out/tsim.txt"
{
  echo "t_sim_ns $hi"
  echo "fails_at_ns $lo"
  echo "first_failure $first_failure"
  echo "first_failure_policy $(awk -v p="$first_policy" '$1 == p {print NR - 1; exit}' "$out/policies_all.txt")"
} > "$out/tsim_shard.txt"
write_partial
echo "gatesim.sh: T_sim = $hi ns (fails at $lo ns)$([[ $shard_count -eq 1 ]] || echo " for the policies of shard $shard_index/$shard_count")"
