#!/usr/bin/env python3
"""silicon_report.md and silicon_summary.json from the files scripts/flows/synthesis/silicon.sh wrote.

  report.py OUT_DIR TOP TOP_DIR

Reads stat.txt (Yosys, areas per module), rom_model.json (the ROM macros), sta_summary.txt
and path_*.txt (OpenSTA), gatesim/tsim.txt (the T_sim bisection, when run), hazards.json
and hazards.md (gatesim.sh --hazards, when run), times.txt,
TOP_DIR/top.json (the per-top blocks, expected control-unit cells, paths, clocks per
result), and for a design variant (top.json "clocks_per_result": "testbench")
tb_rtl.txt (rtl/tb/specular_variant_tb.v in RTL: clocks per result, latency) and
gatesim_replay.txt (the same testbench at gate level at 1.1 T_sim). The summary's keys
are stable (docs/silicon.md and docs/design_space.md list them).
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))  # scripts/
from specular_flows import liberty  # noqa: E402

UTILISATION = 0.70     # standard-cell rows: cells over row area (room for wiring)
MACRO_HALO = 1.10      # ROM macros: 10 % halo for their power ring and pin access


def read(path):
    with open(path) as f:
        return f.read()


def module_label(name):
    """`$paramod\\register\\W=s32'...100101` -> `register W=37`; hashes dropped."""
    name = name.lstrip("\\")
    m = re.match(r"\$paramod\\(\w+)\\W=s32'([01]+)$", name)
    if m:
        return f"{m.group(1)} W={int(m.group(2), 2)}"
    m = re.match(r"\$paramod\$[0-9a-f]+\\(\w+)$", name)
    return m.group(1) if m else name


def parse_stat(text):
    modules = {}
    current = None
    for line in text.splitlines():
        m = re.match(r"=== (.*) ===$", line.strip())
        if m:
            current = m.group(1)
            if current != "design hierarchy":
                modules[module_label(current)] = {"cells": {}, "area": 0.0}
            continue
        if current is None or current == "design hierarchy":
            continue
        label = module_label(current)
        m = re.match(r"\s+([A-Z][A-Z0-9_]+)\s+(\d+)$", line)
        if m:
            modules[label]["cells"][m.group(1)] = int(m.group(2))
        m = re.search(r"Chip area for (?:top )?module '(.*)': ([\d.]+)", line)
        if m and module_label(m.group(1)) == label:
            modules[label]["area_incl"] = float(m.group(2))
    # instances per module from the hierarchy section (nested by indentation)
    instances = {}
    section = text.split("=== design hierarchy ===")[1].split("Number of wires")[0]
    stack = []
    for line in section.splitlines():
        m = re.match(r"(\s+)(\S+)\s+(\d+)$", line)
        if not m:
            continue
        indent, name, count = len(m.group(1)), module_label(m.group(2)), int(m.group(3))
        while stack and stack[-1][0] >= indent:
            stack.pop()
        total = count * (stack[-1][1] if stack else 1)
        instances[name] = instances.get(name, 0) + total
        stack.append((indent, total))
    flat = {}
    tail = text.split("=== design hierarchy ===")[1]
    for m in re.finditer(r"^\s+([A-Z][A-Z0-9_]+)\s+(\d+)$", tail, re.M):
        flat[m.group(1)] = int(m.group(2))
    return modules, instances, flat


def parse_path(path_file):
    text = read(path_file)
    sentence = text.splitlines()[0].lstrip("# ")
    if "No paths found" in text:
        return {"sentence": sentence, "found": False}
    start = re.search(r"Startpoint: (\S+)", text).group(1)
    end = re.search(r"Endpoint: (\S+)", text).group(1)
    arrival = float(re.search(r"([\d.-]+)\s+data arrival time", text).group(1))
    slack = float(re.search(r"([\d.-]+)\s+slack", text).group(1))
    required = float(re.search(r"([\d.-]+)\s+data required time", text).group(1))
    # Data path: the lines between the launching clock pin and "data arrival time";
    # every cell output is a gate level (the launching flip-flop's CLK -> Q is not).
    data = text.split("data arrival time")[0]
    cells = re.findall(r"^\s+[\d.-]+\s+[\d.-]+ [v^] (\S+)/(\w+)(?:\[\d+\])? \((\w+)\)", data, re.M)
    outputs = [(inst, cell) for inst, pin, cell in cells if pin in ("Y", "Q", "YS", "YC")]
    launch = outputs[0] if outputs and outputs[0][1].startswith("DFF") else None
    levels = [o for o in outputs if o is not launch]
    launch_clock = float(re.search(r"^\s+[\d.-]+\s+([\d.-]+)\s+clock \S+ \((?:rise|fall) edge\)", text, re.M).group(1))
    network = re.findall(r"^\s+([\d.-]+)\s+[\d.-]+\s+clock network delay", text, re.M)
    launch_latency = float(network[0]) if network else 0.0
    # a path from an input pin: its external input delay is the protocol's, not the path's
    external = re.search(r"^\s+([\d.-]+)\s+[\d.-]+ [v^] input external delay", text, re.M)
    delay = arrival - launch_clock - launch_latency - (float(external.group(1)) if external else 0.0)
    blocks = []
    for inst, _ in levels:
        block = inst.split("/")[0]
        if not blocks or blocks[-1] != block:
            blocks.append(block)
    return {"sentence": sentence, "found": True, "startpoint": start, "endpoint": end,
            "delay_ns": round(delay, 3), "arrival_ns": arrival, "required_ns": required,
            "slack_ns": slack, "gate_levels": len(levels), "blocks": blocks}


def parse_tb(path):
    """The last line of rtl/tb/specular_variant_tb.v's run: PASS with its figures, or the
    first MISMATCH/FATAL; with the period tried (a first line `period_ns X`, if any)."""
    if not os.path.exists(path):
        return None
    text = read(path)
    period = re.search(r"^period_ns ([\d.]+)", text, re.M)
    m = re.search(r"PASS (\d+) vectors: clocks_per_result ([\d.na]+) latency_clocks (\d+) "
                  r"first_latency_clocks (\d+)", text)
    result = {"period_ns": float(period.group(1)) if period else None}
    if m:
        result.update({"result": "PASS", "vectors": int(m.group(1)),
                       "clocks_per_result": float(m.group(2)) if m.group(2) != "na" else None,
                       "latency_clocks": int(m.group(3)), "first_latency_clocks": int(m.group(4))})
    elif re.search(r"\bPASS\b", text) and not re.search(r"MISMATCH|FATAL", text):
        result.update({"result": "PASS"})   # a device top's testbench: no figures
    else:
        bad = re.search(r"(MISMATCH.*|FATAL.*)$", text, re.M)
        result.update({"result": "FAIL", "first_failure": bad.group(1) if bad else "no result"})
    return result


def fmt(n, digits=0):
    s = f"{n:,.{digits}f}"
    return s.replace(",", " ")


def hazard_keys(hazards):
    """The hazard figures under stable summary keys (None when not measured)."""
    if hazards is None:
        return None
    keys = {"flip_flop41_" + k: v for k, v in hazards["flip_flop41_checks"].items()}
    for label, p in zip(("t_sim", "2_t_sim"), hazards["periods"].values()):
        h = p["at_offset_0"] or {}
        keys.update({
            f"{label}_period_ns": p["period_ns"],
            f"{label}_start_offsets_failing_of_16": p["offsets_failing"],
            f"{label}_start_failing_windows_ns": [[r["from_ns"], r["to_ns"]] for r in p["failing_windows"]],
            f"{label}_reset41_narrowest_ns": h.get("reset41_narrowest_ns"),
            f"{label}_reset41_recovery_margin_ns": h.get("recovery_margin_ns"),
            f"{label}_reset41_removal_margin_ns": h.get("removal_margin_ns"),
            f"{label}_reset41_not_cleared": h.get("reset41_not_cleared"),
            f"{label}_select36_after_clk_fall_ns": (h.get("select36_after_clk_fall_ns") or [None])[0],
            f"{label}_reg9_d_settle_ns": h.get("reg9_d_settle_ns"),
            f"{label}_strobe37_pulses": p["strobe37_pulses"],
            f"{label}_strobe37_narrowest_ns": p["strobe37_narrowest_ns"],
            f"{label}_pin35_pulses": p["pin35_pulses"],
            f"{label}_pin35_narrowest_ns": p["pin35_narrowest_ns"],
        })
    return keys


def main():
    out, top, top_dir = sys.argv[1], sys.argv[2], sys.argv[3]
    spec = json.loads(read(f"{top_dir}/top.json"))
    modules, instances, flat = parse_stat(read(f"{out}/stat.txt"))
    roms = json.loads(read(f"{out}/rom_model.json"))
    macros = {m["name"]: m for m in roms["macros"]}
    osu = liberty.cell_areas(read(os.environ.get("SPECULAR_OSU018_LIB",
                                        "/usr/share/qflow/tech/osu018/osu018_stdcells.lib")))

    def own_area(label):
        return sum(osu.get(c, 0.0) * n for c, n in modules[label]["cells"].items())

    # ---- area per block ----
    rows = []
    blocks = spec["blocks"]
    if blocks == "by_module":   # a design variant: every module Yosys kept, by name
        blocks = [[label, label] for label in sorted(modules)
                  if label not in ("inverter", "and2", "nand2", "nand3", "d_flip_flop")]
    for label, block in blocks:
        if label not in modules:
            raise SystemExit(f"report.py: module {label} not in stat.txt")
        n = instances.get(label, 1)
        cells = sum(v for c, v in modules[label]["cells"].items() if not c.endswith("_MACRO"))
        rows.append((block, label, n, cells * n, own_area(label) * n))
    known = {label for label, _ in blocks}
    for label in modules:
        if label not in known and not label in ("inverter", "and2", "nand2", "nand3", "d_flip_flop"):
            rows.append((label, label, instances.get(label, 1), 0, own_area(label) * instances.get(label, 1)))
    logic_area = sum(r[4] for r in rows)
    used = [n for n in macros if flat.get(n, 0) > 0]
    macro_area = sum(macros[n]["area_um2"] * flat[n] for n in used)
    one_bank = macro_area - macros["ROM38_MACRO"]["area_um2"] + macros["ROM38_BANK_MACRO"]["area_um2"] \
        if "ROM38_MACRO" in used else macro_area
    total = logic_area + macro_area
    total_one_bank = logic_area + one_bank
    die = logic_area / UTILISATION + macro_area * MACRO_HALO
    die_one_bank = logic_area / UTILISATION + one_bank * MACRO_HALO
    cells_total = sum(v for c, v in flat.items() if not c.endswith("_MACRO"))
    flip_flops = sum(v for c, v in flat.items() if c.startswith("DFF"))

    # ---- control unit cells ----
    cu = spec["control_unit_module"]
    cu_cells = modules[cu]["cells"] if cu else None
    cu_ok = cu_cells == spec["control_unit_cells"] if cu else None

    # ---- timing ----
    sta = dict(line.split() for line in read(f"{out}/sta_summary.txt").splitlines() if line.strip())
    t_sta = float(sta["t_sta_ns"])
    paths = {}
    for name, _, _ in spec["paths"]:
        paths[name] = parse_path(f"{out}/path_{name}.txt")
    # The worst path of the whole top (sta_worst_paths.txt's first), named by its ends.
    worst = None
    worst_text = read(f"{out}/sta_worst_paths.txt") if os.path.exists(f"{out}/sta_worst_paths.txt") else ""
    m = re.search(r"Startpoint: (\S+).*?\nEndpoint: (\S+).*?([\d.-]+)\s+data arrival time", worst_text, re.S)
    if m:
        worst = {"startpoint": m.group(1), "endpoint": m.group(2), "arrival_ns": float(m.group(3))}
    # Shares of the area (top.json "shares", e.g. the whole IP's bus, register block and
    # device): each a list of blocks' modules, the ROM macros apart.
    shares = []
    for name, labels in spec.get("shares", []):
        missing = [label for label in labels if label not in modules]
        if missing:
            raise SystemExit(f"report.py: share '{name}' names modules not in stat.txt: {missing}")
        cells = sum(v * instances.get(label, 1) for label in labels
                    for c, v in modules[label]["cells"].items() if not c.endswith("_MACRO"))
        area = sum(own_area(label) * instances.get(label, 1) for label in labels)
        shares.append({"name": name, "cells": cells, "area_um2": round(area, 1)})
    t_sim = None
    tsim_file = f"{out}/gatesim/tsim.txt"
    if os.path.exists(tsim_file):
        t = dict(line.split(None, 1) for line in read(tsim_file).splitlines() if line.strip())
        t_sim = float(t["t_sim_ns"])
    # Fig. 2's hazards (gatesim.sh --hazards via silicon.sh), when measured.
    hazards = None
    if os.path.exists(f"{out}/hazards.json"):
        hazards = json.loads(read(f"{out}/hazards.json"))
    times = dict(line.split() for line in read(f"{out}/times.txt").splitlines() if line.strip())
    unconstrained_counts = re.findall(r"There are (\d+) (.*?)\.", read(f"{out}/sta_unconstrained.txt"))

    # Clocks per result and latency: the device tops state theirs (top.json, from their
    # protocol: a start every 2 T, 3 T with a reload); a variant's are measured by the
    # generic testbench (silicon.sh runs it in RTL: tb_rtl.txt).
    cpr = spec.get("clocks_per_result", {"streamed": 2, "reload": 3, "latency": None})
    tb_rtl = gate_replay = None
    if cpr == "testbench":
        tb_rtl = parse_tb(f"{out}/tb_rtl.txt")
        if tb_rtl is None or tb_rtl["result"] != "PASS":
            raise SystemExit(f"report.py: no passing RTL testbench run in {out}/tb_rtl.txt")
        cpr = {"streamed": tb_rtl["clocks_per_result"], "reload": tb_rtl["clocks_per_result"],
               "latency": tb_rtl["latency_clocks"]}
    if os.path.exists(f"{out}/gatesim_replay.txt"):
        gate_replay = parse_tb(f"{out}/gatesim_replay.txt")
    streamed = 1e9 / (cpr["streamed"] * t_sta)
    reload = 1e9 / (cpr["reload"] * t_sta)
    summary = {
        "top": top,
        "library": "OSU 0.18 um (qflow-tech-osu018, osu018_stdcells.lib, typical 1.8 V 25 C)",
        "area_logic_um2": round(logic_area, 1),
        "area_macros_um2": round(macro_area, 1),
        "area_total_um2": round(total, 1),
        "area_total_one_rom38_bank_um2": round(total_one_bank, 1),
        "die_area_estimate_mm2": round(die / 1e6, 3),
        "die_area_estimate_one_rom38_bank_mm2": round(die_one_bank / 1e6, 3),
        "utilisation_assumed": UTILISATION,
        "cells": cells_total,
        "flip_flops": flip_flops,
        "rom_macros": {n: {"words": macros[n]["words"], "width": macros[n]["width"],
                           "area_um2": macros[n]["area_um2"], "access_ns": macros[n]["access_ns"]}
                       for n in macros},
        "rom_macro_instances": {n: flat[n] for n in used},
        "control_unit_cells": cu_cells,
        "control_unit_cells_match_fig2": cu_ok,
        "t_sta_ns": t_sta,
        "t_sim_ns": t_sim,
        "results_per_second_streamed_at_t_sta": round(streamed),
        "results_per_second_reload_at_t_sta": round(reload),
        "results_per_second_per_mm2_streamed": round(streamed / (die / 1e6)),
        "area_total_mm2": round(total / 1e6, 4),
        "clocks_per_result_streamed": cpr["streamed"],
        "clocks_per_result_reload": cpr["reload"],
        "latency_clocks": cpr["latency"],
        "latency_ns_at_t_sta": round(cpr["latency"] * t_sta, 2) if cpr["latency"] is not None else None,
        "results_per_second_per_mm2_area_total_streamed": round(streamed / (total / 1e6)),
        "rtl_testbench": tb_rtl,
        "gatesim_replay_1_1_t_sim": gate_replay,
        "paths": {name: {k: p[k] for k in ("delay_ns", "slack_ns", "gate_levels") if k in p}
                  for name, p in paths.items()},
        "worst_path": worst,
        "shares": shares,
        "times_s": {k: float(v) for k, v in times.items()},
        "hazards": hazard_keys(hazards),
    }
    with open(f"{out}/silicon_summary.json", "w") as f:
        json.dump(summary, f, indent=1)

    lines = []
    w = lines.append
    w(f"# {top} in silicon: OSU 0.18 um (scripts/flows/synthesis/silicon.sh)\n")
    w("Library: osu018_stdcells.lib (qflow-tech-osu018), typical corner (1.8 V, 25 C), no wire "
      "load model in the library (pin capacitances only). Mapping: Yosys `dfflibmap` + "
      "`abc -fast -liberty`, hierarchy kept per block; ROMs 5 and 38 as macros "
      "(scripts/flows/synthesis/rom_model.py); control unit 16 as Fig. 2's library cells.\n")
    w("## Area per block\n")
    w("| block | module | instances | cells | area (um^2) |")
    w("|---|---|---:|---:|---:|")
    for block, label, n, cells, area in rows:
        w(f"| {block} | {label} | {n} | {fmt(cells)} | {fmt(area)} |")
    w(f"| **logic total** | | | **{fmt(cells_total)}** | **{fmt(logic_area)}** |\n")
    w("## ROM macros\n")
    w("| macro | words x bits | rows x columns | array (um^2) | periphery (um^2) | area (um^2) | access (ns) |")
    w("|---|---|---|---:|---:|---:|---:|")
    for m in roms["macros"]:
        w(f"| {m['name']} | {fmt(m['words'])} x {m['width']} | {m['rows']} x {m['columns']} | "
          f"{fmt(m['array_um2'])} | {fmt(m['periphery_um2'])} | {fmt(m['area_um2'])} | {m['access_ns']:.2f} |")
    w("")
    w("ROM38_MACRO holds the 16 banks of rtl/device/rom38.v (the netlist's); ROM38_BANK_MACRO is the one "
      "bank a device built for one policy holds.\n")
    w("## Area total\n")
    w("| part | area (um^2) |")
    w("|---|---:|")
    w(f"| logic (standard cells) | {fmt(logic_area)} |")
    for n in used:
        w(f"| {n} | {fmt(macros[n]['area_um2'])} |")
    w(f"| **total (16 ROM 38 banks)** | **{fmt(total)}** |")
    w(f"| total with one ROM 38 bank | {fmt(total_one_bank)} |")
    w(f"| die estimate (cells at {UTILISATION:.0%} utilisation, macros + {MACRO_HALO - 1:.0%} halo) | "
      f"{fmt(die)} ({die / 1e6:.2f} mm^2) |")
    w(f"| die estimate, one ROM 38 bank | {fmt(die_one_bank)} ({die_one_bank / 1e6:.2f} mm^2) |\n")
    if shares:
        w("## Shares of the area\n")
        w("| part | cells | area (um^2) | of the logic | of logic and ROM macros |")
        w("|---|---:|---:|---:|---:|")
        for sh in shares:
            w(f"| {sh['name']} | {fmt(sh['cells'])} | {fmt(sh['area_um2'])} | "
              f"{100 * sh['area_um2'] / logic_area:.1f} % | {100 * sh['area_um2'] / total:.1f} % |")
        w(f"| ROM macros | | {fmt(macro_area)} | | {100 * macro_area / total:.1f} % |\n")
    w("## Cells and flip-flops\n")
    w("| cell | count |")
    w("|---|---:|")
    for c, v in sorted(flat.items()):
        w(f"| {c} | {fmt(v)} |")
    w(f"| **cells (macros apart)** | **{fmt(cells_total)}** |")
    w(f"| flip-flops | {flip_flops} (DFFPOSX1 {flat.get('DFFPOSX1', 0)}, DFFSR {flat.get('DFFSR', 0)}) |\n")
    if cu:
        w("## Control unit 16: Fig. 2's gates\n")
        w(f"Mapped cells of {cu}: " + ", ".join(f"{c} {v}" for c, v in sorted(cu_cells.items())) +
          f"; expected: " + ", ".join(f"{c} {v}" for c, v in sorted(spec["control_unit_cells"].items())) +
          f" ({spec['control_unit_cells_why']}). " + ("Match." if cu_ok else "**MISMATCH.**") + "\n")
    w("## Static timing (OpenSTA)\n")
    w(f"**T_sta = {t_sta:.2f} ns** (the smallest clock period with no negative setup slack, "
      f"bisection to 0.01 ns; clocks propagated through inverter 44 and NANDs 45-47).\n")
    w("| path | budget | worst delay (ns) | slack at T_sta (ns) | gate levels | blocks |")
    w("|---|---|---:|---:|---:|---|")
    for name, title, budget in spec["paths"]:
        p = paths[name]
        if not p["found"]:
            w(f"| {title} | {budget} | no path | | | |")
            continue
        w(f"| {title} | {budget} | {p['delay_ns']:.3f} | {p['slack_ns']:.3f} | {p['gate_levels']} | "
          f"{' -> '.join(p['blocks'])} |")
    w("")
    for name, title, _ in spec["paths"]:
        p = paths[name]
        if p["found"]:
            w(f"- {p['sentence']}; from {p['startpoint']} to {p['endpoint']} (path_{name}.txt)")
    if worst:
        w(f"- worst path of the top: from {worst['startpoint']} to {worst['endpoint']}, "
          f"arrival {worst['arrival_ns']:.3f} ns (sta_worst_paths.txt)")
    w("")
    w("## Results per second\n")
    w(f"| at T_sta = {t_sta:.2f} ns | results/s |")
    w("|---|---:|")
    w(f"| streamed (a start every {cpr['streamed']:g} T) | {fmt(streamed)} |")
    if cpr["reload"] != cpr["streamed"]:
        w(f"| with a reload of n, R, G, B ({cpr['reload']:g} T) | {fmt(reload)} |")
    w(f"| streamed, per mm^2 of die estimate | {fmt(streamed / (die / 1e6))} |\n")
    if cpr["latency"] is not None:
        w(f"Latency: {cpr['latency']:g} clocks = {cpr['latency'] * t_sta:.2f} ns at T_sta.\n")
    if gate_replay is not None:
        w(f"Gate-level replay at 1.1 T_sim = {gate_replay['period_ns']} ns: **{gate_replay['result']}**"
          + (f" ({gate_replay['vectors']} vectors, {gate_replay['clocks_per_result']} clocks per result, "
             f"latency {gate_replay['latency_clocks']} clocks)" if "vectors" in gate_replay
             else f" ({gate_replay['first_failure']})" if gate_replay["result"] == "FAIL" else "") + "\n")
    w("## T_sta beside T_sim\n")
    if t_sim is None:
        w("T_sim: not measured in this run (--no-gatesim).\n")
    else:
        w(f"| T_sta (ns) | T_sim (ns) | T_sim / T_sta |")
        w("|---:|---:|---:|")
        w(f"| {t_sta:.2f} | {t_sim:.1f} | {t_sim / t_sta:.3f} |\n")
        w("T_sim: the smallest period (bisection to 0.1 ns) at which scripts/flows/gatelevel/gatesim.sh replays "
          "every vector with the SDF delays (gatesim/tsim.txt).\n")
    w("## Fig. 2's hazards in the gate-level simulation\n")
    if hazards is None:
        if os.path.exists(f"{out}/hazards_skipped.txt"):
            w("Not measured: " + read(f"{out}/hazards_skipped.txt").strip() + ".\n")
        else:
            w("Not measured in this run (--no-gatesim or --no-hazards).\n")
    else:
        table = read(f"{out}/hazards.md").split("\n", 2)[2]  # without its title
        w(table)
    w("## What STA does not time, and what it assumes there\n")
    for count, what in unconstrained_counts:
        w(f"- OpenSTA check_setup: {count} {what} (sta_unconstrained.txt)")
    for what, why in spec["unconstrained"]:
        w(f"- {what}: {why}")
    w("")
    w("## Run times\n")
    w("| step | s |")
    w("|---|---:|")
    for k, v in times.items():
        w(f"| {k} | {float(v):.1f} |")
    w("")
    w("## Summary\n")
    w("```")
    for key in ("area_logic_um2", "area_macros_um2", "area_total_um2", "die_area_estimate_mm2",
                "cells", "flip_flops", "t_sta_ns", "t_sim_ns", "results_per_second_streamed_at_t_sta"):
        w(f"{key}: {summary[key]}")
    w("```")
    with open(f"{out}/silicon_report.md", "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"silicon.sh: report in {out}/silicon_report.md (area {total / 1e6:.3f} mm^2, "
          f"T_sta {t_sta:.2f} ns" + (f", T_sim {t_sim:.1f} ns" if t_sim else "") + ")")
    return 0 if cu_ok in (True, None) else 1


if __name__ == "__main__":
    sys.exit(main())
