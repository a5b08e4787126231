#!/usr/bin/env python3
"""scripts/flows/design_space/layout_fronts.py (issue 48): the Pareto column of the table after layout is
checked against the fronts its own figures give.

  layout_fronts_test.py PROJECT_DIR SCRATCH made-up   # four made-up designs
  layout_fronts_test.py PROJECT_DIR SCRATCH committed # docs/design_space/layout_table.md

made-up: a table of four designs whose fronts are known by construction:
  a  2.0 → 3.0 mm², 20 → 10 M/s/mm², 1000 → 1200 pJ, error 0.1 (laid out)
  b  2.5 mm², 12 M/s/mm², 900 pJ, error 0.1 (estimate)
  c  4.0 → 4.2 mm², 5 → 4 M/s/mm², 2000 → 2100 pJ, error 0.01 (laid out)
  d  1.0 mm², 1 M/s/mm², — pJ, error 0.2 (estimate, no energy)
After layout b dominates a on all three planes (smaller, faster, less energy at the same
error); d (smallest, largest error) is on the area front only; c (the smallest error) is on
every front. The right column passes; a mark planted on a, or taken off c, fails naming
the row; --fix writes the right column; a 'yes' row without a figure after layout and a
figure that is not a number fail naming them.
--set b from a made-up run (die 3.2 mm², T_sta 16 ns, 2 clocks per result, 950 pJ) writes
b's row as worked out here (10^9 / (16 · 2) / 3.2 = 9.77 M/s/mm²) and the marks again: b,
now larger and slower than a at the same error, hands a the area and throughput fronts
and keeps the energy one (950 < 1 200 pJ); --embed puts the table in a page between its
markers; a run with a DRC error, or of another design, is refused, and so is an energy
after layout beside a row's '—' before it.
committed: the committed table passes, and docs/design_space.md embeds it unchanged.
Exit 0 pass, 1 fail.
"""
import json
import os
import shutil
import subprocess
import sys

HEAD = ("| design | after layout | die (mm²): estimate → layout | T_sta (ns) | results/s per mm² (M) | "
        "energy per result at 50 ns (pJ) | lobe max \\|err\\| | Pareto (mixed figures) |\n"
        "|---|---|---:|---:|---:|---:|---:|---|\n")
ROWS = {
    "a": "| a | yes | 2.000 → **3.000** | 10.00 → **20.00** | 20.00 → **10.00** | 1000 → **1200** | 0.1 | {} |",
    "b": "| b | no (estimate) | 2.500 | 15.00 | 12.00 | 900 | 0.1 | {} |",
    "c": "| c | yes | 4.000 → **4.200** | 30.00 → **31.00** | 5.00 → **4.00** | 2000 → **2100** | 0.01 | {} |",
    "d": "| d | no (estimate) | 1.000 | 40.00 | 1.00 | — | 0.2 | {} |",
}
RIGHT = {"a": "", "b": "area, throughput/mm², energy–error", "c": "area, throughput/mm², energy–error",
         "d": "area"}


def table(marks, override=None):
    rows = dict(ROWS)
    rows.update(override or {})
    return HEAD + "\n".join(rows[k].format(marks[k]) for k in "abcd") + "\n"


def run(project, path, *args):
    return subprocess.run([sys.executable, os.path.join(project, "scripts", "flows", "design_space", "layout_fronts.py"), path, *args],
                          capture_output=True, text=True)


def made_up(project, scratch):
    fails = []
    path = os.path.join(scratch, "layout_table.md")

    def case(name, text, want_rc, want_in=(), *args):
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        r = run(project, path, *args)
        if r.returncode != want_rc or any(w not in r.stderr for w in want_in):
            fails.append(f"{name}: exit {r.returncode} (want {want_rc}), stderr {r.stderr!r} "
                         f"(want {list(want_in)})")
        return r

    case("right column", table(RIGHT), 0)
    case("mark planted on a", table({**RIGHT, "a": "area"}), 1, ("a: Pareto 'area', the figures give ''",))
    case("mark taken off c", table({**RIGHT, "c": "area, throughput/mm²"}), 1,
         ("c: Pareto 'area, throughput/mm²', the figures give 'area, throughput/mm², energy–error'",))
    case("--fix", table({k: "" for k in RIGHT}), 0, (), "--fix")
    if open(path, encoding="utf-8").read() != table(RIGHT):
        fails.append(f"--fix wrote:\n{open(path, encoding='utf-8').read()}")
    case("'yes' without a figure after layout", table(RIGHT, {"a": ROWS["a"].replace("2.000 → **3.000**", "2.000")}),
         1, ("a: 'yes' after layout but",))
    case("not a number", table(RIGHT, {"d": ROWS["d"].replace("| 1.000 |", "| 1,0 |")}), 1,
         ("d: die '1,0' is not",))
    # --set b from a made-up layout run
    run_dir = os.path.join(scratch, "run_b")
    os.makedirs(run_dir)
    files = {"layout": {"top": "specular_b", "die_area_mm2": 3.2, "t_sta_ns": 16.0, "unrouted_nets": 0,
                        "drc_errors": 0, "lvs_match": True},
             "silicon": {"top": "specular_b", "die_area_estimate_mm2": 2.5, "t_sta_ns": 15.0,
                         "clocks_per_result_streamed": 2},
             "energy": {"total_pj_at_period": 999.0, "random_total_pj_at_period": 950.0}}
    paths = {}
    for k, v in files.items():
        paths[k] = os.path.join(run_dir, k + ".json")
        with open(paths[k], "w") as f:
            json.dump(v, f)
    page = os.path.join(scratch, "page.md")
    with open(page, "w", encoding="utf-8") as f:
        f.write("before\n<!-- layout_table.md -->\nold\n<!-- /layout_table.md -->\nafter\n")
    tput = 1e9 / (16.0 * 2) / 3.2 / 1e6
    want_b = f"| b | yes | 2.500 → **3.200** | 15.00 → **16.00** | 12.00 → **{tput:.2f}** | 900 → **950** | 0.1 | {{}} |"
    want = table({**RIGHT, "a": "area, throughput/mm²", "b": "energy–error"}, {"b": want_b})
    case("--set b", table(RIGHT), 0, (), "--set", "b", paths["layout"], paths["silicon"], paths["energy"],
         "--embed", page)
    if open(path, encoding="utf-8").read() != want:
        fails.append(f"--set b wrote:\n{open(path, encoding='utf-8').read()}\nwant:\n{want}")
    if open(page, encoding="utf-8").read() != "before\n<!-- layout_table.md -->\n" + want + "<!-- /layout_table.md -->\nafter\n":
        fails.append(f"--embed wrote:\n{open(page, encoding='utf-8').read()}")
    files["layout"]["drc_errors"] = 2
    with open(paths["layout"], "w") as f:
        json.dump(files["layout"], f)
    case("--set with a DRC error", table(RIGHT), 1, ("not clean (drc_errors 2)",),
         "--set", "b", paths["layout"], paths["silicon"])
    files["layout"]["drc_errors"] = 0
    with open(paths["layout"], "w") as f:
        json.dump(files["layout"], f)
    case("--set of another design", table(RIGHT), 1, ("layout summary's top 'specular_b' is not the row's design",),
         "--set", "c", paths["layout"], paths["silicon"])
    # an energy after layout with none before it ('—') would make a cell the check refuses
    case("--set an energy beside '—'", table(RIGHT, {"b": ROWS["b"].replace("| 900 |", "| — |")}), 1,
         ("no energy before layout ('—')",), "--set", "b", paths["layout"], paths["silicon"], paths["energy"])
    return fails


def committed(project):
    fails = []
    path = os.path.join(project, "docs", "design_space", "layout_table.md")
    r = run(project, path)
    if r.returncode != 0:
        fails.append(f"{path}: exit {r.returncode}: {r.stderr}")
    page = open(os.path.join(project, "docs", "design_space.md"), encoding="utf-8").read()
    start, end = "<!-- layout_table.md -->\n", "<!-- /layout_table.md -->"
    if start not in page or end not in page:
        fails.append("docs/design_space.md: no <!-- layout_table.md --> markers")
    elif page.split(start, 1)[1].split(end, 1)[0] != open(path, encoding="utf-8").read():
        fails.append("docs/design_space.md's embedded layout table differs from docs/design_space/layout_table.md")
    return fails


def main():
    project, scratch, mode = sys.argv[1:4]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    fails = made_up(project, scratch) if mode == "made-up" else committed(project)
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print(f"PASS ({mode})")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
