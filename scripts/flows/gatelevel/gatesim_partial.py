#!/usr/bin/env python3
"""Partial results of a sharded gate-level run (scripts/flows/gatelevel/gatesim.sh --shard I/N --partial F)
and their merge (scripts/flows/gatelevel/gatesim.sh --merge), with specular_tb --merge's semantics
(run_support/partial_set.cpp, docs/farm.md).

  gatesim_partial.py write OUT_DIR PARTIAL      (gatesim.sh, at the end of a shard's run)
  gatesim_partial.py merge [--output DIR] [--partial FILE] PARTIAL...

A partial holds kind ("gatesim"), version, commit, settings (mode, top, period or T_sta or
T_sim, policies, groups, random, and SHA-256 digests of the netlist, the SDF, the ROM
images, the testbench settings and every policy's vectors: what makes two shards parts
of one run), shard {index, count}, the shard's results and timing {wall, cpu, host}.

Shards split the work by policy (the k-th policy of the run, in the order of
policies.txt, belongs to shard k mod N) for a period run and the T_sim bisection (each
shard bisects its own policies), and by (period, offset group) unit for the hazard sweep
(8 units: 2 periods x 4 groups of 4 start offsets; unit u to shard u mod N).

The merge refuses (exit 2, nothing written) a set that is not exactly one run: a missing
shard, a shard given twice, a shard of another count, other settings or another commit
(naming the files), a file that is not a gatesim partial. A complete set gives the
unsharded run's answer: the verdict and summary (exit 0 PASS, 1 FAIL); --partial writes
the merged partial (shard 0/1), whose summary equals the unsharded run's; a hazard merge
writes hazards/, hazards.md and hazards.json into --output DIR.
"""
import glob
import hashlib
import json
import os
import shutil
import socket
import subprocess
import sys

VERSION = 1


def sha256(paths):
    h = hashlib.sha256()
    for p in paths:
        h.update(os.path.basename(p).encode() + b"\0")
        with open(p, "rb") as f:
            h.update(f.read())
    return h.hexdigest()


def read_info(out):
    info = {}
    for line in open(os.path.join(out, "partial_info.txt")):
        key, _, value = line.rstrip("\n").partition("=")
        info[key] = value
    return info


def policies_of(path):
    rows = []
    if os.path.exists(path):
        for line in open(path):
            if line.strip():
                name, _c, _n, _l, vectors = line.split()
                rows.append((name, vectors))
    return rows


def vector_count(path):
    with open(path) as f:
        return max(0, sum(1 for line in f if line.strip()) - 1)


def cpu_seconds(times):
    """The sum of bash's `times` (shell and children, user and system: 0m1.234s ...)."""
    total = 0.0
    for word in times.split():
        if "m" in word and word.endswith("s"):
            minutes, seconds = word[:-1].split("m")
            total += int(minutes) * 60 + float(seconds)
    return round(total, 2)


def commit(root):
    try:
        head = subprocess.run(["git", "-C", root, "rev-parse", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return head + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write(out, partial):
    info = read_info(out)
    everyone = policies_of(os.path.join(out, "policies_all.txt"))
    index_of = {name: k for k, (name, _) in enumerate(everyone)}
    settings = {
        "mode": info["mode"], "top": info["top"], "period_ns": info["period"],
        "policies": info["policies"], "groups": int(info["groups"]), "random": int(info["random"]),
        "policy_names": [name for name, _ in everyone],
        "netlist_sha256": sha256([os.path.join(info["netlist_dir"], f)
                                  for f in ("mapped.v", "device.sdf", "rom_macros_sim.v")]),
        "rom_sha256": sha256([os.path.join(info["rom_dir"], f) for f in ("rom5.hex", "rom38.hex", "pins.hex")]),
        "testbench_sha256": sha256([info["conf"]]),
        "vectors_sha256": sha256([v for _, v in everyone]),
    }
    result = {}
    if info["mode"] == "period":
        rows = []
        results = os.path.join(out, "results.tsv")
        if os.path.exists(results):
            for line in open(results):
                _t, name, verdict, seconds, first = (line.rstrip("\n").split("\t") + [""])[:5]
                rows.append({"policy": name, "index": index_of[name],
                             "vectors": vector_count(dict(everyone)[name]), "verdict": verdict,
                             "first_mismatch": first if verdict != "PASS" else "", "seconds": float(seconds)})
        result["policies"] = rows
    elif info["mode"] == "bisect":
        tsim = {}
        path = os.path.join(out, "tsim_shard.txt")
        if os.path.exists(path):
            for line in open(path):
                key, _, value = line.rstrip("\n").partition(" ")
                tsim[key] = value
        result["bisection"] = {
            "policies": [index_of[name] for name, _ in policies_of(os.path.join(out, "policies.txt"))],
            "t_sim_ns": tsim.get("t_sim_ns"), "fails_at_ns": tsim.get("fails_at_ns"),
            "first_failure": tsim.get("first_failure", ""),
            "first_failure_policy": int(tsim["first_failure_policy"]) if "first_failure_policy" in tsim else None,
            "error": tsim.get("error", ""),
        }
    else:  # hazards
        units = []
        for u in sorted(int(x) for x in info.get("hazard_units", "").split() if x):
            d = os.path.join(out, "hazards", "unit%d" % u)
            units.append({"unit": u, "period_ns": open(os.path.join(d, "period")).read().strip(),
                          "sweep": open(os.path.join(d, "sweep.txt")).read().splitlines(),
                          "boundaries": (open(os.path.join(d, "boundaries.txt")).read().splitlines()
                                         if os.path.exists(os.path.join(d, "boundaries.txt")) else [])})
        result["hazards"] = {"units": units, "out_dir": out}
    p = {"kind": "gatesim", "version": VERSION, "commit": info.get("commit") or commit(info["root"]), "settings": settings,
         "shard": {"index": int(info["shard_index"]), "count": int(info["shard_count"])},
         "result": result,
         "timing": {"wall_seconds": float(info.get("wall_seconds", 0)),
                    "cpu_seconds": cpu_seconds(info.get("cpu", "")), "host": socket.gethostname()}}
    tmp = partial + ".tmp"
    with open(tmp, "w") as f:
        json.dump(p, f, indent=1)
        f.write("\n")
    os.replace(tmp, partial)


class Refused(Exception):
    pass


def copy_file(src, dst):
    """shutil.copy, except a file onto itself: the unsharded hazard sweep (gatesim.sh
    --hazards without --shard) merges its own partial into its own folder (issue 35)."""
    target = os.path.join(dst, os.path.basename(src)) if os.path.isdir(dst) else dst
    if os.path.exists(target) and os.path.samefile(src, target):
        return
    shutil.copy(src, target)


def first_difference(a, b):
    for key in a:
        if key not in b or a[key] != b[key]:
            return "%s %s vs %s" % (key, json.dumps(a[key]), json.dumps(b[key]) if key in b else "(none)")
    for key in b:
        if key not in a:
            return "%s (none) vs %s" % (key, json.dumps(b[key]))
    return "?"


def complete_set(files):
    if not files:
        raise Refused("--merge needs the partial files of every shard (FILE...)")
    parts = []
    for path in files:
        try:
            p = json.load(open(path))
            if p.get("kind") != "gatesim" or p.get("version") != VERSION:
                raise ValueError("kind %r version %r, not a gatesim partial (version %d)"
                                 % (p.get("kind"), p.get("version"), VERSION))
            index, count = int(p["shard"]["index"]), int(p["shard"]["count"])
            if not 0 <= index < count:
                raise ValueError("shard %d/%d" % (index, count))
            p["settings"], p["commit"], p["result"]
        except (OSError, ValueError, KeyError, TypeError) as e:
            raise Refused("--merge: '%s' is not a complete gatesim partial result: %s" % (path, e))
        parts.append((path, p))
    first_path, first = parts[0]
    count = first["shard"]["count"]
    by_index = [None] * count
    for path, p in parts:
        if p["commit"] != first["commit"]:
            raise Refused("--merge: '%s' comes from commit %s, '%s' from %s: shards of one run come from one build"
                          % (path, p["commit"], first_path, first["commit"]))
        if p["settings"] != first["settings"]:
            raise Refused("--merge: '%s' has other settings than '%s' (%s)"
                          % (path, first_path, first_difference(p["settings"], first["settings"])))
        if p["shard"]["count"] != count:
            raise Refused("--merge: '%s' is shard %d/%d of %d, '%s' one of %d shards"
                          % (path, p["shard"]["index"], p["shard"]["count"], p["shard"]["count"], first_path, count))
        i = p["shard"]["index"]
        if by_index[i] is not None:
            raise Refused("--merge: shard %d/%d is given twice: '%s' and '%s'" % (i, count, by_index[i][0], path))
        by_index[i] = (path, p)
    missing = ["%d/%d" % (i, count) for i in range(count) if by_index[i] is None]
    if missing:
        raise Refused("--merge: %d of %d shards missing: %s%s"
                      % (len(missing), count, ", ".join(missing[:10]), ", ..." if len(missing) > 10 else ""))
    return by_index


def summarise(settings, results):
    """The run's answer from the results of every shard (order-free): the summary."""
    mode = settings["mode"]
    if mode == "period":
        rows = sorted((r for res in results for r in res["policies"]), key=lambda r: r["index"])
        failed = [r for r in rows if r["verdict"] != "PASS"]
        complete = len(rows) == len(settings["policy_names"])
        return {"verdict": "PASS" if complete and not failed else "FAIL",
                "policies": len(rows), "vectors": sum(r["vectors"] for r in rows),
                "passed": len(rows) - len(failed), "failed": len(failed),
                "per_policy": [{"policy": r["policy"], "vectors": r["vectors"], "verdict": r["verdict"],
                                "first_mismatch": r["first_mismatch"]} for r in rows],
                "first_mismatch": ({"policy": failed[0]["policy"], "line": failed[0]["first_mismatch"]}
                                   if failed else None)}
    if mode == "bisect":
        b = [res["bisection"] for res in results if res["bisection"]["policies"]]
        errors = [x["error"] for x in b if x["error"] or x["t_sim_ns"] is None]
        if errors:
            return {"verdict": "FAIL", "error": errors[0] or "a shard found no T_sim"}
        t_sim = max(float(x["t_sim_ns"]) for x in b)
        at_max = [x for x in b if float(x["t_sim_ns"]) == t_sim]
        worst = min(at_max, key=lambda x: x["first_failure_policy"])
        return {"verdict": "PASS", "t_sim_ns": "%.1f" % t_sim, "fails_at_ns": worst["fails_at_ns"],
                "first_failure": worst["first_failure"], "policies": settings["policies"],
                "vectors_per_policy": settings["groups"] * 10 + settings["random"]}
    units = sorted((u for res in results for u in res["hazards"]["units"]), key=lambda u: u["unit"])
    periods = {}
    for u in units:
        p = periods.setdefault(u["period_ns"], {"sweep": {}, "boundaries": []})
        for line in u["sweep"]:
            x, ok = line.split()
            p["sweep"][x] = ok
        p["boundaries"] += u["boundaries"]
    return {"verdict": "PASS" if len(units) == 8 else "FAIL", "units": len(units),
            "periods": {t: {"sweep": dict(sorted(v["sweep"].items(), key=lambda kv: float(kv[0]))),
                            "boundaries": sorted(v["boundaries"])} for t, v in periods.items()}}


def text(settings, s):
    head = "gatesim merge: top %s, %s" % (settings["top"], settings["mode"])
    if settings["mode"] == "period":
        lines = ["%s at T = %s ns: %d policies, %d vectors, %d passed, %d failed: %s"
                 % (head, settings["period_ns"], s["policies"], s["vectors"], s["passed"], s["failed"], s["verdict"])]
        for r in s["per_policy"]:
            lines.append("  policy %s: %s (%d vectors)%s" % (r["policy"], r["verdict"], r["vectors"],
                                                            ": " + r["first_mismatch"] if r["first_mismatch"] else ""))
        if s["first_mismatch"]:
            lines.append("first mismatch: policy %s: %s" % (s["first_mismatch"]["policy"], s["first_mismatch"]["line"]))
        return "\n".join(lines) + "\n"
    if settings["mode"] == "bisect":
        if s["verdict"] != "PASS":
            return "%s: FAIL: %s\n" % (head, s["error"])
        return ("%s: T_sim = %s ns (fails at %s ns): PASS\nt_sim_ns %s\nfails_at_ns %s\nfirst_failure %s\n"
                "policies %s\nvectors_per_policy %d\n"
                % (head, s["t_sim_ns"], s["fails_at_ns"], s["t_sim_ns"], s["fails_at_ns"], s["first_failure"],
                   s["policies"], s["vectors_per_policy"]))
    return "%s at T_sim = %s ns: %d of 8 units: %s\n" % (head, settings["period_ns"], s["units"], s["verdict"])


def merge(argv):
    output, merged_partial, files = None, None, []
    while argv:
        a = argv.pop(0)
        if a in ("--output", "--partial"):
            if not argv:
                raise Refused("%s needs a value" % a)
            if a == "--output":
                output = argv.pop(0)
            else:
                merged_partial = argv.pop(0)
        else:
            files.append(a)
    ordered = complete_set(files)
    first = ordered[0][1]
    settings = first["settings"]
    s = summarise(settings, [p["result"] for _, p in ordered])
    if settings["mode"] == "hazards":
        if output is None:
            raise Refused("--merge of a hazard sweep needs --output DIR (the tables are written there)")
        os.makedirs(output, exist_ok=True)
        out0 = first["result"]["hazards"]["out_dir"]
        copy_file(os.path.join(out0, "icarus.sdf"), os.path.join(output, "icarus.sdf"))
        sweeps = {}
        for _, p in ordered:
            for u in p["result"]["hazards"]["units"]:
                d = os.path.join(output, "hazards", "T" + u["period_ns"])
                os.makedirs(d, exist_ok=True)
                lines = sweeps.setdefault(d, ([], []))
                lines[0].extend(u["sweep"])
                lines[1].extend(u["boundaries"])
                for log in glob.glob(os.path.join(p["result"]["hazards"]["out_dir"], "hazards",
                                                  "unit%d" % u["unit"], "x*.log")):
                    copy_file(log, d)
        for d, (sweep, boundaries) in sweeps.items():
            with open(os.path.join(d, "sweep.txt"), "w") as f:
                f.writelines(line + "\n" for line in sweep)
            with open(os.path.join(d, "boundaries.txt"), "w") as f:
                f.writelines(line + "\n" for line in boundaries)
        here = os.path.dirname(os.path.abspath(__file__))
        r = subprocess.run([sys.executable, os.path.join(here, "hazards_report.py"), output, settings["period_ns"]])
        if r.returncode != 0:
            s["verdict"] = "FAIL"
    elif output is not None:
        with open(output, "w") as f:
            f.write(text(settings, s))
    sys.stdout.write(text(settings, s))
    if merged_partial:
        m = {"kind": "gatesim", "version": VERSION, "commit": first["commit"], "settings": settings,
             "shard": {"index": 0, "count": 1}, "summary": s,
             "timing": {"wall_seconds": round(sum(p["timing"]["wall_seconds"] for _, p in ordered), 2),
                        "cpu_seconds": round(sum(p["timing"]["cpu_seconds"] for _, p in ordered), 2),
                        "host": socket.gethostname()}}
        with open(merged_partial, "w") as f:
            json.dump(m, f, indent=1)
            f.write("\n")
    return 0 if s["verdict"] == "PASS" else 1


def main():
    if len(sys.argv) >= 2 and sys.argv[1] == "write" and len(sys.argv) == 4:
        write(sys.argv[2], sys.argv[3])
        return 0
    if len(sys.argv) >= 2 and sys.argv[1] == "summary" and len(sys.argv) == 3:
        # The summary of one partial as the merge computes it (for a shard 0/1 run).
        p = json.load(open(sys.argv[2]))
        json.dump(p["summary"] if "summary" in p else summarise(p["settings"], [p["result"]]), sys.stdout,
                  indent=1, sort_keys=True)
        sys.stdout.write("\n")
        return 0
    if len(sys.argv) >= 2 and sys.argv[1] == "merge":
        try:
            return merge(sys.argv[2:])
        except Refused as e:
            sys.stderr.write("gatesim.sh %s\n" % e)
            return 2
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
