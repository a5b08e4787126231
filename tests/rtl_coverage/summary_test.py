#!/usr/bin/env python3
"""The RTL coverage summariser (scripts/verify/rtl_coverage.py summary) on a small coverage file
written here point by point, with its figures counted by hand (issue 37): per design the
line points (v_line and v_branch) and toggle points hit / total, every unhit point listed,
an exclusion that covers a point, and exit 1 while a point is neither hit nor excluded.
Standard library only; well under a second. ctest rtl_coverage_summary."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "verify", "rtl_coverage.py")


def point(page, hier, comment, line, count, file="rtl/device/x.v"):
    fields = [("f", file), ("l", str(line)), ("n", "3"), ("page", page), ("o", comment), ("h", hier)]
    return "C '" + "".join("\001%s\002%s" % kv for kv in fields) + "' %d\n" % count


# Design specular_device: 3 line points (2 hit) and 4 toggle points (2 hit: the two bits of
# u_mul13's `above` are not). Design specular_patent: 1 line point, hit; 2 toggle points, 1
# hit. The same point twice (two processes' files before a merge) counts once: 0 + 5, hit.
POINTS = [
    point("v_line/specular_device", "TOP.specular_device", "block", 10, 7),
    point("v_branch/specular_device", "TOP.specular_device", "if", 12, 1),
    point("v_branch/specular_device", "TOP.specular_device", "else", 12, 0),
    point("v_toggle/specular_device", "TOP.specular_device", "pin27_start", 5, 9),
    point("v_toggle/multiply_round_saturate", "TOP.specular_device.u_mul13.u_mrs", "above[0]", 8, 0),
    point("v_toggle/multiply_round_saturate", "TOP.specular_device.u_mul13.u_mrs", "above[1]", 8, 0),
    point("v_toggle/multiply_round_saturate", "TOP.specular_device.u_mul39.u_mrs", "above[0]", 8, 0),
    point("v_toggle/multiply_round_saturate", "TOP.specular_device.u_mul39.u_mrs", "above[0]", 8, 5),
    point("v_line/specular_patent", "TOP.specular_patent", "block", 4, 2),
    point("v_toggle/specular_patent", "TOP.specular_patent", "start", 3, 1),
    point("v_toggle/specular_patent", "TOP.specular_patent", "valid", 3, 0),
]
EXPECTED_ROWS = [
    "| specular_device | 2 / 3 | 66.7 % | 2 / 4 | 50.0 % |",
    "| specular_patent | 1 / 1 | 100.0 % | 1 / 2 | 50.0 % |",
]


def run(folder, exclusions):
    dat = os.path.join(folder, "tiny.dat")
    with open(dat, "w") as f:
        f.write("# SystemC::Coverage-3\n" + "".join(POINTS))
    tsv = os.path.join(folder, "exclusions.tsv")
    with open(tsv, "w") as f:
        f.write("# design\tinstance\tmodule\tnet\treason\n" + exclusions)
    out = os.path.join(folder, "report")
    done = subprocess.run([sys.executable, SCRIPT, "summary", dat, "--exclusions", tsv, "--out", out],
                          capture_output=True, text=True)
    summary = open(os.path.join(out, "summary.md")).read() if os.path.exists(os.path.join(out, "summary.md")) else ""
    return done, summary


def check(condition, message, failures):
    if not condition:
        failures.append(message)


def main():
    failures = []
    with tempfile.TemporaryDirectory(prefix="rtl_coverage_summary.") as folder:
        # No exclusion: 4 unhit points open (else at 12, u_mul13's two bits, valid).
        done, summary = run(folder, "")
        check(done.returncode == 1, "without exclusions: exit %d, not 1" % done.returncode, failures)
        for row in EXPECTED_ROWS:
            check(row in summary, "missing row %r in:\n%s" % (row, summary), failures)
        check("4 point(s) neither hit nor excluded" in done.stdout, "open count: " + done.stdout, failures)
        for name in ("specular_device u_mul13.u_mrs multiply_round_saturate above[0]",
                     "specular_device u_mul13.u_mrs multiply_round_saturate above[1]",
                     "specular_device (top) specular_device line:12 else",
                     "specular_patent (top) specular_patent valid"):
            check("- " + name + "\n" in summary, "unhit point not listed: " + name, failures)
        check("u_mul39" not in summary.split("## Points not hit and not excluded")[1],
              "u_mul39's above[0] was hit in one file: listed as unhit", failures)
        # Every unhit point excluded, u_mul13's by a glob: exit 0, the figures unchanged.
        done, summary = run(folder, "specular_device\tu_mul13.*\tmultiply_round_saturate\tabove[*]\tsaturation unreachable\n"
                                    "specular_device\t\tspecular_device\tline:12\tthe else no pin reaches\n"
                                    "*\t\tspecular_patent\tvalid\ta reason\n")
        check(done.returncode == 0, "all excluded: exit %d, not 0: %s%s" % (done.returncode, done.stdout, done.stderr), failures)
        for row in EXPECTED_ROWS:
            check(row in summary, "excluded run: missing row %r" % row, failures)
        check("(exclusions.tsv:2: saturation unreachable)" in summary, "exclusion's reason not shown", failures)
        # An exclusion of another instance leaves u_mul13's bits open.
        done, _ = run(folder, "specular_device\tu_mul14.*\tmultiply_round_saturate\tabove[*]\tr\n")
        check(done.returncode == 1, "an exclusion of u_mul14 closed u_mul13's points", failures)
        # A bit range: above[1-1] leaves bit 0 open (2 open: it and the else, valid excluded).
        done, _ = run(folder, "specular_device\tu_mul13.u_mrs\tmultiply_round_saturate\tabove[1-1]\tr\n"
                              "specular_device\t\tspecular_device\tline:12\tr\n*\t\tspecular_patent\tvalid\tr\n")
        check(done.returncode == 1 and "1 point(s) neither hit nor excluded" in done.stdout,
              "bit range above[1-1]: " + done.stdout, failures)
    for f in failures:
        print("FAIL: " + f)
    print("rtl_coverage_summary: %d check(s) failed" % len(failures) if failures else "rtl_coverage_summary: PASS")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
