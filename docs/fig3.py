#!/usr/bin/env python3
"""Fig. 3 of UA 59965 U, redrawn: the timing of one operation, as an SVG.

The waveforms are computed from the control-unit equations of the spec (§3), half
period by half period, and checked against the spec's timing table before anything
is drawn, so the figure cannot drift from either. Standard library only.

Usage: docs/fig3.py [OUTPUT.svg]   (default: fig3.svg next to this script)
"""
import os
import sys

HALF_PERIODS = range(-1, 8)  # t = k·T/2 for k = -1 … 7 (from −T/2 to 7T/2)


def simulate():
    """Control unit 16 per spec §3; returns {signal: [level at each k in HALF_PERIODS]}.

    Start (pin 27) rises with the clock at t = 0 and falls half a period later, as the
    protocol Decision and the testbench drive it. Reset (pin 29) stays high.
    """
    q41 = q42 = q43 = 0
    rst_n = 1
    waves = {name: [] for name in ("clk", "start", "q41", "q42", "q43", "nand45", "nand46", "w37")}
    prev_clk, prev_start = 0, 0
    for k in HALF_PERIODS:
        clk = 1 if k % 2 == 0 else 0          # rising edges at even k
        start = 1 if k == 0 else 0            # high during [0, T/2)
        if start and not prev_start:          # dff41: C = start, D = 1
            q41 = 1
        if prev_clk and not clk:              # inv44 rises: dff42, dff43 clock together
            q42, q43 = q41, q42
        # combinational settle, then asynchronous reset of 41 through AND 40
        for _ in range(3):
            nand45 = 0 if ((1 - q43) and q42 and clk) else 1
            nand46 = 0 if (clk and (1 - q42) and q43) else 1
            and40 = rst_n and nand45
            if not and40:
                q41 = 0
        w37 = 0 if (nand45 and nand46) else 1
        for name, value in (("clk", clk), ("start", start), ("q41", q41), ("q42", q42),
                            ("q43", q43), ("nand45", nand45), ("nand46", nand46), ("w37", w37)):
            waves[name].append(value)
        prev_clk, prev_start = clk, start
    return waves


def check_against_spec_table(waves):
    """The spec's timing table (§3), event by event: fail loudly if the equations disagree."""
    at = {k: i for i, k in enumerate(HALF_PERIODS)}

    def rises(sig, k):
        return waves[sig][at[k] - 1] == 0 and waves[sig][at[k]] == 1

    def falls(sig, k):
        return waves[sig][at[k] - 1] == 1 and waves[sig][at[k]] == 0

    table = [
        ("0: Q41 <- 1", rises("q41", 0)),
        ("T/2: Q42 <- 1", rises("q42", 1)),
        ("T: 37 rises (pass 1 written)", rises("w37", 2)),
        ("T: and40 clears Q41", falls("q41", 2)),
        ("3T/2: Q43 <- 1 (select 36 = 1)", rises("q43", 3)),
        ("3T/2: Q42 <- 0", falls("q42", 3)),
        ("2T: 35 falls", falls("nand46", 4)),
        ("2T: 37 rises (pass 2 written)", rises("w37", 4)),
        ("5T/2: Q43 <- 0", falls("q43", 5)),
        ("5T/2: 35 rises (result valid)", rises("nand46", 5)),
    ]
    bad = [event for event, ok in table if not ok]
    if bad:
        sys.exit("fig3.py: the equations disagree with the spec's timing table at: " + "; ".join(bad))
    # 37 rises exactly twice, 35 falls exactly once
    edges37 = sum(1 for i in range(1, len(waves["w37"])) if waves["w37"][i] > waves["w37"][i - 1])
    if edges37 != 2:
        sys.exit("fig3.py: register 9 must be written twice per operation, got %d" % edges37)


# ---------------------------------------------------------------- drawing
LEFT, TOP, ROW, HALF, HIGH = 250, 78, 40, 70, 22
FONT = 'font-family="DejaVu Sans, Verdana, sans-serif"'
BLUE, RED, GREY, INK = "#1f4e99", "#a02020", "#999999", "#222222"


def x_of(k):
    return LEFT + (k - HALF_PERIODS[0]) * HALF


def wire(levels, row, colour):
    y0 = TOP + row * ROW + ROW - 10
    pts = []
    for i, k in enumerate(HALF_PERIODS):
        y = y0 - HIGH * levels[i]
        if pts:
            pts.append((x_of(k), pts[-1][1]))
        pts.append((x_of(k), y))
    pts.append((x_of(HALF_PERIODS[-1] + 1), pts[-1][1]))
    path = " ".join("%s%.1f,%.1f" % ("M" if i == 0 else "L", x, y) for i, (x, y) in enumerate(pts))
    return '<path d="%s" fill="none" stroke="%s" stroke-width="2"/>' % (path, colour)


def bus(segments, row, colour):
    """segments: (k_from, k_to, text, fill); drawn as the usual hexagon bus shape."""
    y_mid = TOP + row * ROW + ROW - 10 - HIGH / 2
    out = []
    for k0, k1, text, fill in segments:
        x0, x1, s = x_of(k0), x_of(k1), 5
        d = "M%.1f,%.1f L%.1f,%.1f L%.1f,%.1f L%.1f,%.1f L%.1f,%.1f L%.1f,%.1f Z" % (
            x0, y_mid, x0 + s, y_mid - HIGH / 2, x1 - s, y_mid - HIGH / 2, x1, y_mid,
            x1 - s, y_mid + HIGH / 2, x0 + s, y_mid + HIGH / 2)
        out.append('<path d="%s" fill="%s" stroke="%s" stroke-width="1.5"/>' % (d, fill, colour))
        out.append('<text x="%.1f" y="%.1f" %s font-size="12" text-anchor="middle" fill="%s">%s</text>'
                   % ((x0 + x1) / 2, y_mid + 4, FONT, INK, text))
    return "\n".join(out)


def draw(waves):
    rows = [
        ("pin 28  clock", "wire", waves["clk"], RED),
        ("pin 27  start / write 1", "wire", waves["start"], RED),
        ("Q41", "wire", waves["q41"], INK),
        ("Q42", "wire", waves["q42"], INK),
        ("Q43 = 36  select", "wire", waves["q43"], INK),
        ("nand45", "wire", waves["nand45"], INK),
        ("37  write register 9", "wire", waves["w37"], BLUE),
        ("35  done = nand46", "wire", waves["nand46"], RED),
        ("register 9", "bus", [(-1, 2, "previous", "#ffffff"),
                               (2, 4, "1 − n·log2 cos λ", "#eef3fb"),
                               (4, 8, "A ≈ cosⁿ λ", "#dfeadb")], BLUE),
        ("pins 24–26", "bus", [(-1, 2, "previous", "#ffffff"),
                               (2, 4, "meaningless", "#f4f4f4"),
                               (4, 8, "K·A·I (read at 35↑)", "#dfeadb")], BLUE),
    ]
    width = x_of(HALF_PERIODS[-1] + 1) + 30
    height = TOP + len(rows) * ROW + 50
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">'
           % (width, height, width, height),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="24" %s font-size="15" font-weight="bold" text-anchor="middle">'
           'Fig. 3 — one operation of UA 59965 U, computed from the control-unit equations (spec §3)</text>'
           % (width / 2, FONT),
           '<text x="%d" y="44" %s font-size="11" text-anchor="middle" fill="#444">start rises with a rising'
           ' clock edge at t = 0; register 9 is written on each rising edge of 37; results are valid at the'
           ' rising edge of 35 (2.5 T after start)</text>' % (width / 2, FONT)]
    # time grid
    labels = {-1: "−T/2", 0: "0", 1: "T/2", 2: "T", 3: "3T/2", 4: "2T", 5: "5T/2", 6: "3T", 7: "7T/2"}
    for k in HALF_PERIODS:
        x = x_of(k)
        svg.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-dasharray="%s"/>'
                   % (x, TOP - 8, x, TOP + len(rows) * ROW, GREY if k % 2 else "#666", "2,4" if k % 2 else "5,3"))
        svg.append('<text x="%d" y="%d" %s font-size="11" text-anchor="middle" fill="#444">%s</text>'
                   % (x, TOP - 12, FONT, labels[k]))
    # events
    events = [(2, "pass 1 written"), (4, "pass 2 written"), (5, "35↑ result valid")]
    for i, (k, text) in enumerate(events):
        y_ev = TOP + len(rows) * ROW + 18 + 15 * (i % 2)  # staggered: the events are T/2 apart
        svg.append('<text x="%d" y="%d" %s font-size="11" text-anchor="middle" fill="%s">%s</text>'
                   % (x_of(k), y_ev, FONT, BLUE if "written" in text else RED, text))
    for row, (name, kind, data, colour) in enumerate(rows):
        y_text = TOP + row * ROW + ROW - 16
        svg.append('<text x="%d" y="%d" %s font-size="13" text-anchor="end" fill="%s">%s</text>'
                   % (LEFT - 14, y_text, FONT, INK, name))
        svg.append(wire(data, row, colour) if kind == "wire" else bus(data, row, colour))
    svg.append("</svg>")
    return "\n".join(svg) + "\n"


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "fig3.svg")
    waves = simulate()
    check_against_spec_table(waves)
    with open(out, "w", encoding="utf-8") as f:
        f.write(draw(waves))


if __name__ == "__main__":
    main()
