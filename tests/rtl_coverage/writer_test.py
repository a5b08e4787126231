#!/usr/bin/env python3
"""The RTL coverage writer (twin/coverage/rtl_coverage.h), in a build with
-DSPECULAR_RTL_COVERAGE=ON only (ctest rtl_coverage_writer): a test process of the twin run
with SPECULAR_RTL_COVERAGE=DIR writes exactly one DIR/rtlcov-<pid>-<random>.dat holding
points of the design it drove, some hit; run without the variable it writes nothing (into
its working folder, the only place it could).

Usage: writer_test.py EXECUTABLE GTEST_FILTER DESIGN SCRATCH"""
import glob
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "verify"))
import rtl_coverage  # noqa: E402  (the summariser's own reader)


def main():
    executable, test_filter, design, scratch = sys.argv[1:5]
    shutil.rmtree(scratch, ignore_errors=True)
    with_variable, without = os.path.join(scratch, "with"), os.path.join(scratch, "without")
    os.makedirs(with_variable)
    os.makedirs(without)
    failures = []
    env = dict(os.environ, SPECULAR_RTL_COVERAGE=with_variable)
    done = subprocess.run([executable, "--gtest_filter=" + test_filter], env=env, cwd=without,
                          capture_output=True, text=True)
    if done.returncode != 0 or "[  PASSED  ] 1 test." not in done.stdout:
        failures.append("%s %s did not run one test and pass: %s" % (executable, test_filter, done.stdout[-2000:]))
    files = sorted(glob.glob(os.path.join(with_variable, "*")))
    names = [os.path.basename(f) for f in files]
    if len(files) != 1 or not names[0].startswith("rtlcov-") or not names[0].endswith(".dat"):
        failures.append("expected one rtlcov-<pid>-<random>.dat, found %s" % names)
    else:
        points = [rtl_coverage.Point(fields, count) for fields, count in rtl_coverage.read_points(files[0])]
        mine = [p for p in points if p.design == design]
        if not mine:
            failures.append("no point of %s in %s (designs: %s)" % (design, names[0], sorted({p.design for p in points})))
        elif not any(p.count > 0 for p in mine if p.group == "toggle"):
            failures.append("no toggle point of %s hit" % design)
        elif not any(p.count > 0 for p in mine if p.group == "line"):
            failures.append("no line point of %s hit" % design)
    env = dict(os.environ)
    env.pop("SPECULAR_RTL_COVERAGE", None)
    subprocess.run([executable, "--gtest_filter=" + test_filter], env=env, cwd=without, capture_output=True)
    if os.listdir(without):
        failures.append("without the variable the process wrote %s" % os.listdir(without))
    for f in failures:
        print("FAIL: " + f)
    print("rtl_coverage_writer: %s" % ("PASS" if not failures else "%d check(s) failed" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
