#!/usr/bin/env python3
"""C++ mutation analysis (issue 37, docs/testing/coverage.md "Coverage and mutants: how strong the suite is").

A small mutator of our own: one change at a time in arith.cpp, core.cpp, control/*.cpp
and tlm/target.cpp of modules/src -- a relational operator swapped (< <=, > >=, == !=),
an arithmetic one (+ -, * /, += -=, ++ --), a logical one (&& ||), an integer constant
+1 or -1, an if/while condition negated, a one-line statement deleted. Each mutant is
written into the source tree, the test executables that exercise its file are rebuilt
(cmake --build, ccache), and their quick tests run one process per test (SystemC
elaborates once per process) until one fails: killed. A mutant that does not compile
is not counted. The file is restored after every mutant (and on an interrupt).

  cpp_mutants.py list                              every mutant: id, file:line, change
  cpp_mutants.py run [--sample K --seed S] [--ids A,B] [--shard I/N] [--partial F] [--build DIR]
                     [--tests EXE,...]             (survivors again under a sanitizer build: run it
                                                   through scripts/verify/sanitizer_env.sh); exit 1 below
                                                   --goal, or 0 once --partial's file is written
  cpp_mutants.py merge PARTIAL...                  shards -> per-file scores (exit 1 below --goal)
  cpp_mutants.py report PARTIAL...                 the scores of any partials together (strata, samples;
                                                   a mutant given twice counts as the later partial says)
  cpp_mutants.py check-triage                      CI: every triaged mutant still exists, with a reason

A survivor argued equivalent (it changes no output the device's contract lets anyone see)
is listed in scripts/verify/cpp_mutants_triage.tsv (file, change, the line, the mutated line, the
reason) and counted apart: the score is killed / (killed + survived), equivalents left
out, as for the RTL mutants that Yosys proves equivalent.

The ids are stable for a given source tree (files in a fixed order, lines top-down,
changes left to right), so a seeded sample and a shard (id mod N = I) are the same on
every machine. Run it in a tree of its own (the farm task copies the commit): it edits
the sources while it runs.
"""
import argparse
import collections
import concurrent.futures
import json
import math
import os
import random
import re
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SRC = os.path.join(ROOT, "modules", "src")
# The mutated files and the test executables that exercise them (their quick tests).
CORE_TESTS = ["test_arith_accuracy", "test_arith_bus", "test_constants", "test_block_rom5",
              "test_block_rom38", "test_core_kernel_free", "test_device_policies", "test_format_inputs"]
CONTROL_TESTS = ["test_control_protocol", "test_control_timing", "test_block_dff", "test_block_gates",
                 "test_power_on_reset"]
TLM_TESTS = ["test_tlm_registers", "test_tlm_legal_use", "test_misuse_tlm", "test_tlm_timing", "test_tlm_idle",
             "test_tlm_integration", "test_tlm_operand_burst", "test_tlm_strict_delay", "test_tlm_rtl",
             "test_tlm_diagnostics", "test_tlm_access_sweep", "test_tlm_interrupt_orders", "test_tlm_operand_classes"]
FILES = [("arith.cpp", CORE_TESTS), ("core.cpp", CORE_TESTS),
         ("control/control_unit16.cpp", CONTROL_TESTS), ("control/d_flip_flop.cpp", CONTROL_TESTS),
         ("control/gates.cpp", CONTROL_TESTS), ("tlm/target.cpp", TLM_TESTS)]
SWAPS = [(" <= ", " < "), (" < ", " <= "), (" >= ", " > "), (" > ", " >= "), (" == ", " != "),
         (" != ", " == "), (" + ", " - "), (" - ", " + "), (" * ", " / "), (" / ", " * "),
         (" += ", " -= "), (" -= ", " += "), ("++", "--"), ("--", "++"), (" && ", " || "),
         (" || ", " && ")]


TRIAGE = os.path.join(ROOT, "scripts", "verify", "cpp_mutants_triage.tsv")


def triage():
    """{(file, change, line stripped, mutated line stripped): reason} of the survivors argued
    equivalent."""
    entries = {}
    with open(TRIAGE) as f:
        for line in f:
            if not line.strip() or line.startswith("#"):
                continue
            fields = line.rstrip("\n").split("\t")
            fields += [""] * (5 - len(fields))
            entries[tuple(fields[:4])] = fields[4]
    return entries


def key_of(m):
    """A mutant's identity across trees: file, change, the line before and after."""
    return (m["file"], m["change"], m["original"].strip(), m["new"].strip())


def check_triage():
    """Every triaged mutant is still exactly one mutant of the tree, and has a reason (a line
    whose text repeats would make the entry name two mutants, one of them unargued)."""
    current = collections.Counter(key_of(m) for m in all_mutants())
    status = 0
    entries = triage()
    for key, reason in entries.items():
        if current[key] != 1:
            where = "no longer" if current[key] == 0 else "%d times" % current[key]
            print("cpp_mutants.py: triaged mutant %s in the tree: %s %s: %s -> %s" % ((where,) + key),
                  file=sys.stderr)
            status = 1
        if not reason.strip():
            print("cpp_mutants.py: triaged mutant without a reason: %s %s: %s -> %s" % key, file=sys.stderr)
            status = 1
    if status == 0:
        print("cpp_mutants.py: every one of %d triaged mutants is in the tree, with a reason" % len(entries))
    return status


def die(message, status=2):
    print("cpp_mutants.py: error: " + message, file=sys.stderr)
    sys.exit(status)


def masked(line):
    """The line with string/char literals and a trailing // comment blanked (same length),
    so that no change lands inside them."""
    out, i, quote = list(line), 0, None
    while i < len(line):
        c = line[i]
        if quote:
            if c == "\\":
                out[i] = " "
                if i + 1 < len(line):
                    out[i + 1] = " "
                i += 2
                continue
            if c == quote:
                quote = None
            else:
                out[i] = " "
        elif c in "\"'":
            quote = c
        elif line.startswith("//", i):
            return "".join(out[:i]) + " " * (len(line) - i)
        i += 1
    return "".join(out)


def balanced_end(text, start):
    """Index after the parenthesis that closes the one at text[start]."""
    depth = 0
    for i in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return i + 1
    return -1


def mutants_of(rel, lines):
    """Every mutant of one file: (line number, description, new line)."""
    result = []
    in_block_comment = False
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        if in_block_comment:
            in_block_comment = "*/" not in stripped
            continue
        if stripped.startswith("/*"):
            in_block_comment = "*/" not in stripped
            continue
        if not stripped or stripped.startswith(("//", "#", "namespace", "}")) or "static_assert" in stripped:
            continue
        m = masked(line)
        for old, new in SWAPS:
            for hit in re.finditer(re.escape(old), m):
                i = hit.start()
                if old in ("++", "--") and (m[i:i + 3] in ("+++", "---") or (i and m[i - 1] in "+-")):
                    continue
                if old in (" < ", " > ") and ("<<" in m[i - 1:i + 3] or ">>" in m[i - 1:i + 3]):
                    continue
                result.append((number, "'%s' -> '%s'" % (old.strip(), new.strip()),
                               line[:i] + new + line[i + len(old):]))
        for hit in re.finditer(r"(?<![\w.])(\d+)(?![\w.])", m):
            value = int(hit.group(1))
            for delta in (1, -1):
                if value + delta < 0:
                    continue
                result.append((number, "constant %d -> %d" % (value, value + delta),
                               line[:hit.start()] + str(value + delta) + line[hit.end():]))
        for hit in re.finditer(r"\b(if|while) \(", m):
            open_at = hit.end() - 1
            close = balanced_end(m, open_at)
            if close < 0:
                continue
            result.append((number, "%s condition negated" % hit.group(1),
                           line[:open_at + 1] + "!(" + line[open_at + 1:close - 1] + ")" + line[close - 1:]))
        if (stripped.endswith(";") and not stripped.startswith(("return", "const ", "auto ", "using "))
                and m.count("(") == m.count(")") and not re.match(r"^[\w:<>,\s*&]+\s+\w+(\s*[=({].*)?;$", stripped)):
            result.append((number, "statement deleted", re.match(r"\s*", line).group(0) + ";\n"))
    return result


def all_mutants():
    """[(id, rel file, line, description, new line)] in a fixed order."""
    out = []
    for rel, _ in FILES:
        with open(os.path.join(SRC, rel)) as f:
            lines = f.readlines()
        for number, description, new in mutants_of(rel, lines):
            out.append({"id": len(out), "file": rel, "line": number, "change": description, "new": new,
                        "original": lines[number - 1]})
    return out


def tests_of(rel):
    return dict(FILES)[rel]


def run_tests(build, executables, timeout, jobs):
    """The quick tests of the executables, one process each; the first failure's name, or
    None when every test passed."""
    cases = []
    for exe in executables:
        path = os.path.join(build, "tests", exe)
        listed = subprocess.run([path, "--gtest_list_tests"], capture_output=True, text=True,
                                cwd=os.path.join(build, "tests"), timeout=timeout,
                                env=dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1"))
        if listed.returncode != 0:
            return "%s --gtest_list_tests (exit %d)" % (exe, listed.returncode)
        suite = None
        for line in listed.stdout.splitlines():
            if not line.startswith(" "):
                suite = line.strip()
            else:
                name = line.split("#")[0].strip()
                if suite and not suite.startswith("DISABLED_") and not name.startswith("DISABLED_"):
                    cases.append((exe, path, suite + name))

    def one(case):
        exe, path, name = case
        try:
            r = subprocess.run([path, "--gtest_filter=" + name], capture_output=True, text=True,
                               cwd=os.path.join(build, "tests"), timeout=timeout,
                               env=dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1"))
        except subprocess.TimeoutExpired:
            return "%s %s (timeout %d s)" % (exe, name, timeout)
        if r.returncode != 0 and "[  SKIPPED ]" not in r.stdout:
            return "%s %s" % (exe, name)
        return None

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(one, c) for c in cases]
        for future in futures:  # in order; the others are cancelled once one failed
            failure = future.result()
            if failure:
                for f in futures:
                    f.cancel()
                return failure
    return None


def build_targets(build, targets, log):
    r = subprocess.run(["cmake", "--build", build, "-j2", "--target"] + targets, capture_output=True,
                       text=True)
    with open(log, "a") as f:
        f.write(r.stdout[-3000:] + r.stderr[-3000:])
    return r.returncode == 0


def run_in_copy(args):
    """The farm's way: the commit copied into DIR/src (git archive), configured and built in
    DIR/build (Release, ccache when present), then this script of the copy mutates the copy.
    The copy builds specular and specular_core as shared libraries whose change relinks no
    executable (CMAKE_LINK_DEPENDS_NO_SHARED): a mutant then costs one object and one
    library link, not the relinking of every test executable of its file (up to 13, some
    with the verilated twin)."""
    copy = os.path.abspath(args.copy)
    src, build = os.path.join(copy, "src"), os.path.join(copy, "build")
    os.makedirs(src, exist_ok=True)
    archive = subprocess.run(["git", "-C", ROOT, "archive", "HEAD"], capture_output=True, check=True).stdout
    subprocess.run(["tar", "-x", "-C", src], input=archive, check=True)
    launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"] \
        if subprocess.run(["sh", "-c", "command -v ccache"], capture_output=True).returncode == 0 else []
    subprocess.run(["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_SHARED_LIBS=ON",
                    "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON"] + launcher,
                   check=True, stdout=subprocess.DEVNULL)
    argv = [a for a in sys.argv[1:]]
    k = argv.index("--copy")
    del argv[k:k + 2]
    # the partial is written where the task asked for it, with the commit of this tree
    return subprocess.run([sys.executable, os.path.join(src, "scripts", "verify", "cpp_mutants.py")] + argv +
                          ["--build", build, "--commit", commit()]).returncode


def run(args):
    if args.copy:
        return run_in_copy(args)
    mutants = all_mutants()
    build = os.path.abspath(args.build)
    if args.files:  # a stratum: only the mutants of files whose path starts so
        mutants = [m for m in mutants if m["file"].startswith(args.files)]
    if args.ids:
        chosen = [m for m in mutants if m["id"] in args.ids]
    elif args.sample:
        chosen = sorted(random.Random(args.seed).sample(mutants, min(args.sample, len(mutants))),
                        key=lambda m: m["id"])
    else:
        chosen = mutants
    index, count = parse_shard(args.shard)
    chosen = [m for k, m in enumerate(chosen) if k % count == index]
    log = os.path.abspath(args.log or os.path.join(build, "cpp_mutants_build.log"))
    originals = {}

    def restore(*_):
        for path, text in originals.items():
            with open(path, "w") as f:
                f.write(text)
        originals.clear()

    def interrupted(signum, _):
        restore()
        sys.exit(128 + signum)
    signal.signal(signal.SIGTERM, interrupted)
    signal.signal(signal.SIGINT, interrupted)
    if args.tests:  # a re-run in a sanitizer build: only these executables of each file's list
        unknown = sorted(set(args.tests) - {t for _, ts in FILES for t in ts})
        if unknown:
            die("--tests: %s not among the mutated files' test executables" % ", ".join(unknown))
        tests = lambda rel: [t for t in tests_of(rel) if t in args.tests]
        untested = sorted({m["file"] for m in chosen if not tests(m["file"])})
        if untested:
            die("--tests: no executable of %s's list among them: its mutants would survive untested"
                % ", ".join(untested))
    else:
        tests = tests_of
    all_targets = sorted({t for rel, _ in FILES for t in tests(rel)})
    # Configure again first: a test file added since the last configure is a target the
    # generated build files do not know yet (a build of it by name fails before the glob
    # is looked at again).
    subprocess.run(["cmake", build], capture_output=True)
    if not build_targets(build, all_targets, log):
        die("the unmutated tree does not build (see %s)" % log, 1)
    # The unmutated tests must pass, or a failure would "kill" every mutant.
    for rel in sorted({m["file"] for m in chosen}):
        failure = run_tests(build, tests(rel), args.timeout, args.jobs)
        if failure:
            die("the unmutated tree fails %s: a mutant cannot be judged by it" % failure, 1)
    results = []
    try:
        for m in chosen:
            started = time.time()
            path = os.path.join(SRC, m["file"])
            text = open(path).read()
            originals[path] = text
            lines = text.splitlines(keepends=True)
            lines[m["line"] - 1] = m["new"]
            with open(path, "w") as f:
                f.write("".join(lines))
            entry = {k: m[k] for k in ("id", "file", "line", "change")}
            entry["original"] = m["original"].strip()
            entry["mutated"] = m["new"].strip()
            if not build_targets(build, tests(m["file"]), log):
                entry["verdict"] = "uncompilable"
            else:
                failure = run_tests(build, tests(m["file"]), args.timeout, args.jobs)
                entry["verdict"] = "killed" if failure else "survived"
                if failure:
                    entry["by"] = failure
            restore()
            entry["seconds"] = round(time.time() - started, 1)
            print("mutant %d %s:%d %s: %s %s" % (m["id"], m["file"], m["line"], m["change"],
                                                 entry["verdict"], entry.get("by", "")), flush=True)
            results.append(entry)
    finally:
        restore()
        build_targets(build, all_targets, log)  # the unmutated objects back (ccache)
    partial = {"kind": "cpp_mutants", "version": 1, "commit": args.commit or commit(),
               "settings": {"sample": args.sample, "seed": args.seed, "ids": args.ids, "files": args.files,
                            "mutants_in_tree": len(mutants)},
               "shard": {"index": index, "count": count}, "results": results}
    if args.partial:
        with open(args.partial, "w") as f:
            json.dump(partial, f, indent=1)
    status = report([partial], args.goal)
    # A farm task (--partial) has done its part when the partial is written: the merge of
    # every shard judges the score, and a failing task would keep the merge from running.
    return 0 if args.partial else status


def commit():
    r = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    return r.stdout.strip() or "unknown"


def parse_shard(text):
    m = re.fullmatch(r"(\d+)/(\d+)", text or "0/1")
    if not m or int(m.group(2)) < 1 or int(m.group(1)) >= int(m.group(2)):
        die("--shard: '%s' is not I/N with 0 <= I < N" % text)
    return int(m.group(1)), int(m.group(2))


def wilson(k, n, z=1.96):
    """The 95 % Wilson score interval of k successes in n draws."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def report(partials, goal):
    # A mutant in several partials counts once, as the last one says: a re-run of the
    # survivors (--ids) against newer tests, given after the first run, replaces its verdict.
    latest = {}
    for p in partials:
        for r in p["results"]:
            if "original" not in r:  # a partial of before the field: the line of this tree
                with open(os.path.join(SRC, r["file"])) as f:
                    r["original"] = f.readlines()[r["line"] - 1].strip()
            r["key"] = (r["file"], r["change"], r["original"], r["mutated"])  # as key_of()
            latest[(r["file"], r["line"], r["change"], r["mutated"])] = r  # the line: texts repeat
    results = list(latest.values())
    equivalent = triage()
    for r in results:  # a survivor argued equivalent is counted apart
        if r["verdict"] == "survived" and r["key"] in equivalent:
            r["verdict"] = "equivalent"
    print("file | mutants run | killed | survived | equivalent (argued) | uncompilable | score (killed / (killed + survived))")
    total_k = total_n = 0
    for rel, _ in FILES + [("all", None)]:
        rs = results if rel == "all" else [r for r in results if r["file"] == rel]
        k = sum(r["verdict"] == "killed" for r in rs)
        s = sum(r["verdict"] == "survived" for r in rs)
        e = sum(r["verdict"] == "equivalent" for r in rs)
        u = sum(r["verdict"] == "uncompilable" for r in rs)
        if rel == "all":
            total_k, total_n = k, k + s
        score = "%.1f %%" % (100.0 * k / (k + s)) if k + s else "-"
        print("%s | %d | %d | %d | %d | %d | %s" % (rel, len(rs), k, s, e, u, score))
    low, high = wilson(total_k, total_n)
    print("score %d/%d = %.1f %%, 95 %% Wilson interval [%.1f %%, %.1f %%]"
          % (total_k, total_n, 100.0 * total_k / total_n if total_n else 0, 100 * low, 100 * high))
    for r in results:
        if r["verdict"] == "survived":
            print("  survived %d %s:%d %s: %s" % (r["id"], r["file"], r["line"], r["change"], r["mutated"]))
    for r in results:
        if r["verdict"] == "equivalent":
            print("  equivalent %d %s:%d %s: %s -- %s" % (r["id"], r["file"], r["line"], r["change"], r["mutated"],
                                                         equivalent[r["key"]]))
    return 0 if total_n and total_k / total_n >= goal else 1


def merge(args):
    partials = []
    for f in args.partials:
        p = json.load(open(f))
        if p.get("kind") != "cpp_mutants":
            die("merge: '%s' is not a cpp_mutants partial" % f)
        partials.append((f, p))
    count = partials[0][1]["shard"]["count"]
    seen = {}
    for f, p in partials:
        if p["settings"] != partials[0][1]["settings"]:
            die("merge: '%s' has other settings than '%s'" % (f, partials[0][0]))
        if p["commit"] != partials[0][1]["commit"]:
            die("merge: '%s' is of commit %s, '%s' of %s" % (f, p["commit"], partials[0][0], partials[0][1]["commit"]))
        i = p["shard"]["index"]
        if i in seen:
            die("merge: shard %d/%d is given twice: '%s' and '%s'" % (i, count, seen[i], f))
        seen[i] = f
    missing = [i for i in range(count) if i not in seen]
    if missing:
        die("merge: %d of %d shards missing: %s" % (len(missing), count, ", ".join("%d/%d" % (i, count) for i in missing)))
    return report([p for _, p in partials], args.goal)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--merge":  # farm.sh's merge convention
        sys.argv[1] = "merge"
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list")
    sub.add_parser("check-triage")
    r = sub.add_parser("run")
    r.add_argument("--sample", type=int, default=0, help="a seeded random sample of K mutants (0: all)")
    r.add_argument("--seed", type=int, default=37)
    r.add_argument("--ids", type=lambda t: [int(x) for x in t.split(",")])
    r.add_argument("--tests", type=lambda t: t.split(","),
                   help="only these test executables (e.g. survivors again in a sanitizer build)")
    r.add_argument("--files", help="only the mutants of files whose path starts with this (a stratum)")
    r.add_argument("--shard")
    r.add_argument("--partial")
    r.add_argument("--log")
    r.add_argument("--timeout", type=int, default=120)
    r.add_argument("--jobs", type=int, default=2)
    r.add_argument("--goal", type=float, default=0.90)
    r.add_argument("--build", default=os.path.join(ROOT, "build"))
    r.add_argument("--commit", help=argparse.SUPPRESS)
    r.add_argument("--copy", help="copy this commit into DIR/src, build it in DIR/build and mutate the copy (farm)")
    m = sub.add_parser("merge")
    m.add_argument("partials", nargs="+")
    m.add_argument("--goal", type=float, default=0.90)
    rp = sub.add_parser("report")
    rp.add_argument("partials", nargs="+")
    rp.add_argument("--goal", type=float, default=0.90)
    args = parser.parse_args()
    if args.command == "list":
        for m in all_mutants():
            print("%d\t%s:%d\t%s\t%s" % (m["id"], m["file"], m["line"], m["change"], m["new"].strip()))
        return 0
    if args.command == "check-triage":
        return check_triage()
    if args.command == "report":  # any partials (strata, samples): no shard bookkeeping
        return report([json.load(open(f)) for f in args.partials], args.goal)
    if args.command == "run":
        if args.sample < 0:
            die("--sample: %d is outside the allowed range [0, number of mutants]" % args.sample)
        return run(args)
    return merge(args)


if __name__ == "__main__":
    sys.exit(main())
