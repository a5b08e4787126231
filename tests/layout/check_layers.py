#!/usr/bin/env python3
"""layers_include_down: no include runs from a lower layer up to a higher one.

C++ (each folder's rank; a file may include only headers of its own rank or lower):
  0 modules/            the model: blocks, core, TLM, references (installed headers)
  0 firmware/           the C header and driver (no C++ at all)
  1 twin/               the RTL verilated, behind the model's interfaces
  2 run_support/        what specular_tb and the tools share: partials, shards, progress
  3 testbench/          specular_tb
  4 tools/NAME/         the other commands
  5 bench/ fuzz/ examples/ tests/   users of all of the above
Verilog: rtl/primitives/ < rtl/device/ < rtl/design_space/ (a module may instantiate only
modules of its own folder or a lower one), and rtl/tb/, rtl/formal/ above them all.

Usage: check_layers.py SOURCE_DIR. Prints each include or instance that runs upwards
(file:line) and exits 1; exits 0 with a count of what it checked.
"""
import os
import re
import sys

CPP_RANKS = [("modules/", 0), ("firmware/", 0), ("twin/", 1), ("run_support/", 2),
             ("testbench/", 3), ("tools/", 4), ("bench/", 5), ("fuzz/", 5), ("examples/", 5),
             ("tests/", 5)]
RTL_RANKS = [("rtl/primitives/", 0), ("rtl/device/", 1), ("rtl/design_space/", 2),
             ("rtl/tb/", 3), ("rtl/formal/", 3)]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
CPP_EXT = (".h", ".hpp", ".cpp", ".c")


def rank_of(rel, ranks):
    for prefix, rank in ranks:
        if rel.startswith(prefix):
            return rank
    return None


def main(root):
    files = []
    for top in ("modules", "firmware", "twin", "run_support", "tools", "testbench", "bench", "fuzz", "examples", "tests", "rtl"):
        for d, _, names in os.walk(os.path.join(root, top)):
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
    by_name = {}  # a bare include's candidates: every header of that name
    for f in files:
        by_name.setdefault(os.path.basename(f), []).append(f)
    upward, checked = [], 0

    for f in (f for f in files if f.endswith(CPP_EXT)):
        own = rank_of(f, CPP_RANKS)
        if own is None:
            continue
        for line_no, line in enumerate(open(os.path.join(root, f), encoding="utf-8", errors="replace"), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            name = m.group(1)
            beside = os.path.normpath(os.path.join(os.path.dirname(f), name))
            if beside in files:
                target = beside
            else:  # an include path: the file whose path ends with the name
                candidates = [c for c in by_name.get(os.path.basename(name), [])
                              if c.endswith("/" + name) and rank_of(c, CPP_RANKS) is not None]
                if not candidates:
                    continue  # generated (git_commit.h, verilated models) or a system header
                target = min(candidates, key=lambda c: rank_of(c, CPP_RANKS))
            checked += 1
            if rank_of(target, CPP_RANKS) > own:
                upward.append(f"{f}:{line_no}: includes {target} (layer {rank_of(target, CPP_RANKS)} above {own})")

    module_of = {}  # Verilog module name -> file
    sources = [f for f in files if f.endswith(".v") and rank_of(f, RTL_RANKS) is not None]
    for f in sources:
        for m in re.finditer(r"^\s*module\s+(\w+)", open(os.path.join(root, f)).read(), re.M):
            module_of[m.group(1)] = f
    for f in sources:
        own = rank_of(f, RTL_RANKS)
        text = re.sub(r"//[^\n]*", "", open(os.path.join(root, f)).read())
        for m in re.finditer(r"^\s*(\w+)\s+(?:#\s*\(|\w+\s*\()", text, re.M):
            target = module_of.get(m.group(1))
            if target is None or target == f:
                continue
            checked += 1
            if rank_of(target, RTL_RANKS) > own:
                line_no = text.count("\n", 0, m.start()) + 1
                upward.append(f"{f}:{line_no}: instantiates {m.group(1)} of {target}")

    for u in upward:
        print(u)
    if upward:
        print(f"layers_include_down: FAIL: {len(upward)} of {checked} includes/instances run upwards")
        return 1
    print(f"layers_include_down: PASS: {checked} includes and instances, none upwards")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]) if len(sys.argv) == 2 else (print(__doc__) or 2))
