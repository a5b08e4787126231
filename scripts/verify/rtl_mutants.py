#!/usr/bin/env python3
"""RTL mutation analysis (issue 37, docs/testing/coverage.md "Coverage and mutants: how strong the suite is").

Yosys's `mutate` plants one fault at a time in a flattened copy of a target module
(specular_device, specular_device_sync or control_unit16); the mutant is written back as
Verilog and replayed by the RTL tests' own Icarus run (rtl/tb/run_icarus.cmake, the
vectors of specular_tb) on every policy combination until one fails: then it is killed.
A mutant that passes every combination is screened by a formal equivalence check (Yosys
`miter -equiv` + `sat -tempinduct` on the original against the mutant, the ROM words cut
to shared free inputs and the ROM addresses compared as outputs, so a proof holds for any
ROM contents): proven equivalent, or a survivor to triage.

The whole IP's targets (issue 46: specular_reg_block, specular_ip_axi) mutate their own
module only, the other IP module and the device read as black boxes, and replay the AXI
testbench's run (rtl/tb/run_ip_axi.cmake) in the cases of its ctest tests; they get no
sat screen (docs/rtl_ip/mutants_silicon.md, "Mutants"): a survivor is killed or argued.

  rtl_mutants.py run --target T [--count N] [--seed S] [--shard I/N] [--partial F] [--out DIR]
                                         (exit 1 on an unargued survivor, or 0 once --partial's
                                         file is written: the merge judges a farm task's shard)
  rtl_mutants.py merge PARTIAL...        the shards of one run -> the report (exit 1 on a survivor
                                         not argued in the triage file)
  rtl_mutants.py report PARTIAL...       any partials together (a run and a re-run of its survivors:
                                         a mutant given twice counts as the later partial says)
  rtl_mutants.py smoke [--kind device|ip] CI: the unmutated round trip passes, a few mutants die
  rtl_mutants.py check-triage            CI: every triaged mutant is still that mutant of its list

A survivor argued equivalent or unreachable through the pins' contract is listed in
scripts/verify/rtl_mutants_triage.tsv (target, count, seed, index, the mutation, the reason) and
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
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RTL = os.path.join(ROOT, "rtl")
# The device's Verilog (rtl/sources.cmake): the targets live in device/.
DEVICE_SOURCES = sorted(glob.glob(os.path.join(RTL, "device", "*.v")) + glob.glob(os.path.join(RTL, "primitives", "*.v")))
# The device's targets (module file in device/, testbench, testbench top): replayed by the
# RTL tests' Icarus run (run_icarus.cmake) on every policy combination.
DEVICE_TARGETS = {
    "specular_device": ("specular_device.v", "specular_device_tb.v", "specular_device_tb"),
    "specular_device_sync": ("specular_device_sync.v", "specular_device_sync_tb.v", "specular_device_sync_tb"),
    "control_unit16": ("control_unit16.v", "specular_device_tb.v", "specular_device_tb"),
}
CONSTANTS = ["patent", "minimax-half", "minimax"]
NORMALISATIONS = ["patent", "energy", "none", "device-energy"]
# Every combination the Icarus tests replay; the first is tried first (most mutants die there).
COMBINATIONS = [(c, n, s) for s in ("clamp", "literal") for c in CONSTANTS for n in NORMALISATIONS]
# The whole IP's targets (module file in ip/, rtl/sources.cmake's SPECULAR_RTL_IP_SOURCES):
# the mutant replaces its module only, the other IP module and the device are kept. Replayed
# by the AXI testbench's own run (run_ip_axi.cmake) in the cases rtl/CMakeLists.txt runs:
# (ctest name, STALL, COUNT, SEED).
IP_TARGETS = {"specular_reg_block": "specular_reg_block.v", "specular_ip_axi": "specular_ip_axi.v"}
IP_SOURCES = [os.path.join(RTL, "ip", f) for f in ("specular_reg_block.v", "specular_ip_axi.v")]
IP_CASES = [("rtl_ip_axi_icarus", 1, 200, 1), ("rtl_ip_axi_icarus_no_stall", 0, 100, 2)]
TARGETS = sorted(DEVICE_TARGETS) + sorted(IP_TARGETS)
TRIAGE = os.path.join(ROOT, "scripts", "verify", "rtl_mutants_triage.tsv")
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


def module_file(target):
    if target in IP_TARGETS:
        return os.path.join(RTL, "ip", IP_TARGETS[target])
    return os.path.join(RTL, "device", DEVICE_TARGETS[target][0])


def read_design(target):
    """Yosys commands: a device target flattened with every RTL source (ROM words left to the
    simulator: the memories are declared without their images); an IP target's module alone,
    its neighbours (the other IP module, the synchronous device) read as black boxes, so
    mutants land in the target's own logic and its connections only."""
    if target in IP_TARGETS:
        neighbours = [f for f in IP_SOURCES if f != module_file(target)]
        reads = "read_verilog -lib %s\nread_verilog -defer %s\n" % (
            " ".join([os.path.join(RTL, "device", "specular_device_sync.v")] + neighbours), module_file(target))
    else:
        reads = "read_verilog -DSPECULAR_ROM_WORDS_FROM_HOST -defer %s\n" % " ".join(DEVICE_SOURCES)
    # The AXI top at ADDR_WIDTH 32, as its testbench (specular_ip_axi_tb.v) instantiates it:
    # the mutant is written at the parameters it is elaborated with.
    chparam = " -chparam ADDR_WIDTH 32" if target == "specular_ip_axi" else ""
    return reads + "hierarchy -top %s%s\nproc\nflatten\nopt_clean\nhierarchy -top %s\n" % (target, chparam, target)


def portable(mutation):
    """A mutation without its -src attributes and with the sources' folder left out of its
    cell names: the same mutant in every checkout ('$/any/where/rtl/device/rom5.v:61$20'
    -> '$rtl/device/rom5.v:61$20')."""
    return re.sub(r"\$/\S*?/rtl/", "$rtl/", mutation.split(" -src ")[0])


def triage():
    """scripts/verify/rtl_mutants_triage.tsv: {(target, count, seed, index): (mutation, reason)}."""
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
    src = open(module_file(target)).read()
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
    # The AXI top's device instance: its ROM images from the top's parameters again (the
    # testbench sets them), not the defaults Yosys wrote.
    for param, _, _ in ROM_MEMORIES.values():
        text = re.sub(r"\.%s\(\"[^\"]*\"\)" % param, ".%s(%s)" % (param, param), text)
    open(path, "w").write(text)
    return path


def replay(target, mutant_file, case, build, work):
    """One Icarus replay of the target's tests (case: one of replay_cases(target)):
    'pass', 'fail', 'refused'."""
    scratch = os.path.join(work, "replay")
    tools = ["cmake", "-DIVERILOG=iverilog", "-DVVP=vvp",
             "-DSPECULAR_TB=" + os.path.join(build, "testbench", "specular_tb"),
             "-DROM_DIR=" + os.path.join(build, "rtl", "rom", "default"), "-DSCRATCH=" + scratch]
    if target in IP_TARGETS:
        _, stall, count, seed = case
        sources = [mutant_file if f == module_file(target) else f for f in IP_SOURCES]
        sources += DEVICE_SOURCES + [os.path.join(RTL, "ip", "specular_ip_axi_props.v")]
        command = tools + ["-DSOURCES=" + "|".join(sources),
                           "-DTESTBENCH=" + os.path.join(RTL, "tb", "specular_ip_axi_tb.v"),
                           "-DSTALL=%d" % stall, "-DCOUNT=%d" % count, "-DSEED=%d" % seed,
                           "-P", os.path.join(RTL, "tb", "run_ip_axi.cmake")]
    else:
        module, testbench, tb_top = DEVICE_TARGETS[target]
        sources = [s for s in DEVICE_SOURCES if os.path.basename(s) != module] + [mutant_file]
        constants, normalisation, saturation = case
        command = tools + ["-DSOURCES=" + "|".join(sources), "-DTESTBENCH=" + os.path.join(RTL, "tb", testbench),
                           "-DTB_TOP=" + tb_top, "-DWIDTHS=", "-DPARAMS=",
                           "-DCONSTANTS=" + constants, "-DCONSTANTS_VALUE=%d" % CONSTANTS.index(constants),
                           "-DNORMALISATION=" + normalisation,
                           "-DNORMALISATION_VALUE=%d" % NORMALISATIONS.index(normalisation),
                           "-DSATURATION=" + saturation, "-P", os.path.join(RTL, "tb", "run_icarus.cmake")]
    # Its own process group: on a timeout, vvp (cmake's child) holds the pipes open and
    # must be killed with cmake, or the harness would wait for it for ever.
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               start_new_session=True)
    try:
        text = process.communicate(timeout=120)[0]
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return "fail", "timeout (120 s)"
    if "combination refused by the model" in text:
        return "refused", ""
    if process.returncode == 0 and ": PASS" in text:
        return "pass", ""
    first = [l for l in text.splitlines() if "MISMATCH" in l or "ERROR" in l or "rror" in l]
    return "fail", (first[0] if first else text[-300:]).strip()[:300]


def replay_cases(target):
    """(test name, case) in the order tried: the IP's ctest cases, or the device's policy
    combinations."""
    if target in IP_TARGETS:
        return [(c[0], c) for c in IP_CASES]
    return [("rtl_icarus_%s_%s_%s" % c, c) for c in COMBINATIONS]


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
    baseline, detail = replay(args.target, unmutated, replay_cases(args.target)[0][1], build, work)
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
        for name, case in replay_cases(args.target):
            outcome, detail = replay(args.target, mutant, case, build, work)
            if outcome == "fail":
                entry.update(verdict="killed", by=name, detail=detail)
                break
        if entry["verdict"] == "survived" and args.target in IP_TARGETS:
            # No sat screen for the IP's targets: the miter of the whole IP (the device cut
            # open by `expose -evert`, the AXI outputs, done_irq and the device's inputs
            # compared) gave no proof in 45 min even with the unmutated IP on both sides.
            entry["detail"] = "no sat screen for the IP's targets: argue it or kill it"
        elif entry["verdict"] == "survived":
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


# CI's smokes: per kind, (target, list length, the planned mutants: each the first of
# Yosys's list (seed 1) whose mutation holds every one of these strings).
SMOKE_PLANS = {
    # NAND 47's output stuck at 1, flip-flop 41 clocked by the inverted start, the done pin inverted
    "device": [("control_unit16", 1000, [("-mode const1", "nand47", "-port Y"), ("-mode inv", "-port CLK", "dff41"),
                                         ("-mode inv", "-wire done35")])],
    # the strobe check inverted (a whole-word write refused, a 0101 one taken), G's word
    # decode stuck at 0 (a hole), the AXI top's done_irq stuck at 0
    "ip": [("specular_reg_block", 40, [("-mode inv", "-wire w_strb_ok "), ("-mode const0", "-wire w_g ")]),
           ("specular_ip_axi", 40, [("-mode const0", "-cell regs -port done_irq ")])],
}


def smoke(args):
    """CI's smoke (seconds): each planned target's unmutated round trip passes its first
    replay, and each planned mutant (SMOKE_PLANS) is killed by it."""
    build = os.path.abspath(args.build)
    work = tempfile.mkdtemp(prefix="rtl_mutants_smoke_")
    status = 0
    try:
        for target, count, plan in SMOKE_PLANS[args.kind]:
            first_case = replay_cases(target)[0][1]
            baseline, detail = replay(target, write_mutant(target, None, work), first_case, build, work)
            if baseline != "pass":
                die("the unmutated %s fails its replay: %s" % (target, detail), 1)
            print("unmutated %s: pass" % target)
            mutants = list_mutants(target, count, 1, work)
            picks = [next((m for m in mutants if all(k in m for k in keys)), None) for keys in plan]
            if None in picks:
                die("smoke: Yosys's list of %s mutants lacks a planned mutant (%d of %d)"
                    % (target, len(picks) - picks.count(None), len(picks)), 1)
            for m in picks:
                outcome, detail = replay(target, write_mutant(target, m, work), first_case, build, work)
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
    s.add_argument("--kind", choices=sorted(SMOKE_PLANS), default="device",
                   help="the device's control unit, or the IP's register block and AXI top")
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
