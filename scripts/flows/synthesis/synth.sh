#!/usr/bin/env bash
# What the device costs: Yosys synthesises rtl/ to CMOS gates and writes a report.
#
#   scripts/flows/synthesis/synth.sh OUT_DIR [ROM_DIR]
#
# OUT_DIR gets synth_report.md (the tables docs/rtl.md quotes) and the raw Yosys output
# (yosys.log, stat_hierarchy.txt, stat_flat.txt, ltp.txt, memories.txt). ROM_DIR holds
# rom5.hex and rom38.hex (default: build/rtl/rom/default, written by the CMake target
# specular_rom_images); Yosys reads them with $readmemh.
#
# The flow keeps both ROMs as memories (`memory -nomap`): mapped to gates, the
# 32 K-word ROM 5 would never finish. They are counted in bits (size x width) instead,
# since `stat` prints no memory bits for them. Logic is mapped to NAND/NOR/NOT
# (`abc -g cmos2 -fast`; the full ABC script spends minutes on the multipliers), then
#   - cells per block, hierarchical (one row per module, times its instances);
#   - flip-flops: registers 1, 2, 9-12 ($_DFF_P_) and flip-flops 41-43 ($_DFFSR_);
#   - transistors: `stat -tech cmos` (NOT 2, NAND/NOR 4, $_DFF_P_ 16) plus what it does
#     not count, at stated costs: ASYNC_FF_T per flip-flop with asynchronous set and
#     reset, ROM_BIT_T per ROM bit, the ROM share shown apart;
#   - the longest combinational path in gate levels, flattened (`ltp -noff`).
# Takes about 15 s. Exit status: 0 report written, 1 Yosys failed, 2 bad arguments.
set -euo pipefail

# Costs `stat -tech cmos` leaves out (docs/rtl.md explains the choice):
ASYNC_FF_T=36  # a D flip-flop with asynchronous set and reset as in the 7474: six 3-input NANDs
ROM_BIT_T=1    # a mask-programmed NOR ROM: one transistor site per bit (decoders, sense not counted)

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flows="$(dirname "$here")"   # scripts/flows: each flow a folder, the designs in designs/
root="$(cd "$flows/../.." && pwd)"
if [[ $# -lt 1 || $# -gt 2 || "$1" == -* ]]; then
  echo "usage: scripts/flows/synthesis/synth.sh OUT_DIR [ROM_DIR]   (ROM_DIR default: build/rtl/rom/default)" >&2
  exit 2
fi
out="$1"
rom_dir="${2:-$root/build/rtl/rom/default}"
for image in rom5.hex rom38.hex; do
  if [[ ! -f "$rom_dir/$image" ]]; then
    echo "synth.sh: '$rom_dir/$image' not found: build the ROM images first" \
         "(cmake --build build --target specular_rom_images) or name their folder" >&2
    exit 2
  fi
done
for tool in yosys python3; do
  command -v "$tool" >/dev/null || { echo "synth.sh: $tool not found (bash scripts/setup.sh installs it)" >&2; exit 2; }
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rom_dir="$(cd "$rom_dir" && pwd)"

sources=()
for f in "$root"/rtl/{device,primitives,design_space}/*.v; do sources+=("$f"); done  # rtl/sources.cmake

# multiply_round_saturate, the primitive multipliers 39 and 13–15 share, is flattened
# into each, and the leading-one normaliser into ROM 5: the cells stay counted per block
# of Fig. 1, and ABC sees the same logic.
script="read_verilog ${sources[*]}
hierarchy -check -top specular_device
setattr -mod -set keep_hierarchy 1 *
setattr -mod -unset keep_hierarchy *multiply_round_saturate *leading_one_normaliser
flatten
setattr -mod -unset keep_hierarchy *
proc; opt; memory -nomap; opt; wreduce; opt
techmap; opt
abc -g cmos2 -fast
opt_clean
tee -q -o $out/stat_hierarchy.txt stat -tech cmos
tee -q -o $out/memories.txt dump t:\$mem_v2
flatten; opt_clean
tee -q -o $out/stat_flat.txt stat -tech cmos
tee -q -o $out/ltp.txt ltp -noff"

if ! (cd "$rom_dir" && yosys -q -l "$out/yosys.log" -p "$script" >/dev/null 2>&1); then
  echo "synth.sh: yosys failed; see $out/yosys.log" >&2
  exit 1
fi

python3 - "$out" "$ASYNC_FF_T" "$ROM_BIT_T" <<'PY'
import re, sys
out, async_ff_t, rom_bit_t = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])

def read(name):
    with open(f"{out}/{name}") as f:
        return f.read()

# ---- hierarchical stat: primitive cells and transistors per module ----------------
hier = read("stat_hierarchy.txt")
modules, order = {}, []
current = None
for line in hier.splitlines():
    m = re.match(r"=== (.*) ===$", line.strip())
    if m:
        current = m.group(1)
        if current != "design hierarchy":
            modules[current] = {"cells": 0, "types": {}, "transistors": 0}
            order.append(current)
        continue
    if current is None or current == "design hierarchy":
        continue
    m = re.match(r"\s+(\S+)\s+(\d+)$", line)
    if m and (m.group(1).startswith("$_") or m.group(1).startswith("$mem")):
        modules[current]["types"][m.group(1)] = int(m.group(2))
        modules[current]["cells"] += int(m.group(2))
    m = re.search(r"Estimated number of transistors:\s+(\d+)", line)
    if m:
        modules[current]["transistors"] = int(m.group(1))

# instance counts: the design hierarchy section, nested by indentation
section = hier.split("=== design hierarchy ===")[1]
instances = {}
stack = []  # (indent, multiplicity)
for line in section.splitlines():
    m = re.match(r"(\s+)(\S+)\s+(\d+)$", line)
    if not m or m.group(2) not in modules:
        continue
    indent, name, count = len(m.group(1)), m.group(2), int(m.group(3))
    while stack and stack[-1][0] >= indent:
        stack.pop()
    total = count * (stack[-1][1] if stack else 1)
    instances[name] = instances.get(name, 0) + total
    stack.append((indent, total))

def label(module):
    base = module.split("\\")[1] if "\\" in module else module
    m = re.search(r"\\W=s32'([01]+)", module)
    return f"{base} (W={int(m.group(1), 2)})" if m else base

blocks = {  # module -> reference numbers, in Fig. 1 / Fig. 2 order
    "register (W=17)": "register 1", "register (W=10)": "register 2",
    "multiplexer3": "multiplexer 3", "multiplexer4": "multiplexer 4",
    "rom5": "ROM 5 (leading-one detector, normaliser; the ROM below)",
    "multiplier6": "multiplier 6", "inverter7": "inverter 7", "adder8": "adder 8",
    "inverter7 (W=37)": "inverter 7", "adder8 (W=37)": "adder 8",
    "register (W=37)": "register 9", "register (W=8)": "registers 10, 11, 12",
    "multiplier_rgb": "multipliers 13, 14, 15", "control_unit16": "control unit 16 (wiring)",
    "rom38": "ROM 38 (the ROM below)", "multiplier39": "multiplier 39",
    "d_flip_flop": "flip-flops 41, 42, 43", "and2": "AND 40", "inverter": "inverter 44",
    "nand3": "NANDs 45, 46", "nand2": "NAND 47", "specular_device": "top (wiring)"}
order_keys = list(blocks)
rows = []
for module in order:
    name = label(module)
    n = instances.get(module, 0)
    c = modules[module]
    key = name if name in blocks else name.split(" (")[0]
    rows.append((order_keys.index(key) if key in order_keys else 99, blocks.get(key, name),
                 name, n, c["cells"], c["cells"] * n, c["transistors"] * n))
rows.sort()
total_cells_hier = sum(r[5] for r in rows)

# ---- flattened totals, flip-flops, memories, longest path ------------------------
flat = read("stat_flat.txt")
flat_types = {m.group(1): int(m.group(2)) for m in re.finditer(r"^\s+(\$\S+)\s+(\d+)$", flat, re.M)}
total_cells = int(re.search(r"Number of cells:\s+(\d+)", flat).group(1))
stat_t = int(re.search(r"Estimated number of transistors:\s+(\d+)", flat).group(1))
sync_ff = sum(v for k, v in flat_types.items() if re.match(r"\$_DFFE?_[PN]+_$", k))
async_ff = sum(v for k, v in flat_types.items() if k.startswith("$_DFFSR"))
gates = {k: v for k, v in flat_types.items() if k in ("$_NAND_", "$_NOR_", "$_NOT_")}

mems = []  # (name, words, width); the dump's INIT parameters are dropped from the file
dump = read("memories.txt")
rom_names = {"mantissa_rom": "ROM 5 (rom5.mantissa_rom)", "k_rom": "ROM 38 (rom38.k_rom)"}
for m in re.finditer(r"cell \$mem_v2 (\S+)(.*?)\n  end", dump, re.S):
    size = int(re.search(r"parameter \\SIZE (\d+)", m.group(2)).group(1))
    width = int(re.search(r"parameter \\WIDTH (\d+)", m.group(2)).group(1))
    name = m.group(1).lstrip("\\")
    mems.append((rom_names.get(name, name), size, width))
mems.sort(key=lambda m: int(re.search(r'\d+', m[0]).group(0)) if re.search(r'\d+', m[0]) else 0)
with open(f"{out}/memories.txt", "w") as f:
    f.write("\n".join(l for l in dump.splitlines() if "parameter \\INIT" not in l) + "\n")
rom_bits = sum(s * w for _, s, w in mems)

ltp = read("ltp.txt")
levels = int(re.search(r"Longest topological path in \S+ \(length=(\d+)\)", ltp).group(1))
path = re.findall(r"^\s+(?:\d+|ff): (\S+(?: \[\d+\])?)", ltp, re.M)

logic_t = stat_t + async_ff * async_ff_t
rom_t = rom_bits * rom_bit_t
total_t = logic_t + rom_t
rom38 = [(size, width) for name, size, width in mems if name.startswith("ROM 38")][0]
rom38_all = rom38[0] * rom38[1]
rom38_one_bank = 1024 * rom38[1]  # a device built for one policy holds one bank

def fmt(n):
    return f"{n:,}".replace(",", " ")

lines = []
w = lines.append
w("# Synthesis cost of the RTL device (Yosys, scripts/flows/synthesis/synth.sh)\n")
w("Flow: `proc; opt; memory -nomap; opt; wreduce; opt; techmap; opt; abc -g cmos2 -fast`: "
  "logic mapped to NAND, NOR and NOT; ROMs kept as memories and counted in bits.\n")
w("## Cells per block (hierarchical)\n")
w("| block | module | instances | cells each | cells | transistors (stat) |")
w("|---|---|---:|---:|---:|---:|")
for _, block, name, n, each, cells, trans in rows:
    w(f"| {block} | {name} | {n} | {fmt(each)} | {fmt(cells)} | {fmt(trans)} |")
w(f"| **total** | | | | **{fmt(total_cells_hier)}** | **{fmt(sum(r[6] for r in rows))}** |\n")
w(f"Flattened: {fmt(total_cells)} cells (" +
  ", ".join(f"{k} {fmt(v)}" for k, v in sorted(flat_types.items())) + ").\n")
w("## Flip-flops\n")
w(f"- {sync_ff} edge-triggered flip-flops without reset ($_DFF_P_): registers 1, 2, 9, 10-12 "
  f"(17 + 10 + 37 + 3 x 8 = 88 bits)")
w(f"- {async_ff} flip-flops with asynchronous set and reset ($_DFFSR_): 41, 42, 43 of Fig. 2")
w(f"- total {sync_ff + async_ff}\n")
w("## ROMs (kept as memories, counted as size x width)\n")
w("| ROM | words | width | bits |")
w("|---|---:|---:|---:|")
for name, size, width in mems:
    w(f"| {name} | {fmt(size)} | {width} | {fmt(size * width)} |")
w(f"| **total** | | | **{fmt(rom_bits)}** |\n")
w(f"ROM 38 holds one bank per (constants, normalisation) policy, chosen by cfg_rom38_bank; "
  f"a device built for one policy holds one bank: 1 024 x {rom38[1]} = {fmt(rom38_one_bank)} bits.\n")
w("## Transistor estimate\n")
w(f"Costs: `stat -tech cmos` for NOT (2), NAND and NOR (4) and $_DFF_P_ (16); it counts "
  f"neither the asynchronous flip-flops nor the memories, added here at {async_ff_t} per "
  f"flip-flop with asynchronous set and reset (the 7474's six 3-input NANDs) and "
  f"{rom_bit_t} per ROM bit (a mask-programmed NOR ROM cell; decoders and sense amplifiers "
  f"not counted).\n")
w("| part | transistors |")
w("|---|---:|")
w(f"| logic (`stat -tech cmos`) | {fmt(stat_t)} |")
w(f"| asynchronous flip-flops ({async_ff} x {async_ff_t}) | {fmt(async_ff * async_ff_t)} |")
w(f"| **logic total** | **{fmt(logic_t)}** |")
for name, size, width in mems:
    w(f"| {name} ({fmt(size * width)} bits x {rom_bit_t}) | {fmt(size * width * rom_bit_t)} |")
w(f"| **ROM total** | **{fmt(rom_t)}** |")
w(f"| **device total** | **{fmt(total_t)}** |")
w(f"| device total with one ROM 38 bank | {fmt(total_t - (rom38_all - rom38_one_bank) * rom_bit_t)} |\n")
w(f"ROM share: {100.0 * rom_t / total_t:.1f} % of the total (logic {100.0 * logic_t / total_t:.1f} %).\n")
w("## Longest combinational path (flattened, `ltp -noff`)\n")
w(f"{levels} gate levels (a memory read counts as one level), from {path[0] if path else '?'} "
  f"to {path[-1] if path else '?'}.\n")
w("## Summary\n")
w("```")
for key, value in [("total_cells", total_cells), ("flip_flops", sync_ff + async_ff),
                   ("async_flip_flops", async_ff), ("rom_bits", rom_bits),
                   ("logic_transistors", logic_t), ("rom_transistors", rom_t),
                   ("total_transistors", total_t), ("gate_levels", levels)]:
    w(f"{key}: {value}")
w("```")
with open(f"{out}/synth_report.md", "w") as f:
    f.write("\n".join(lines) + "\n")
print(f"synth.sh: report in {out}/synth_report.md ({fmt(total_cells)} cells, "
      f"{fmt(total_t)} transistors, {levels} gate levels)")
PY
