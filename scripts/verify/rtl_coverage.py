#!/usr/bin/env python3
"""rtl_coverage.py: the report of Verilator's line and toggle coverage of the RTL (issue 37,
docs/testing/code_coverage.md "Toggle and line coverage of the RTL (Verilator)").

  rtl_coverage.py summary MERGED.dat [--exclusions TSV] [--out DIR]
      per design (the top under TOP.): line points (Verilator's v_line and v_branch pages)
      and toggle points (v_toggle) hit / total; every point not hit, with the exclusion
      that covers it or none. Writes DIR/summary.md and DIR/unhit.tsv; exit 1 when a
      point is neither hit nor excluded (or an exclusion matches no point of the file).
  rtl_coverage.py check-exclusions [--exclusions TSV]
      CI (ctest rtl_coverage_exclusions_exist): every exclusion names a design top, a
      module and a net (or line) that exist in rtl/'s sources, and gives a reason.

A point of Verilator's coverage file is one line `C '<key>' <count>`, the key a list of
\\001name\\002value fields: f file, l line, page (v_line/MODULE, v_branch/MODULE,
v_toggle/MODULE), o comment (the net and bit of a toggle point, "block", "if", "else"...),
h hierarchy (TOP.design.instance...; rtl_coverage.h asks for every instance's own points).

Exclusions (scripts/verify/rtl_coverage_exclusions.tsv), tab-separated, '#' comments:
  design  instance  module  net  reason
design: the top as it appears under TOP. (specular_device, specular_patent, ...), or *;
instance: a glob over the hierarchy below the design ("u_mul13", "*" for any, "" for the
top itself); module: the Verilog module of the point; net: a glob over the toggle point's
net and bit (`above[*]`, `in_range`) or `line:N` for the line points of line N of the
module's file (NET[LO-HI]: bits LO to HI); reason: why no test can toggle or reach it.
"""
import argparse
import fnmatch
import os
import re
import sys
from collections import OrderedDict, defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_EXCLUSIONS = os.path.join(ROOT, "scripts", "verify", "rtl_coverage_exclusions.tsv")
RTL_DIRS = [os.path.join(ROOT, "rtl", d) for d in ("device", "primitives", "design_space")]


def fail(message):
    print("rtl_coverage.py: error: " + message, file=sys.stderr)
    sys.exit(2)


def parse_key(key):
    """The \\001name\\002value fields of a point's key, as a dict."""
    fields = {}
    for field in key.split("\001"):
        if not field:
            continue
        name, sep, value = field.partition("\002")
        if not sep:
            raise ValueError("field without a value: %r" % field)
        fields[name] = value
    return fields


def read_points(path):
    """Yields (fields, count) for every point of a Verilator coverage file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            close = line.rfind("' ")
            if not line.startswith("C '") or close < 3:
                raise ValueError("%s:%d: not a coverage point: %r" % (path, number, line[:80]))
            count = line[close + 2:].strip()
            if not count.isdigit():
                raise ValueError("%s:%d: count %r is not a number" % (path, number, count))
            yield parse_key(line[3:close]), int(count)


class Point:
    def __init__(self, fields, count):
        page = fields.get("page", "")
        self.kind, _, module = page.partition("/")
        # Verilator names a module specialised by its parameters NAME__W25, NAME__pi2...
        self.module = re.sub(r"__.*$", "", module)
        hier = fields.get("h", "")
        parts = hier.split(".")
        if parts and parts[0] == "TOP":
            parts = parts[1:]
        self.design = parts[0] if parts else ""
        self.instance = ".".join(parts[1:])
        self.comment = fields.get("o", "")
        self.file = fields.get("f", "")
        self.line = fields.get("l", "")
        self.count = count

    @property
    def group(self):
        """'toggle' or 'line' (Verilator's line and branch points), else the page kind."""
        if self.kind == "v_toggle":
            return "toggle"
        if self.kind in ("v_line", "v_branch"):
            return "line"
        return self.kind

    def name(self):
        where = self.instance or "(top)"
        if self.group == "toggle":
            return "%s %s %s %s" % (self.design, where, self.module, self.comment)
        return "%s %s %s line:%s %s" % (self.design, where, self.module, self.line, self.comment)


def read_exclusions(path):
    rows = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.startswith("#"):
                continue
            cells = line.split("\t")
            if len(cells) != 5:
                fail("%s:%d: %d fields, not design, instance, module, net, reason" % (path, number, len(cells)))
            rows.append({"at": "%s:%d" % (os.path.basename(path), number), "design": cells[0],
                         "instance": cells[1], "module": cells[2], "net": cells[3], "reason": cells[4]})
    return rows


def excludes(row, point):
    if row["design"] != "*" and row["design"] != point.design:
        return False
    if not fnmatch.fnmatchcase(point.instance, row["instance"]):
        return False
    if row["module"] != point.module:
        return False
    if row["net"].startswith("line:"):
        return point.group == "line" and row["net"][5:] == point.line
    return point.group == "toggle" and net_matches(row["net"], point.comment)


def net_matches(pattern, comment):
    """NET[LO-HI]: bits LO to HI of NET; otherwise a glob whose * and ? are wildcards and
    whose brackets are the bit's own (`above[*]`, `in_range`)."""
    bits = re.fullmatch(r"(\w+)\[(\d+)-(\d+)\]", pattern)
    if bits:
        point = re.fullmatch(r"(\w+)\[(\d+)\]", comment)
        return bool(point) and point.group(1) == bits.group(1) and \
            int(bits.group(2)) <= int(point.group(2)) <= int(bits.group(3))
    return fnmatch.fnmatchcase(comment, pattern.replace("[", "[[]"))


def summary(args):
    points = OrderedDict()  # the same point from several files (already merged: once)
    for fields, count in read_points(args.dat):
        p = Point(fields, count)
        key = (p.design, p.instance, p.module, p.kind, p.file, p.line, fields.get("n", ""), p.comment)
        if key in points:
            points[key].count += count
        else:
            points[key] = p
    if not points:
        fail("%s holds no coverage point" % args.dat)
    exclusions = read_exclusions(args.exclusions) if args.exclusions else []
    used = [0] * len(exclusions)
    figures = defaultdict(lambda: {"line": [0, 0, 0], "toggle": [0, 0, 0]})  # hit, excluded, total
    unhit = []
    for p in points.values():
        if p.group not in ("line", "toggle"):
            continue
        f = figures[p.design][p.group]
        f[2] += 1
        if p.count > 0:
            f[0] += 1
            continue
        reason = None
        for i, row in enumerate(exclusions):
            if excludes(row, p):
                used[i] += 1
                reason = row
                break
        if reason:
            f[1] += 1
        unhit.append((p, reason))

    def pct(hit, total):
        return "%.1f %%" % (100.0 * hit / total) if total else "-"

    lines = ["# RTL coverage (Verilator): %s" % os.path.basename(args.dat), "",
             "| design | line hit / total | line % | toggle hit / total | toggle % | unhit, excluded | unhit, not excluded |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    open_count = 0
    for design in sorted(figures):
        line, toggle = figures[design]["line"], figures[design]["toggle"]
        excluded = line[1] + toggle[1]
        missing = (line[2] - line[0] - line[1]) + (toggle[2] - toggle[0] - toggle[1])
        open_count += missing
        lines.append("| %s | %d / %d | %s | %d / %d | %s | %d | %d |" % (
            design, line[0], line[2], pct(line[0], line[2]), toggle[0], toggle[2],
            pct(toggle[0], toggle[2]), excluded, missing))
    nets = OrderedDict()  # the open toggle points by net: its bits together
    for p, reason in unhit:
        if reason is None and p.group == "toggle":
            base, _, bit = p.comment.partition("[")
            nets.setdefault((p.design, p.instance or "(top)", p.module, base), []).append(bit.rstrip("]"))
    lines += ["", "## Nets not toggled and not excluded (%d)" % len(nets), ""]
    lines += ["- %s %s %s %s%s" % (k + ("[%s]" % ",".join(sorted(v, key=lambda b: (len(b), b))) if v != [""] else "",))
              for k, v in sorted(nets.items())] or ["(none)"]
    lines += ["", "## Points not hit and not excluded", ""]
    lines += ["- " + p.name() for p, reason in unhit if reason is None] or ["(none)"]
    lines += ["", "## Points not hit, excluded", ""]
    lines += ["- %s (%s: %s)" % (p.name(), reason["at"], reason["reason"]) for p, reason in unhit if reason] or ["(none)"]
    stale = [row for row, n in zip(exclusions, used) if n == 0 and (args.designs is None or row["design"] in args.designs)]
    if stale:
        lines += ["", "## Exclusions that matched no unhit point", ""]
        lines += ["- %s: %s %s %s %s" % (r["at"], r["design"], r["instance"], r["module"], r["net"]) for r in stale]
    text = "\n".join(lines) + "\n"
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, "summary.md"), "w") as f:
            f.write(text)
        with open(os.path.join(args.out, "unhit.tsv"), "w") as f:
            f.write("design\tinstance\tmodule\tkind\tfile\tline\tpoint\texclusion\n")
            for p, reason in unhit:
                f.write("\t".join([p.design, p.instance, p.module, p.group, p.file, p.line, p.comment,
                                   reason["at"] if reason else ""]) + "\n")
    print("\n".join(lines[:4 + len(figures)]))
    print("rtl_coverage.py: %d point(s) neither hit nor excluded%s" % (
        open_count, "" if not args.out else " (listed in %s/summary.md)" % args.out))
    if stale and args.strict_exclusions:
        print("rtl_coverage.py: %d exclusion(s) matched no unhit point" % len(stale), file=sys.stderr)
        return 1
    return 1 if open_count else 0


def rtl_modules():
    """module name -> its text, from every source of rtl/'s three folders."""
    modules = {}
    for folder in RTL_DIRS:
        for name in sorted(os.listdir(folder)):
            if not name.endswith((".v", ".vh")):
                continue
            text = open(os.path.join(folder, name), encoding="utf-8").read()
            for m in re.finditer(r"^\s*module\s+(\w+)(.*?)^\s*endmodule", text, re.S | re.M):
                modules[m.group(1)] = (os.path.join(folder, name), m.group(0))
    return modules


def check_exclusions(args):
    modules = rtl_modules()
    status = 0
    rows = read_exclusions(args.exclusions)
    for row in rows:
        problems = []
        if not row["reason"].strip():
            problems.append("no reason")
        if row["design"] != "*" and row["design"] not in modules:
            problems.append("no design top '%s' in rtl/" % row["design"])
        if row["module"] not in modules:
            problems.append("no module '%s' in rtl/" % row["module"])
        else:
            path, body = modules[row["module"]]
            if row["net"].startswith("line:"):
                number = row["net"][5:]
                lines = open(path, encoding="utf-8").read().split("\n")
                if not number.isdigit() or not 1 <= int(number) <= len(lines):
                    problems.append("no line %s in %s" % (number, os.path.relpath(path, ROOT)))
            else:
                net = re.match(r"[A-Za-z_]\w*", row["net"].split(".")[-1])
                if not net or not re.search(r"\b%s\b" % re.escape(net.group(0)), body):
                    problems.append("no net '%s' in module %s" % (row["net"], row["module"]))
        if problems:
            status = 1
            print("rtl_coverage.py: %s: %s" % (row["at"], "; ".join(problems)), file=sys.stderr)
    if status == 0:
        print("rtl_coverage.py: every exclusion of %d names a design, module and net of rtl/, with a reason" % len(rows))
    return status


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("summary")
    s.add_argument("dat")
    s.add_argument("--exclusions", default=DEFAULT_EXCLUSIONS)
    s.add_argument("--out")
    s.add_argument("--designs", nargs="*", help="designs run (an exclusion of another is not stale)")
    s.add_argument("--strict-exclusions", action="store_true", help="exit 1 when an exclusion matched nothing")
    c = sub.add_parser("check-exclusions")
    c.add_argument("--exclusions", default=DEFAULT_EXCLUSIONS)
    args = parser.parse_args()
    try:
        return summary(args) if args.command == "summary" else check_exclusions(args)
    except (OSError, ValueError) as error:
        fail(str(error))


if __name__ == "__main__":
    sys.exit(main())
