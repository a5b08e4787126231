#!/usr/bin/env python3
"""The design space after layout, from its table (issue 48): docs/design_space/layout_table.md
read back, its Pareto column checked against the fronts worked out from the table's own
figures, and the three *_layout.svg plots drawn from them.

Why: the layout runs behind that table (silicon.sh's and layout.sh's folders, hours of
CPU each) do not outlive the machine they ran on, so rows are added by hand when a layout
finishes. design_space.py needs every design's folders; this needs only the table, so a
hand-written row cannot leave a wrong Pareto mark or a stale plot behind.

  python3 scripts/flows/design_space/layout_fronts.py TABLE [--fix] [--svg-dir DIR] [--embed PAGE]
          [--set LABEL LAYOUT_SUMMARY SILICON_SUMMARY [ENERGY_JSON]]

Each row: design | after layout (yes / no (estimate)) | die (mm²) | T_sta (ns) |
results/s per mm² (M) | energy per result (pJ) | lobe max |err| | Pareto. A figure is
"before → **after**" for a design laid out, "before" for one that is not (energy may be
"—"). The fronts, as design_space.py draws them (design_space.pareto: both axes
minimised), are from the mixed figures: after layout where there is one, the estimate
otherwise. area: die against error; throughput/mm²: results/s per mm² (maximised) against
error; energy–error: energy per result against error.

Without --fix: exit 1 if a row's Pareto column differs from the fronts worked out (each
such row named, with what it says and what the figures give), or if its "after layout"
column disagrees with its figures. --fix rewrites the Pareto column in place instead.
--svg-dir (needs matplotlib: Debian's /usr/bin/python3) draws area_vs_error_layout.svg,
throughput_vs_error_layout.svg and energy_vs_error_layout.svg.

--set writes one design's row from its layout run (then the Pareto column, as --fix):
layout.sh's layout_summary.json (refused unless clean: 0 unrouted nets, 0 DRC errors, LVS
match), the silicon.sh summary it was laid out from (its top must be the row's design, its
die estimate and T_sta the row's estimates) and energy.sh's energy.json on the post-layout
netlist. The figures are design_space.py's: die_area_mm2, t_sta_ns, 10^9 / (T_sta ×
clocks_per_result_streamed) / die, and the random operands' mean energy. --embed PAGE puts
the table written into PAGE between its <!-- NAME --> and <!-- /NAME --> markers (NAME:
the table's file name). Exit 0 as checked or written, 1 a disagreement, an unreadable row
or a refused run, 2 bad arguments.
"""
import argparse
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# the fronts' rule, the plots, the designs' labels and the energy figure: once, there
from design_space import DEVICE_TOPS, design_name, energy_figure, layout_faults, pareto, plot  # noqa: E402

FRONTS = ("area", "throughput/mm²", "energy–error")
ARROW = re.compile(r"^([0-9.e+-]+) → \*\*([0-9.e+-]+)\*\*$")


class RowError(Exception):
    pass


def figure(cell, label, column):
    """(before, after) of one cell: after is None where the design is not laid out."""
    cell = cell.strip()
    if cell == "—":
        return None, None
    m = ARROW.match(cell)
    try:
        return (float(m.group(1)), float(m.group(2))) if m else (float(cell), None)
    except ValueError:
        raise RowError(f"{label}: {column} '{cell}' is not 'N' or 'N → **M**'")


def read_table(path):
    """The table's lines and its designs: label, laid out, (before, after) per figure,
    error, the Pareto marks as written, and the line index of each row."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    designs = []
    for i, line in enumerate(lines):
        cells = [c.strip() for c in line.split("|")]
        if len(cells) < 10 or not line.startswith("| ") or cells[1] == "design" or cells[1].startswith("---"):
            continue
        label = cells[1]
        if cells[2] not in ("yes", "no (estimate)"):
            raise RowError(f"{label}: after layout '{cells[2]}' is not 'yes' or 'no (estimate)'")
        fig = {k: figure(cells[n], label, k) for n, k in ((3, "die"), (4, "t_sta"), (5, "tput"), (6, "energy"))}
        try:
            err = float(cells[7])
        except ValueError:
            raise RowError(f"{label}: lobe max |err| '{cells[7]}' is not a number")
        marks = [m.strip() for m in cells[8].split(",") if m.strip()]
        unknown = [m for m in marks if m not in FRONTS]
        if unknown:
            raise RowError(f"{label}: Pareto mark '{unknown[0]}' is none of {', '.join(FRONTS)}")
        designs.append({"label": label, "laid_out": cells[2] == "yes", "fig": fig, "error": err,
                        "marks": marks, "line": i, "cells": cells})
    if not designs:
        raise RowError("no design rows")
    return lines, designs


def consistency(d):
    """A row laid out has a figure after layout for die and T_sta; one that is not has none."""
    has = [k for k in ("die", "t_sta", "tput", "energy") if d["fig"][k][1] is not None]
    if d["laid_out"] and not {"die", "t_sta", "tput"} <= set(has):
        return f"{d['label']}: 'yes' after layout but die, T_sta or results/s per mm² has no '→ **after**'"
    if not d["laid_out"] and has:
        return f"{d['label']}: 'no (estimate)' but {', '.join(has)} has a figure after layout"
    return None


def mixed(designs, key):
    return [d["fig"][key][1] if d["fig"][key][1] is not None else d["fig"][key][0] for d in designs]


def fronts(designs):
    err = [d["error"] for d in designs]
    die, tput, energy = mixed(designs, "die"), mixed(designs, "tput"), mixed(designs, "energy")
    return {"area": pareto(list(zip(die, err))),
            "throughput/mm²": pareto([(-t if t is not None else None, e) for t, e in zip(tput, err)]),
            "energy–error": pareto(list(zip(energy, err)))}


def set_row(designs, lines, label, paths):
    """Rewrite the row of `label` from its layout run (see --set); RowError if refused."""
    rows = [d for d in designs if d["label"] == label]
    if not rows:
        raise RowError(f"--set: no row '{label}' (rows: {', '.join(d['label'] for d in designs)})")
    d = rows[0]
    loaded = []
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                loaded.append(json.load(f))
        except (OSError, ValueError) as e:
            raise RowError(f"--set {label}: {path}: {e}")
    lay, sil = loaded[0], loaded[1]
    energy = loaded[2] if len(loaded) > 2 else None
    faults = layout_faults(lay)
    if faults:
        raise RowError(f"--set {label}: {paths[0]}: not clean ({', '.join(faults)})")
    for what, top in (("layout summary", lay.get("top")), ("silicon summary", sil.get("top"))):
        if DEVICE_TOPS.get(top, design_name(top or "")) != label:
            raise RowError(f"--set {label}: the {what}'s top '{top}' is not the row's design")
    for key, column, fmt in (("die_area_estimate_mm2", "die", "{:.3f}"), ("t_sta_ns", "t_sta", "{:.2f}")):
        if fmt.format(sil[key]) != fmt.format(d["fig"][column][0]):
            raise RowError(f"--set {label}: the silicon summary's {key} {sil[key]} is not the row's "
                           f"estimate {fmt.format(d['fig'][column][0])}")
    die, t_sta, cpr = lay["die_area_mm2"], lay["t_sta_ns"], sil["clocks_per_result_streamed"]
    after = {"die": ("{:.3f}", die), "t_sta": ("{:.2f}", t_sta), "tput": ("{:.2f}", 1e9 / (t_sta * cpr) / die / 1e6),
             "energy": ("{:.0f}", energy_figure(energy) if energy else None)}
    cells = d["cells"]
    if after["energy"][1] is not None and cells[6].split(" → ")[0] == "—":
        raise RowError(f"--set {label}: the row has no energy before layout ('—') to set one after "
                       "beside: write the figure of energy.sh on the run's silicon/ there first")
    cells[2] = "yes"
    for n, key in ((3, "die"), (4, "t_sta"), (5, "tput"), (6, "energy")):
        fmt, value = after[key]
        before = cells[n].split(" → ")[0]
        cells[n] = before if value is None else f"{before} → **{fmt.format(value)}**"
        d["fig"][key] = (d["fig"][key][0], None if value is None else float(fmt.format(value)))
    d["laid_out"] = True
    lines[d["line"]] = "| " + " | ".join(cells[1:-1]) + " |"


def embed(page, table_path, text):
    """Put the table into PAGE between <!-- NAME --> and <!-- /NAME --> (NAME: its file name)."""
    name = os.path.basename(table_path)
    start, end = f"<!-- {name} -->\n", f"<!-- /{name} -->"
    with open(page, encoding="utf-8") as f:
        body = f.read()
    if start not in body or end not in body:
        raise RowError(f"--embed: {page} has no '<!-- {name} -->' ... '<!-- /{name} -->' markers")
    head, rest = body.split(start, 1)
    with open(page, "w", encoding="utf-8") as f:
        f.write(head + start + text + end + rest.split(end, 1)[1])


def draw(designs, front, svg_dir):
    os.makedirs(svg_dir, exist_ok=True)
    err = [d["error"] for d in designs]
    estimates = {i for i, d in enumerate(designs) if not d["laid_out"]}

    def origins(key):
        return [(d["fig"][key][0], d["error"]) if d["fig"][key][1] is not None else None for d in designs]

    plot(designs, mixed(designs, "die"), err, front["area"],
         "die (mm², OSU 0.18 µm): after layout, or the estimate", "lobe max |error| (K(n)·cos^n, S10.20)",
         "Area against error after layout (Pareto front: red)",
         os.path.join(svg_dir, "area_vs_error_layout.svg"), origins=origins("die"), estimates=estimates)
    plot(designs, mixed(designs, "tput"), err, front["throughput/mm²"],
         "results/s streamed per mm² of die (M, at T_sta): after layout, or the estimate",
         "lobe max |error| (K(n)·cos^n, S10.20)", "Throughput per mm² against error after layout (Pareto front: red)",
         os.path.join(svg_dir, "throughput_vs_error_layout.svg"), x_log=True, where="pre",
         origins=origins("tput"), estimates=estimates)
    plot(designs, mixed(designs, "energy"), err, front["energy–error"],
         "energy per result (pJ, random operands, 50 ns): after layout, or before",
         "lobe max |error| (K(n)·cos^n, S10.20)", "Energy against error after layout (Pareto front: red)",
         os.path.join(svg_dir, "energy_vs_error_layout.svg"), origins=origins("energy"),
         estimates={i for i, d in enumerate(designs) if d["fig"]["energy"][1] is None})


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("table")
    p.add_argument("--fix", action="store_true", help="rewrite the Pareto column from the figures")
    p.add_argument("--svg-dir", help="draw the three *_layout.svg plots here")
    p.add_argument("--embed", metavar="PAGE", help="put the table into PAGE between its markers")
    p.add_argument("--set", nargs="+", metavar="ARG",
                   help="LABEL LAYOUT_SUMMARY SILICON_SUMMARY [ENERGY_JSON]: that row from its layout run")
    a = p.parse_args()
    if not os.path.isfile(a.table):
        p.error(f"'{a.table}' is not a file")
    if a.set and len(a.set) not in (3, 4):
        p.error(f"--set takes LABEL LAYOUT_SUMMARY SILICON_SUMMARY [ENERGY_JSON], not {len(a.set)} arguments")
    try:
        lines, designs = read_table(a.table)
        if a.set:
            set_row(designs, lines, a.set[0], a.set[1:])
            a.fix = True
    except RowError as e:
        sys.stderr.write(f"layout_fronts.py: {a.table}: {e}\n")
        return 1
    problems = [c for c in map(consistency, designs) if c]
    front = fronts(designs)
    for i, d in enumerate(designs):
        want = [f for f in FRONTS if i in front[f]]
        if want == d["marks"]:
            continue
        if a.fix:
            cells = d["cells"]
            cells[8] = ", ".join(want)
            lines[d["line"]] = "| " + " | ".join(cells[1:-1]) + " |"
        else:
            problems.append(f"{d['label']}: Pareto '{', '.join(d['marks'])}', "
                            f"the figures give '{', '.join(want)}'")
    for msg in problems:
        sys.stderr.write(f"layout_fronts.py: {a.table}: {msg}\n")
    if problems:
        return 1
    if a.fix:
        with open(a.table, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
    if a.embed:
        try:
            embed(a.embed, a.table, open(a.table, encoding="utf-8").read())
        except (RowError, OSError) as e:
            sys.stderr.write(f"layout_fronts.py: {e}\n")
            return 1
    if a.svg_dir:
        draw(designs, front, a.svg_dir)
    laid = sum(d["laid_out"] for d in designs)
    print(f"layout_fronts.py: {len(designs)} designs, {laid} after layout; "
          + "; ".join(f"{f}: {', '.join(designs[i]['label'] for i in front[f])}" for f in FRONTS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
