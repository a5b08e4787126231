#!/usr/bin/env python3
"""The routed die as an SVG (scripts/flows/layout/layout.sh; the PNG is KLayout's, layout_picture.rb).

  layout_svg.py OUT_DIR TOP SVG [MAX_SEGMENTS [BIN_UM]]

From OUT_DIR/qflow/TOP_route.def and layout_summary.json: the die, the ROM macros (grey,
named), the standard cells binned on a 10 um grid and each bin coloured by the block of
Fig. 1 that has most cells in it (the instance names, instances.tsv), each block named at
its centre, and the routed wires, each metal in its colour. A whole device has some
300 000 wire segments: the longest are drawn, at most MAX_SEGMENTS, and the caption says
from what length on. MAX_SEGMENTS and BIN_UM (default 40000 and 10) make a smaller file
(docs/layout/ keeps each picture under about 1 MB).
"""
import json
import re
import sys

MAX_SEGMENTS = 40000
BIN_UM = 10.0
METALS = {"metal1": "#1f77b4", "metal2": "#d62728", "metal3": "#2ca02c", "metal4": "#ff7f0e",
          "metal5": "#9467bd", "metal6": "#8c564b"}
BLOCK_COLOURS = ["#fde0dd", "#e5f5e0", "#deebf7", "#fff7bc", "#efedf5", "#fee6ce", "#e0f3f8",
                 "#f7fcb9", "#fcc5c0", "#c7e9c0", "#c6dbef", "#fdd0a2", "#dadaeb", "#d9f0a3",
                 "#f0f0f0", "#ccece6"]


def main():
    global MAX_SEGMENTS, BIN_UM
    if len(sys.argv) not in (4, 5, 6):
        sys.stderr.write("usage: layout_svg.py OUT_DIR TOP SVG [MAX_SEGMENTS [BIN_UM]]\n")
        return 2
    out, top, svg_path = sys.argv[1:4]
    try:
        MAX_SEGMENTS = int(sys.argv[4]) if len(sys.argv) > 4 else MAX_SEGMENTS
        BIN_UM = float(sys.argv[5]) if len(sys.argv) > 5 else BIN_UM
    except ValueError:
        sys.stderr.write(f"layout_svg.py: MAX_SEGMENTS '{sys.argv[4]}' must be a whole number >= 1, BIN_UM a length > 0\n")
        return 2
    if MAX_SEGMENTS < 1 or BIN_UM <= 0:
        sys.stderr.write(f"layout_svg.py: MAX_SEGMENTS {MAX_SEGMENTS} must be >= 1, BIN_UM {BIN_UM} > 0\n")
        return 2
    s = json.load(open(f"{out}/layout_summary.json"))
    text = open(f"{out}/qflow/{top}_route.def").read()
    u = float(re.search(r"UNITS DISTANCE MICRONS (\d+)", text).group(1))
    x0, y0, x1, y1 = (float(v) / u for v in re.search(
        r"DIEAREA\s+\(\s*(\S+)\s+(\S+)\s*\)\s*\(\s*(\S+)\s+(\S+)\s*\)", text).groups())
    names = dict(l.split("\t") for l in open(f"{out}/instances.tsv").read().splitlines()[1:])
    blocks = sorted(s["blocks"])
    colour = {b: BLOCK_COLOURS[i % len(BLOCK_COLOURS)] for i, b in enumerate(blocks)}
    bins = {}
    for m in re.finditer(r"^-\s+(\S+)\s+(\S+)\s+\+\s+(?:PLACED|FIXED)\s+\(\s*(\S+)\s+(\S+)", text, re.M):
        inst = m.group(1)
        if inst not in names or m.group(2).startswith("ROM"):
            continue
        net = names[inst]
        block = net.split(".")[0] if "." in net and not net.startswith("$") else "(top)"
        key = (int((float(m.group(3)) / u - x0) // BIN_UM), int((float(m.group(4)) / u - y0) // BIN_UM))
        bins.setdefault(key, {}).setdefault(block, 0)
        bins[key][block] += 1
    segs = []
    nets = re.search(r"^NETS.*?^END NETS", text, re.M | re.S)
    for stmt in (nets.group(0).split(";") if nets else []):
        for m in re.finditer(r"(?:ROUTED|NEW)\s+(metal\d)(.*?)(?=\bNEW\b|$)", stmt, re.S):
            pts, px, py = [], None, None
            for pm in re.finditer(r"\(\s*(-?[\d.]+|\*)\s+(-?[\d.]+|\*)", m.group(2)):
                x = px if pm.group(1) == "*" else float(pm.group(1)) / u
                y = py if pm.group(2) == "*" else float(pm.group(2)) / u
                pts.append((x, y))
                px, py = x, y
            for a, b in zip(pts, pts[1:]):
                segs.append((abs(b[0] - a[0]) + abs(b[1] - a[1]), m.group(1), a, b))
    segs.sort(key=lambda t: -t[0])
    shown = segs[:MAX_SEGMENTS]
    min_len = shown[-1][0] if len(segs) > MAX_SEGMENTS else 0.0
    W, H = x1 - x0, y1 - y0
    scale = 1000.0 / max(W, H)
    fx = lambda x: (x - x0) * scale
    fy = lambda y: (y1 - y) * scale
    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W * scale + 220:.0f}" height="{H * scale + 40:.0f}" '
         f'font-family="sans-serif" font-size="11">',
         f'<rect x="0" y="0" width="{W * scale:.1f}" height="{H * scale:.1f}" fill="white" stroke="black"/>']
    for (bx, by), counts in bins.items():
        block = max(counts, key=counts.get)
        o.append(f'<rect x="{bx * BIN_UM * scale:.1f}" y="{fy(y0 + (by + 1) * BIN_UM):.1f}" '
                 f'width="{BIN_UM * scale:.1f}" height="{BIN_UM * scale:.1f}" fill="{colour[block]}"/>')
    for mac in s["macros"]:
        o.append(f'<rect x="{fx(mac["x_um"]):.1f}" y="{fy(mac["y_um"] + mac["h_um"]):.1f}" width="{mac["w_um"] * scale:.1f}" '
                 f'height="{mac["h_um"] * scale:.1f}" fill="#d9d9d9" stroke="black"/>')
    for layer in METALS:
        lines = [f'M{fx(a[0]):.1f} {fy(a[1]):.1f}L{fx(b[0]):.1f} {fy(b[1]):.1f}' for _, l, a, b in shown if l == layer]
        if lines:
            o.append(f'<path d="{"".join(lines)}" stroke="{METALS[layer]}" stroke-width="0.5" fill="none" opacity="0.7"/>')
    for mac in s["macros"]:
        o.append(f'<text x="{fx(mac["x_um"] + mac["w_um"] / 2):.1f}" y="{fy(mac["y_um"] + mac["h_um"] / 2):.1f}" '
                 f'text-anchor="middle" font-size="16">{mac["cell"]} ({mac["instance"].split(".")[0]})</text>')
    for b, info in s["blocks"].items():
        cx, cy = info["centre_um"]
        o.append(f'<text x="{fx(cx):.1f}" y="{fy(cy):.1f}" text-anchor="middle" font-weight="bold">{b}</text>')
    lx = W * scale + 10
    for i, b in enumerate(blocks):
        o.append(f'<rect x="{lx:.0f}" y="{10 + 14 * i}" width="10" height="10" fill="{colour[b]}" stroke="black"/>'
                 f'<text x="{lx + 14:.0f}" y="{19 + 14 * i}">{b} ({s["blocks"][b]["cells"]})</text>')
    base = 20 + 14 * len(blocks)
    for i, (layer, c) in enumerate(METALS.items()):
        o.append(f'<line x1="{lx:.0f}" y1="{base + 14 * i + 5}" x2="{lx + 10:.0f}" y2="{base + 14 * i + 5}" stroke="{c}" stroke-width="3"/>'
                 f'<text x="{lx + 14:.0f}" y="{base + 14 * i + 9}">{layer}</text>')
    o.append(f'<text x="0" y="{H * scale + 16:.0f}">{top}: die {W:.0f} x {H:.0f} um; cells binned on {BIN_UM:.0f} um by block; '
             f'{len(shown)} of {len(segs)} wire segments drawn'
             + (f' (those of {min_len:.1f} um and longer)' if min_len else '') + '</text>')
    o.append("</svg>")
    open(svg_path, "w").write("\n".join(o) + "\n")
    print(f"layout_svg.py: {svg_path}: {len(shown)} of {len(segs)} segments")
    return 0


if __name__ == "__main__":
    sys.exit(main())
