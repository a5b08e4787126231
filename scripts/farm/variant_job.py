#!/usr/bin/env python3
"""A design variant's farm jobs (issue 26) in the farm's task form (scripts/farm/farm.sh):

  specular_variant_job rtl NAME --shard I/N --partial FILE
      the exhaustive RTL proof's shard: tests/test_long_variant_rtl_NAME (the verilated
      top equals the C++ model, every cos code x the n with (n - 1) mod N == I) under
      SPECULAR_OPERATION_SHARD=I/N
  specular_variant_job rtl-quick NAME --shard 0/1 --partial FILE
      the quick slice: tests/test_variant_rtl_NAME
  specular_variant_job silicon NAME --shard 0/1 --partial FILE
      scripts/flows/synthesis/silicon.sh --top specular_NAME --no-hazards into silicon/NAME beside the
      partials' folder (the run's folder), ROMs from BUILD/rtl/rom/default
  specular_variant_job energy NAME --shard 0/1 --partial FILE
      scripts/flows/energy/energy.sh --top specular_NAME into energy/NAME beside the partials' folder
      (the run's folder): the mapping, the SDF and zero-delay replays, the energy per
      result (issue 36); NAME may also be device or device_sync (the two device tops)
  specular_variant_job layout NAME [--utilisation U] [--no-cleanup] --shard 0/1 --partial FILE
      the design after layout (issue 48): scripts/flows/layout/layout.sh --top specular_NAME (its own
      silicon.sh --no-gatesim, then placement, routing, DRC, LVS, SPEF, post-layout STA)
      into layout/NAME beside the partials' folder, then scripts/flows/energy/energy.sh on its
      postlayout/ (each net weighed by its pins and its routed wire) into layout/NAME/energy;
      NAME may be device or device_sync; --utilisation and --no-cleanup go to layout.sh
      (the placement's density, qrouter's stage 3 left out: farm.sh gives
      one_pass_pipelined both). Hours per design (docs/silicon/layout.md, "Layout: placed, routed, DRC and LVS checked")
  specular_variant_job --merge FILE...
      one complete set (same job, every shard 0..N-1 once), every shard passed: exit 0

build/tools/variant_job/specular_variant_job (written by CMake) runs this with --build BUILD.
A partial is JSON: kind, version, settings {job, name}, shard {index, count},
summary {exit, passed_tests, ...}, timing {wall_seconds}.
"""
import json
import os
import re
import subprocess
import sys
import time

KIND = "specular_variant_job partial result"
JOBS = ("rtl", "rtl-quick", "silicon", "energy", "layout")
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def die(message, status=2):
    print("specular_variant_job: error: " + message, file=sys.stderr)
    sys.exit(status)


def parse_shard(text):
    m = re.fullmatch(r"(\d+)/(\d+)", text or "")
    if not m or not 0 <= int(m.group(1)) < int(m.group(2)):
        die("--shard: '%s' is not I/N with 0 <= I < N" % text)
    return int(m.group(1)), int(m.group(2))


def run_job(build, job, name, shard, partial, layout_options):
    index, count = shard
    env = dict(os.environ)
    started = time.time()
    summary = {}
    if job in ("rtl", "rtl-quick"):
        binary = os.path.join(build, "tests", ("test_long_variant_rtl_" if job == "rtl" else "test_variant_rtl_") + name)
        if not os.access(binary, os.X_OK):
            die("no %s (build target %s)" % (binary, os.path.basename(binary)), 1)
        if job == "rtl":
            env["SPECULAR_OPERATION_SHARD"] = "%d/%d" % (index, count)
        elif count != 1:
            die("rtl-quick is one task: --shard 0/1")
        result = subprocess.run([binary], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(result.stdout)
        passed = re.search(r"\[  PASSED  \] (\d+) test", result.stdout)
        summary = {"exit": result.returncode, "passed_tests": int(passed.group(1)) if passed else 0}
    elif job == "energy":
        if count != 1:
            die("energy is one task: --shard 0/1")
        out = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(partial))), "energy", name)
        command = ["bash", os.path.join(ROOT, "scripts", "flows", "energy", "energy.sh"), "--top", "specular_" + name,
                   "--vectors-tool", os.path.join(build, "tools", "variant_vectors", "specular_variant_vectors"),
                   "--specular-tb", os.path.join(build, "testbench", "specular_tb"),
                   "--counter", os.path.join(build, "tools", "vcd_activity", "specular_vcd_activity"),
                   out, os.path.join(build, "rtl", "rom", "default")]
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(result.stdout)
        summary = {"exit": result.returncode, "passed_tests": 1 if result.returncode == 0 else 0, "out": out}
        figures = os.path.join(out, "energy.json")
        if result.returncode == 0 and os.path.exists(figures):
            with open(figures) as f:
                summary["energy"] = json.load(f)
    elif job == "layout":
        if count != 1:
            die("layout is one task: --shard 0/1")
        summary = run_layout(build, name, partial, layout_options)
    else:
        if count != 1:
            die("silicon is one task: --shard 0/1")
        out = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(partial))), "silicon", name)
        command = ["bash", os.path.join(ROOT, "scripts", "flows", "synthesis", "silicon.sh"), "--top", "specular_" + name, "--no-hazards",
                   out, os.path.join(build, "rtl", "rom", "default")]
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        sys.stdout.write(result.stdout)
        summary = {"exit": result.returncode, "passed_tests": 1 if result.returncode == 0 else 0, "out": out}
        figures = os.path.join(out, "silicon_summary.json")
        if result.returncode == 0 and os.path.exists(figures):
            with open(figures) as f:
                summary["silicon_summary"] = json.load(f)
    document = {"kind": KIND, "version": 1, "settings": {"job": job, "name": name},
                "shard": {"index": index, "count": count}, "summary": summary,
                "timing": {"wall_seconds": round(time.time() - started, 3)}}
    with open(partial + ".tmp", "w") as f:
        json.dump(document, f, indent=2)
        f.write("\n")
    os.replace(partial + ".tmp", partial)
    return 0 if summary["exit"] == 0 else 1


def run_layout(build, name, partial, options):
    """layout.sh (with OPTIONS), then energy.sh on its post-layout netlist: the summary of
    both."""
    out = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(partial))), "layout", name)
    rom = os.path.join(build, "rtl", "rom", "default")
    steps = {}
    started = time.time()
    layout = subprocess.run(["bash", os.path.join(ROOT, "scripts", "flows", "layout", "layout.sh"), "--top", "specular_" + name,
                             "--rom-dir", rom] + options + [out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(layout.stdout)
    steps["layout_wall_seconds"] = round(time.time() - started, 1)
    summary = {"exit": layout.returncode, "passed_tests": 0, "out": out, "layout_options": options,
               "steps": steps}
    figures = os.path.join(out, "layout_summary.json")
    if os.path.exists(figures):
        with open(figures) as f:
            summary["layout_summary"] = json.load(f)
    if layout.returncode != 0 or not os.path.isdir(os.path.join(out, "postlayout")):
        return summary
    started = time.time()
    energy = subprocess.run(["bash", os.path.join(ROOT, "scripts", "flows", "energy", "energy.sh"), "--top", "specular_" + name,
                             "--netlist-dir", os.path.join(out, "postlayout"),
                             "--vectors-tool", os.path.join(build, "tools", "variant_vectors", "specular_variant_vectors"),
                             "--specular-tb", os.path.join(build, "testbench", "specular_tb"),
                             "--counter", os.path.join(build, "tools", "vcd_activity", "specular_vcd_activity"),
                             os.path.join(out, "energy"), rom], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(energy.stdout)
    steps["energy_wall_seconds"] = round(time.time() - started, 1)
    summary["exit"] = energy.returncode
    summary["passed_tests"] = 1 if energy.returncode == 0 else 0
    figures = os.path.join(out, "energy", "energy.json")
    if energy.returncode == 0 and os.path.exists(figures):
        with open(figures) as f:
            summary["energy"] = json.load(f)
    return summary


def merge(files):
    if not files:
        die("--merge needs the partial files of every shard (FILE...)")
    parts = []
    for path in files:
        try:
            with open(path) as f:
                p = json.load(f)
            if p.get("kind") != KIND or p.get("version") != 1:
                die("--merge: '%s' is not a %s" % (path, KIND))
            parts.append((path, p, p["shard"]["index"], p["shard"]["count"]))
        except (OSError, ValueError, KeyError, TypeError) as e:
            die("--merge: '%s' is not a complete partial result: %s" % (path, e))
    first = parts[0][1]
    count = parts[0][3]
    seen = {}
    for path, p, index, n in parts:
        if p["settings"] != first["settings"]:
            die("--merge: '%s' has other settings than '%s' (%s vs %s)" % (path, parts[0][0], p["settings"], first["settings"]))
        if n != count:
            die("--merge: '%s' is shard %d/%d, '%s' one of %d shards" % (path, index, n, parts[0][0], count))
        if index in seen:
            die("--merge: shard %d/%d is given twice: '%s' and '%s'" % (index, count, seen[index], path))
        seen[index] = path
    missing = ["%d/%d" % (i, count) for i in range(count) if i not in seen]
    if missing:
        die("--merge: %d of %d shards missing: %s" % (len(missing), count, ", ".join(missing[:10])))
    failed = [path for path, p, _, _ in parts if p["summary"].get("exit") != 0]
    s = first["settings"]
    tests = sum(p["summary"].get("passed_tests", 0) for _, p, _, _ in parts)
    wall = sum(p["timing"].get("wall_seconds", 0) for _, p, _, _ in parts)
    verdict = "FAIL" if failed else "PASS"
    print("variant %s, %s: %d shard(s), %d test(s) passed, %.1f s of tasks: %s" % (s["name"], s["job"], count, tests, wall, verdict))
    for path in failed:
        print("  failed: " + path)
    for _, p, _, _ in parts:
        if "silicon_summary" in p["summary"]:
            print(json.dumps(p["summary"]["silicon_summary"], indent=2))
        if "layout_summary" in p["summary"]:
            print(json.dumps(p["summary"]["layout_summary"], indent=2))
        if "energy" in p["summary"]:
            print(json.dumps(p["summary"]["energy"], indent=2))
    return 1 if failed else 0


def main(argv):
    build = os.path.join(ROOT, "build")
    if argv[:1] == ["--build"]:
        if len(argv) < 2:
            die("--build needs a folder")
        build, argv = argv[1], argv[2:]
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    if argv[0] == "--merge":
        return merge(argv[1:])
    if argv[0] not in JOBS:
        die("unknown job '%s' (allowed: %s, or --merge FILE...)" % (argv[0], ", ".join(JOBS)))
    job, rest = argv[0], argv[1:]
    if not rest or rest[0].startswith("--"):
        die("%s needs a variant's NAME" % job)
    name, rest = rest[0], rest[1:]
    shard, partial, layout_options = (0, 1), None, []
    while rest:
        if rest[0] == "--no-cleanup":
            if job != "layout":
                die("--no-cleanup is an option of layout, not of %s" % job)
            layout_options.append("--no-cleanup")
            rest = rest[1:]
        elif rest[0] in ("--shard", "--partial", "--utilisation") and len(rest) >= 2:
            if rest[0] == "--shard":
                shard = parse_shard(rest[1])
            elif rest[0] == "--partial":
                partial = rest[1]
            else:
                if job != "layout":
                    die("--utilisation is an option of layout, not of %s" % job)
                if not re.fullmatch(r"0?\.\d+", rest[1]) or not 0.2 <= float(rest[1]) <= 0.9:
                    die("--utilisation: '%s' is not a density from 0.2 to 0.9" % rest[1])
                layout_options += ["--utilisation", rest[1]]
            rest = rest[2:]
        else:
            die("unknown or incomplete option '%s' (allowed: --shard I/N, --partial FILE, "
                "--utilisation U and --no-cleanup for layout)" % rest[0])
    if partial is None:
        die("--partial FILE is needed (the farm's merge reads it)")
    if not re.fullmatch(r"[a-z0-9_]+", name):
        die("'%s' is not a variant's name" % name)
    return run_job(build, job, name, shard, partial, layout_options)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
