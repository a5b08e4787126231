#!/usr/bin/env python3
"""The design space in silicon (issue 26): every design's silicon_summary.json beside its
error JSON, as one markdown table and two Pareto plots (docs/design_space/flow.md, "Silicon
flow for variants").

  /usr/bin/python3 scripts/flows/design_space/design_space.py RUNS_DIR [--error NAME=FILE ...]
                   [--table FILE] [--svg-dir DIR]

RUNS_DIR holds one folder per design, each a `scripts/flows/synthesis/silicon.sh` OUT_DIR (its
silicon_summary.json names the top: specular_NAME), and beside the summary the design's
error JSON, `error.json` (`specular_variant_error NAME --json error.json`: lobe_max_abs,
lobe_mean_abs, lobe_max_at {cos_code, n}, out_max_abs, out_mean_abs, out_max_at).
--error NAME=FILE names an error JSON elsewhere (NAME: the design, e.g. patent). The drawn
device (specular_device) and the synchronous one (specular_device_sync) compute the
patent's bits: without an error file of their own they take the patent's.

Energy (issue 36): a design folder may also hold `energy.json` (scripts/flows/energy/energy.sh's):
--energy-table FILE writes the energy table (every design with one; --energy-only: nothing
else, the other table and plots untouched) and, with --svg-dir,
energy_vs_error.svg and energy_vs_area.svg (energy per result at the common clock, the random operands' mean, against
the lobe's max |error| and against the die estimate, Pareto fronts marked).

After layout (issue 48): --layout-dir DIR names the designs laid out, one folder each
holding scripts/flows/layout/layout.sh's layout_summary.json (its top names the design) and, from
energy.sh on the post-layout netlist, energy/energy.json (the farm's `layout` regression
leaves them so). --layout-table FILE writes the table of each design before and after
layout (die, T_sta, results/s per mm², energy per result) and, with --svg-dir,
area_vs_error_layout.svg, throughput_vs_error_layout.svg and energy_vs_error_layout.svg:
each laid-out design at its figure after layout with an arrow from its estimate, every
other at its estimate (hollow), the Pareto fronts from those mixed figures. A layout that
is not clean (an unrouted net, a DRC error, no LVS match) is left out, named on stderr.

Writes the table (markdown, default RUNS_DIR/design_space_table.md; printed too) and,
with --svg-dir, area_vs_error.svg (die estimate against the lobe's max |error|) and
throughput_vs_error.svg (results/s streamed per mm² of die against the same error), the
Pareto front of each marked (no other design is at least as good on both axes and better
on one). Exit status: 0 written, 1 a file missing or unreadable, 2 bad arguments.
"""
import argparse
import json
import os
import sys

DEVICE_TOPS = {"specular_device": "device (Fig. 2, drawn)",
               "specular_device_sync": "device, synchronous"}


def design_name(top):
    return top[len("specular_"):] if top.startswith("specular_") else top


def load(runs, errors):
    designs = []
    for entry in sorted(os.listdir(runs)):
        path = os.path.join(runs, entry, "silicon_summary.json")
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            s = json.load(f)
        name = design_name(s["top"])
        error_file = errors.get(name) or os.path.join(runs, entry, "error.json")
        if not os.path.isfile(error_file) and s["top"] in DEVICE_TOPS:
            error_file = errors.get("patent") or os.path.join(runs, "patent", "error.json")
        e = None
        if os.path.isfile(error_file):
            with open(error_file) as f:
                e = json.load(f)
        energy = None
        energy_file = os.path.join(runs, entry, "energy.json")
        if os.path.isfile(energy_file):
            with open(energy_file) as f:
                energy = json.load(f)
        designs.append({"name": name, "top": s["top"], "summary": s, "error": e,
                        "energy": energy, "label": DEVICE_TOPS.get(s["top"], name)})
    # the device's tops first (drawn, synchronous), the patent behind the common ports,
    # then the variants by name
    order = {"specular_device": 0, "specular_device_sync": 1, "specular_patent": 2}
    designs.sort(key=lambda d: (order.get(d["top"], 3), d["name"]))
    return designs


def layout_faults(lay):
    """What keeps a layout_summary.json from being clean: unrouted nets, DRC errors, no LVS match."""
    faults = [f"{k} {lay.get(k)}" for k in ("unrouted_nets", "drc_errors") if lay.get(k) != 0]
    if lay.get("lvs_match") is not True:
        faults.append("no LVS match")
    return faults


def load_layouts(layout_dir):
    """The designs after layout: name -> {"layout": layout_summary.json, "energy":
    energy/energy.json or None}. A layout that is not clean is no figure: left out."""
    out = {}
    for entry in sorted(os.listdir(layout_dir)):
        path = os.path.join(layout_dir, entry, "layout_summary.json")
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            lay = json.load(f)
        faults = layout_faults(lay)
        if faults:
            sys.stderr.write(f"design_space.py: {path}: not clean ({', '.join(faults)}): left out\n")
            continue
        energy = None
        energy_file = os.path.join(layout_dir, entry, "energy", "energy.json")
        if os.path.isfile(energy_file):
            with open(energy_file) as f:
                energy = json.load(f)
        out[design_name(lay["top"])] = {"layout": lay, "energy": energy}
    return out


def after_layout(d, lay):
    """A design's figures after layout (None where it has none): die (mm²), T_sta (ns),
    results/s streamed per mm² of die at that T_sta, energy per result with the wires."""
    if lay is None:
        return {"die": None, "t_sta": None, "tput": None, "energy": None}
    s, L = d["summary"], lay["layout"]
    die, t_sta = L["die_area_mm2"], L.get("t_sta_ns")
    cpr = s.get("clocks_per_result_streamed")
    tput = 1e9 / (t_sta * cpr) / die if t_sta and cpr else None
    energy = energy_figure(lay["energy"]) if lay["energy"] else None
    return {"die": die, "t_sta": t_sta, "tput": tput, "energy": energy}


def pick(after, before):
    """The figure a front is drawn from: after layout where there is one."""
    return [a if a is not None else b for a, b in zip(after, before)]


def layout_table(designs, after, fronts):
    """Each design before and after layout; the fronts from the mixed figures."""
    arrow = lambda b, a, fmt: (f"{fmt(b)} → **{fmt(a)}**" if a is not None else fmt(b)) if b is not None else "—"
    lines = ["| design | after layout | die (mm²): estimate → layout | T_sta (ns) | "
             "results/s per mm² (M) | energy per result at 50 ns (pJ) | lobe max \\|err\\| | "
             "Pareto (mixed figures) |",
             "|---|---|---:|---:|---:|---:|---:|---|"]
    for i, d in enumerate(designs):
        s, e, a = d["summary"], d["error"] or {}, after[i]
        before_energy = energy_figure(d["energy"]) if d["energy"] else None
        marks = [m for m, f in fronts if i in f]
        lines.append(
            f"| {d['label']} | {'yes' if a['die'] is not None else 'no (estimate)'} | "
            f"{arrow(s['die_area_estimate_mm2'], a['die'], lambda v: f'{v:.3f}')} | "
            f"{arrow(s['t_sta_ns'], a['t_sta'], lambda v: f'{v:.2f}')} | "
            f"{arrow(s['results_per_second_per_mm2_streamed'], a['tput'], lambda v: f'{v / 1e6:.2f}')} | "
            f"{arrow(before_energy, a['energy'], lambda v: f'{v:.0f}')} | "
            f"{sci(e.get('lobe_max_abs'))} | {', '.join(marks)} |")
    return "\n".join(lines) + "\n"


def pareto(points):
    """Indices of the points no other point dominates; each point (x, y), both minimised."""
    front = []
    for i, (x, y) in enumerate(points):
        if x is None or y is None:
            continue
        dominated = any(j != i and a is not None and b is not None and a <= x and b <= y
                        and (a < x or b < y) for j, (a, b) in enumerate(points))
        if not dominated:
            front.append(i)
    return front


def num(v, digits=2):
    if v is None:
        return "—"
    if isinstance(v, float) and not v.is_integer() and digits > 0:
        return f"{v:.{digits}f}"
    return f"{round(v):,}".replace(",", " ")


def sci(v):
    return "—" if v is None else f"{v:.3g}"


def table(designs, front_area, front_tput):
    lines = [
        "| design | logic (µm²) | ROM macros (µm²) | total (mm²) | total, one ROM 38 bank (mm²) | die est. (mm²) | flip-flops | "
        "T_sta (ns) | T_sim (ns) | clocks / result | latency (clocks) | latency (ns) | "
        "results/s streamed | results/s per mm² (die) | lobe max \\|err\\| (at cos code, n) | "
        "lobe mean \\|err\\| | pins max \\|err\\| | pins mean \\|err\\| | gate level at 1.1 T_sim | Pareto |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---|---|"]
    for i, d in enumerate(designs):
        s, e = d["summary"], d["error"] or {}
        at = e.get("lobe_max_at")
        where = f" ({at['cos_code']}, {at['n']})" if at else ""
        replay = s.get("gatesim_replay_1_1_t_sim")
        replay = (f"{replay['result']} ({replay['period_ns']} ns)" if replay else "not run")
        cpr = s.get("clocks_per_result_streamed")
        cpr_text = num(cpr)
        if s.get("clocks_per_result_reload") not in (None, cpr):
            cpr_text += f" ({num(s['clocks_per_result_reload'])} reloading)"
        marks = [m for m, f in (("area", front_area), ("throughput/mm²", front_tput)) if i in f]
        lines.append(
            f"| {d['label']} | {num(s['area_logic_um2'], 0)} | {num(s['area_macros_um2'], 0)} | "
            f"{s['area_total_um2'] / 1e6:.3f} | {s['area_total_one_rom38_bank_um2'] / 1e6:.3f} | "
            f"{s['die_area_estimate_mm2']:.3f} | {s['flip_flops']} | "
            f"{s['t_sta_ns']:.2f} | {num(s.get('t_sim_ns'), 1)} | {cpr_text} | "
            f"{num(s.get('latency_clocks'), 1)} | {num(s.get('latency_ns_at_t_sta'), 1)} | "
            f"{s['results_per_second_streamed_at_t_sta'] / 1e6:.1f} M | "
            f"{s['results_per_second_per_mm2_streamed'] / 1e6:.2f} M | "
            f"{sci(e.get('lobe_max_abs'))}{where} | {sci(e.get('lobe_mean_abs'))} | "
            f"{sci(e.get('out_max_abs'))} | {sci(e.get('out_mean_abs'))} | {replay} | "
            f"{', '.join(marks) if marks else ''} |")
    return "\n".join(lines) + "\n"


def energy_table(designs, front_error, front_area):
    """Energy per result (scripts/flows/energy/energy.sh): designs with an energy.json. The figure is
    the mean over the common stream's random operands (the same distribution for every
    design) with its standard error; the parts and the glitch shares are over the whole
    stream replayed (its 18 edge cases too)."""
    lines = ["| design | die est. (mm²) | lobe max \\|err\\| | clocks / result | "
             "**energy per result at 50 ns (pJ, random operands ± s.e.)** | random results | settled to 1 % | "
             "T_sim (ns) | at T_sim (pJ) | "
             "whole stream (pJ): logic internal | switching | ROM reads | leakage | total | "
             "ROM reads / result | zero-delay logic (pJ) | glitches: share of the logic energy | "
             "share of the toggles | Pareto |",
             "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---|"]
    for i, d in enumerate(designs):
        g = d["energy"]
        if g is None:
            continue
        s, e = d["summary"], d["error"] or {}
        short = lambda k: k.split(".genblk1")[0].rsplit("/", 1)[0] if "/" in k else k
        reads = ", ".join(f"{short(k)} {v:.2f}" for k, v in sorted(g["rom_reads_per_result"].items()))
        marks = [m for m, f in (("energy–error", front_error), ("energy–area", front_area)) if i in f]
        pct = lambda k: f"{100 * g[k]:.0f} %" if g.get(k) is not None else "—"
        settled = ("yes" if g.get("settled_1pct") else "**no**") if "settled_1pct" in g else "—"
        sem = f" ± {100 * g['random_dynamic_sem_rel']:.1f} %" if "random_dynamic_sem_rel" in g else " (whole stream)"
        lines.append(
            f"| {d['label']} | {s['die_area_estimate_mm2']:.3f} | "
            f"{sci(e.get('lobe_max_abs'))} | {num(g['clocks_per_result'])} | "
            f"**{energy_figure(g):.0f}**{sem} | "
            f"{g.get('random_results', 0)} | {settled} | {num(g.get('t_sim_ns'), 1)} | "
            f"{num(g.get('random_total_pj_at_t_sim'), 0)} | {g['internal_pj']:.0f} | "
            f"{g['switching_pj']:.0f} | {g['rom_pj']:.0f} | {g['leakage_pj_at_period']:.2f} | "
            f"{g['total_pj_at_period']:.0f} | {reads} | {num(g.get('zero_delay_logic_pj'), 0)} | "
            f"{pct('glitch_logic_energy_share')} | {pct('glitch_toggle_share')} | "
            f"{', '.join(marks)} |")
    return "\n".join(lines) + "\n"


def energy_figure(g):
    """A design's energy per result at the common clock: the random operands' mean; without
    random operands (fewer than 4), the whole stream's."""
    return g.get("random_total_pj_at_period", g["total_pj_at_period"])


def times_table(designs):
    """The flow's run time per design (silicon.sh's times.txt: the shared 2-core machine)."""
    lines = ["| design | mapping (s) | STA (s) | T_sim bisection + replay (s) | ROM macros |",
             "|---|---:|---:|---:|---|"]
    for d in designs:
        s = d["summary"]
        t = s.get("times_s", {})
        used = s.get("rom_macro_instances") or {}
        macros = "; ".join(f"{used.get(n, 1)} × {n} ({m['words']} × {m['width']}, {num(m['area_um2'], 0)} µm²)"
                           for n, m in sorted(s.get("rom_macros", {}).items())
                           if n != "ROM38_BANK_MACRO" and (not used or n in used))
        lines.append(f"| {d['label']} | {t.get('mapping_s', 0):.0f} | {t.get('sta_s', 0):.0f} | "
                     f"{t.get('gatesim_s', 0):.0f} | {macros} |")
    return "\n".join(lines) + "\n"


def plot(designs, xs, ys, front, xlabel, ylabel, title, path, x_log=False, where="post",
         origins=None, estimates=()):
    """One plane, the front in red. origins: per design, the (x, y) it moved from (after
    layout: its estimate) or None, drawn as a grey arrow; estimates: the designs whose
    point is still an estimate, drawn hollow."""
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "specular-design-space"  # reproducible ids
    matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: small, diffable SVG
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    for i, d in enumerate(designs):
        if xs[i] is None or ys[i] is None:
            continue
        on = i in front
        colour = "tab:red" if on else "tab:blue"
        ax.scatter([xs[i]], [ys[i]], s=60 if on else 36, marker="o" if on else "s",
                   color=colour, facecolors="none" if i in estimates else colour, zorder=3)
        if origins and origins[i] is not None and origins[i][0] is not None:
            ax.annotate("", xy=(xs[i], ys[i]), xytext=origins[i], zorder=2,
                        arrowprops=dict(arrowstyle="->", color="0.55", linewidth=0.8))
            ax.scatter([origins[i][0]], [origins[i][1]], s=14, color="0.55", zorder=2)
        # labels of near points staggered (the devices sit on top of each other)
        ax.annotate(d["label"], (xs[i], ys[i]), textcoords="offset points",
                    xytext=(6, (4, -11, 15, -22)[i % 4]), fontsize=8)
    pts = sorted((xs[i], ys[i]) for i in front)
    if len(pts) > 1:
        ax.step([p[0] for p in pts], [p[1] for p in pts], where=where, color="tab:red",
                linestyle="--", linewidth=1, label="Pareto front")
    if estimates or origins:
        ax.scatter([], [], s=36, marker="s", color="tab:blue", label="after layout")
        ax.scatter([], [], s=36, marker="s", color="tab:blue", facecolors="none", label="estimate (not laid out)")
    if len(pts) > 1 or estimates or origins:
        ax.legend(loc="best", fontsize=8)
    ax.set_yscale("log")
    ax.margins(x=0.2, y=0.15)
    if x_log:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", linewidth=0.3)
    fig.tight_layout()
    fig.savefig(path, format="svg", metadata={"Date": None})
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs")
    p.add_argument("--error", action="append", default=[], metavar="NAME=FILE")
    p.add_argument("--table")
    p.add_argument("--svg-dir")
    p.add_argument("--energy-table")
    p.add_argument("--layout-dir", help="designs after layout (layout_summary.json, energy/energy.json)")
    p.add_argument("--layout-table", help="the table before and after layout (needs --layout-dir)")
    p.add_argument("--energy-only", action="store_true",
                   help="only the energy table and plots (the other table and plots untouched)")
    a = p.parse_args()
    errors = {}
    for item in a.error:
        if "=" not in item:
            p.error(f"--error '{item}' is not NAME=FILE")
        k, v = item.split("=", 1)
        errors[k] = v
    if not os.path.isdir(a.runs):
        sys.stderr.write(f"design_space.py: '{a.runs}' is not a folder\n")
        return 1
    designs = load(a.runs, errors)
    if not designs:
        sys.stderr.write(f"design_space.py: no silicon_summary.json under '{a.runs}'\n")
        return 1
    err = [d["error"]["lobe_max_abs"] if d["error"] else None for d in designs]
    die = [d["summary"]["die_area_estimate_mm2"] for d in designs]
    text, out = "", None
    if not a.energy_only:  # the other table needs the whole flow's summary; the energy one not
        tput = [d["summary"]["results_per_second_per_mm2_streamed"] for d in designs]
        front_area = pareto(list(zip(die, err)))
        front_tput = pareto([(-t, e) for t, e in zip(tput, err)])
        text = table(designs, front_area, front_tput) + "\n" + times_table(designs)
        out = a.table or os.path.join(a.runs, "design_space_table.md")
    if out:
        with open(out, "w") as f:
            f.write(text)
    print(text, end="")
    if a.svg_dir:
        os.makedirs(a.svg_dir, exist_ok=True)
    if a.svg_dir and not a.energy_only:
        plot(designs, die, err, front_area, "die estimate (mm², OSU 0.18 µm)",
             "lobe max |error| (K(n)·cos^n, S10.20)",
             "Area against error (Pareto front: red)", os.path.join(a.svg_dir, "area_vs_error.svg"))
        plot(designs, [t / 1e6 for t in tput], err, front_tput,
             "results/s streamed per mm² of die (M, at T_sta)",
             "lobe max |error| (K(n)·cos^n, S10.20)",
             "Throughput per mm² against error (Pareto front: red)",
             os.path.join(a.svg_dir, "throughput_vs_error.svg"), x_log=True, where="pre")
    if a.layout_table or a.layout_dir:
        if not (a.layout_table and a.layout_dir):
            p.error("--layout-table and --layout-dir go together")
        if not os.path.isdir(a.layout_dir):
            sys.stderr.write(f"design_space.py: --layout-dir '{a.layout_dir}' is not a folder\n")
            return 1
        layouts = load_layouts(a.layout_dir)
        unknown = sorted(set(layouts) - {d["name"] for d in designs})
        if unknown:
            sys.stderr.write(f"design_space.py: laid out but not in {a.runs}: {', '.join(unknown)}\n")
            return 1
        after = [after_layout(d, layouts.get(d["name"])) for d in designs]
        estimates = {i for i, x in enumerate(after) if x["die"] is None}
        die_m = pick([x["die"] for x in after], die)
        tput_b = [d["summary"]["results_per_second_per_mm2_streamed"] for d in designs]
        tput_m = pick([x["tput"] for x in after], tput_b)
        energy_b = [energy_figure(d["energy"]) if d["energy"] else None for d in designs]
        energy_m = pick([x["energy"] for x in after], energy_b)
        fronts = [("area", pareto(list(zip(die_m, err)))),
                  ("throughput/mm²", pareto([(-t, e) for t, e in zip(tput_m, err)])),
                  ("energy–error", pareto(list(zip(energy_m, err))))]
        text = layout_table(designs, after, fronts)
        with open(a.layout_table, "w") as f:
            f.write(text)
        print(text, end="")
        if a.svg_dir:
            moved = lambda xb, xa: [(b, e) if x is not None else None for b, x, e in zip(xb, xa, err)]
            plot(designs, die_m, err, fronts[0][1], "die (mm², OSU 0.18 µm): after layout, or the estimate",
                 "lobe max |error| (K(n)·cos^n, S10.20)", "Area against error after layout (Pareto front: red)",
                 os.path.join(a.svg_dir, "area_vs_error_layout.svg"),
                 origins=moved(die, [x["die"] for x in after]), estimates=estimates)
            plot(designs, [t / 1e6 for t in tput_m], err, fronts[1][1],
                 "results/s streamed per mm² of die (M, at T_sta): after layout, or the estimate",
                 "lobe max |error| (K(n)·cos^n, S10.20)",
                 "Throughput per mm² against error after layout (Pareto front: red)",
                 os.path.join(a.svg_dir, "throughput_vs_error_layout.svg"), x_log=True, where="pre",
                 origins=moved([t / 1e6 for t in tput_b], [x["tput"] for x in after]), estimates=estimates)
            plot(designs, energy_m, err, fronts[2][1],
                 "energy per result (pJ, random operands, 50 ns): after layout, or before",
                 "lobe max |error| (K(n)·cos^n, S10.20)", "Energy against error after layout (Pareto front: red)",
                 os.path.join(a.svg_dir, "energy_vs_error_layout.svg"),
                 origins=moved(energy_b, [x["energy"] for x in after]),
                 estimates={i for i, x in enumerate(after) if x["energy"] is None})
    if a.energy_table:
        have = [d for d in designs if d["energy"] is not None]
        if not have:
            sys.stderr.write(f"design_space.py: no energy.json under '{a.runs}'\n")
            return 1
        energy = [energy_figure(d["energy"]) for d in have]
        err_e = [d["error"]["lobe_max_abs"] if d["error"] else None for d in have]
        die_e = [d["summary"]["die_area_estimate_mm2"] for d in have]
        front_error = pareto(list(zip(energy, err_e)))
        front_area = pareto(list(zip(energy, die_e)))
        text = energy_table(have, front_error, front_area)
        with open(a.energy_table, "w") as f:
            f.write(text)
        print(text, end="")
        if a.svg_dir:
            plot(have, energy, err_e, front_error, "energy per result (pJ, random operands, 50 ns clock)",
                 "lobe max |error| (K(n)·cos^n, S10.20)",
                 "Energy against error (Pareto front: red)", os.path.join(a.svg_dir, "energy_vs_error.svg"))
            plot(have, energy, die_e, front_area, "energy per result (pJ, random operands, 50 ns clock)",
                 "die estimate (mm², OSU 0.18 µm)",
                 "Energy against area (Pareto front: red)", os.path.join(a.svg_dir, "energy_vs_area.svg"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
