#!/usr/bin/env python3
"""RTL mutation analysis (issue 37, docs/testing.md "Coverage and mutants").

Yosys's `mutate` plants one fault at a time in a flattened copy of a target module
(specular_device, specular_device_sync or control_unit16); the mutant is written back as
Verilog and replayed by the RTL tests' own Icarus run (rtl/tb/run_icarus.cmake, the
vectors of specular_tb) on every policy combination until one fails: then it is killed.
A mutant that passes every combination is screened by a formal equivalence check (Yosys
`miter -equiv` + `sat -tempinduct` on the original against the mutant, the ROM words cut
to shared free inputs and the ROM addresses compared as outputs, so a proof holds for any
ROM contents): proven equivalent, or a survivor to triage.

  rtl_mutants.py run --target T [--count N] [--seed S] [--shard I/N] [--partial F] [--out DIR]
                                         (exit 1 on an unargued survivor, or 0 once --partial's
                                         file is written: the merge judges a farm task's shard)
  rtl_mutants.py merge PARTIAL...        the shards of one run -> the report (exit 1 on a survivor
                                         not argued in the triage file)
  rtl_mutants.py report PARTIAL...       any partials together (a run and a re-run of its survivors:
                                         a mutant given twice counts as the later partial says)
  rtl_mutants.py smoke                   CI: the unmutated round trip passes, a few mutants die
  rtl_mutants.py check-triage            CI: every triaged mutant is still that mutant of its list

A survivor argued equivalent or unreachable through the pins' contract is listed in
scripts/rtl_mutants_triage.tsv (target, count, seed, index, the mutation, the reason) and
counted apart, as the mutants sat proves equivalent are: the score is killed / (killed +
survived). A mutation names cells by their source line, so an entry outlives no change
of the RTL it argues about: check-triage then fails and the survivor must be argued again.

The list of mutants is Yosys's (`mutate -list N -seed S`): the same N and seed give the
same mutants, so shards split it by index (i mod N = I) and merge back into the run.
"""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTL = os.path.join(ROOT, "rtl")
# The device's Verilog (rtl/sources.cmake): the targets live in device/.
DEVICE_SOURCES = sorted(glob.glob(os.path.join(RTL, "device", "*.v")) + glob.glob(os.path.join(RTL, "primitives", "*.v")))
TARGETS = {
    # target: (module file, testbench, testbench top, top the mutant replaces)
    "specular_device": ("specular_device.v", "specular_device_tb.v", "specular_device_tb"),
    "specular_device_sync": ("specular_device_sync.v", "specular_device_sync_tb.v", "specular_device_sync_tb"),
    "control_unit16": ("control_unit16.v", "specular_device_tb.v", "specular_device_tb"),
}
CONSTANTS = ["patent", "minimax-half", "minimax"]
NORMALISATIONS = ["patent", "energy", "none", "device-energy"]
# Every combination the Icarus tests replay; the first is tried first (most mutants die there).
COMBINATIONS = [(c, n, s) for s in ("clamp", "literal") for c in CONSTANTS for n in NORMALISATIONS]
TRIAGE = os.path.join(ROOT, "scripts", "rtl_mutants_triage.tsv")
ROM_MEMORIES = {"rom5": ("ROM5_IMAGE", "mantissa_rom", 32767), "rom38": ("ROM38_IMAGE", "k_rom", 16383)}


def die(message, status=2):
    print("rtl_mutants.py: error: " + message, file=sys.stderr)
    sys.exit(status)


def yosys(script, work, timeout=None):
    path = os.path.join(work, "script.ys")
    with open(path, "w") as f:
        f.write(script)
    try:
        result = subprocess.run(["yosys", "-q", "-s", path], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise RuntimeError("ERROR: no proof within %d s (timeout)" % timeout)
    if result.returncode != 0:
        raise RuntimeError("yosys failed:\n" + result.stdout[-2000:] + result.stderr[-2000:])
    return result.stdout


def read_design(target):
    """Yosys commands: every RTL source, the target flattened (ROM words left to the
    simulator: the memories are declared without their images)."""
    sources = " ".join(DEVICE_SOURCES)
    return ("read_verilog -DSPECULAR_ROM_WORDS_FROM_HOST -defer %s\n"
            "hierarchy -top %s\nproc\nflatten\nopt_clean\nhierarchy -top %s\n" % (sources, target, target))


def portable(mutation):
    """A mutation without its -src attributes and with the sources' folder left out of its
    cell names: the same mutant in every checkout ('$/any/where/rtl/device/rom5.v:61$20'
    -> '$rtl/device/rom5.v:61$20')."""
    return re.sub(r"\$/\S*?/rtl/", "$rtl/", mutation.split(" -src ")[0])


def triage():
    """scripts/rtl_mutants_triage.tsv: {(target, count, seed, index): (mutation, reason)}."""
    entries = {}
    for number, line in enumerate(open(TRIAGE), 1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.rstrip("\n").split("\t")
        if len(fields) != 6:
            die("%s line %d: %d fields, not 6 (target, count, seed, index, mutation, reason)"
                % (TRIAGE, number, len(fields)))
        target, count, seed, index, mutation, reason = fields
        entries[(target, int(count), int(seed), int(index))] = (mutation, reason)
    return entries


def check_triage():
    """Every triaged mutant is still, at its index, the mutation it argues about, with a reason."""
    entries = triage()
    status = 0
    work = tempfile.mkdtemp(prefix="rtl_mutants_triage_")
    try:
        lists = {}
        for (target, count, seed, index), (mutation, reason) in sorted(entries.items()):
            if target not in TARGETS:
                print("rtl_mutants.py: triage: '%s' is not one of: %s" % (target, ", ".join(TARGETS)), file=sys.stderr)
                status = 1
                continue
            if (target, count, seed) not in lists:
                lists[(target, count, seed)] = [portable(m) for m in list_mutants(target, count, seed, work)]
            mutants = lists[(target, count, seed)]
            if index >= len(mutants) or mutants[index] != mutation:
                print("rtl_mutants.py: triage: %s mutant %d of (count %d, seed %d) is no longer '%s'"
                      % (target, index, count, seed, mutation), file=sys.stderr)
                status = 1
            if not reason.strip():
                print("rtl_mutants.py: triage: %s mutant %d has no reason" % (target, index), file=sys.stderr)
                status = 1
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if status == 0:
        print("rtl_mutants.py: every one of %d triaged mutants is still its mutation, with a reason" % len(entries))
    return status


def list_mutants(target, count, seed, work):
    out = os.path.join(work, "list.ys")
    yosys(read_design(target) + "mutate -list %d -seed %d -o %s\n" % (count, seed, out), work)
    return [line.strip() for line in open(out) if line.strip()]


def parameter_block(target):
    """The target's parameters and localparams as body declarations: the testbench sets
    the parameters and reads the derived widths (dut.COS_W ...) of the mutant as of the
    original."""
    src = open(os.path.join(RTL, "device", TARGETS[target][0])).read()
    m = re.search(r"module\s+%s\s*#\((.*?)\)\s*\(" % target, src, re.S)
    if not m:
        return ""
    body = re.sub(r"//[^\n]*", "", m.group(1))
    chunks = [c.strip().rstrip(",").strip() for c in re.split(r"\bparameter\b", body) if c.strip()]
    block = "".join("  parameter %s;\n" % c for c in chunks)
    block += "".join(l.strip() + "\n" for l in re.findall(r"^\s*localparam[^;]*;", src, re.M))
    return block


def write_mutant(target, mutation, work):
    """The flattened target with one mutation (None: unmutated), as Verilog for Icarus."""
    path = os.path.join(work, target + "_mutant.v")
    # opt_expr + opt_dff: a flip-flop whose asynchronous set or reset the mutant made
    # constant is a constant in Yosys's semantics (and in silicon), but write_verilog's
    # `always @(posedge SET ...)` never sees a constant rise, and Icarus would simulate the
    # original flip-flop. Folding it first keeps the written Verilog faithful.
    yosys(read_design(target) + (mutation + "\n" if mutation else "") +
          "opt_clean\nopt_expr\nopt_dff\nopt_clean\nwrite_verilog -noattr %s\n" % path, work)
    text = open(path).read()
    shutil.copyfile(path, path[:-2] + "_raw.v")
    text = re.sub(r"(module %s\(.*?\);\n)" % target, lambda m: m.group(1) + parameter_block(target),
                  text, count=1, flags=re.S)
    loads = ""
    for rom, (param, memory, last) in ROM_MEMORIES.items():
        if "\\%s.%s " % (rom, memory) in text:
            loads += "  initial $readmemh(%s, \\%s.%s , 0, %d);\n" % (param, rom, memory, last)
    text = text.replace("endmodule", loads + "endmodule")
    open(path, "w").write(text)
    return path


def replay(target, mutant_file, combination, build, work):
    """One Icarus replay of the RTL tests (run_icarus.cmake): 'pass', 'fail', 'refused'."""
    module_file, testbench, tb_top = TARGETS[target]
    sources = [s for s in DEVICE_SOURCES if os.path.basename(s) != module_file]
    sources.append(mutant_file)
    constants, normalisation, saturation = combination
    scratch = os.path.join(work, "replay")
    command = ["cmake", "-DIVERILOG=iverilog", "-DVVP=vvp",
               "-DSPECULAR_TB=" + os.path.join(build, "testbench", "specular_tb"),
               "-DROM_DIR=" + os.path.join(build, "rtl", "rom", "default"),
               "-DSOURCES=" + "|".join(sources), "-DTESTBENCH=" + os.path.join(RTL, "tb", testbench),
               "-DTB_TOP=" + tb_top, "-DWIDTHS=", "-DPARAMS=",
               "-DCONSTANTS=" + constants, "-DCONSTANTS_VALUE=%d" % CONSTANTS.index(constants),
               "-DNORMALISATION=" + normalisation,
               "-DNORMALISATION_VALUE=%d" % NORMALISATIONS.index(normalisation),
               "-DSATURATION=" + saturation, "-DSCRATCH=" + scratch,
               "-P", os.path.join(RTL, "tb", "run_icarus.cmake")]
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return "fail", "timeout (120 s)"
    text = result.stdout + result.stderr
    if "combination refused by the model" in text:
        return "refused", ""
    if result.returncode == 0 and ": PASS" in text:
        return "pass", ""
    first = [l for l in text.splitlines() if "MISMATCH" in l or "ERROR" in l or "rror" in l]
    return "fail", (first[0] if first else text[-300:]).strip()[:300]


def cut_roms(text, target):
    """The ROM reads of a written netlist cut open: each word becomes an input port
    (shared by both sides of the miter: the same name) and each address an output port
    (compared by the miter), so the check needs no ROM image and holds for any contents."""
    ports, body = [], ""
    for rom, (_, memory, last) in ROM_MEMORIES.items():
        name = "\\%s.%s " % (rom, memory)
        decl = re.search(r"\n\s*reg \[(\d+):0\] %s\s*\[\d+:0\];" % re.escape(name), text)
        read = re.search(r"\n\s*assign ([^=]+?) = %s\[(.*)\];" % re.escape(name), text)
        if not decl or not read:
            continue
        address_bits = (last + 1).bit_length() - 1
        ports += ["%s_word_in" % rom, "%s_address_out" % rom]
        body += ("  input [%s:0] %s_word_in;\n  output [%d:0] %s_address_out;\n"
                 "  assign %s_address_out = %s;\n  assign %s = %s_word_in;\n"
                 % (decl.group(1), rom, address_bits - 1, rom, rom, read.group(2), read.group(1), rom))
        text = text.replace(decl.group(0), "\n").replace(read.group(0), "\n")
    if ports:
        text = re.sub(r"module %s\(" % target, "module %s(%s, " % (target, ", ".join(ports)), text, count=1)
        text = text.replace("endmodule", body + "endmodule")
    return text


def equivalence(target, gold_file, gate_file, work, depth, timeout):
    """Formal screen: 'equivalent' when sat proves the mutant's outputs equal to the
    original's for every input sequence from the same initial state (every flip-flop 0,
    every clock and the start pin modelled as sampled signals by clk2fflogic) and any ROM
    contents; else 'not proven' (a difference found, or no proof within DEPTH steps)."""
    for name, source in (("gold", gold_file), ("gate", gate_file)):
        text = cut_roms(open(source).read(), target).replace("module %s(" % target, "module %s(" % name, 1)
        open(os.path.join(work, name + "_formal.v"), "w").write(text)
    script = ("read_verilog %s %s\nproc\nclk2fflogic\nopt_clean\n"
              "miter -equiv -flatten -make_outputs -ignore_gold_x gold gate miter\nhierarchy -top miter\n"
              "sat -verify -tempinduct -prove trigger 0 -set-init-zero -maxsteps %d miter\n"
              % (os.path.join(work, "gold_formal.v"), os.path.join(work, "gate_formal.v"), depth))
    try:
        yosys(script, work, timeout)
        return "equivalent", "sat -tempinduct proved the miter's trigger 0 (any ROM contents)"
    except RuntimeError as e:
        m = re.search(r"ERROR: ([^\n]*)", str(e))
        return "not proven", (m.group(1) if m else "sat found a difference or no proof")[:200]


def run(args):
    if args.target not in TARGETS:
        die("--target: '%s' is not one of: %s" % (args.target, ", ".join(TARGETS)))
    index, count = parse_shard(args.shard)
    build = os.path.abspath(args.build)
    if not os.access(os.path.join(build, "testbench", "specular_tb"), os.X_OK):
        die("no %s/testbench/specular_tb (build specular_tb and specular_rom_images)" % build)
    work = tempfile.mkdtemp(prefix="rtl_mutants_", dir=args.out)
    mutants = list_mutants(args.target, args.count, args.seed, work)
    # The harness must pass the unmutated round trip, or no kill means anything.
    unmutated = write_mutant(args.target, None, work)
    gold = os.path.join(work, "gold_raw.v")
    shutil.copyfile(unmutated[:-2] + "_raw.v", gold)
    baseline, detail = replay(args.target, unmutated, COMBINATIONS[0], build, work)
    if baseline != "pass":
        die("the unmutated %s (Yosys round trip) fails its replay: %s" % (args.target, detail), 1)
    results = []
    for i, mutation in enumerate(mutants):
        if i % count != index or (args.only and i not in args.only):
            continue
        started = time.time()
        entry = {"index": i, "mutation": mutation}
        try:
            mutant = write_mutant(args.target, mutation, work)
        except RuntimeError as e:
            entry.update(verdict="invalid", detail=str(e)[-200:])
            results.append(entry)
            continue
        entry["verdict"] = "survived"
        for combination in COMBINATIONS:
            outcome, detail = replay(args.target, mutant, combination, build, work)
            if outcome == "fail":
                entry.update(verdict="killed", by="rtl_icarus_%s_%s_%s" % combination, detail=detail)
                break
        if entry["verdict"] == "survived":
            verdict, detail = equivalence(args.target, gold, mutant[:-2] + "_raw.v", work, args.depth,
                                          args.formal_timeout)
            entry.update(verdict="equivalent" if verdict == "equivalent" else "survived", detail=detail)
        entry["seconds"] = round(time.time() - started, 2)
        print("mutant %d: %s %s" % (i, entry["verdict"], entry.get("by", "")), flush=True)
        results.append(entry)
    shutil.rmtree(work, ignore_errors=True)
    partial = {"kind": "rtl_mutants", "version": 1, "commit": commit(),
               "settings": {"target": args.target, "count": args.count, "seed": args.seed,
                            "mutants": len(mutants)},
               "shard": {"index": index, "count": count}, "results": results}
    if args.partial:
        json.dump(partial, open(args.partial, "w"), indent=1)
    status = report([partial])
    # A farm task (--partial) has done its part when the partial is written: the merge of
    # every shard judges the survivors, and a failing task would keep the merge from running.
    return 0 if args.partial else status


def commit():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
    except OSError:
        return "unknown"


def parse_shard(text):
    m = re.fullmatch(r"(\d+)/(\d+)", text or "0/1")
    if not m or int(m.group(2)) < 1 or int(m.group(1)) >= int(m.group(2)):
        die("--shard: '%s' is not I/N with 0 <= I < N" % text)
    return int(m.group(1)), int(m.group(2))


def report(partials):
    """The summary of partials (a mutant given twice counts as the later partial says); a
    survivor argued in the triage file counts as argued, apart. Exit 1 when a mutant
    survived unargued."""
    argued = triage()
    by_target = {}
    for p in partials:
        settings = p["settings"]
        results = by_target.setdefault(settings["target"], {})
        for r in p["results"]:
            r = dict(r)
            key = (settings["target"], settings["count"], settings["seed"], r["index"])
            if r["verdict"] == "survived" and key in argued:
                if argued[key][0] != portable(r["mutation"]):
                    die("triage: %s mutant %d is '%s' in the run but '%s' in %s" % (
                        key[0], key[3], portable(r["mutation"]), argued[key][0], TRIAGE))
                r.update(verdict="argued", detail=argued[key][1])
            results[(settings["count"], settings["seed"], r["index"])] = r
    status = 0
    for target, keyed in sorted(by_target.items()):
        results = [keyed[k] for k in sorted(keyed)]
        counts = {v: sum(1 for r in results if r["verdict"] == v)
                  for v in ("killed", "equivalent", "argued", "survived", "invalid")}
        non_equivalent = counts["killed"] + counts["survived"]
        score = 100.0 * counts["killed"] / non_equivalent if non_equivalent else 100.0
        print("%s: %d mutants: %d killed, %d equivalent (proven), %d argued equivalent or unreachable "
              "(%s), %d survived, %d invalid; score %.1f %% of the non-equivalent"
              % (target, len(results), counts["killed"], counts["equivalent"], counts["argued"],
                 os.path.relpath(TRIAGE, ROOT), counts["survived"], counts["invalid"], score))
        for r in results:
            if r["verdict"] in ("survived", "equivalent", "argued"):
                print("  %s %d: %s (%s)" % (r["verdict"], r["index"], r["mutation"].split(" -src")[0],
                                            r.get("detail", "")))
        if counts["survived"]:
            status = 1
    return status


def merge(files):
    partials = [json.load(open(f)) for f in files]
    if not partials:
        die("merge: no partial given")
    groups = {}
    for f, p in zip(files, partials):
        if p.get("kind") != "rtl_mutants":
            die("merge: '%s' is not an rtl_mutants partial" % f)
        key = json.dumps(p["settings"], sort_keys=True)
        groups.setdefault(key, []).append((f, p))
    for key, members in groups.items():
        count = members[0][1]["shard"]["count"]
        seen = {}
        for f, p in members:
            i = p["shard"]["index"]
            if p["shard"]["count"] != count:
                die("merge: '%s' is a shard of %d, not %d" % (f, p["shard"]["count"], count))
            if i in seen:
                die("merge: shard %d/%d is given twice: '%s' and '%s'" % (i, count, seen[i], f))
            seen[i] = f
        missing = [i for i in range(count) if i not in seen]
        if missing:
            die("merge: %d of %d shards missing: %s" % (len(missing), count,
                ", ".join("%d/%d" % (i, count) for i in missing)))
    return report(partials)


def smoke(args):
    """CI's smoke (seconds): the unmutated round trip of the control unit passes, and three
    of Yosys's mutants of it (NAND 47's output stuck at 1, flip-flop 41 clocked by the
    inverted start, the done pin inverted) must each be killed by the first replay."""
    build = os.path.abspath(args.build)
    work = tempfile.mkdtemp(prefix="rtl_mutants_smoke_")
    try:
        baseline, detail = replay("control_unit16", write_mutant("control_unit16", None, work),
                                  COMBINATIONS[0], build, work)
        if baseline != "pass":
            die("the unmutated control_unit16 fails its replay: %s" % detail, 1)
        print("unmutated control_unit16: pass")
        mutants = list_mutants("control_unit16", 1000, 1, work)
        picks = [m for m in mutants if "-mode const1" in m and "nand47" in m and "-port Y" in m][:1]
        picks += [m for m in mutants if "-mode inv" in m and "-port CLK" in m and "dff41" in m][:1]
        picks += [m for m in mutants if "-mode inv" in m and "-wire done35" in m][:1]
        if len(picks) != 3:
            die("smoke: Yosys's list of control_unit16 mutants lacks a planned mutant (%d of 3)" % len(picks), 1)
        status = 0
        for m in picks:
            outcome, detail = replay("control_unit16", write_mutant("control_unit16", m, work),
                                     COMBINATIONS[0], build, work)
            print("%s: %s" % (m.split(" -src")[0], "killed" if outcome == "fail" else "NOT KILLED"))
            if outcome != "fail":
                status = 1
        return status
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--merge":  # farm.sh's merge convention
        sys.argv[1] = "merge"
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("--target", required=True)
    r.add_argument("--count", type=int, default=60)
    r.add_argument("--seed", type=int, default=1)
    r.add_argument("--depth", type=int, default=20, help="sat -tempinduct's maximum steps")
    r.add_argument("--formal-timeout", type=int, default=120, help="seconds for one equivalence check")
    r.add_argument("--only", type=lambda t: [int(x) for x in t.split(",")], help="these indices only (triage)")
    r.add_argument("--shard")
    r.add_argument("--partial")
    r.add_argument("--out")
    r.add_argument("--build", default=os.path.join(ROOT, "build"))
    m = sub.add_parser("merge")
    m.add_argument("partials", nargs="+")
    rp = sub.add_parser("report")
    rp.add_argument("partials", nargs="+")
    s = sub.add_parser("smoke")
    s.add_argument("--build", default=os.path.join(ROOT, "build"))
    sub.add_parser("check-triage")
    args = parser.parse_args()
    if args.command == "run":
        if args.count < 1:
            die("--count: %d is outside the allowed range [1, 100000]" % args.count)
        sys.exit(run(args))
    if args.command == "merge":
        sys.exit(merge(args.partials))
    if args.command == "report":
        sys.exit(report([json.load(open(f)) for f in args.partials]))
    if args.command == "check-triage":
        sys.exit(check_triage())
    sys.exit(smoke(args))


if __name__ == "__main__":
    main()
