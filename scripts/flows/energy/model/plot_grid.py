#!/usr/bin/python3
"""Energy per result over (cos, n), gate level beside the model (issue 61), from the grid
stream's points (each behind the same reference operation) in fit.py's --json.

    /usr/bin/python3 scripts/flows/energy/model/plot_grid.py FIT_JSON OUT.svg

Needs matplotlib (Debian's python3-matplotlib).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from streams import grid  # noqa: E402  (the grid's operands: cos k/15, n 1000^(j/15))


def main():
    fit = json.load(open(sys.argv[1]))
    points = [l.split() for l in grid()[1::2]]
    cos_vals = sorted({int(p[0], 16) / 65536 for p in points})
    n_vals = sorted({int(p[1], 16) for p in points})
    rows = [(top, d) for top, d in fit["devices"].items() if "grid" in d]
    fig, axes = plt.subplots(len(rows), 2, figsize=(10, 4.2 * len(rows)), squeeze=False)
    for r, (top, d) in enumerate(rows):
        gate = [[0.0] * 16 for _ in range(16)]
        model = [[0.0] * 16 for _ in range(16)]
        for p, (_, g, m) in zip(points, d["grid"]):
            i, j = n_vals.index(int(p[1], 16)), cos_vals.index(int(p[0], 16) / 65536)
            gate[i][j], model[i][j] = g / 1000, m / 1000
        lo = min(min(x) for x in gate + model)
        hi = max(max(x) for x in gate + model)
        for c, (what, z) in enumerate((("gate level", gate), ("model", model))):
            ax = axes[r][c]
            im = ax.imshow(z, origin="lower", aspect="auto", vmin=lo, vmax=hi, cmap="viridis",
                           extent=(-0.5, 15.5, -0.5, 15.5))
            ax.set_xticks(range(0, 16, 3))
            ax.set_xticklabels([f"{cos_vals[k]:.1f}" for k in range(0, 16, 3)])
            ax.set_yticks(range(0, 16, 3))
            ax.set_yticklabels([str(n_vals[k]) for k in range(0, 16, 3)])
            ax.set_xlabel("cos λ")
            ax.set_ylabel("n")
            ax.set_title(f"{d['label']}: {what}")
            fig.colorbar(im, ax=ax, label="nJ per result")
    fig.suptitle("Energy of one operation after the reference operation (cos 0.5, n 32), same colour")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=80)
    return 0


if __name__ == "__main__":
    sys.exit(main())
