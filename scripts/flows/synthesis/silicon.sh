#!/usr/bin/env bash
# The device in silicon: rtl/ mapped onto the OSU 0.18 um standard cells (qflow-tech-osu018),
# ROMs 5 and 38 as memory macros, static timing with OpenSTA, and (unless --no-gatesim)
# T_sim from the gate-level simulation (scripts/flows/gatelevel/gatesim.sh) and Fig. 2's hazards measured
# there (unless --no-hazards). docs/silicon.md explains it.
#
#   scripts/flows/synthesis/silicon.sh [--top NAME] [--no-gatesim] [--no-hazards] OUT_DIR [ROM_DIR]
#
#   --top NAME    the top module (default specular_device; specular_device_sync, or
#                 specular_ip_axi, the whole IP of rtl/ip/); its own pieces (SDC, named
#                 paths, the control unit's expected cells, the testbench timing) live in
#                 scripts/flows/designs/NAME/.
#   --no-gatesim  skip the T_sim bisection and the hazards (T_sim is then reported as
#                 not measured).
#   --no-hazards  skip the hazard measurements (gatesim.sh --hazards, 10-15 minutes;
#                 a top without a hazard probe, a variant, skips them with a note).
#   --vectors-tool PATH  specular_variant_vectors (default
#                 build/tools/variant_vectors/specular_variant_vectors): a design variant's vectors.
#   ROM_DIR       rom5.hex, rom38.hex, pins.hex and a variant's tables (default
#                 build/rtl/rom/default).
#
# A design variant's top (rtl/design_space/specular_NAME.v, the common ports of docs/design_space.md)
# without a folder of its own takes scripts/flows/designs/variant/ (one clock, inputs 3T/4,
# outputs read at the next edge); its clocks per result and latency are measured by
# rtl/tb/specular_variant_tb.v in RTL (tb_rtl.txt, 200 vectors), and after the T_sim
# bisection every top's vectors are replayed at 1.1 T_sim (gatesim_replay.txt).
#
# OUT_DIR gets silicon_report.md, silicon_summary.json, the mapped netlist (mapped.v), the
# SDC (constraints.sdc), the SDF (device.sdf), the ROM macros' Liberty (rom_macros.lib)
# the hazard table (hazards.md, hazards.json) and the raw tool logs (yosys.log, sta.log,
# sta_*.txt, path_*.txt, gatesim/).
# Exit status: 0 report written, 1 a tool failed, 2 bad arguments or a missing package.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"

usage() {
  sed -n '2,24p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

top=specular_device
vectors_tool="$root/build/tools/variant_vectors/specular_variant_vectors"
gatesim=1
hazards=1
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --top) [[ $# -ge 2 ]] || { echo "silicon.sh: --top needs a module name" >&2; exit 2; }
           top="$2"; shift 2 ;;
    --top=*) top="${1#--top=}"; shift ;;
    --no-gatesim) gatesim=0; shift ;;
    --no-hazards) hazards=0; shift ;;
    --vectors-tool) [[ $# -ge 2 ]] || { echo "silicon.sh: --vectors-tool needs a path" >&2; exit 2; }
           vectors_tool="$2"; shift 2 ;;
    -*) echo "silicon.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
if [[ ${#args[@]} -lt 1 || ${#args[@]} -gt 2 ]]; then
  echo "usage: scripts/flows/synthesis/silicon.sh [--top NAME] [--no-gatesim] [--no-hazards] OUT_DIR [ROM_DIR]  (--help)" >&2
  exit 2
fi
top_dir="$flows/designs/$top"
# A design variant's top (rtl/design_space/specular_NAME.v with the common ports of
# docs/design_space.md) without a folder of its own takes the generic one.
if [[ ! -d "$top_dir" && "$top" == specular_* && -f "$root/rtl/design_space/$top.v" ]]; then
  top_dir="$flows/designs/variant"
fi
if [[ ! -f "$top_dir/constraints.tcl" ]]; then
  echo "silicon.sh: top '$top' has no flow pieces (scripts/flows/designs/$top/constraints.tcl)" \
       "and is no design variant (rtl/design_space/specular_NAME.v); known tops: $(cd "$flows/designs" && ls -d */ | tr -d / | tr '\n' ' ')" >&2
  exit 2
fi
out="${args[0]}"
rom_dir="${args[1]:-$root/build/rtl/rom/default}"
# Fig. 2's hazard step needs the top's hazard probe (TB_PROBE in its gatesim.conf); a top
# without one (a design variant: one clock, no gated one) skips it with a note (issue 35).
hazards_note=""
if [[ $gatesim -eq 1 && $hazards -eq 1 ]]; then
  probe=$(flows="$flows" root="$root" top="$top"; TB_PROBE=""; source "$top_dir/gatesim.conf"; echo "${TB_PROBE:-}")
  if [[ -z "$probe" ]]; then
    hazards=0
    hazards_note="top '$top' has no hazard probe (TB_PROBE in $(basename "$top_dir")/gatesim.conf): Fig. 2's hazard step is skipped"
    echo "silicon.sh: note: $hazards_note" >&2
  fi
fi

# ---- what the flow needs, each named with its install line ------------------------
need() {  # need FILE_OR_COMMAND PACKAGE
  if [[ "$1" == /* ]]; then [[ -e "$1" ]] && return 0; else command -v "$1" >/dev/null && return 0; fi
  echo "silicon.sh: $1 not found: sudo apt-get install $2 (or bash scripts/setup.sh)" >&2
  exit 2
}
need "$OSU018/osu018_stdcells.lib" qflow-tech-osu018
need "$OSU018/osu018_stdcells.v" qflow-tech-osu018
need sta opensta
need yosys yosys
need /usr/bin/python3 python3
need bc bc
[[ $gatesim -eq 0 ]] || { need iverilog iverilog; need vvp iverilog; }
for image in rom5.hex rom38.hex pins.hex; do
  if [[ ! -f "$rom_dir/$image" ]]; then
    echo "silicon.sh: '$rom_dir/$image' not found: build the ROM images first" \
         "(cmake --build build --target specular_rom_images) or name their folder" >&2
    exit 2
  fi
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rom_dir="$(cd "$rom_dir" && pwd)"
lib="$OSU018/osu018_stdcells.lib"
seconds() { date +%s.%N; }
t0=$(seconds)

# ---- mapping (Yosys) ---------------------------------------------------------------
# Hierarchy kept (area per block of Fig. 1); only Fig. 2's leaf gates are flattened into
# control unit 16, where they are library cells already (synthesis/fig2_cells.v), and
# multiply_round_saturate, the primitive multipliers 39 and 13–15 share, into each of
# them (as scripts/flows/synthesis/synth.sh does), so their cells stay counted per block; likewise the
# leading-one normaliser into ROM 5.
sources=()
# The Verilog folders of rtl/sources.cmake; the design-space tops include variant_ports.vh.
for f in "$root"/rtl/{device,primitives,design_space}/*.v; do sources+=("$f"); done
# The whole IP (rtl/ip/, docs/rtl_ip.md): the register block and the AXI4-Lite top (its
# assertions file is for simulation and proof only), read only for a top of rtl/ip/:
# more modules read reorder Yosys's names and so ABC's mapping of every other top
# (specular_exp2's T_sta moved by 0.3 ns).
if [[ -f "$root/rtl/ip/$top.v" ]]; then
  sources+=("$root/rtl/ip/specular_reg_block.v" "$root/rtl/ip/specular_ip_axi.v")
fi
front_rest="read_verilog ${sources[*]}
read_verilog -overwrite $flows/synthesis/fig2_cells.v
hierarchy -check -top $top
setattr -mod -set keep_hierarchy 1 *
setattr -mod -unset keep_hierarchy inverter and2 nand2 nand3 d_flip_flop *multiply_round_saturate *leading_one_normaliser
flatten
proc; opt; memory -nomap; opt"
front="read_liberty -lib $lib
$front_rest"

# ---- ROM macros: every read-only memory of the top (a probe of the same front end),
# its Liberty, blackbox, behavioural model and techmap (synthesis/rom_model.py) ----------
if ! (cd "$rom_dir" && yosys -q -l "$out/yosys_memories.log" \
        -p "$front
select -clear
write_json $out/memories.json" >/dev/null 2>&1); then
  echo "silicon.sh: yosys failed reading the top; see $out/yosys_memories.log" >&2
  exit 1
fi
/usr/bin/python3 "$flows/synthesis/rom_model.py" "$out" "$out/memories.json" \
  || { echo "silicon.sh: rom_model.py failed" >&2; exit 1; }
rm -f "$out/memories.json"

script="read_liberty -lib $lib
read_verilog $out/rom_macros_bb.v
$front_rest
script $out/rom_macro_map.ys
opt; wreduce; opt
techmap; opt
dfflibmap -liberty $lib
abc -fast -liberty $lib
opt_clean
tee -q -o $out/stat.txt stat -liberty $lib
write_verilog -noattr $out/mapped.v"
if ! (cd "$rom_dir" && yosys -q -l "$out/yosys.log" -p "$script" >/dev/null 2>&1); then
  echo "silicon.sh: yosys failed; see $out/yosys.log" >&2
  exit 1
fi
# OpenSTA 2.0.17 stops reading a module at an assignment to a concatenation (Yosys's
# aliases of merged flip-flops): one assignment per bit (synthesis/netlist_assigns.py).
/usr/bin/python3 "$flows/synthesis/netlist_assigns.py" "$out/mapped.v" > /dev/null \
  || { echo "silicon.sh: netlist_assigns.py failed on $out/mapped.v" >&2; exit 1; }
if grep -q '\$mem' "$out/mapped.v"; then
  echo "silicon.sh: a memory was left unmapped (not a ROM macro); see $out/mapped.v" >&2
  exit 1
fi
t1=$(seconds)

# ---- static timing (OpenSTA) --------------------------------------------------------
{
  echo "set lib {$lib}"
  echo "set rom_lib {$out/rom_macros.lib}"
  echo "set netlist {$out/mapped.v}"
  echo "set top {$top}"
  echo "set top_dir {$top_dir}"
  echo "set out {$out}"
  echo "source {$flows/synthesis/sta.tcl}"
} > "$out/sta_run.tcl"
# An error in the log (a netlist line OpenSTA could not read) fails the step: its
# timing would miss what it skipped.
if ! sta -no_splash -exit "$out/sta_run.tcl" > "$out/sta.log" 2>&1 || ! grep -q t_sta_ns "$out/sta_summary.txt" 2>/dev/null \
   || grep -q '^Error' "$out/sta.log"; then
  echo "silicon.sh: sta failed; see $out/sta.log" >&2
  exit 1
fi
t2=$(seconds)

# ---- a design variant: clocks per result and latency from the generic testbench in RTL
if [[ "$top_dir" == "$flows/designs/variant" ]]; then
  [[ -x "$vectors_tool" ]] || { echo "silicon.sh: specular_variant_vectors not found at '$vectors_tool'" \
    "(cmake --build build --target specular_variant_vectors, or --vectors-tool PATH)" >&2; exit 2; }
  "$vectors_tool" "${top#specular_}" --count 200 --seed 1 --out "$out/tb_rtl_vectors.txt" \
    || { echo "silicon.sh: specular_variant_vectors ${top#specular_} failed" >&2; exit 1; }
  if ! iverilog -g2005 -o "$out/tb_rtl.vvp" -s specular_variant_tb "-DVARIANT_TOP=$top" -I "$root/rtl/design_space" \
         "-Pspecular_variant_tb.VECTORS=\"$out/tb_rtl_vectors.txt\"" "${sources[@]}" \
         "$root/rtl/tb/specular_variant_tb.v" > "$out/tb_rtl_compile.log" 2>&1 \
     || ! (cd "$rom_dir" && vvp -n "$out/tb_rtl.vvp") > "$out/tb_rtl.txt" 2>&1 \
     || ! grep -q '^PASS' "$out/tb_rtl.txt"; then
    echo "silicon.sh: the RTL testbench of $top failed; see $out/tb_rtl.txt, $out/tb_rtl_compile.log" >&2
    exit 1
  fi
fi

# ---- T_sim: gate-level simulation, bisection to 0.1 ns ------------------------------
if [[ $gatesim -eq 1 ]]; then
  t_sta=$(awk '/t_sta_ns/ {print $2}' "$out/sta_summary.txt")
  if ! bash "$flows/gatelevel/gatesim.sh" --top "$top" --netlist-dir "$out" --vectors-tool "$vectors_tool" \
       --bisect "$t_sta" "$out/gatesim" "$rom_dir" > "$out/gatesim.log" 2>&1; then
    echo "silicon.sh: the T_sim bisection failed; see $out/gatesim.log" >&2
    exit 1
  fi
  # the same vectors replayed at 1.1 T_sim: PASS or FAIL into the summary
  t_sim=$(awk '/t_sim_ns/ {print $2}' "$out/gatesim/tsim.txt")
  t_replay=$(printf '%.2f' "$(echo "$t_sim * 1.1" | bc -l)")
  echo "period_ns $t_replay" > "$out/gatesim_replay.txt"
  bash "$flows/gatelevel/gatesim.sh" --top "$top" --netlist-dir "$out" --vectors-tool "$vectors_tool" --quiet \
    "$t_replay" "$out/gatesim_replay" "$rom_dir" >> "$out/gatesim_replay.txt" 2>&1 || true
fi
t3=$(seconds)
# ---- Fig. 2's hazards at T_sim and 2 T_sim -------------------------------------------
if [[ $gatesim -eq 1 && $hazards -eq 1 ]]; then
  t_sim=$(awk '/t_sim_ns/ {print $2}' "$out/gatesim/tsim.txt")
  if ! bash "$flows/gatelevel/gatesim.sh" --top "$top" --netlist-dir "$out" --hazards "$t_sim" "$out/hazards" "$rom_dir" \
       > "$out/hazards.log" 2>&1; then
    echo "silicon.sh: the hazard measurements failed; see $out/hazards.log" >&2
    exit 1
  fi
  cp "$out/hazards/hazards.md" "$out/hazards/hazards.json" "$out/"
fi
rm -f "$out/hazards_skipped.txt"
[[ -z "$hazards_note" ]] || echo "$hazards_note" > "$out/hazards_skipped.txt"
t4=$(seconds)
printf 'mapping_s %.1f\nsta_s %.1f\ngatesim_s %.1f\nhazards_s %.1f\n' "$(echo "$t1 - $t0" | bc)" \
  "$(echo "$t2 - $t1" | bc)" "$(echo "$t3 - $t2" | bc)" "$(echo "$t4 - $t3" | bc)" > "$out/times.txt"

# ---- the report --------------------------------------------------------------------
if ! /usr/bin/python3 "$flows/synthesis/report.py" "$out" "$top" "$top_dir"; then
  echo "silicon.sh: report.py failed" >&2
  exit 1
fi
