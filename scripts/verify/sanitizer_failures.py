#!/usr/bin/env python3
"""Says what kind of failure each failed sanitizer run was (issue 45), so that a failed
sanitizer stage names its cause at once.

    scripts/verify/sanitizer_failures.py --junit FILE      ctest's --output-junit of a run
    scripts/verify/sanitizer_failures.py --logs FILE...    the log of each failed run (fuzz.sh's)

Each failure is put in the first class whose sign its output holds:
  sanitizer fatal error   the sanitizer itself failed ("... has encountered a fatal
                          error", "Tracer caught signal"): a fault of the tool's set-up,
                          not a finding in our code
  leak                    "ERROR: LeakSanitizer: detected memory leaks"
  memory error            "ERROR: AddressSanitizer: ..."
  undefined behaviour     UBSan's "runtime error:"
  test failure            none of these: an ordinary failed assertion, exit status or
                          timeout (ctest's JUnit file does not tell a timeout apart;
                          its console output marks it "***Timeout")
Prints one line of counts and the failed names of each class (10 at most each). Exit 0
when nothing failed, 1 when something did, 2 on bad arguments or an unreadable file.
"""
import re
import sys
import xml.etree.ElementTree as ET

CLASSES = [
    ("sanitizer fatal error", re.compile(r"Sanitizer has encountered a fatal error|Tracer caught signal")),
    ("leak", re.compile(r"ERROR: LeakSanitizer: detected memory leaks")),
    ("memory error", re.compile(r"ERROR: AddressSanitizer")),
    ("undefined behaviour", re.compile(r"runtime error:")),
]
ORDINARY = "test failure"
ORDER = [name for name, _ in CLASSES] + [ORDINARY]
SHOWN_PER_CLASS = 10


def classify(output):
    for name, sign in CLASSES:
        if sign.search(output):
            return name
    return ORDINARY


def junit_failures(path):
    """(name, class) of every failed test case in ctest's JUnit file, and the number run."""
    root = ET.parse(path).getroot()
    failures, total = [], 0
    for case in root.iter("testcase"):
        total += 1
        failure = case.find("failure")
        status = case.get("status", "")
        if failure is None and status not in ("fail", "failed"):
            continue
        out = case.find("system-out")
        failures.append((case.get("name", "?"), classify("".join(out.itertext()) if out is not None else "")))
    return failures, total


def log_failures(paths):
    failures = []
    for path in paths:
        with open(path, errors="replace") as f:
            failures.append((path, classify(f.read())))
    return failures, None


def report(failures, total, what):
    if not failures:
        print(f"sanitizer_failures: none of {total} {what} failed")
        return 0
    counts = {name: 0 for name in ORDER}
    for _, kind in failures:
        counts[kind] += 1
    parts = ", ".join(f"{counts[name]} {name}" for name in ORDER if counts[name])
    of_total = f" of {total}" if total is not None else ""
    print(f"sanitizer_failures: {len(failures)}{of_total} {what} failed: {parts}")
    for name in ORDER:
        names = [n for n, kind in failures if kind == name]
        if not names:
            continue
        more = f" (and {len(names) - SHOWN_PER_CLASS} more)" if len(names) > SHOWN_PER_CLASS else ""
        print(f"  {name}: {', '.join(names[:SHOWN_PER_CLASS])}{more}")
    return 1


def main(argv):
    if len(argv) == 2 and argv[0] == "--junit":
        try:
            failures, total = junit_failures(argv[1])
        except (OSError, ET.ParseError) as error:
            print(f"sanitizer_failures: cannot read JUnit file '{argv[1]}': {error}", file=sys.stderr)
            return 2
        return report(failures, total, "tests")
    if len(argv) >= 2 and argv[0] == "--logs":
        try:
            failures, total = log_failures(argv[1:])
        except OSError as error:
            print(f"sanitizer_failures: cannot read log: {error}", file=sys.stderr)
            return 2
        return report(failures, total, "runs")
    print("usage: sanitizer_failures.py --junit FILE | --logs FILE...", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
