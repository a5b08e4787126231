#!/usr/bin/env python3
"""The figures of a layout (scripts/flows/layout/layout.sh): layout_summary.json and layout_report.md.

  layout_report.py OUT_DIR TOP UTILISATION_ASKED UNROUTED DRC_ERRORS LVS_MATCH STA_NOTE

Reads OUT_DIR/qflow/TOP_route.def (the routed layout), the cells' and macros' LEF for
their sizes, OUT_DIR/instances.tsv (layout name -> netlist name: the block of Fig. 1 is
the netlist name's part before the first dot), OUT_DIR/times.txt and, when STA ran,
OUT_DIR/sta/. Gives the die and core, the standard cells' area and the macros', the
utilisation (cell area over the standard-cell core: the placed cells' extent, fill included), the wire length per metal, where
each block was placed (bounding box and centre of its cells) and the worst post-layout
path with its instances named.
"""
import json
import os
import re
import sys

OSU018 = os.environ.get("SPECULAR_OSU018_DIR", "/usr/share/qflow/tech/osu018")


def lef_sizes(path):
    sizes, name = {}, None
    for line in open(path):
        m = re.match(r"\s*MACRO\s+(\S+)", line)
        if m:
            name = m.group(1)
        m = re.match(r"\s*SIZE\s+([\d.]+)\s+BY\s+([\d.]+)", line)
        if m and name:
            sizes[name] = (float(m.group(1)), float(m.group(2)))
    return sizes


def read_def(path):
    """DIEAREA, ROWs, COMPONENTS (name, cell, x, y, orientation) and the routed wire
    length per layer, in um."""
    text = open(path).read()
    units = float(re.search(r"UNITS DISTANCE MICRONS (\d+)", text).group(1))
    die = [float(v) / units for v in re.search(r"DIEAREA\s+\(\s*(\S+)\s+(\S+)\s*\)\s*\(\s*(\S+)\s+(\S+)\s*\)", text).groups()]
    rows = []
    for m in re.finditer(r"^ROW\s+\S+\s+\S+\s+(\S+)\s+(\S+)\s+\S+\s+DO\s+(\d+)\s+BY\s+(\d+)\s+STEP\s+(\S+)\s+(\S+)", text, re.M):
        x, y, nx, ny, sx, sy = (float(v) for v in m.groups())
        rows.append((x / units, y / units, nx * sx / units if nx > 1 else sx / units))
    comps = []
    sect = re.search(r"^COMPONENTS.*?^END COMPONENTS", text, re.M | re.S).group(0)
    for m in re.finditer(r"-\s+(\S+)\s+(\S+)\s+\+\s+(?:PLACED|FIXED)\s+\(\s*(\S+)\s+(\S+)\s*\)\s+(\S+)", sect):
        comps.append((m.group(1), m.group(2), float(m.group(3)) / units, float(m.group(4)) / units, m.group(5)))
    length = {}
    bare = 0   # nets of two or more pins without a routed wire (a check beside qrouter's)
    nets = re.search(r"^NETS.*?^END NETS", text, re.M | re.S)
    if nets:
        for stmt in nets.group(0).split(";"):
            if stmt.count("(") - stmt.count("( *") >= 2 and "ROUTED" not in stmt and "- " in stmt:
                pins = re.findall(r"\(\s*(\S+)\s+(\S+)\s*\)", stmt.split("+")[0])
                if len(pins) >= 2:
                    bare += 1
            # every wire: a layer then points ( x y ) with * for the unchanged coordinate
            for m in re.finditer(r"(?:ROUTED|NEW)\s+(\S+)(.*?)(?=\bNEW\b|$)", stmt, re.S):
                layer = m.group(1)
                pts, px, py = [], None, None
                for pm in re.finditer(r"\(\s*(-?[\d.]+|\*)\s+(-?[\d.]+|\*)", m.group(2)):
                    x = px if pm.group(1) == "*" else float(pm.group(1))
                    y = py if pm.group(2) == "*" else float(pm.group(2))
                    pts.append((x, y))
                    px, py = x, y
                for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
                    length[layer] = length.get(layer, 0.0) + (abs(x1 - x0) + abs(y1 - y0)) / units
    return die, rows, comps, length, bare


def main():
    if len(sys.argv) != 8:
        sys.stderr.write("usage: layout_report.py OUT_DIR TOP UTILISATION UNROUTED DRC_ERRORS LVS_MATCH STA_NOTE\n")
        return 2
    out, top, util_asked, unrouted, drc, lvs, sta_note = sys.argv[1:]
    proj = f"{out}/qflow"
    sizes = lef_sizes(f"{OSU018}/osu018_stdcells.lef")
    macro_names = set()
    macro_dir = f"{proj}/source/macros"
    for f in sorted(os.listdir(macro_dir)) if os.path.isdir(macro_dir) else []:
        ms = lef_sizes(f"{macro_dir}/{f}")
        macro_names |= set(ms)
        sizes.update(ms)
    die, rows, comps, length, bare = read_def(f"{proj}/{top}_route.def")
    names = {}
    for line in open(f"{out}/instances.tsv").read().splitlines()[1:]:
        lay, net = line.split("\t")
        names[lay] = net
    cell_area = macro_area = fill_area = 0.0
    blocks = {}
    macros = []
    for name, cell, x, y, orient in comps:
        w, h = sizes.get(cell, (0.0, 0.0))
        if cell in macro_names:
            macro_area += w * h
            macros.append({"instance": names.get(name, name), "cell": cell, "x_um": x, "y_um": y,
                           "w_um": w, "h_um": h, "orientation": orient})
            continue
        if cell.startswith("FILL") or name not in names:
            fill_area += w * h
            continue
        cell_area += w * h
        net = names[name]
        block = net.split(".")[0] if "." in net and not net.startswith("$") else "(top)"
        b = blocks.setdefault(block, {"cells": 0, "area_um2": 0.0, "x": [], "y": []})
        b["cells"] += 1
        b["area_um2"] += w * h
        b["x"].append(x + w / 2)
        b["y"].append(y + h / 2)
    die_w, die_h = die[2] - die[0], die[3] - die[1]
    # qflow's DEF has no ROW statements: the core is the placed cells' extent (the rows
    # graywolf made, fill included) and the macros'
    placed = [(x, y, x + sizes.get(c, (0, 0))[0], y + sizes.get(c, (0, 0))[1])
              for _, c, x, y, _ in comps if c not in macro_names]
    core = (min(p[0] for p in placed), min(p[1] for p in placed),
            max(p[2] for p in placed), max(p[3] for p in placed))
    core_area = (core[2] - core[0]) * (core[3] - core[1])
    block_list = {}
    for k, b in sorted(blocks.items()):
        xs, ys = sorted(b["x"]), sorted(b["y"])
        lo, hi = int(0.05 * (len(xs) - 1)), int(0.95 * (len(xs) - 1))
        block_list[k] = {"cells": b["cells"], "area_um2": round(b["area_um2"], 1),
                         "centre_um": [round(sum(xs) / len(xs), 1), round(sum(ys) / len(ys), 1)],
                         "box_5_95_um": [round(xs[lo], 1), round(ys[lo], 1), round(xs[hi], 1), round(ys[hi], 1)]}
    times = {}
    if os.path.exists(f"{out}/times.txt"):
        for line in open(f"{out}/times.txt"):
            k, v = line.split()
            times[k] = float(v)
    # layout.sh's mending of qrouter's DEF (layout/layout_repair.py), and netgen's symmetries
    repairs = []
    if os.path.exists(f"{out}/repairs.txt"):
        repairs = [l for l in open(f"{out}/repairs.txt").read().splitlines()[2:] if l]
    m = re.search(r"Netlists match with (\d+) symmetr", open(f"{out}/lvs.txt").read()) \
        if os.path.exists(f"{out}/lvs.txt") else None
    symmetries = int(m.group(1)) if m else 0
    # qrouter's stage 3 (the clean-up reroute), left out by layout.sh --no-cleanup
    route_log = f"{proj}/log/route.log"
    stage3 = "Running stage3" in open(route_log).read() if os.path.exists(route_log) else None
    summary = {
        "top": top,
        "die_um": [round(die_w, 2), round(die_h, 2)],
        "die_area_mm2": round(die_w * die_h / 1e6, 4),
        "core_um": [round(v, 2) for v in core],
        "core_area_mm2": round(core_area / 1e6, 4),
        "standard_cells": sum(b["cells"] for b in blocks.values()),
        "standard_cell_area_um2": round(cell_area, 1),
        "macro_area_um2": round(macro_area, 1),
        "fill_and_spacer_area_um2": round(fill_area, 1),
        "utilisation_asked": float(util_asked),
        "utilisation": round(cell_area / max(core_area, 1e-9), 4),
        "utilisation_with_macros": round((cell_area + macro_area) / max(die_w * die_h, 1e-9), 4),
        "wire_length_um": {k: round(v, 1) for k, v in sorted(length.items())},
        "wire_length_total_um": round(sum(length.values()), 1),
        "unrouted_nets": unrouted if unrouted == "unknown" else int(unrouted),
        "nets_without_wire_in_def": bare,
        "drc_errors": int(drc),
        "lvs_match": lvs == "1",
        "lvs_symmetries": symmetries,
        "repairs": repairs,
        "router_stage3": stage3,
        "drc_lvs_views": "abstract (LEF): qflow-tech-osu018 has no cell GDS",
        "macros": macros,
        "blocks": block_list,
        "times_s": times,
        "sta_note": sta_note or None,
        "t_sta_ns": None,
        "worst_path": None,
    }
    sta_dir = f"{out}/sta"
    if os.path.exists(f"{sta_dir}/sta_summary.txt"):
        for line in open(f"{sta_dir}/sta_summary.txt"):
            k, v = line.split()
            if k == "t_sta_ns":
                summary["t_sta_ns"] = float(v)
        worst = open(f"{sta_dir}/sta_worst_paths.txt").read() if os.path.exists(f"{sta_dir}/sta_worst_paths.txt") else ""
        m = re.search(r"Startpoint: (\S+).*?Endpoint: (\S+)", worst, re.S)
        if m:
            tr = lambda pin: (names.get(pin.split("/")[0], pin.split("/")[0]) + ("/" + pin.split("/")[1] if "/" in pin else ""))
            summary["worst_path"] = {"startpoint": tr(m.group(1)), "endpoint": tr(m.group(2)),
                                     "startpoint_layout": m.group(1), "endpoint_layout": m.group(2)}
    json.dump(summary, open(f"{out}/layout_summary.json", "w"), indent=1)
    md = [f"# Layout of {top}", "",
          "| figure | value |", "|---|---:|",
          f"| die | {die_w:.1f} x {die_h:.1f} um = {summary['die_area_mm2']} mm² |",
          f"| standard cells | {summary['standard_cells']} ({cell_area:.0f} um²) |",
          f"| macros | {len(macros)} ({macro_area:.0f} um²) |",
          f"| utilisation (cells over the standard-cell core; asked {util_asked}) | {summary['utilisation']:.3f} |",
          f"| wire length | {summary['wire_length_total_um'] / 1000:.1f} mm |",
          f"| unrouted nets | {unrouted} |", f"| DRC errors (abstract views) | {drc} |",
          f"| LVS | {'match' if lvs == '1' else 'MISMATCH'}"
          f"{f' ({symmetries} symmetries)' if symmetries else ''} |",
          f"| qrouter's stage 3 (clean-up reroute) | {'run' if stage3 else 'left out' if stage3 is False else 'unknown'} |",
          f"| qrouter's DEF mended (layout_repair.py) | {len(repairs)} |",
          f"| T_sta after layout | {summary['t_sta_ns'] if summary['t_sta_ns'] else (sta_note or 'not run')} |", ""]
    if summary["worst_path"]:
        md += [f"Worst path: {summary['worst_path']['startpoint']} -> {summary['worst_path']['endpoint']}", ""]
    md += [f"- {r}" for r in repairs] + ([""] if repairs else [])
    md += ["| step | s |", "|---|---:|"] + [f"| {k} | {v} |" for k, v in times.items()] + [""]
    md += ["| block | cells | centre (um) |", "|---|---:|---|"]
    md += [f"| {k} | {b['cells']} | {b['centre_um']} |" for k, b in block_list.items()]
    open(f"{out}/layout_report.md", "w").write("\n".join(md) + "\n")
    print(f"layout.sh: die {summary['die_area_mm2']} mm², utilisation {summary['utilisation']:.3f}, "
          f"wire {summary['wire_length_total_um'] / 1000:.1f} mm, unrouted {unrouted}, DRC {drc}, "
          f"LVS {'match' if lvs == '1' else 'mismatch'}, T_sta {summary['t_sta_ns']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
