#!/usr/bin/env bash
# The device in layout: the mapped netlist of scripts/flows/synthesis/silicon.sh placed, routed, checked
# and extracted with Debian's open flow for the OSU 0.18 um cells (issue 48,
# docs/silicon/layout.md "Layout: placed, routed, DRC and LVS checked"): qflow 1.3.17's scripts drive graywolf (placement) and
# qrouter (routing, wire R and C to SPEF), magic checks DRC and extracts the layout's
# netlist, netgen compares it with the mapped netlist (LVS), OpenSTA times it with the
# SPEF. The ROM macros are hard blocks: their LEF abstracts come from
# scripts/flows/synthesis/rom_model.py, the model that gives their Liberty.
#
#   scripts/flows/layout/layout.sh [options] OUT_DIR
#
#   --netlist-dir DIR  silicon.sh's output folder: mapped.v, rom_model.json,
#                      rom_macros.lib, rom_macros_bb.v (default: run silicon.sh
#                      --no-gatesim --top TOP into OUT_DIR/silicon first)
#   --rom-dir DIR      ROM images for that silicon.sh run (its ROM_DIR argument)
#   --netlist FILE     a mapped netlist of OSU cells alone (no ROM macros), instead of DIR
#   --top NAME         the module to lay out (default specular_device_sync); any module
#                      of the netlist (a block: control_unit_sync, multiplier6, ...)
#   --utilisation U    standard-cell density the placement is padded to, 0.2-0.9
#                      (default 0.6, qflow's initial_density): room for the router
#   --plant FAULT      for the tests (tests/layout, rtl/tb/layout_block_test.py): plant
#                      one fault the checks must catch: drc (a 0.1 um metal1 square,
#                      below the 0.3 um minimum width, painted beside the cells), lvs (one
#                      pin of one instance of the mapped netlist left open after layout),
#                      unrouted (every metal obstructed before routing)
#   --no-cleanup       end qrouter's routing once stage 2 has routed every net: its
#                      stage 3 (each net ripped up and routed again, shorter, two rounds)
#                      is left out. On one_pass_pipelined (31 680 nets, density 0.45)
#                      stages 1 and 2 routed every net in 74-79 min, and stage 3 would
#                      then route all of them twice more (docs/silicon.md);
#                      layout_summary.json says whether it ran (router_stage3)
#   --resume           keep OUT_DIR/qflow and go on after its last finished step: after
#                      its placement (graywolf takes tens of minutes on the whole device),
#                      or, when a routed DEF, its R and C and a route log newer than the
#                      placed DEF are there (qflow/TOP_route.def and TOP_route.rc or TOP.rc,
#                      qflow/log/route.log: a qrouter run by hand leaves its log there), straight
#                      to DRC, LVS, extraction, STA and the picture; times.txt then gives
#                      routing_before_resume_s (TOP.cfg written to TOP_route.def written)
#   --no-sta           skip post-layout STA (a top without scripts/flows/designs/TOP/constraints.tcl
#                      skips it with a note)
#
# OUT_DIR gets qflow/ (the project: TOP.def routed, TOP.spef, the tools' logs in
# qflow/log/), drc.txt (magic's count and every error with its reason), lvs.txt (netgen),
# instances.tsv (layout name -> netlist name), repairs.txt (what layout_repair.py
# mended in qrouter's DEF before DRC: lone vias, a pin passed over), sta/ (post-layout reports, with
# sta_summary.txt), layout_summary.json and layout_report.md (die, utilisation, wire
# length, DRC, LVS, unrouted nets, T_sta, each step's time), floorplan.txt (where the
# macros went), die.png (KLayout) and die.svg (the blocks of Fig. 1 marked), and with
# --netlist-dir and STA postlayout/ (gatesim.sh --netlist-dir: the laid-out netlist and
# its SDF with the wires).
# DRC and LVS run on abstract views: qflow-tech-osu018 has the cells' LEF but no GDS, so
# magic checks the routing and the cells' pins and obstructions, not the cells' insides.
# Exit status: 0 clean (no unrouted net, 0 DRC errors, LVS match), 1 a tool failed or a
# check did not pass (named on standard error), 2 bad arguments or a missing package.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
OSU018="${SPECULAR_OSU018_DIR:-/usr/share/qflow/tech/osu018}"
QFLOW_SCRIPTS="${SPECULAR_QFLOW_SCRIPTS:-/usr/lib/qflow/scripts}"
MACRO_GAP_UM=20   # between the core and the macros, and between macros: room for the wires to their pins
usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'; }
fail_args() { echo "layout.sh: $1 (see --help)" >&2; exit 2; }

top=specular_device_sync
netlist_dir=""
netlist=""
rom_dir=""
utilisation=0.6
sta=1
cleanup=1
resume=0
routed_before=0
plant=""
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --no-sta) sta=0; shift ;;
    --no-cleanup) cleanup=0; shift ;;
    --resume) resume=1; shift ;;
    --top|--netlist-dir|--netlist|--utilisation|--plant|--rom-dir)
      [[ $# -ge 2 ]] || fail_args "$1 needs a value"
      case "$1" in
        --top) top="$2" ;; --netlist-dir) netlist_dir="$2" ;; --netlist) netlist="$2" ;;
        --utilisation) utilisation="$2" ;; --plant) plant="$2" ;; --rom-dir) rom_dir="$2" ;;
      esac
      shift 2 ;;
    -*) fail_args "unknown option '$1'" ;;
    *) args+=("$1"); shift ;;
  esac
done
[[ ${#args[@]} -eq 1 ]] || fail_args "usage: layout.sh [options] OUT_DIR"
[[ "$utilisation" =~ ^0?[.][0-9]+$ ]] && (( $(echo "$utilisation >= 0.2 && $utilisation <= 0.9" | bc) )) \
  || fail_args "--utilisation '$utilisation' is not a density from 0.2 to 0.9"
[[ -z "$plant" || "$plant" =~ ^(drc|lvs|unrouted)$ ]] || fail_args "--plant '$plant' is not one of drc, lvs, unrouted"
[[ "$top" =~ ^[A-Za-z_][A-Za-z0-9_]*$ ]] || fail_args "--top '$top' is not a module name"
[[ -z "$netlist" || -z "$netlist_dir" ]] || fail_args "give --netlist or --netlist-dir, not both"
[[ -z "$netlist" || -f "$netlist" ]] || fail_args "--netlist '$netlist' is not a file"
[[ -z "$netlist_dir" || -f "$netlist_dir/mapped.v" ]] || fail_args "--netlist-dir '$netlist_dir' holds no mapped.v"

need() {  # need FILE_OR_COMMAND PACKAGE
  if [[ "$1" == /* ]]; then [[ -e "$1" ]] && return 0; else command -v "$1" >/dev/null && return 0; fi
  echo "layout.sh: $1 not found: apt-get install $2 (or bash scripts/setup.sh)" >&2
  exit 2
}
need "$OSU018/osu018_stdcells.lef" qflow-tech-osu018
need "$QFLOW_SCRIPTS/placement.sh" qflow
need /usr/lib/qflow/bin/blif2BSpice qflow
need graywolf graywolf
need qrouter qrouter
need magic magic
need netgen-lvs netgen-lvs
need tcsh tcsh
need yosys yosys
need sta opensta
need bc bc

out="${args[0]}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
lib="$OSU018/osu018_stdcells.lib"
proj="$out/qflow"
[[ $resume -eq 1 ]] || rm -rf "$proj"
mkdir -p "$proj/source" "$proj/log"
seconds() { date +%s.%N; }
declare -a step_names=() step_times=() step_cpus=()
# CPU seconds (user + system) of this shell's finished children: the second line of
# `times`, run in this shell (in a pipe or $(...) it would report a fresh subshell's zero)
children_cpu_file() {
  times > "$proj/log/.times"
}
step_start=$(seconds)
step_cpu_start=0
step_done() {  # step_done NAME: prints and keeps the step's wall and CPU time
  local now; now=$(seconds)
  local dt; dt=$(printf '%.1f' "$(echo "$now - $step_start" | bc)")
  children_cpu_file
  local cpu
  cpu=$(awk 'NR == 2 {n = 0; for (i = 1; i <= 2; i++) {split($i, p, "m"); n += p[1] * 60 + p[2]} printf "%.1f", n}' \
    "$proj/log/.times")
  local dc; dc=$(printf '%.1f' "$(echo "$cpu - $step_cpu_start" | bc)")
  step_names+=("$1"); step_times+=("$dt"); step_cpus+=("$dc")
  echo "layout.sh: $1 ${dt} s (CPU ${dc} s)"
  step_start=$now
  step_cpu_start=$cpu
}

# ---- the netlist: silicon.sh's, or made here --------------------------------------
if [[ -z "$netlist" && -z "$netlist_dir" ]]; then
  netlist_dir="$out/silicon"
  bash "$flows/synthesis/silicon.sh" --top "$top" --no-gatesim "$netlist_dir" ${rom_dir:+"$rom_dir"} \
    || { echo "layout.sh: silicon.sh failed for '$top'" >&2; exit 1; }
  step_done mapping
fi
macros_lef=""
bb=""
rom_lib=""
if [[ -n "$netlist_dir" ]]; then
  netlist_dir="$(cd "$netlist_dir" && pwd)"
  netlist="$netlist_dir/mapped.v"
  if [[ -f "$netlist_dir/rom_model.json" ]]; then
    bb="read_verilog $netlist_dir/rom_macros_bb.v"
    rom_lib="$netlist_dir/rom_macros.lib"
  fi
fi
netlist="$(cd "$(dirname "$netlist")" && pwd)/$(basename "$netlist")"

# SPICE for LVS: the cells' subcircuits and an empty one per ROM macro (a black box)
spice="$proj/cells.sp"
qb=/usr/lib/qflow/bin
netlist_files() {  # the full netlist (macros included) as Verilog and SPICE, as qflow names them
  "$qb/blif2Verilog" -c -v vdd -g gnd "${top}_full.blif" > "$top.rtl.v"
  "$qb/blif2Verilog" -c -p -v vdd -g gnd "${top}_full.blif" > "$top.rtlnopwr.v"
  "$qb/blif2Verilog" -c -p -b -n -v vdd -g gnd "${top}_full.blif" > "$top.rtlbb.v"
  "$qb/blif2BSpice" -i -p vdd -g gnd -l "$spice" "${top}_full.blif" > "$top.spc"
}
write_qflow_vars() {  # qflow's variables of the project, where it is now (a resumed copy may have moved)
  cat > "$proj/qflow_vars.sh" <<EOF
#!/usr/bin/tcsh -f
# qflow variables of scripts/flows/layout/layout.sh's project (as qflow itself writes them)
set projectpath=$proj
set techdir=$OSU018
set sourcedir=$proj/source
set synthdir=$proj
set layoutdir=$proj
set techname=osu018
set scriptdir=$QFLOW_SCRIPTS
set bindir=/usr/lib/qflow/bin
set logdir=$proj/log
EOF
}
# A routing that finished before this run (--resume): qrouter's DEF, R and C and log,
# all newer than the placed and floorplanned DEF it routed. qrouter run by hand
# (qrouter -s TOP.cfg, its standard_route) leaves TOP_route.def and TOP_route.rc; qflow's
# router.sh moves them to TOP.def and TOP.rc (and this script copies TOP_route.def back).
route_done() {
  local placed="${top}_unroute.def" rc="${top}.rc"
  [[ -f "$placed" ]] || placed="${top}_placed.def"
  [[ ! -f "${top}_route.rc" ]] || rc="${top}_route.rc"
  [[ -f "$placed" && -f "${top}_route.def" && -f "$rc" && -f log/route.log ]] || return 1
  [[ "${top}_route.def" -nt "$placed" && "$rc" -nt "$placed" && log/route.log -nt "$placed" ]] || return 1
  grep -q '^\*\*\* Writing DEF file' log/route.log
}
cd "$proj"
if [[ $resume -eq 1 ]]; then
  [[ -f "$proj/${top}_full.blif" && -f "$proj/$top.def" ]] \
    || { echo "layout.sh: --resume: no placed project in $proj" >&2; exit 1; }
  ! compgen -G "$proj/source/macros/*.lef" >/dev/null || macros_lef="$proj/source/macros/rom_macros.lef"
  grep -q '^read_def' "$proj/$top.cfg" || { echo "layout.sh: --resume: placement.sh wrote no $top.cfg" >&2; exit 1; }
  write_qflow_vars
  # the macros' LEF where the project is now (the router's script names them by path)
  route_started=$(stat -c %Y "$proj/$top.cfg")   # written as the routing started, if it did
  grep '^read_lef .*/source/macros/' "$proj/$top.cfg" | grep -qv "^read_lef $proj/" && \
  sed -i "s|^read_lef .*/source/macros/\([^/]*\.lef\)\$|read_lef $proj/source/macros/\1|" "$proj/$top.cfg"
  # and the cells' SPICE the LVS netlist includes (blif2BSpice writes its absolute path)
  [[ ! -f "$proj/$top.spc" ]] || sed -i "1,5s|^\.include .*/cells\.sp\$|.include $spice|" "$proj/$top.spc"
  if route_done; then
    routed_before=1
    echo "layout.sh: --resume: $proj holds a finished routing (${top}_route.def): on to DRC"
  else
    # placement.sh's DEF as it left it (kept at the first pass), whatever came after
    [[ -f "$proj/${top}_placed.def" ]] || cp "$proj/$top.def" "$proj/${top}_placed.def"
    cp "$proj/${top}_placed.def" "$proj/$top.def"
  fi
else
# ---- the netlist as qflow's synthesis would leave it: flat BLIF, Verilog, SPICE ------
# Flattened (instance names keep their block: mul6._123_), constants as BUFX2 from
# gnd/vdd, aliases merged (opt_clean -purge; no buffer is added). An undefined bit (x:
# us5739820's squarer drives a 32-bit product from a 31-bit square) is tied to 0
# (setundef -zero): a cell pin needs a net, and 0 is one of the values an x allows.
if ! yosys -q -l "$proj/log/prep_yosys.log" -p "read_liberty -lib $lib
$bb
read_verilog $netlist
hierarchy -check -top $top
flatten
setundef -zero
hilomap -singleton -hicell LOGIC1 O -locell LOGIC0 O
opt_clean -purge
tee -q -o $proj/log/prep_stat.txt stat
write_blif -buf BUFX2 A Y -cname $proj/${top}_raw.blif" >/dev/null 2>&1; then
  echo "layout.sh: yosys could not flatten '$top' from $netlist; see $proj/log/prep_yosys.log" >&2
  exit 1
fi
/usr/bin/python3 "$flows/layout/layout_prep.py" "$proj/${top}_raw.blif" "$proj/$top.blif" "$out/instances.tsv" \
  || { echo "layout.sh: layout_prep.py failed" >&2; exit 1; }
printf 'set vddnet="vdd"\nset gndnet="gnd"\n' > "$proj/${top}_powerground"
# the ROM macros the netlist holds: their LEF abstracts, from the model of their Liberty
if [[ -n "$rom_lib" ]]; then
  used=$(awk '$1==".gate" && $2 ~ /^ROM/ {print $2}' "$proj/$top.blif" | sort -u)
  if [[ -n "$used" ]]; then
    # One file per macro: qflow 1.3.17's blif2cel.tcl reads a hard-macro LEF to its end
    # (its END test never matches) and so takes only the first macro of a file.
    mkdir -p "$proj/source/macros"
    macros_lef="$proj/source/macros/rom_macros.lef"
    rm -f "$macros_lef"
    for name in $used; do
      /usr/bin/python3 "$flows/synthesis/rom_model.py" --lef "$netlist_dir/rom_model.json" \
        "$proj/source/macros/$name.lef" "$name" \
        || { echo "layout.sh: rom_model.py --lef failed" >&2; exit 1; }
    done
  fi
fi
cp "$OSU018/osu018_stdcells.sp" "$spice"
if [[ -n "$macros_lef" ]]; then
  awk '/^MACRO /{name=$2; pins=""} /^  PIN /{pins=pins" "$2} /^END /&&$2==name{print ".subckt "name pins"\n.ends"}' \
    "$proj"/source/macros/*.lef >> "$spice"
fi
# graywolf places the standard cells alone (its macro mode crashed on the whole device:
# mc_compact, "stack smashing detected"); the macros go beside the core afterwards
# (layout/layout_floorplan.py), so the BLIF graywolf reads leaves them out.
mv "$top.blif" "${top}_full.blif"
awk '!($1 == ".gate" && $2 ~ /^ROM/)' "${top}_full.blif" > "$top.blif"
netlist_files
write_qflow_vars
{
  echo "# scripts/flows/layout/layout.sh: the standard cells padded to this density by qflow's decongest"
  echo "set initial_density = $utilisation"
  echo "set graywolf_options = \"-n\""
  [[ -z "$macros_lef" ]] || echo "set hard_macros = (macros)"
} > "$proj/project_vars.sh"
# what qflow.sh copies into a new project: graywolf's parameters, magic's start-up file
cp "$OSU018/osu018.par" "$proj/$top.par"
cp "$OSU018/osu018.magicrc" "$proj/.magicrc"
step_done prepare

# ---- placement (graywolf), the DEF ------------------------------------------------
if ! tcsh -f "$QFLOW_SCRIPTS/placement.sh" -d "$proj" "$top" > "$proj/log/place_run.log" 2>&1 \
   || [[ ! -f "$proj/$top.def" ]]; then
  echo "layout.sh: placement failed; see $proj/log/place_run.log, $proj/log/place.log" >&2
  exit 1
fi
step_done placement
cp "$proj/$top.def" "$proj/${top}_placed.def"
fi

# the floorplan: the ROM macros in a row below the core, pins facing it, on the routing
# grid; the netlist files again from the full BLIF (placement rewrote them without macros)
if [[ -n "$macros_lef" && $routed_before -eq 0 ]]; then
  /usr/bin/python3 "$flows/layout/layout_floorplan.py" "$proj/$top.def" "$proj/$top.cfg" \
    "$proj/${top}_full.blif" "$MACRO_GAP_UM" "$proj"/source/macros/*.lef | tee "$out/floorplan.txt" \
    || { echo "layout.sh: layout_floorplan.py failed" >&2; exit 1; }
  cp "$proj/$top.def" "$proj/${top}_unroute.def"
  netlist_files
fi

if [[ "$plant" == unrouted && $routed_before -eq 0 ]]; then   # every metal obstructed: no net can be routed
  obstructions=$(for m in 1 2 3 4 5 6; do echo "obstruction -1000 -1000 100000 100000 metal$m"; done)
  awk -v o="$obstructions" '/^read_def/ {print o} {print}' "$proj/$top.cfg" > "$proj/$top.cfg.planted"
  mv "$proj/$top.cfg.planted" "$proj/$top.cfg"
fi

# The clock nets first: the netlist has no clock tree, so clk is one net of some 300
# flip-flop pins. Routed in its turn, it found the die full: exp2's qrouter run ended
# stage 1 with clk alone unrouted and spent hours in stage 2 ripping it up. qrouter's
# `priority` routes the nets named before all others (the nets on the flip-flops' CLK
# pins in the placed netlist; braces keep a bus bit's brackets from Tcl).
if [[ $routed_before -eq 0 ]] && ! grep -q '^priority' "$proj/$top.cfg"; then
  clocks=$(grep -o 'CLK=[^ ]*' "$proj/$top.blif" | sed 's/^CLK=//' | sort -u | sed 's/.*/{&}/' | tr '\n' ' ')
  if [[ -n "$clocks" ]]; then
    awk -v p="priority $clocks" '{print} /^read_def/ {print p}' "$proj/$top.cfg" > "$proj/$top.cfg.clk"
    mv "$proj/$top.cfg.clk" "$proj/$top.cfg"
  fi
fi

# --no-cleanup: qflow's script calls `qrouter::standard_route FILE false` (do not quit);
# its third argument, nocleanup, skips stage 3 (a --resume without the option puts it back)
if [[ $routed_before -eq 0 ]]; then
  sed -i 's/^\(qrouter::standard_route [^ ]*\) false true$/\1 false/' "$proj/$top.cfg"
  if [[ $cleanup -eq 0 ]]; then
    sed -i 's/^\(qrouter::standard_route [^ ]*\) false$/\1 false true/' "$proj/$top.cfg"
    grep -q '^qrouter::standard_route [^ ]* false true$' "$proj/$top.cfg" \
      || { echo "layout.sh: --no-cleanup: no 'qrouter::standard_route FILE false' line in $proj/$top.cfg" >&2; exit 1; }
  fi
fi

# ---- routing (qrouter), wire R and C (rc2dly: SPEF, SDF) ---------------------------
# router.sh leaves the routed DEF as TOP.def (the placed one is TOP_unroute.def) and the
# routes' R and C as TOP.rc; rc2dly (qflow) turns those into SPEF for OpenSTA.
if [[ $routed_before -eq 0 ]]; then
  tcsh -f "$QFLOW_SCRIPTS/router.sh" "$proj" "$top" > "$proj/log/route_run.log" 2>&1 || true
  if ! grep -q '^\*\*\* Writing DEF file' "$proj/log/route.log" 2>/dev/null || [[ ! -f "$proj/$top.rc" ]]; then
    echo "layout.sh: routing failed (qrouter wrote no DEF); see $proj/log/route.log" >&2
    exit 1
  fi
  cp "$proj/$top.def" "$proj/${top}_route.def"
else
  # the routing's wall time: from its script (TOP.cfg, written as it started) to its DEF;
  # unknown when an earlier --resume of a moved copy rewrote TOP.cfg after the routing
  routed_for=$(( $(stat -c %Y "$proj/${top}_route.def") - route_started ))
  if (( routed_for >= 0 )); then
    echo "routing_before_resume_s $routed_for" > "$proj/log/routing_before_resume.txt"
  else
    : > "$proj/log/routing_before_resume.txt"
    echo "layout.sh: note: $top.cfg is newer than the routed DEF: the routing's wall time is unknown" >&2
  fi
  if [[ -f "$proj/${top}_route.rc" ]]; then
    # qrouter run by hand: what router.sh does after it. The fill cells placement added
    # (fillcells.txt) go into the Verilog and SPICE netlists (annotate.tcl), so that they
    # list every instance of the layout (netgen matched the control unit without them
    # too: fill cells have no signal pin); the R and C file takes router.sh's name.
    cp "$proj/fillcells.txt" "$proj/antenna.out" 2>/dev/null || : > "$proj/antenna.out"
    if [[ -s "$proj/antenna.out" ]]; then
      "$QFLOW_SCRIPTS/annotate.tcl" "$proj/antenna.out" "$proj/$top.rtlnopwr.v" "$proj/$top.spc" \
        "$proj/$top.rtlnopwr.anno.v" "$proj/$top.anno.spc" "$OSU018/osu018_stdcells.sp" \
        "$proj/${top}_powerground" > "$proj/log/annotate.log" 2>&1 \
        || { echo "layout.sh: annotate.tcl failed; see $proj/log/annotate.log" >&2; exit 1; }
      for f in rtlnopwr rtl rtlbb; do
        [[ ! -f "$proj/$top.$f.anno.v" ]] || mv "$proj/$top.$f.anno.v" "$proj/$top.$f.v"
      done
      [[ ! -f "$proj/$top.anno.spc" ]] || mv "$proj/$top.anno.spc" "$proj/$top.spc"
    fi
    mv "$proj/${top}_route.rc" "$proj/$top.rc"
  fi
fi
/usr/lib/qflow/bin/rc2dly -D : -r "$proj/$top.rc" -l "$lib" -d "$proj/${top}_rc2dly.spef" > "$proj/log/rc2dly.log" 2>&1 \
  || { echo "layout.sh: rc2dly failed; see $proj/log/rc2dly.log" >&2; exit 1; }
# its node names and net spellings as OpenSTA reads them (layout/spef_fix.py says which)
/usr/bin/python3 "$flows/layout/spef_fix.py" "$proj/${top}_rc2dly.spef" "$proj/$top.rtlnopwr.v" "$proj/$top.spef" \
  "$out/wire_cap.txt" \
  >> "$proj/log/rc2dly.log" || { echo "layout.sh: spef_fix.py failed" >&2; exit 1; }
step_done routing
# qrouter's verdict: "Final: No failed routes!" or "Final: Failed net routes: N"
unrouted=$(grep -h '^Final:' "$proj/log/route.log" | tail -1 | sed -n 's/.*Failed net routes: *\([0-9]*\).*/\1/p')
if ! grep -q '^Final: No failed routes' "$proj/log/route.log" && [[ -z "$unrouted" ]]; then
  unrouted=unknown
fi
unrouted=${unrouted:-0}

# ---- qrouter's dangling vias, and a pin it passed over on metal2 without a via ---------
# (layout/layout_repair.py says what it found on the device); the DEF magic reads is the
# mended one, qrouter's own is kept as TOP_route_qrouter.def
[[ $routed_before -eq 1 && -f "$proj/${top}_route_qrouter.def" ]] || cp "$proj/${top}_route.def" "$proj/${top}_route_qrouter.def"
repair_lefs=("$OSU018/osu018_stdcells.lef")
[[ -z "$macros_lef" ]] || repair_lefs+=("$proj"/source/macros/*.lef)
repair_rc=0
/usr/bin/python3 "$flows/layout/layout_repair.py" "$proj/${top}_route_qrouter.def" "$proj/${top}_route.def" \
  "$out/repairs.txt" "${repair_lefs[@]}" > "$proj/log/repair.log" 2>&1 || repair_rc=$?
case $repair_rc in
  0) ;;
  1) echo "layout.sh: note: layout_repair.py left a pin open; see $out/repairs.txt (LVS will say)" >&2 ;;
  *) cat "$proj/log/repair.log" >&2; echo "layout.sh: layout_repair.py could not read the routed DEF" >&2; exit 1 ;;
esac
sed 's/^layout_repair.py: /layout.sh: repaired: /' "$proj/log/repair.log"

# ---- DRC and extraction (magic, abstract views) ------------------------------------
lefs="lef read $OSU018/osu018_stdcells.lef"
if [[ -n "$macros_lef" ]]; then
  for f in "$proj"/source/macros/*.lef; do lefs="$lefs
lef read $f"; done
fi
planted_drc=""
[[ "$plant" != drc ]] || planted_drc="box -200 -200 -199 -199
paint metal1
select top cell"
cat > "$proj/magic_drc_extract.tcl" <<EOF
$lefs
def read ${top}_route.def
load $top
select top cell
expand
$planted_drc
drc on
drc check
drc catchup
set f [open $out/drc.txt w]
puts \$f "drc_errors [drc list count total]"
foreach {why boxes} [drc listall why] {
  puts \$f "error: \$why"
  foreach b \$boxes { puts \$f "  at \$b" }
}
close \$f
drc off
extract all
ext2spice hierarchy on
ext2spice format ngspice
ext2spice scale off
ext2spice renumber off
ext2spice cthresh infinite
ext2spice rthresh infinite
ext2spice blackbox on
ext2spice subcircuit top auto
ext2spice global off
ext2spice -o ${top}_layout.spice
quit -noprompt
EOF
rm -f "$out/drc.txt"
(cd "$proj" && magic -dnull -noconsole -rcfile "$OSU018/osu018.magicrc" magic_drc_extract.tcl) \
  > "$proj/log/magic.log" 2>&1 || true
if [[ ! -f "$out/drc.txt" || ! -f "$proj/${top}_layout.spice" ]]; then
  echo "layout.sh: magic failed (no drc.txt or extracted netlist); see $proj/log/magic.log" >&2
  exit 1
fi
drc_errors=$(awk '/^drc_errors/ {print $2}' "$out/drc.txt")
step_done drc_extract

# ---- LVS (netgen): the layout's netlist against the mapped one, macros black boxes ---
if [[ "$plant" == lvs ]]; then   # the first instance's first signal pin left open
  awk '!done && /^X/ {for (i = 2; i < NF; i++) if ($i != "vdd" && $i != "gnd") {$i = "planted_open"; done = 1; break}} {print}' \
    "$proj/$top.spc" > "$proj/$top.spc.planted" && mv "$proj/$top.spc.planted" "$proj/$top.spc"
fi
(cd "$proj" && netgen-lvs -batch lvs "${top}_layout.spice $top" "$top.spc $top" \
   "$OSU018/osu018_setup.tcl" "$out/lvs.txt" -blackbox) > "$proj/log/lvs.log" 2>&1 || true
# a match: "Netlists match uniquely", or "Netlists match with N symmetries" (nets netgen
# cannot tell apart by their connections, exp2's two; it pairs them by name and reports
# "Circuits match uniquely")
lvs_match=0
if grep -q 'Netlists match uniquely\|Netlists match with [0-9]* symmetr' "$out/lvs.txt" 2>/dev/null \
   && ! grep -qi 'Netlists do not match\|Top level cell failed' "$out/lvs.txt"; then
  lvs_match=1
fi
step_done lvs

# ---- post-layout STA (OpenSTA with the SPEF) ---------------------------------------
sta_note=""
top_dir="$flows/designs/$top"
# a design variant without a folder of its own takes the generic one, as silicon.sh does
[[ -d "$top_dir" || "$top" != specular_* || ! -f "$root/rtl/design_space/$top.v" ]] || top_dir="$flows/designs/variant"
constraints="$top_dir/constraints.tcl"
if [[ $sta -eq 1 && -f "$constraints" && -f "$proj/$top.spef" ]]; then
  mkdir -p "$out/sta"
  {
    echo "set lib {$lib}"
    echo "set rom_lib {${rom_lib:-}}"
    echo "set netlist {$proj/$top.rtlnopwr.v}"
    echo "set top {$top}"
    echo "set top_dir {$top_dir}"
    echo "set out {$out/sta}"
    echo "set spef {$proj/$top.spef}"
    echo "source {$flows/synthesis/sta.tcl}"
  } > "$out/sta/sta_run.tcl"
  if ! sta -no_splash -exit "$out/sta/sta_run.tcl" > "$out/sta/sta.log" 2>&1 \
     || ! grep -q t_sta_ns "$out/sta/sta_summary.txt" 2>/dev/null; then
    echo "layout.sh: post-layout sta failed; see $out/sta/sta.log" >&2
    exit 1
  fi
  step_done sta
  # a netlist folder gatesim.sh reads (--netlist-dir OUT_DIR/postlayout): the laid-out
  # netlist and the SDF OpenSTA wrote with the wires, beside silicon.sh's ROM models
  if [[ -n "$netlist_dir" ]]; then
    rm -rf "$out/postlayout"
    mkdir -p "$out/postlayout"
    cp -r "$netlist_dir"/. "$out/postlayout/"
    # blif2Verilog's macro bus pins (.A[0](n)) as Verilog Icarus reads (.A({..., n}))
    /usr/bin/python3 "$flows/layout/verilog_bus_pins.py" "$proj/$top.rtlnopwr.v" "$out/postlayout/mapped.v" \
      || { echo "layout.sh: verilog_bus_pins.py failed" >&2; exit 1; }
    cp "$out/sta/device.sdf" "$out/postlayout/device.sdf"
    cp "$out/sta/sta_summary.txt" "$out/postlayout/sta_summary.txt"
    cp "$out/wire_cap.txt" "$out/postlayout/wire_cap.txt"   # energy.sh weighs each net's wire
  fi
elif [[ $sta -eq 1 ]]; then
  sta_note="no post-layout STA: $top has no scripts/flows/designs/$top/constraints.tcl"
  echo "layout.sh: note: $sta_note" >&2
fi

# ---- the summary ---------------------------------------------------------------------
{
  [[ $routed_before -eq 0 ]] || cat "$proj/log/routing_before_resume.txt"
  for i in "${!step_names[@]}"; do echo "${step_names[$i]}_s ${step_times[$i]}"; done
  for i in "${!step_names[@]}"; do echo "${step_names[$i]}_cpu_s ${step_cpus[$i]}"; done
} > "$out/times.txt"
/usr/bin/python3 "$flows/layout/layout_report.py" "$out" "$top" "$utilisation" "$unrouted" \
  "$drc_errors" "$lvs_match" "$sta_note" || { echo "layout.sh: layout_report.py failed" >&2; exit 1; }

# ---- the picture: PNG (KLayout, batch) and SVG (layout/layout_svg.py) ----------------
if command -v klayout >/dev/null; then
  lef_list="$OSU018/osu018_stdcells.lef"
  [[ -z "$macros_lef" ]] || for f in "$proj"/source/macros/*.lef; do lef_list="$lef_list,$f"; done
  (cd "$proj" && QT_QPA_PLATFORM=offscreen klayout -b -rd def="$proj/${top}_route.def" -rd lefs="$lef_list" \
     -rd summary="$out/layout_summary.json" -rd png="$out/die.png" -rd width=2000 \
     -r "$flows/layout/layout_picture.rb") > "$proj/log/klayout.log" 2>&1 \
    || echo "layout.sh: note: klayout could not draw the die; see $proj/log/klayout.log" >&2
else
  echo "layout.sh: note: klayout not installed: no die.png" >&2
fi
/usr/bin/python3 "$flows/layout/layout_svg.py" "$out" "$top" "$out/die.svg" > /dev/null \
  || echo "layout.sh: note: layout_svg.py could not draw the die" >&2
step_done picture
printf 'picture_s %s\npicture_cpu_s %s\n' "${step_times[-1]}" "${step_cpus[-1]}" >> "$out/times.txt"

verdict=0
bare=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["nets_without_wire_in_def"])' "$out/layout_summary.json")
[[ "$bare" == 0 ]] || { echo "layout.sh: $bare nets of two or more pins have no wire in the routed DEF" >&2; verdict=1; }
[[ "$unrouted" == 0 ]] || { echo "layout.sh: $unrouted nets unrouted (qrouter); see $proj/log/route.log" >&2; verdict=1; }
[[ "$drc_errors" == 0 ]] || { echo "layout.sh: $drc_errors DRC errors; each with its reason in $out/drc.txt" >&2; verdict=1; }
[[ $lvs_match -eq 1 ]] || { echo "layout.sh: LVS mismatch; see $out/lvs.txt" >&2; verdict=1; }
exit $verdict
