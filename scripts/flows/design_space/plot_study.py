#!/usr/bin/python3
"""Draws the pictures of the numerical study (issue 4) from specular_study's CSV files.

    /usr/bin/python3 scripts/flows/design_space/plot_study.py [STUDY_DIR] [FIGURE_DIR]

STUDY_DIR defaults to study-output/, FIGURE_DIR to docs/study/. Needs Debian's
python3-numpy and python3-matplotlib (scripts/setup.sh installs them); run it with
/usr/bin/python3, since a pyenv python on PATH may lack numpy. Writes PNG files only.
"""

import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import SymLogNorm  # noqa: E402

BOUND = 2.0 ** -10  # the device's accuracy bound against the double formula (issue 2)
DPI = 90

# One colour and one label per lobe, the same in every picture.
STYLE = {
    "exact": dict(color="black", label="exact cos$^n$"),
    "device_clamp": dict(color="tab:blue", label="device, patent constants (clamp)"),
    "device_minimax_half": dict(color="tab:purple", label="device, minimax-half: s·A (h = ½)"),
    "device_minimax": dict(color="tab:pink", lw=1.8, label="device, minimax: s·A (h = 41/256)"),
    "device_literal": dict(color="tab:cyan", ls="--", label="device (literal)"),
    "formula_clamp": dict(color="tab:orange", ls=":", label="formula, double (clamp)"),
    "formula_literal": dict(color="tab:brown", ls=":", label="formula, double (literal)"),
    "schlick": dict(color="tab:green", label="Schlick t/(n−nt+t)"),
    "us5739820": dict(color="tab:red", label="US 5739820 (1−n(1−t)/4)$^4$"),
}


def fail(message):
    sys.stderr.write("plot_study.py: " + message + "\n")
    sys.exit(1)


def read_table(path):
    """A CSV file as a dict of column name -> numpy array (floats where possible)."""
    if not os.path.isfile(path):
        fail("missing '%s' (run specular_study first)" % path)
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        fail("'%s' has no data rows" % path)
    header, body = rows[0], rows[1:]
    table = {}
    for i, name in enumerate(header):
        column = [r[i] for r in body]
        try:
            table[name] = np.array([float(v) for v in column])
        except ValueError:
            table[name] = np.array(column)
    return table


def read_matrix(path):
    """heatmap_*.csv: first column n, the header's other cells are λ in degrees."""
    if not os.path.isfile(path):
        fail("missing '%s' (run specular_study first)" % path)
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    lambdas = np.array([float(v) for v in rows[0][1:]])
    ns = np.array([float(r[0]) for r in rows[1:]])
    values = np.array([[float(v) for v in r[1:]] for r in rows[1:]])
    return ns, lambdas, values


def save(fig, out_dir, name):
    path = os.path.join(out_dir, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    print("wrote %s (%d kB)" % (path, (os.path.getsize(path) + 512) // 1024))


def plot_lobes_and_errors(study, out_dir):
    """error_curves.png (f − cos^n against λ) and lobes.png (the values themselves)."""
    t = read_table(os.path.join(study, "error_curves.csv"))
    ns = sorted(set(int(v) for v in t["n"]))
    methods = ["device_clamp", "device_literal", "formula_clamp", "schlick", "us5739820",
               "device_minimax_half", "device_minimax"]
    columns = 4
    rows = (len(ns) + columns - 1) // columns
    for kind in ("errors", "lobes"):
        fig, axes = plt.subplots(rows, columns, figsize=(15, 3.6 * rows), squeeze=False)
        for k, n in enumerate(ns):
            ax = axes[k // columns][k % columns]
            sel = t["n"] == n
            lam = t["lambda_deg"][sel]
            order = np.argsort(lam)
            lam = lam[order]
            # Show the lobe and a little beyond where the formula turns negative.
            zero_lambda = math.degrees(math.acos(2.0 ** (-3.0 / n)))
            right = min(90.0, 2.2 * zero_lambda)
            if kind == "lobes":
                ax.plot(lam, t["exact"][sel][order], lw=2.2, **STYLE["exact"])
            for m in methods:
                y = t[m][sel][order] if kind == "lobes" else t[m + "_err"][sel][order]
                style = dict(STYLE[m])
                ax.plot(lam, y, lw=style.pop("lw", 1.3), **style)
            ax.axvline(zero_lambda, color="grey", lw=0.8, ls="-.")
            ax.axhline(0.0, color="grey", lw=0.5)
            ax.set_xlim(0, right)
            if kind == "errors":
                ax.set_ylim(-0.35, 0.35)
                ax.axhline(0.125, color="tab:blue", lw=0.5, ls=":")
                ax.axhline(-0.125, color="tab:blue", lw=0.5, ls=":")
            else:
                ax.set_ylim(-0.6, 1.05)
            ax.set_title("n = %d   (formula < 0 beyond λ = %.3g°)" % (n, zero_lambda), fontsize=10)
            ax.set_xlabel("λ (degrees)")
            ax.grid(alpha=0.3)
        for k in range(len(ns), rows * columns):
            axes[k // columns][k % columns].axis("off")
        axes[0][0].set_ylabel("f(cos λ) − cos$^n$ λ" if kind == "errors" else "f(cos λ)")
        handles, labels = axes[0][0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=9)
        if kind == "errors":
            fig.suptitle("Error against the exact lobe cos$^n$ λ (device: register 9 after pass 2; "
                         "dash-dot: where the formula crosses 0; the literal curves leave the "
                         "frame below it)", fontsize=11)
        else:
            fig.suptitle("The lobes: cos$^n$ λ and its approximations (dash-dot: where "
                         "1 − ½·log2(1 − n·log2 cos λ) crosses 0)", fontsize=11)
        fig.tight_layout(rect=(0, 0.08, 1, 0.95))
        save(fig, out_dir, "error_curves.png" if kind == "errors" else "lobes.png")


def plot_max_error(study, out_dir):
    """max_error_by_n.png: the largest |f − cos^n| for every n, and the fixed-point error."""
    t = read_table(os.path.join(study, "max_error_by_n.csv"))
    n = t["n"]
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(17, 5),
                                              gridspec_kw={"width_ratios": [1.3, 0.8, 1.1]})
    marker = "." if len(n) < 20 else None
    for m in ["device_clamp", "formula_clamp", "schlick", "us5739820", "device_minimax_half",
              "device_minimax"]:
        style = dict(STYLE[m])
        left.plot(n, t[m + "_max_err"], lw=style.pop("lw", 1.4), marker=marker, **style)
    left.set_xscale("log")
    left.set_ylim(0.0, 0.35)
    left.set_xlabel("n")
    left.set_ylabel("max over cos λ of |f − cos$^n$ λ|")
    left.set_title("Maximum error against the exact lobe, every n (Schlick exact at n = 1,\n"
                   "US 5739820 at n = 4; minimax: the same datapath, other constants)", fontsize=10)
    left.grid(alpha=0.3, which="both")
    left.legend(fontsize=9)

    for m in ["device_literal", "formula_literal"]:
        middle.plot(n, t[m + "_max_err"], lw=1.4, marker=marker, **STYLE[m])
    middle.set_xscale("log")
    middle.set_xlabel("n")
    middle.set_title("Without the clamp (literal): the negative\n"
                     "tail dominates, at cos λ = 0", fontsize=10)
    middle.grid(alpha=0.3, which="both")
    middle.legend(fontsize=9)

    right.plot(n, t["device_vs_formula_clamp_max"], lw=1.0, label="device − formula (clamp)",
               color="tab:blue")
    right.plot(n, t["device_vs_formula_literal_max"], lw=1.0, ls="--",
               label="device − formula (literal)", color="tab:cyan")
    right.axhline(BOUND, color="tab:red", lw=1.0, label="bound 2$^{-10}$")
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel("n")
    right.set_ylabel("max over cos codes of |A$_{device}$ − A$_{formula}$|")
    right.set_title("Fixed-point error: device against the same formula in double")
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=9)
    fig.tight_layout()
    save(fig, out_dir, "max_error_by_n.png")


def plot_energy(study, out_dir):
    """energy_integrals.png: equation 6 per policy — the Fig. 5 / Fig. 6 equivalents."""
    t = read_table(os.path.join(study, "energy_integrals.csv"))
    policies = [("patent", "patent: K = 2π/(n+2) (the claim; default)"),
                ("energy", "energy: K = (n+2)/(2π)"),
                ("none", "none: K = 1 (prototype UA 22802)")]
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.2))
    for ax, (policy, title) in zip(axes, policies):
        sel = t["policy"] == policy
        n = t["n"][sel]
        marker = "o" if len(n) < 20 else None
        ax.plot(n, t["exact_closed_form"][sel], lw=2.4, marker=marker, **STYLE["exact"])
        ax.plot(n, t["formula_clamp"][sel], lw=1.4, marker=marker, **STYLE["formula_clamp"])
        ax.plot(n, t["device_clamp"][sel], lw=1.2, marker=marker, **STYLE["device_clamp"])
        ax.plot(n, t["device_literal"][sel], lw=1.2, marker=marker, **STYLE["device_literal"])
        ax.plot(n, t["schlick"][sel], lw=1.2, marker=marker, **STYLE["schlick"])
        ax.plot(n, t["us5739820"][sel], lw=1.2, marker=marker, **STYLE["us5739820"])
        ax.axhline(1.0, color="grey", lw=1.0, ls="-.", label="1 (energy conserved)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("2π ∫ K(n)·f(cos θ) cos θ sin θ dθ over [0, π/2]")
    axes[0].legend(fontsize=8, loc="lower left")
    fig.suptitle("Hemisphere integral of the normalised lobe (patent's equation 6): 1 means "
                 "the surface reflects exactly the light it receives", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    save(fig, out_dir, "energy_integrals.png")

    # The energy policy alone on a linear scale: how far below 1 the approximations stay.
    sel = t["policy"] == "energy"
    n = t["n"][sel]
    fig, ax = plt.subplots(figsize=(8, 4.6))
    for m in ["formula_clamp", "device_clamp", "device_literal", "us5739820"]:
        ax.plot(n, t[m][sel], lw=1.4, **STYLE[m])
    ax.plot(n, t["exact"][sel], lw=2.0, **STYLE["exact"])
    ax.set_xscale("log")
    ax.set_ylim(0.5, 1.15)
    ax.set_xlabel("n")
    ax.set_ylabel("integral with K = (n+2)/(2π)")
    ax.set_title("Energy policy, linear scale (Schlick leaves the frame: 1.64 at n = 10, "
                 "5.4 at n = 1000)", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=9)
    fig.tight_layout()
    save(fig, out_dir, "energy_policy.png")


def plot_heatmaps(study, out_dir):
    """heatmap_error.png: signed error over (λ, n) for three lobes and the fixed-point error."""
    maps = [("device_clamp", "device (clamp) − cos$^n$"),
            ("schlick", "Schlick − cos$^n$"),
            ("us5739820", "US 5739820 − cos$^n$"),
            ("device_vs_formula", "device − formula in double (fixed-point error)")]
    fig, axes = plt.subplots(2, 2, figsize=(13, 9.5))
    for ax, (name, title) in zip(axes.flat, maps):
        ns, lambdas, values = read_matrix(os.path.join(study, "heatmap_%s.csv" % name))
        if name == "device_vs_formula":
            limit = max(np.abs(values).max(), 1e-9)
            norm = SymLogNorm(linthresh=1e-6, vmin=-limit, vmax=limit, base=10)
        else:
            norm = SymLogNorm(linthresh=1e-3, vmin=-0.32, vmax=0.32, base=10)
        image = ax.pcolormesh(lambdas, ns, values, cmap="RdBu_r", norm=norm, shading="nearest")
        zero = np.degrees(np.arccos(2.0 ** (-3.0 / ns)))
        ax.plot(zero, ns, color="black", lw=0.8, ls="--", label="formula = 0: cos λ = 2$^{-3/n}$")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("λ (degrees)")
        ax.set_ylabel("n")
        ax.set_title(title, fontsize=10)
        fig.colorbar(image, ax=ax)
    axes[0][0].legend(fontsize=8, loc="lower left")
    fig.suptitle("Signed error over (λ, n): red above, blue below the reference "
                 "(symmetric log colour scale)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    save(fig, out_dir, "heatmap_error.png")


def plot_spheres(study, out_dir):
    """spheres.png: one sphere per lobe (columns) and n (rows), specular over a dim diffuse."""
    columns = [("exact", "exact cos$^n$\n(K = 1)"),
               ("device_none", "device, none\n(K = 1)"),
               ("device_patent", "device, patent\n(K = 2π/(n+2))"),
               ("device_energy", "device, energy\n(K = (n+2)/2π)"),
               ("schlick", "Schlick\n(K = 1)"),
               ("us5739820", "US 5739820\n(K = 1)"),
               ("device_minimax_half", "device, minimax-half\n(s·A, K = 1)"),
               ("device_minimax", "device, minimax\n(s·A, K = 1)"),
               ("device_minimax_device_energy", "device, minimax,\ndevice-energy")]
    ns = [1, 10, 100, 1000]
    fig, axes = plt.subplots(len(ns), len(columns), figsize=(2.1 * len(columns), 2.25 * len(ns)))
    for r, n in enumerate(ns):
        t = read_table(os.path.join(study, "sphere_n%d.csv" % n))
        size = int(t["size"][0])
        x = t["x"].astype(int)
        y = t["y"].astype(int)
        diffuse = 0.22 * np.clip(t["n_dot_l"], 0.0, 1.0) + 0.05
        for c, (name, title) in enumerate(columns):
            ax = axes[r][c]
            image = np.zeros((size, size))
            image[y, x] = np.clip(diffuse + t[name], 0.0, 1.0)  # display clips at white
            ax.imshow(image, cmap="gray", vmin=0.0, vmax=1.0, interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_xlabel("peak %.3g" % t[name].max(), fontsize=8)
            if r == 0:
                ax.set_title(title, fontsize=9)
            if c == 0:
                ax.set_ylabel("n = %d" % n, fontsize=11)
    fig.suptitle("Specular highlight of one white light (display clips at 1; 'peak' is the "
                 "largest K·f on the sphere)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    save(fig, out_dir, "spheres.png")


def plot_widths(study, out_dir):
    """widths.png: the fixed-point error and the ROM sizes as each width varies."""
    t = read_table(os.path.join(study, "widths.csv"))
    default = t["is_default"] == 1
    d_addr = int(t["rom5_addr_bits"][default][0])
    d_word = int(t["rom5_word_bits"][default][0])
    fig, axes = plt.subplots(2, 3, figsize=(17, 9.5))
    sweeps = [("rom5_addr", "rom5_addr_bits", "ROM 5 address bits (word %d)" % d_word,
               "max_err_vs_formula", "rom5_bits"),
              ("rom5_word", "rom5_word_bits", "ROM 5 word bits (address %d)" % d_addr,
               "max_err_vs_formula", "rom5_bits"),
              ("reg9_frac", "reg9_frac_bits", "register 9 fraction bits (S14.F)",
               "max_err_vs_formula", None),
              ("rom38_frac", "rom38_frac_bits", "ROM 38 fraction bits (U8.F), patent policy",
               "max_norm_err", "rom38_bits")]
    for ax, (sweep, column, xlabel, err, bits) in zip(axes.flat, sweeps):
        sel = t["sweep"] == sweep
        if not sel.any():
            ax.axis("off")
            continue
        x = t[column][sel]
        ax.plot(x, t[err][sel], marker="o", color="tab:blue",
                label="max |A$_{device}$ − A$_{formula}$|" if err == "max_err_vs_formula"
                else "max |K·A$_{device}$ − K·A$_{formula}$| / max(1, K)")
        ax.axhline(BOUND, color="tab:red", lw=1.0, label="bound 2$^{-10}$")
        default_x = t[column][default][0]
        ax.axvline(default_x, color="grey", ls="--", lw=1.0, label="default")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("error (every n, every cos code)")
        ax.grid(alpha=0.3, which="both")
        if bits:
            twin = ax.twinx()
            twin.plot(x, t[bits][sel] / 1024.0, color="tab:green", marker="s", ms=3, lw=1.0,
                      label="ROM size")
            twin.set_yscale("log")
            twin.set_ylabel("%s size (kbit)" % ("ROM 5" if bits == "rom5_bits" else "ROM 38"),
                            color="tab:green")
            lines = ax.get_legend_handles_labels()
            more = twin.get_legend_handles_labels()
            ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper right")
        else:
            ax.legend(fontsize=8, loc="upper right")

    # The grid: error over ROM 5 address × word, each cell annotated with the ROM size.
    ax = axes.flat[4]
    sel = t["sweep"] == "grid"
    if sel.any():
        addrs = sorted(set(int(v) for v in t["rom5_addr_bits"][sel]))
        words = sorted(set(int(v) for v in t["rom5_word_bits"][sel]))
        grid = np.full((len(words), len(addrs)), np.nan)
        for a, w, e in zip(t["rom5_addr_bits"][sel], t["rom5_word_bits"][sel],
                           t["max_err_vs_formula"][sel]):
            grid[words.index(int(w)), addrs.index(int(a))] = e
        image = ax.imshow(np.log2(grid), origin="lower", cmap="viridis_r", aspect="auto",
                          extent=(addrs[0] - 0.5, addrs[-1] + 0.5, words[0] - 1, words[-1] + 1))
        for i, w in enumerate(words):
            for j, a in enumerate(addrs):
                e = grid[i, j]
                kbit = (2 ** a) * w / 1024.0
                ok = e <= BOUND
                # viridis_r is light at small errors, dark at large ones.
                ax.text(a, w, "%.0f\n%s" % (kbit, "ok" if ok else ""), ha="center",
                        va="center", fontsize=6.5, color="black" if math.log2(e) < -9 else "white")
        ax.plot([d_addr], [d_word], marker="s", ms=16, mfc="none", mec="red", mew=1.5)
        ax.set_xlabel("ROM 5 address bits")
        ax.set_ylabel("ROM 5 word bits")
        ax.set_title("log2 max |A$_{device}$ − A$_{formula}$| (cells: ROM 5 kbit; "
                     "'ok' ≤ 2$^{-10}$; red: default)", fontsize=9)
        fig.colorbar(image, ax=ax, label="log2 of the error")
    else:
        ax.axis("off")

    # Near cos λ = 1 at n = 1000: what too few address bits do.
    ax = axes.flat[5]
    path = os.path.join(study, "widths_near_one.csv")
    if os.path.isfile(path):
        near = read_table(path)
        for a in sorted(set(int(v) for v in near["rom5_addr_bits"])):
            s = near["rom5_addr_bits"] == a
            ax.plot(near["cos_code"][s], near["device"][s], lw=1.0,
                    label="device, %d address bits" % a)
        s = near["rom5_addr_bits"] == near["rom5_addr_bits"][0]
        ax.plot(near["cos_code"][s], near["formula"][s], color="black", lw=1.6, ls=":",
                label="formula in double")
        ax.set_xlabel("cos code (U1.16) near 1.0, n = %d" % int(near["n"][0]))
        ax.set_ylabel("A")
        ax.set_title("Too few address bits: neighbouring cos codes share a ROM 5 word",
                     fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    else:
        ax.axis("off")
    fig.suptitle("Fixed-point widths: the device against the same formula in double, every n "
                 "in the study × every cos code", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    save(fig, out_dir, "widths.png")


def plot_constants(study, out_dir):
    """constants.png: the minimax search's trade-off, and device-energy's integrals."""
    t = read_table(os.path.join(study, "constants_search.csv"))
    e = read_table(os.path.join(study, "energy_device_energy.csv"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(14, 4.8))
    minimax = t["search"] == "minimax"
    f = t["F"][minimax]
    left.plot(f, t["max_error"][minimax], marker="o", color="tab:pink",
              label="minimax: h on F fraction bits")
    for name, colour in (("patent", "tab:blue"), ("minimax-half", "tab:purple")):
        value = t["max_error"][t["search"] == name][0]
        left.axhline(value, color=colour, ls="--", lw=1.0, label="%s: %.4f" % (name, value))
    left.axhline(0.203, color="tab:green", ls=":", lw=1.0, label="Schlick: 0.203")
    left.set_yscale("log")
    left.set_xlabel("F: fraction bits of pin 19 / multiplexer 4 (multiplier 6 grows by F − 1 bits)")
    left.set_ylabel("max over x ≥ 0 of |s·A − 2$^{-x}$|")
    left.set_title("Constants on pins 19/20 by minimax search (peak exact)", fontsize=10)
    left.grid(alpha=0.3, which="both")
    left.legend(fontsize=9)
    for name, colour in (("patent", "tab:blue"), ("minimax-half", "tab:purple"),
                         ("minimax", "tab:pink")):
        sel = e["constants"] == name
        right.plot(e["n"][sel], e["device_energy"][sel] - 1.0, lw=1.2, color=colour,
                   label="device-energy, constants %s" % name)
    worst = max(np.max(np.abs(e["device_energy"] - 1.0)), 1e-6)
    right.set_xscale("log")
    right.set_ylim(-1.5 * worst, 1.5 * worst)
    right.set_xlabel("n")
    right.set_ylabel("equation-6 integral of multiplier 39 − 1")
    right.set_title("Normalisation device-energy: the device reflects what it receives\n"
                    "(largest |integral − 1| = %.1e; the bound 0.1 %% is %.0f× off this scale)"
                    % (worst, 1e-3 / (1.5 * worst)), fontsize=10)
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=9)
    fig.tight_layout()
    save(fig, out_dir, "constants.png")


def main(argv):
    if len(argv) > 3 or (len(argv) > 1 and argv[1] in ("-h", "--help")):
        sys.stdout.write(__doc__)
        return 0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2
    study = argv[1] if len(argv) > 1 else "study-output"
    out_dir = argv[2] if len(argv) > 2 else os.path.join("docs", "study")
    if not os.path.isdir(study):
        fail("no study directory '%s' (run specular_study --out %s first)" % (study, study))
    os.makedirs(out_dir, exist_ok=True)
    plt.rcParams.update({"font.size": 9})
    plot_lobes_and_errors(study, out_dir)
    plot_max_error(study, out_dir)
    plot_energy(study, out_dir)
    plot_heatmaps(study, out_dir)
    plot_spheres(study, out_dir)
    plot_widths(study, out_dir)
    plot_constants(study, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
