#!/usr/bin/env python3
"""Functional coverage report (issue 37): every declared bin with its hit count.

  functional_coverage.py --bins-from TEST_EXE [--report FILE] DIR...

The bins come from the tests' support code (tests/support/functional_coverage.cpp, the
one place they are declared), printed by any test executable with
--specular-list-functional-bins. DIR holds the hit files the test processes wrote under
SPECULAR_FUNCTIONAL_COVERAGE=DIR (fcov-*.tsv, "bin<TAB>count"); several DIRs (farm
shards) are summed. Exit 0 when every bin that can be hit was hit, 1 when one was not
(each named), 2 on bad input (an undeclared bin in a hit file, no bins).
"""
import argparse
import glob
import os
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bins-from", required=True)
    parser.add_argument("--report")
    parser.add_argument("dirs", nargs="+")
    args = parser.parse_args()
    listed = subprocess.run([args.bins_from, "--specular-list-functional-bins"], capture_output=True, text=True)
    if listed.returncode != 0:
        print("functional_coverage.py: error: %s --specular-list-functional-bins failed" % args.bins_from,
              file=sys.stderr)
        return 2
    bins = []
    for line in listed.stdout.splitlines():
        name, what, ignore = (line.split("\t") + ["", ""])[:3]
        bins.append((name, what, ignore))
    declared = {b[0] for b in bins}
    hits = {name: 0 for name in declared}
    files = 0
    for d in args.dirs:
        if not os.path.isdir(d):
            print("functional_coverage.py: error: '%s' is not a folder" % d, file=sys.stderr)
            return 2
        for path in glob.glob(os.path.join(d, "**", "fcov-*.tsv"), recursive=True):
            files += 1
            for line in open(path):
                name, count = line.rstrip("\n").split("\t")
                if name not in declared:
                    print("functional_coverage.py: error: %s: bin '%s' is not declared" % (path, name),
                          file=sys.stderr)
                    return 2
                hits[name] += int(count)
    required = [b for b in bins if not b[2]]
    # A bin declared impossible that was hit: its reason is wrong (fix the declaration).
    wrongly_ignored = [b for b in bins if b[2] and hits[b[0]] > 0]
    unhit = [b for b in required if hits[b[0]] == 0]
    lines = ["# Functional coverage", "",
             "%d bins (%d can be hit, %d ignored with a reason), %d hit, %d unhit; %d hit files." %
             (len(bins), len(required), len(bins) - len(required), len(required) - len(unhit), len(unhit), files),
             "", "| bin | hits | what | ignored because |", "|---|---:|---|---|"]
    for name, what, ignore in bins:
        lines.append("| %s | %d | %s | %s |" % (name, hits[name], what, ignore))
    groups = {}
    for name, _, ignore in required:
        g = name.split("/")[0]
        total, hit = groups.get(g, (0, 0))
        groups[g] = (total + 1, hit + (hits[name] > 0))
    summary = ["%s: %d/%d" % (g, h, t) for g, (t, h) in groups.items()]
    lines[2:2] = ["By group (hit/required): " + ", ".join(summary), ""]
    text = "\n".join(lines) + "\n"
    if args.report:
        open(args.report, "w").write(text)
    print(lines[2])
    print(lines[4])
    for name, what, _ in unhit:
        print("unhit: %s (%s)" % (name, what), file=sys.stderr)
    for name, _, ignore in wrongly_ignored:
        print("hit although declared impossible ('%s'): %s" % (ignore, name), file=sys.stderr)
    return 1 if unhit or wrongly_ignored else 0


if __name__ == "__main__":
    sys.exit(main())
