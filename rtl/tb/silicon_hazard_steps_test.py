#!/usr/bin/env python3
"""The hazard step of scripts/flows/synthesis/silicon.sh (issue 35): the cheap checks.

  silicon_hazard_steps_test.py ROOT SCRATCH CHECK
  CHECK: merge_in_place | skip_note

- merge_in_place: the unsharded hazard sweep (gatesim.sh --hazards, no --shard) merges
  its own partial into its own folder; gatesim_partial.py's merge copied icarus.sdf onto
  itself and stopped (SameFileError). A partial of 8 units written here, whose out_dir is
  the merge's --output: the merge gets past the copies and writes every period's
  sweep.txt (the lines given here) whatever the hazard report makes of them.
- skip_note: silicon.sh --top specular_exp2 (a variant: no hazard probe) notes before
  any tool runs that the hazard step is skipped; specular_device (a probe) and
  specular_exp2 with --no-hazards do not. A missing ROM folder stops each run right
  after the note (exit 2), so no tool runs.
Exit 0 pass, 1 fail.
"""
import json
import os
import subprocess
import sys


def merge_in_place(root, scratch):
    d = os.path.join(scratch, "hazards")
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "icarus.sdf"), "w").write("(DELAYFILE)\n")
    units = []
    for u in range(8):
        period = "26.7" if u < 4 else "53.40"
        ud = os.path.join(d, "hazards", "unit%d" % u)
        os.makedirs(ud, exist_ok=True)
        x = "%.6f" % (-0.5 + 4 * (u % 4) / 16)
        open(os.path.join(ud, "x%s.log" % x), "w").write("PASS\n")
        units.append({"unit": u, "period_ns": period, "sweep": ["%s 1" % x], "boundaries": []})
    partial = {"kind": "gatesim", "version": 1, "commit": "test",
               "settings": {"mode": "hazards", "top": "specular_device", "period_ns": "26.7"},
               "shard": {"index": 0, "count": 1},
               "result": {"hazards": {"units": units, "out_dir": d}},
               "timing": {"wall_seconds": 0, "cpu_seconds": 0, "host": "test"}}
    path = os.path.join(d, "partial.json")
    json.dump(partial, open(path, "w"))
    r = subprocess.run(["/usr/bin/python3", os.path.join(root, "scripts/flows/gatelevel/gatesim_partial.py"),
                        "merge", "--output", d, path], capture_output=True, text=True)
    if "SameFileError" in r.stderr or "Traceback" in r.stderr and "shutil" in r.stderr:
        print("FAIL: the merge into its own folder stopped at a copy:\n" + r.stderr[-800:])
        return 1
    for period, lines in (("26.7", 4), ("53.40", 4)):
        sweep = os.path.join(d, "hazards", "T" + period, "sweep.txt")
        if not os.path.exists(sweep) or len(open(sweep).read().split("\n")) - 1 != lines:
            print(f"FAIL: {sweep} missing or not {lines} lines (merge exit {r.returncode}):\n{r.stderr[-800:]}")
            return 1
    print("PASS: the unsharded hazard merge into its own folder writes every period's sweep")
    return 0


def skip_note(root, scratch):
    silicon = os.path.join(root, "scripts/flows/synthesis/silicon.sh")
    missing_roms = os.path.join(scratch, "no_roms")
    note = "has no hazard probe"
    cases = [(["--top", "specular_exp2"], True), (["--top", "specular_device"], False),
             (["--top", "specular_exp2", "--no-hazards"], False),
             (["--top", "specular_exp2", "--no-gatesim"], False)]
    for opts, want in cases:
        r = subprocess.run(["bash", silicon] + opts + [os.path.join(scratch, "out"), missing_roms],
                           capture_output=True, text=True)
        if r.returncode != 2 or "not found" not in r.stderr:
            print(f"FAIL: silicon.sh {' '.join(opts)} with no ROM folder: exit {r.returncode}, want 2\n{r.stderr}")
            return 1
        if (note in r.stderr) != want:
            print(f"FAIL: silicon.sh {' '.join(opts)}: the note {'missing' if want else 'given'}:\n{r.stderr}")
            return 1
    print("PASS: a top without a hazard probe skips the hazard step with a note; the device does not")
    return 0


def main():
    root, scratch, check = sys.argv[1:4]
    os.makedirs(scratch, exist_ok=True)
    if check == "merge_in_place":
        return merge_in_place(root, scratch)
    if check == "skip_note":
        return skip_note(root, scratch)
    print(f"unknown check '{check}' (merge_in_place, skip_note)")
    return 2


if __name__ == "__main__":
    sys.exit(main())
