#!/usr/bin/env python3
"""The mapped netlist as OpenSTA reads it (scripts/flows/synthesis/silicon.sh, after Yosys).

  netlist_assigns.py MAPPED_V

Yosys writes the aliases of a merged register as one assignment to a concatenation,
`assign { q[7], q[5:4] } = { q[6], q[6], q[6] };` (the register block of specular_ip_axi:
STATUS.CAUSE's bits that always equal each other). Debian 12's OpenSTA (2.0.17) stops at
it ("syntax error, unexpected '{'") and leaves the rest of the module unread, so its
timing would be silently wrong. Each such line becomes one assignment per bit, highest
first; the file is rewritten in place, every other line unchanged (a netlist without
such a line is left byte for byte). An item this reader does not know (neither
name[i], name[h:l], an escaped \\name [i] or \\name [h:l], nor a sized binary, hex or
decimal constant) or sides of
different widths stop it with exit 1, naming the line.
"""
import re
import sys

ITEM = re.compile(r"^([A-Za-z_$][\w$.]*)(?:\[(\d+)(?::(\d+))?\])?$")
# an escaped identifier ends at white space, so its select follows a space:
# `\mul.biased [64:61]` (us5739820's netlist); its bits keep the space
ESCAPED = re.compile(r"^(\\\S+)\s+\[(\d+)(?::(\d+))?\]$")
CONST = re.compile(r"^(\d+)'([bhd])([0-9a-fA-FxXzZ_]+)$")


def bits(item, line):
    item = item.strip()
    m = CONST.match(item)
    if m:
        width, base, digits = int(m.group(1)), m.group(2), m.group(3).replace("_", "")
        if any(c in "xXzZ" for c in digits):
            raise SystemExit(f"netlist_assigns.py: x or z constant '{item}' in: {line.strip()}")
        value = int(digits, {"b": 2, "h": 16, "d": 10}[base])
        return [f"1'b{(value >> k) & 1}" for k in range(width - 1, -1, -1)]
    m = ESCAPED.match(item) or ITEM.match(item)
    if not m or m.group(2) is None:
        raise SystemExit(f"netlist_assigns.py: '{item}' is not name[i], name[h:l], \\name [i], "
                         f"\\name [h:l] or a sized constant in: {line.strip()}")
    name, hi = m.group(1), int(m.group(2))
    lo = int(m.group(3)) if m.group(3) is not None else hi
    step = -1 if hi >= lo else 1
    gap = " " if name.startswith("\\") else ""
    return [f"{name}{gap}[{k}]" for k in range(hi, lo + step, step)]


def side(text, line):
    text = text.strip()
    if text.startswith("{") and text.endswith("}"):
        return [b for item in text[1:-1].split(",") for b in bits(item, line)]
    return bits(text, line)


def main():
    path = sys.argv[1]
    lines = open(path).read().split("\n")
    out, changed = [], 0
    for line in lines:
        m = re.match(r"^(\s*)assign\s+(\{.*\})\s*=\s*(.*);\s*$", line)
        if not m:
            out.append(line)
            continue
        left, right = side(m.group(2), line), side(m.group(3), line)
        if len(left) != len(right):
            raise SystemExit(f"netlist_assigns.py: {len(left)} bits on the left, {len(right)} on the right in: {line.strip()}")
        out += [f"{m.group(1)}assign {l} = {r};" for l, r in zip(left, right)]
        changed += 1
    if changed:
        with open(path, "w") as f:
            f.write("\n".join(out))
    print(f"netlist_assigns.py: {changed} concatenated assignments split in {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
