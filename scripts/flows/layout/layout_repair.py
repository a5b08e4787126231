#!/usr/bin/env python3
"""Mend the faults qrouter 1.4.71 leaves in a routing it calls complete.

  layout_repair.py ROUTED_DEF OUT_DEF REPORT LEF [LEF...]

Why: on the whole device qrouter ended "No failed routes", yet magic found a metal1 square
below the minimum area and netgen an open pin: the route ran over a cell's metal1 pin on
metal2 and dropped its metal1 via one track beside the pin (a 0.4 um pad touching
nothing), so the pin stayed unconnected. The same dangling pad, on nets whose pins were
all reached, is the rest of magic's "Metal1 area" errors.

What it does, net by net, on metal1 (the cells' pins, the net's metal1 wires, qrouter's
metal1 stubs in SPECIALNETS, the metal1 pads of its vias):
  - a via whose metal1 pad touches no pin, and no other via through metal1, connects
    nothing: it is taken out (connectivity unchanged; magic's DRC would flag its pad);
  - a cell pin that touches none of the net's metal1 is open: where one of the net's metal2
    wires crosses it, a via is put on the pin, at the point of the wire nearest the
    pin's centre.
A pin open with no metal2 wire across it is listed and left: LVS will then fail and say so.

And on every metal, after those: a wire of the net that ends on a wire of the metal above or below,
of the same net but of another piece of its routing (the pieces joined by wires, vias and
the cells' pins), with no via there, gets the via. Why: on schlick_divider qrouter ended
a metal3 wire over the metal2 of a pin's via stack and put no M3_M2 there; the net came
out in two pieces, and netgen found a net too many.
REPORT lists each change; the exit status is 0 whether or not anything changed, 1 when a
pin is left open, 2 when an input cannot be read.
"""
import re
import sys

ORIENTS = ("N", "S", "FN", "FS")
POWER_NETS = ("vdd", "gnd")   # qflow's names (TOP_powerground)


def read_lefs(paths):
    """Cells' size and pin rectangles on metal1 and metal2 (um), vias' metal1 pads (um)."""
    cells, vias = {}, {}
    for path in paths:
        macro = pin = via = layer = None
        for line in open(path):
            t = line.split()
            if not t:
                continue
            if t[0] == "MACRO":
                macro = t[1]
                cells[macro] = {"size": (0.0, 0.0), "pins": {}}
            elif t[0] == "VIA" and len(t) > 1 and macro is None:
                via = t[1]
                vias[via] = []
            elif t[0] == "SIZE" and macro:
                cells[macro]["size"] = (float(t[1]), float(t[3]))
            elif t[0] == "PIN" and macro:
                pin = t[1]
                cells[macro]["pins"][pin] = []
            elif t[0] == "LAYER":
                layer = t[1]
            elif t[0] == "RECT" and layer in ("metal1", "metal2"):
                r = tuple(float(v) for v in t[1:5])
                if macro and pin:
                    cells[macro]["pins"][pin].append((layer, r))
                elif via and not macro and layer == "metal1":
                    vias[via].append(r)
            elif t[0] == "END" and len(t) > 1:
                if macro and t[1] == pin:
                    pin = None
                elif t[1] == macro:
                    macro = pin = None
                elif t[1] == via:
                    via = None
    return cells, vias


def place(rect, origin, orient, size):
    """A cell's rectangle (um) on the die, in DEF units (100 per um)."""
    x0, y0, x1, y1 = rect
    w, h = size
    if orient in ("S", "FN"):
        x0, x1 = w - x1, w - x0
    if orient in ("S", "FS"):
        y0, y1 = h - y1, h - y0
    ox, oy = origin
    return (ox + round(x0 * 100), oy + round(y0 * 100), ox + round(x1 * 100), oy + round(y1 * 100))


def touch(a, b):
    return a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]


def parse_routes(lines, first, last):
    """The route statements of one net: (line index, layer, width, points, vias at points)."""
    out = []
    for i in range(first, last + 1):
        m = re.match(r"\s*(?:\+ ROUTED|NEW)\s+(metal\d)\s*(\d+)?\s*(.*)$", lines[i])
        if not m:
            continue
        layer, width, rest = m.group(1), m.group(2), m.group(3)
        pts, via_at = [], []
        x = y = None
        for tok in re.findall(r"\(\s*(\S+)\s+(\S+)\s*(?:\S+\s*)?\)|([A-Za-z_]\w*)", rest):
            if tok[2]:
                via_at.append((tok[2], (x, y)))
            else:
                x = x if tok[0] == "*" else int(tok[0])
                y = y if tok[1] == "*" else int(tok[1])
                pts.append((x, y))
        out.append((i, layer, int(width) if width else None, pts, via_at))
    return out


def via_layers(name):
    """The metals a via joins (lower, upper) from its name (M3_M2), or None."""
    m = re.fullmatch(r"M(\d)_M(\d)", name)
    return (f"metal{m.group(2)}", f"metal{m.group(1)}") if m and int(m.group(1)) == int(m.group(2)) + 1 else None


def on_segment(seg, p):
    _, a, b = seg
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def layer_breaks(routes, pins, stubs):
    """The vias a net's routing lacks: (lower metal, upper metal, point) where a wire's end
    lies on a wire one metal up or down that belongs to another piece of the net (pieces
    joined by touching shapes on one metal, by vias, by a cell pin's metal1 or metal2 and by
    qrouter's stubs in SPECIALNETS). None judged when
    the net has a via this script does not know the metals of."""
    segs = []
    vias = []
    for _, layer, _, pts, via_at in routes:
        if pts:
            segs += [(layer, pts[0], pts[0])] + [(layer, a, b) for a, b in zip(pts, pts[1:])]
        for v, p in via_at:
            if via_layers(v) is None:
                return []
            vias.append((via_layers(v), p))
    # a via's pads are shapes of both its metals (the lower one may land on a pin alone)
    segs += [(layer, p, p) for layers, p in vias for layer in layers]
    n = len(segs)
    parent = list(range(n + len(pins)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    # joined where their shapes touch: a wire 0.3 um wide, a via's pad 0.4 um; grown to
    # 0.4 um all (qrouter lands a via 0.2 um off its track on an off-grid pin)
    rect = [segments([s[1], s[2]], 20)[0] for s in segs]
    ends = [(k, p) for k, s in enumerate(segs) for p in (s[1], s[2])]
    for k in range(n):
        for j in range(k):
            if segs[j][0] == segs[k][0] and touch(rect[j], rect[k]):
                parent[find(k)] = find(j)
    # a shape touching a pin (the cell joins it to the pin's other wires), or a stub of
    # SPECIALNETS touching either, on the same metal
    stub_nodes = list(range(n + len(pins), n + len(pins) + len(stubs)))
    parent += stub_nodes
    pin_shapes = [(q, layer, r) for q, (_, m1, m2) in enumerate(pins)
                  for layer, rects in (("metal1", m1), ("metal2", m2)) for r in rects]
    for k, s in enumerate(segs):
        for q, layer, pr in pin_shapes:
            if s[0] == layer and touch(rect[k], pr):
                parent[find(k)] = find(n + q)
        for q, (layer, st) in enumerate(stubs):
            if s[0] == layer and touch(rect[k], st):
                parent[find(k)] = find(stub_nodes[q])
    for q, (layer, st) in enumerate(stubs):
        for p_, pin_layer, pr in pin_shapes:
            if layer == pin_layer and touch(st, pr):
                parent[find(stub_nodes[q])] = find(n + p_)
    for layers, p in vias:
        at = [j for j, t in enumerate(segs) if t[0] in layers and touch(rect[j], (p[0], p[1], p[0], p[1]))]
        for j in at[1:]:
            parent[find(j)] = find(at[0])
    metal = lambda layer: int(layer[5:])
    out = []
    for k, p in ends:
        for j, t in enumerate(segs):
            if abs(metal(t[0]) - metal(segs[k][0])) == 1 and find(j) != find(k) and on_segment(t, p):
                lo, hi = sorted((segs[k][0], t[0]), key=metal)
                out.append((lo, hi, p))
                parent[find(j)] = find(k)
    return out


def segments(pts, half):
    """A path's rectangles, each segment grown by half the wire's width."""
    if len(pts) == 1:
        (x, y), = pts
        return [(x - half, y - half, x + half, y + half)]
    return [(min(a[0], b[0]) - half, min(a[1], b[1]) - half, max(a[0], b[0]) + half, max(a[1], b[1]) + half)
            for a, b in zip(pts, pts[1:])]


def net_blocks(lines, start, end):
    """(name, first line, last line) of each net between start and end (the section's lines)."""
    blocks, name, first = [], None, None
    for i in range(start, end):
        m = re.match(r"- (\S+)", lines[i])
        if m:
            name, first = m.group(1), i
        if name is not None and lines[i].rstrip().endswith(";"):
            blocks.append((name, first, i))
            name = None
    return blocks


def section(lines, keyword):
    s = next((i for i, l in enumerate(lines) if l.startswith(keyword + " ")), None)
    if s is None:
        return None, None
    e = next(i for i in range(s, len(lines)) if lines[i].startswith("END " + keyword))
    return s + 1, e


def main():
    if len(sys.argv) < 5:
        sys.stderr.write(__doc__)
        return 2
    src, dst, report = sys.argv[1:4]
    cells, vias = read_lefs(sys.argv[4:])
    lines = open(src).read().splitlines()
    m1_half = 15   # metal1 WIDTH 0.3 um: half of it in DEF units
    # the DEF's own vias (viagen21_post ...): their metal1 rectangles
    vs, ve = section(lines, "VIAS")
    if vs is not None:
        via = None
        for l in lines[vs:ve]:
            m = re.match(r"- (\S+)", l)
            if m:
                via = m.group(1)
                vias[via] = []
            m = re.search(r"RECT metal1 \( (-?\d+) (-?\d+) \) \( (-?\d+) (-?\d+) \)", l)
            if m and via:
                vias[via].append(tuple(int(v) / 100 for v in m.groups()))
    pads = {v: [tuple(round(c * 100) for c in r) for r in rects] for v, rects in vias.items() if rects}
    placed = {}
    cs, ce = section(lines, "COMPONENTS")
    for l in lines[cs:ce]:
        m = re.match(r"- (\S+) (\S+) .*\+ (?:PLACED|FIXED) \( (-?\d+) (-?\d+) \) (\S+)", l)
        if m:
            if m.group(5) not in ORIENTS:
                sys.stderr.write(f"layout_repair.py: orientation {m.group(5)} of {m.group(1)} not read (N, S, FN, FS)\n")
                return 2
            placed[m.group(1)] = (m.group(2), (int(m.group(3)), int(m.group(4))), m.group(5))
    stubs = {}   # qrouter's metal1 stubs to off-grid pins (SPECIALNETS), by net
    stubs_any = {}   # and its stubs on any metal: (layer, rectangle)
    ss, se = section(lines, "SPECIALNETS")
    if ss is not None:
        for name, first, last in net_blocks(lines, ss, se):
            for _, layer, width, pts, _ in parse_routes(lines, first, last):
                if pts:
                    rects = segments(pts, (width or 30) // 2)
                    stubs_any.setdefault(name, []).extend((layer, r) for r in rects)
                    if layer == "metal1":
                        stubs.setdefault(name, []).extend(rects)
    ns, ne = section(lines, "NETS")
    drop, add, notes, left_open = {}, {}, [], 0
    for name, first, last in net_blocks(lines, ns, ne):
        routes = parse_routes(lines, first, last)
        if not routes or name in POWER_NETS:
            continue   # a power net's vias land on the rows' rails, which its DEF lists as no pin
        pins = []
        for inst, pin in re.findall(r"\(\s*(\S+)\s+(\S+)\s*\)", " ".join(lines[first:routes[0][0]])):
            if inst == "PIN" or inst not in placed:
                continue
            cell, origin, orient = placed[inst]
            rects = cells.get(cell, {}).get("pins", {}).get(pin, [])
            size = cells.get(cell, {}).get("size")
            m1 = [place(r, origin, orient, size) for layer, r in rects if layer == "metal1"]
            if m1:
                pins.append((f"{inst}/{pin}", m1, [place(r, origin, orient, size) for layer, r in rects if layer == "metal2"]))
        # metal1 shapes: pins, wires, stubs, via pads; joined where they touch
        shapes, kind = [], []
        # metal2 wires (and via-only points): a pin with a metal2 port (XNOR2X1's A) is
        # reached there
        metal2_rects = [r for _, layer, _, pts, _ in routes if layer == "metal2" and pts for r in segments(pts, 15)]
        for label, rects, m2 in pins:
            for r in rects:
                shapes.append(r); kind.append(("pin", label))
            if any(touch(a, b) for a in m2 for b in metal2_rects):
                shapes.append(rects[0]); kind.append(("via", ("metal2 port", label)))
        for i, layer, _, pts, via_at in routes:
            if layer == "metal1" and len(pts) > 1:
                for r in segments(pts, m1_half):
                    shapes.append(r); kind.append(("wire", i))
            for v, (x, y) in via_at:
                for r in pads.get(v, []):
                    shapes.append((x + r[0], y + r[1], x + r[2], y + r[3])); kind.append(("via", (i, v, x, y)))
        for r in stubs.get(name, []):
            shapes.append(r); kind.append(("stub", None))
        parent = list(range(len(shapes)))

        def find(a):
            while parent[a] != a:
                parent[a] = parent[parent[a]]
                a = parent[a]
            return a
        for a in range(len(shapes)):
            for b in range(a + 1, len(shapes)):
                # a pin's rectangles are one node: the cell joins them inside
                if touch(shapes[a], shapes[b]) or (kind[a][0] == kind[b][0] == "pin" and kind[a][1] == kind[b][1]):
                    parent[find(a)] = find(b)
        groups = {}
        for a in range(len(shapes)):
            groups.setdefault(find(a), []).append(kind[a])
        dangling, open_pins = [], []
        for members in groups.values():
            has_pin = [k[1] for k in members if k[0] == "pin"]
            via_keys = {k[1] for k in members if k[0] == "via"}
            if not has_pin and len(via_keys) == 1 and next(iter(via_keys))[0] != "metal2 port":
                dangling.extend(via_keys)
            # pins joined on metal1 alone reach no other layer: open unless they are the whole net
            if has_pin and not via_keys and len(set(has_pin)) < len(pins):
                open_pins.extend(sorted(set(has_pin)))
        for key in dangling:
            i, v, x, y = key
            if re.match(r"\s*\+ ROUTED\s+metal\d\s*\(\s*-?\d+\s+-?\d+\s*\)\s*\S+\s*;?\s*$", lines[i]):
                # a net opening with the via alone: its next statement would have to open it
                notes.append(f"{name}: via {v} at ({x / 100:.2f}, {y / 100:.2f}) um touches nothing on metal1; "
                             "it opens the net's route and is left")
                continue
            drop.setdefault(i, []).append((v, x, y))
            notes.append(f"{name}: via {v} at ({x / 100:.2f}, {y / 100:.2f}) um taken out: its metal1 pad touches nothing")
        metal2 = [(pts[j], pts[j + 1]) for _, layer, _, pts, _ in routes if layer == "metal2"
                  for j in range(len(pts) - 1)]
        for label in open_pins:
            rects = next(r for l, r, _ in pins if l == label)
            fixed = None
            for r in rects:
                cx, cy = (r[0] + r[2]) // 2, (r[1] + r[3]) // 2
                for a, b in metal2:
                    qx = min(max(cx, min(a[0], b[0])), max(a[0], b[0]))
                    qy = min(max(cy, min(a[1], b[1])), max(a[1], b[1]))
                    if r[0] <= qx <= r[2] and r[1] <= qy <= r[3]:
                        fixed = (qx, qy)
                        break
                if fixed:
                    break
            if fixed:
                add.setdefault(last, []).append(f"  NEW metal1 ( {fixed[0]} {fixed[1]} ) M2_M1")
                notes.append(f"{name}: pin {label} was open; via M2_M1 put on it at "
                             f"({fixed[0] / 100:.2f}, {fixed[1] / 100:.2f}) um, under the net's metal2 wire")
            else:
                left_open += 1
                notes.append(f"{name}: pin {label} is open and no metal2 wire of the net crosses it: left")
        for lo, hi, (x, y) in layer_breaks(routes, pins, stubs_any.get(name, [])):
            via = f"M{hi[5:]}_M{lo[5:]}"
            add.setdefault(last, []).append(f"  NEW {lo} ( {x} {y} ) {via}")
            notes.append(f"{name}: its {lo} and {hi} meet at ({x / 100:.2f}, {y / 100:.2f}) um, two pieces "
                         f"of the net with no via between them; via {via} put there")
    out = []
    for i, l in enumerate(lines):
        for v, x, y in drop.get(i, []):
            # the via ends its statement: a statement of the via alone goes, else its name
            m = re.match(r"(\s*)NEW\s+metal\d\s*\(\s*-?\d+\s+-?\d+\s*\)\s*" + re.escape(v) + r"\s*(;?)\s*$", l)
            if m:
                l = m.group(1) + m.group(2) if m.group(2) else None
            else:
                l = re.sub(r"\s" + re.escape(v) + r"(\s*;?\s*)$", r"\1", l)
            if l is None:
                break
        if l is None:
            continue
        if i in add:
            # before the net's closing ';'
            body = l.rstrip()
            if body.endswith(";"):
                body = body[:-1].rstrip()
                out.append(body) if body.strip() else None
                out.extend(add[i][:-1])
                out.append(add[i][-1] + " ;")
                continue
        out.append(l)
    open(dst, "w").write("\n".join(out) + "\n")
    with open(report, "w") as f:
        f.write(f"repairs {len(notes)}\nleft_open {left_open}\n")
        for n in notes:
            f.write(n + "\n")
    for n in notes:
        print("layout_repair.py: " + n)
    return 1 if left_open else 0


if __name__ == "__main__":
    sys.exit(main())
