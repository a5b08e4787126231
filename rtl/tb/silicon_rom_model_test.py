#!/usr/bin/env python3
"""silicon_rom_model: scripts/flows/synthesis/rom_model.py makes a macro of every read-only
memory of a top, by its size (docs/design_space/flow.md, "Silicon flow for variants").

  silicon_rom_model_test.py ROM_MODEL_PY SCRATCH

A Yosys-like memories JSON with ROM 5's and ROM 38's sizes, two different 512 x 20
tables and a second copy of one of them: ROM5_MACRO and ROM38_MACRO keep their figures
(567 517 and 343 664 um^2, docs/silicon.md), the two tables are ROM_512X20_MACRO and
ROM_512X20B_MACRO (the copy maps onto the first), each table's words come back from its
INIT in NAME.hex; a memory with a write port is refused naming it. Exit 0 pass, 1 fail.
"""
import json
import os
import subprocess
import sys


def mem(words, width, init, wr_ports=0):
    b = lambda v, w=32: format(v, f"0{w}b")
    return {"type": "$mem_v2", "parameters": {
        "SIZE": b(words), "WIDTH": b(width), "ABITS": b(max(1, (words - 1).bit_length())),
        "RD_PORTS": b(1), "WR_PORTS": b(wr_ports), "RD_CLK_ENABLE": "0", "INIT": init}}


def init_of(words, width, f):
    """INIT as Yosys writes it: MSB first, word k at bits [k*width +: width]."""
    return "".join(format(f(k) & ((1 << width) - 1), f"0{width}b") for k in reversed(range(words)))


def main():
    rom_model, scratch = sys.argv[1], sys.argv[2]
    os.makedirs(scratch, exist_ok=True)
    table_a = lambda k: k * 3 + 1
    table_b = lambda k: 0xFFFFF - k
    design = {"modules": {
        "rom5": {"cells": {"mantissa_rom": mem(32768, 22, "0" * (32768 * 22))}},
        "rom38": {"cells": {"k_rom": mem(16384, 25, "1" * (16384 * 25))}},
        "exp2_unit": {"cells": {"table": mem(512, 20, init_of(512, 20, table_a))}},
        "recip": {"cells": {"table": mem(512, 20, init_of(512, 20, table_b))}},
        "exp2_copy": {"cells": {"table": mem(512, 20, init_of(512, 20, table_a))}},
    }}
    path = os.path.join(scratch, "memories.json")
    json.dump(design, open(path, "w"))
    subprocess.run([sys.executable, rom_model, scratch, path], check=True)
    model = json.load(open(os.path.join(scratch, "rom_model.json")))
    macros = {m["name"]: m for m in model["macros"]}
    failures = []
    want = {"ROM5_MACRO": 567517, "ROM38_MACRO": 343664, "ROM38_BANK_MACRO": 36464}
    for name, area in want.items():
        if name not in macros or round(macros[name]["area_um2"]) != area:
            failures.append(f"{name}: area {macros.get(name, {}).get('area_um2')}, want {area}")
    for name in ("ROM_512X20_MACRO", "ROM_512X20B_MACRO"):
        m = macros.get(name)
        if not m or m["words"] != 512 or m["width"] != 20 or m["address_bits"] != 9:
            failures.append(f"{name}: {m}, want 512 x 20 with 9 address bits")
    inst = model["instances"]
    if sorted(inst.get("ROM_512X20_MACRO", [])) != ["exp2_copy/table", "exp2_unit/table"]:
        failures.append(f"ROM_512X20_MACRO instances {inst.get('ROM_512X20_MACRO')}")
    if inst.get("ROM_512X20B_MACRO") != ["recip/table"]:
        failures.append(f"ROM_512X20B_MACRO instances {inst.get('ROM_512X20B_MACRO')}")
    for name, f in (("ROM_512X20_MACRO", table_a), ("ROM_512X20B_MACRO", table_b)):
        hex_file = os.path.join(scratch, f"{name}.hex")
        words = open(hex_file).read().split() if os.path.exists(hex_file) else []
        if [int(w, 16) for w in words] != [f(k) & 0xFFFFF for k in range(512)]:
            failures.append(f"{name}.hex: not the table's words")
    ys = open(os.path.join(scratch, "rom_macro_map.ys")).read()
    if ys.count("techmap -map") != 5:
        failures.append(f"rom_macro_map.ys: {ys.count('techmap -map')} techmaps, want 5")
    # a memory with a write port: refused, named
    design["modules"]["ram"] = {"cells": {"buffer": mem(64, 8, "0" * 512, wr_ports=1)}}
    json.dump(design, open(path, "w"))
    r = subprocess.run([sys.executable, rom_model, scratch, path], capture_output=True, text=True)
    if r.returncode == 0 or "ram/buffer" not in r.stdout + r.stderr:
        failures.append(f"a RAM was not refused by name: status {r.returncode}, {r.stderr.strip()}")
    for f in failures:
        print("FAIL", f)
    print("PASS" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
