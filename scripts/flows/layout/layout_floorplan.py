#!/usr/bin/env python3
"""The ROM macros placed beside graywolf's standard-cell core (scripts/flows/layout/layout.sh).

  layout_floorplan.py DEF CFG FULL_BLIF GAP_UM MACRO_LEF...

graywolf 0.1's mixed (macro) mode crashed on the whole device (mc_compact: "stack
smashing detected"), so graywolf places the standard cells alone and this floorplan puts
the macros in a row below the core, each flipped (FS) so that its pins, on its bottom
edge in the LEF, face the core, GAP_UM from it and from each other; x and y stay on the
routing grid (0.8 um in x, 1 um in y from the die's corner). The DEF gets the macros as
FIXED components, their pins in the nets the full netlist (FULL_BLIF) connects them to,
a die grown around everything and tracks over it. CFG (qrouter's script) is left as
qflow wrote it. Prints the floorplan.
"""
import math
import re
import sys


def lef_macros(paths):
    out = {}
    for path in paths:
        name = None
        for line in open(path):
            m = re.match(r"MACRO\s+(\S+)", line)
            if m:
                name = m.group(1)
            m = re.match(r"\s*SIZE\s+([\d.]+)\s+BY\s+([\d.]+)", line)
            if m and name:
                out[name] = (float(m.group(1)), float(m.group(2)))
    return out


def main():
    if len(sys.argv) < 6:
        sys.stderr.write("usage: layout_floorplan.py DEF CFG FULL_BLIF GAP_UM MACRO_LEF...\n")
        return 2
    def_path, blif_path, gap = sys.argv[1], sys.argv[3], float(sys.argv[4])
    sizes = lef_macros(sys.argv[5:])
    text = open(def_path).read()
    u = int(re.search(r"UNITS DISTANCE MICRONS (\d+)", text).group(1))
    x0, y0, x1, y1 = (int(float(v)) for v in re.search(
        r"DIEAREA\s+\(\s*(\S+)\s+(\S+)\s*\)\s*\(\s*(\S+)\s+(\S+)\s*\)", text).groups())
    gx, gy = round(1.6 * u), round(1.0 * u)   # metal6's pitch in x (twice metal2/4), rows' in y

    # the macros of the full netlist, in order, named as blif2cel names instances
    macros, counts = [], {}
    for line in open(blif_path):
        parts = line.split()
        if len(parts) > 2 and parts[0] == ".gate":
            cell = parts[1]
            counts[cell] = counts.get(cell, 0) + 1
            if cell in sizes:
                pins = dict(p.split("=", 1) for p in parts[2:])
                macros.append((f"{cell}_{counts[cell]}", cell, pins))
    if not macros:
        print("layout_floorplan.py: no macro in the netlist; DEF unchanged")
        return 0
    # a row below the core, left-aligned with it, pins (flipped to the top edge) facing it
    g = round(gap * u)
    x = x0
    top_y = y0 - g
    comps = []
    for inst, cell, pins in macros:
        w, h = (round(v * u) for v in sizes[cell])
        y = top_y - h
        y -= (y - y0) % gy
        comps.append((inst, cell, x, y, w, h))
        x += w + g
        x += (x0 - x) % gx
    nx0 = min(x0, min(c[2] for c in comps)) - g
    ny0 = min(c[3] for c in comps) - g
    nx1 = max(x1, max(c[2] + c[4] for c in comps) + g)
    ny1 = y1
    nx0 -= (nx0 - x0) % gx
    ny0 -= (ny0 - y0) % gy
    nx1 += (x0 - nx1) % gx
    text = re.sub(r"DIEAREA[^;]*;", f"DIEAREA ( {nx0} {ny0} ) ( {nx1} {ny1} ) ;", text, count=1)

    def tracks(m):
        axis, step, layer = m.group(1), int(float(m.group(2))), m.group(3)
        start, end = (nx0, nx1) if axis == "X" else (ny0, ny1)
        return f"TRACKS {axis} {start} DO {(end - start) // step + 1} STEP {step} LAYER {layer} ;"
    text = re.sub(r"TRACKS\s+(X|Y)\s+\S+\s+DO\s+\d+\s+STEP\s+(\S+)\s+LAYER\s+(\S+)\s*;", tracks, text)
    # components
    m = re.search(r"^COMPONENTS\s+(\d+)\s*;", text, re.M)
    n = int(m.group(1)) + len(comps)
    lines = "".join(f"- {inst} {cell} + FIXED ( {x} {y} ) FS ;\n" for inst, cell, x, y, w, h in comps)
    text = text[:m.start()] + f"COMPONENTS {n} ;\n" + lines + text[m.end() + 1:]
    # the macros' pins in their nets
    want = {}
    for inst, cell, pins in macros:
        for pin, net in pins.items():
            want.setdefault(net, []).append(f"  ( {inst} {pin} ) \n")
    nets_m = re.search(r"^NETS\s+(\d+)\s*;\n(.*?)^END NETS", text, re.M | re.S)
    body = nets_m.group(2)
    found = set()

    def add(m):
        net = m.group(1)
        if net in want:
            found.add(net)
            return m.group(0) + "".join(want[net])
        return m.group(0)
    body = re.sub(r"^- (\S+)\n", add, body, flags=re.M)
    extra = [net for net in want if net not in found]
    body += "".join(f"- {net}\n" + "".join(want[net]) + ";\n" for net in extra)
    count = int(nets_m.group(1)) + len(extra)
    text = text[:nets_m.start()] + f"NETS {count} ;\n" + body + text[nets_m.end(2):]
    open(def_path, "w").write(text)

    # CFG keeps qflow's fence: a ring between the old die's edge and the core, metal1
    # all round, metal3/5 above and below, metal2/4/6 left and right: vertical wires
    # still cross its bottom side to the macros.
    a, b, c, d = nx0 / u, ny0 / u, nx1 / u, ny1 / u
    for inst, cell, x, y, w, h in comps:
        print(f"layout_floorplan.py: {inst} at ({x / u:.1f}, {y / u:.1f}) um, {w / u:.1f} x {h / u:.1f} um, FS")
    print(f"layout_floorplan.py: die ({a:.1f}, {b:.1f}) - ({c:.1f}, {d:.1f}) um = "
          f"{(c - a) * (d - b) / 1e6:.4f} mm^2; core ({x0 / u:.1f}, {y0 / u:.1f}) - ({x1 / u:.1f}, {y1 / u:.1f}) um")
    if extra:
        print(f"layout_floorplan.py: {len(extra)} nets connect only macro pins")
    return 0


if __name__ == "__main__":
    sys.exit(main())
