#!/usr/bin/env python3
"""The transaction-level energy model's fit to the gate-level energies (issue 61,
docs/energy/calibration.md).

    scripts/flows/energy/model/fit.py [--features-tool PATH] [--data DIR] [--header FILE]
                                [--report FILE] [--json FILE] [--work DIR]

For each stream of DATA/streams/ it runs tools/energy_features/specular_energy_features
(the features of each operation, from the C++ the model charges with) and reads the
gate-level energy of each operation from DATA/<top>/<stream>.tsv (energy.sh --per-result)
for the synchronous device (specular_device_sync) and the drawn one (specular_device).
Per device it fits an operation's pJ = sum of coefficient x feature over the train_*
streams by non-negative least squares (a feature is a count of toggles: a negative energy
per toggle is unphysical; the intercept, feature "one", is free), each stream's first
operation left out (its registers before are the testbench's reset and own operations, not
the model's reset state). The bus figures come from DATA/energy_ip.json
(scripts/flows/energy/energy_ip.sh): a read's and a write's energy beyond the idle clocks they span,
and the idle clock.

Writes --header (modules/include/specular/energy/calibration.h), --report (markdown: the
fit table and the accuracy table over the test_* streams, which the fit never reads) and
--json (the figures, for the tests and the picture). Runs on any Python 3, no numpy.
Exit status: 0 written, 1 a tool failed, 2 bad input.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))))  # scripts/
from specular_flows.run import run  # noqa: E402

DEVICES = [("specular_device_sync", "synchronous_device_table", "synchronous device"),
           ("specular_device", "drawn_device_table", "drawn device (Fig. 2)")]

MEAN_WEIGHT = 10.0

# Why each feature carries energy (the fit table's last column).
WHY = {
    "one": "every operation: its clocks on every flip-flop's clock pin and the control unit's sequence",
    "toggles_reg1": "register 1's flip-flops and the pass-1 path of cos into multiplexer 3",
    "toggles_reg2": "register 2: n into multiplexer 4 and ROM 38's address",
    "rom38_read": "n changed: ROM 38 reads a new word (135.4 pJ a read) and multiplier 39 takes it",
    "load": "an operand load (n, R, G or B changed): the load strobes and, in the testbenches, one more clock",
    "toggles_rgb": "registers 10-12 into multipliers 13-15",
    "toggles_mux4": "multiplier 6's second operand switching between h (pin 19) and n",
    "start_reg9": "register 9 from the previous pass 2 to pass 1: its flip-flops and fan-out",
    "start_rom5_reads": "ROM 5 reads from the start to pass 1 written (225.1 pJ a read, and the log2 unit's adder after it)",
    "start_log2": "the log2 unit's output bits that change (into multiplier 6)",
    "start_mul6": "multiplier 6's product bits that change (through inverter 7 and adder 8)",
    "start_mul39": "multiplier 39's product bits that change (new K(n), then pass 1 in register 9)",
    "start_mul_rgb": "multipliers 13-15's product bits that change",
    "end_reg9": "the operation's own pass 2 written: register 9 from pass 1",
    "end_rom5_read": "ROM 5 read again on pass 2's value (select 36 still high)",
    "end_log2": "the log2 unit on pass 2's value",
    "end_mul6": "multiplier 6 on pass 2's value",
    "end_mul39": "multiplier 39 settling on the result K·A",
    "end_mul_rgb": "multipliers 13-15 settling on pins 24-26",
    "prev_end_reg9": "the previous operation's pass 2 written, where the replay's interval holds it",
    "prev_end_rom5_read": "the same, ROM 5's read",
    "prev_end_log2": "the same, the log2 unit",
    "prev_end_mul6": "the same, multiplier 6",
    "prev_end_mul39": "the same, multiplier 39",
    "prev_end_mul_rgb": "the same, multipliers 13-15",
    "start_mul6_activity": "multiplier 6's partial products that move (an operand's toggles times the other's ones, /8): its glitches",
    "start_mul39_activity": "multiplier 39's partial products that move: its glitches",
    "start_mul_rgb_activity": "multipliers 13-15's partial products that move: their glitches",
    "end_mul6_activity": "the same for pass 2 written, multiplier 6",
    "end_mul39_activity": "the same, multiplier 39",
    "end_mul_rgb_activity": "the same, multipliers 13-15",
    "prev_end_mul6_activity": "the previous operation's pass 2 written, multiplier 6",
    "prev_end_mul39_activity": "the same, multiplier 39",
    "prev_end_mul_rgb_activity": "the same, multipliers 13-15",
    "idle_rom5_read": "Fig. 2 between operations: register 1 on ROM 5's bus, so a new cos is a read before pass 1",
    "idle_log2": "the same, the log2 unit",
    "idle_mul6": "the same, multiplier 6 (on n)",
    "idle_mul6_activity": "the same, multiplier 6's partial products that move",
    "return_rom5_read": "Fig. 2's select 36 falling after pass 2: ROM 5's bus back from register 9 to register 1, a read",
    "return_log2": "the same, the log2 unit",
    "return_mul6": "the same, multiplier 6 (back to n)",
    "return_mul6_activity": "the same, multiplier 6's partial products that move",
    "prev_return_rom5_read": "the previous operation's return, where the replay's interval holds it",
    "prev_return_log2": "the same, the log2 unit",
    "prev_return_mul6": "the same, multiplier 6",
    "prev_return_mul6_activity": "the same, multiplier 6's partial products that move",
    "ones_norm39": "the result's ones on multiplier 39's output: a lit lobe keeps its fan-out high",
    "ones_out": "the ones on pins 24-26",
}


def die(msg, code=2):
    sys.stderr.write(f"fit.py: {msg}\n")
    raise SystemExit(code)


def read_tsv(path):
    rows = []
    header = None
    for line in open(path):
        if not line.strip():
            continue
        p = line.rstrip("\n").split("\t")
        if line.startswith("#") or header is None and not p[0].lstrip("-").isdigit():
            header = [x.lstrip("# ") for x in p]
            continue
        rows.append([float(x) for x in p])
    return header, rows


def features_of(tool, stream, work):
    out = os.path.join(work, os.path.basename(stream).replace(".txt", ".features.tsv"))
    run([tool, stream, out], "fit.py", f"{tool} {stream}")
    header, rows = read_tsv(out)
    return header[1:], {int(row[0]): row[1:] for row in rows}


def solve(a, b):
    """Gaussian elimination with partial pivoting: a x = b (a square, copied)."""
    n = len(b)
    m = [list(a[i]) + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        if abs(m[p][c]) < 1e-300:
            die("singular normal equations (a feature never varies in the training streams)", 1)
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            if f:
                for k in range(c, n + 1):
                    m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def nnls(g, h, free):
    """Lawson and Hanson's active-set non-negative least squares on the normal equations
    (g = X'X, h = X'y): min |X w - y|^2 with w_i >= 0 for i not in `free`."""
    n = len(h)
    ridge = 1e-12 * max(g[i][i] for i in range(n))

    def sub(p):
        idx = sorted(p)
        z = solve([[g[i][j] + (ridge if i == j else 0.0) for j in idx] for i in idx], [h[i] for i in idx])
        full = [0.0] * n
        for i, v in zip(idx, z):
            full[i] = v
        return full

    passive = set(free)
    x = sub(passive) if passive else [0.0] * n
    for _ in range(10 * n):
        w = [h[i] - sum(g[i][j] * x[j] for j in range(n)) for i in range(n)]
        cand = [i for i in range(n) if i not in passive and w[i] > 1e-9 * (abs(h[i]) + 1)]
        if not cand:
            break
        passive.add(max(cand, key=lambda i: w[i]))
        while True:
            z = sub(passive)
            bad = [i for i in passive if i not in free and z[i] <= 0]
            if not bad:
                x = z
                break
            alpha = min(x[i] / (x[i] - z[i]) for i in bad)
            x = [x[i] + alpha * (z[i] - x[i]) for i in range(n)]
            for i in list(passive):
                if i not in free and x[i] <= 1e-12:
                    passive.discard(i)
                    x[i] = 0.0
    return x


def fmt(v):
    return f"{v:.6g}"


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(here))))  # scripts/flows/energy/model
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--features-tool", default=os.path.join(root, "build", "tools", "energy_features",
                                                            "specular_energy_features"))
    ap.add_argument("--data", default=os.path.join(here, "data"))
    ap.add_argument("--header", help="calibration.h to write")
    ap.add_argument("--report", help="the fit and accuracy tables (markdown)")
    ap.add_argument("--json", help="the figures")
    ap.add_argument("--work", default=None, help="folder for the features' TSVs (default: beside --json, or .)")
    a = ap.parse_args()
    if not os.access(a.features_tool, os.X_OK):
        die(f"specular_energy_features not found at '{a.features_tool}' "
            "(cmake --build build --target specular_energy_features, or --features-tool PATH)")
    work = a.work or (os.path.dirname(os.path.abspath(a.json)) if a.json else ".")
    os.makedirs(work, exist_ok=True)
    sdir = os.path.join(a.data, "streams")
    names = sorted(f[:-4] for f in os.listdir(sdir) if f.endswith(".txt"))
    train = [s for s in names if s.startswith("train_")]
    test = [s for s in names if s.startswith("test_")]
    if not train or not test:
        die(f"{sdir}: no train_* or no test_* streams")
    feats = {}
    feature_names = None
    for s in names:
        fn, rows = features_of(a.features_tool, os.path.join(sdir, s + ".txt"), work)
        if feature_names is not None and fn != feature_names:
            die("the feature tool's columns changed between streams", 1)
        feature_names, feats[s] = fn, rows
    nf = len(feature_names)
    if feature_names[0] != "one":
        die(f"the first feature is '{feature_names[0]}', not the intercept 'one'", 1)

    def gate(top, s):
        path = os.path.join(a.data, top, s + ".tsv")
        if not os.path.exists(path):
            return None
        _, rows = read_tsv(path)
        d = {int(r[0]): r[1] for r in rows}
        if len(d) != len(feats[s]):
            die(f"{path}: {len(d)} operations, the stream {len(feats[s])}")
        return d

    out = {"features": feature_names, "train": train, "test": test, "devices": {}}
    for top, table, label in DEVICES:
        g = [[0.0] * nf for _ in range(nf)]
        h = [0.0] * nf
        ys, xs = [], []
        for s in train:
            e = gate(top, s)
            if e is None:
                die(f"no gate-level data {a.data}/{top}/{s}.tsv")
            ks = sorted(e)[1:]
            for k in ks:
                x, y = feats[s][k], e[k]
                xs.append(x)
                ys.append(y)
                for i in range(nf):
                    h[i] += x[i] * y
                    for j in range(nf):
                        g[i][j] += x[i] * x[j]
            # Each stream's mean as one more row, weighted MEAN_WEIGHT times its operations:
            # the workload's mean is what the model must get right (within 3 %), the single
            # operation's error only reported.
            wm = MEAN_WEIGHT * len(ks)
            xm = [sum(feats[s][k][i] for k in ks) / len(ks) for i in range(nf)]
            ym = sum(e[k] for k in ks) / len(ks)
            for i in range(nf):
                h[i] += wm * xm[i] * ym
                for j in range(nf):
                    g[i][j] += wm * xm[i] * xm[j]
        w = nnls(g, h, set())
        my = sum(ys) / len(ys)
        mx = [sum(x[i] for x in xs) / len(xs) for i in range(nf)]
        res = [y - sum(wi * xi for wi, xi in zip(w, x)) for x, y in zip(xs, ys)]
        dev = {"table": table, "label": label, "coefficients": w, "train_operations": len(ys),
               "train_mean_pj": my, "train_feature_means": mx,
               "train_rms_pj": math.sqrt(sum(r * r for r in res) / len(res)),
               "train_sd_pj": math.sqrt(sum((y - my) ** 2 for y in ys) / len(ys)), "streams": {}}
        for s in names:
            e = gate(top, s)
            if e is None:
                continue
            ks = sorted(e)[1:]
            model = {k: sum(wi * xi for wi, xi in zip(w, feats[s][k])) for k in ks}
            gm = sum(e[k] for k in ks) / len(ks)
            mm = sum(model.values()) / len(ks)
            err = [model[k] - e[k] for k in ks]
            dev["streams"][s] = {"operations": len(ks), "gate_mean_pj": gm, "model_mean_pj": mm,
                                 "mean_error": mm / gm - 1,
                                 "rms_error_pj": math.sqrt(sum(x * x for x in err) / len(err)),
                                 "worst_error_pj": max(err, key=abs),
                                 "gate_sd_pj": math.sqrt(sum((e[k] - gm) ** 2 for k in ks) / len(ks))}
            if s == "grid":
                dev["grid"] = [[feats[s][k], e[k], model[k]] for k in ks if k % 2 == 1]
        out["devices"][top] = dev

    ip_path = os.path.join(a.data, "energy_ip.json")
    ip = json.load(open(ip_path)) if os.path.exists(ip_path) else None
    bus = None
    if ip:
        kinds = ip["per_access"]
        bus = {"read_pj": kinds["read"]["beyond_idle_clocks_pj"],
               "write_pj": kinds["write"]["beyond_idle_clocks_pj"],
               "idle_clock_pj": kinds["idle"]["total_pj"],
               "operation_pj": kinds["operation"]["total_pj"],
               "operation_clocks": kinds["operation"]["clocks_per_access"],
               "operation_beyond_idle_pj": kinds["operation"]["beyond_idle_clocks_pj"]}
        out["bus"] = bus
        # The IP's operation through the registers (energy_ip.sh): five operand writes,
        # START (a write) and three result reads over 28 clocks, on the common stream's
        # random operands (train_common from line 18), charged as the model charges it.
        sync = out["devices"]["specular_device_sync"]
        ks = [k for k in sorted(feats["train_common"]) if k >= 18]
        w = sync["coefficients"]
        op = sum(sum(wi * xi for wi, xi in zip(w, feats["train_common"][k])) for k in ks) / len(ks)
        charged = bus["operation_clocks"] * bus["idle_clock_pj"] + 6 * bus["write_pj"] + 3 * bus["read_pj"] + op
        out["ip_accounting"] = {"operation_model_pj": op, "writes": 6, "reads": 3,
                                "charged_pj": charged, "gate_level_pj": bus["operation_pj"],
                                "error": charged / bus["operation_pj"] - 1}

    if a.header:
        lines = [
            "/// \\file",
            "/// The energy model's coefficients: GENERATED by scripts/flows/energy/model/fit.py from the",
            "/// gate-level data in scripts/flows/energy/model/data/; do not edit (test",
            "/// energy_calibration_current makes it again and compares). docs/energy/calibration.md",
            "/// has the fit and its accuracy on streams the fit never saw.",
            "///",
            "/// Per device an operation's pJ = sum of pj_per_feature[i] x feature[i] (the features of",
            "/// operation_features.h), fitted by non-negative least squares to each operation's",
            "/// gate-level energy (SDF replay at 50 ns, OSU 0.18 um, typical corner: scripts/flows/energy/energy.sh",
            f"/// --per-result) over the streams {', '.join(train)}",
            f"/// ({out['devices'][DEVICES[0][0]]['train_operations']} operations). The bus figures: "
            "specular_ip_axi's replays",
            "/// (scripts/flows/energy/energy_ip.sh; the method in docs/rtl_ip/mutants_silicon.md, \"Silicon cost\").",
            "#pragma once",
            "",
            "#include \"specular/energy/operation_features.h\"",
            "",
            "namespace specular::energy {",
            "",
            "/// One gate-level device's fit: an operation's pJ = Σ pj_per_feature[i] · feature[i].",
            "struct CalibrationTable {",
            "  const char* device;                           ///< the gate-level top the data came from",
            "  std::array<double, feature_count> pj_per_feature;  ///< in the order of feature_names",
            "};",
            "",
            "/// specular_ip_axi's bus (issue 46): the energy of an access beyond the idle clocks it",
            "/// spans, and one clock of the IP with the bus idle (clock pins, clock net, leakage).",
            "struct BusTable {",
            "  double read_pj;        ///< a register read, beyond its 2 idle clocks",
            "  double write_pj;       ///< a register write, beyond its 3 idle clocks",
            "  double idle_clock_pj;  ///< one clock with the bus idle",
            "};",
            "",
        ]
        docs = {"specular_device_sync": "/// The synchronous device (specular_device_sync): the IP's datapath.",
                "specular_device": "/// The drawn device of Fig. 2 (specular_device)."}
        for top, table, _ in DEVICES:
            w = out["devices"][top]["coefficients"]
            lines.append(docs[top])
            lines.append(f"inline constexpr CalibrationTable {table}{{")
            lines.append(f"    \"{top}\",")
            lines.append("    {" + ", ".join(f"{fmt(v)}  /* {n} */" if False else fmt(v) for v, n in zip(w, feature_names)) + "}};")
            lines.append("/// " + ", ".join(feature_names))
        if bus is None:
            die(f"{ip_path}: not found (scripts/flows/energy/energy_ip.sh's energy_ip.json)")
        lines += ["/// specular_ip_axi's register accesses and idle clock.",
                  f"inline constexpr BusTable bus_table{{{fmt(bus['read_pj'])}, {fmt(bus['write_pj'])}, "
                  f"{fmt(bus['idle_clock_pj'])}}};", "", "}  // namespace specular::energy", ""]
        open(a.header, "w").write("\n".join(lines))

    if a.json:
        json.dump(out, open(a.json, "w"), indent=1)

    if a.report:
        r = []
        for top, _, label in DEVICES:
            d = out["devices"][top]
            r += [f"### Fit: {label}, {top}", "",
                  f"{d['train_operations']} operations of {', '.join(train)}; mean {d['train_mean_pj']:.0f} pJ, "
                  f"standard deviation {d['train_sd_pj']:.0f} pJ; the fit's residual RMS {d['train_rms_pj']:.0f} pJ.", "",
                  "| feature | pJ per unit | mean per operation | share of the mean energy | why it costs |",
                  "|---|---:|---:|---:|---|"]
            order = sorted(range(nf), key=lambda i: -d["coefficients"][i] * d["train_feature_means"][i])
            for i in order:
                c, m, n = d["coefficients"][i], d["train_feature_means"][i], feature_names[i]
                if c > 0:
                    r.append(f"| {n} | {c:.2f} | {m:.2f} | {100 * c * m / d['train_mean_pj']:.1f} % | {WHY.get(n, '')} |")
            zero = [feature_names[i] for i in range(nf) if d["coefficients"][i] <= 0]
            r += ["", f"Held at 0 by the fit ({len(zero)} of {nf}): {', '.join(zero)}.", ""]
        r += ["### Accuracy on the streams", "",
              "| device | stream | operations | gate level (pJ) | model (pJ) | mean error | per-operation RMS error (pJ) | worst (pJ) | gate-level s.d. (pJ) |",
              "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
        for top, _, label in DEVICES:
            for s, v in out["devices"][top]["streams"].items():
                r.append(f"| {label} | {s}{' (fitted)' if s in train else ''} | {v['operations']} | {v['gate_mean_pj']:.0f} | "
                         f"{v['model_mean_pj']:.0f} | {100 * v['mean_error']:+.2f} % | {v['rms_error_pj']:.0f} "
                         f"({100 * v['rms_error_pj'] / v['gate_mean_pj']:.0f} %) | {v['worst_error_pj']:+.0f} | {v['gate_sd_pj']:.0f} |")
        r.append("")
        if bus:
            ia = out["ip_accounting"]
            r += [f"### The IP's operation through the registers", "",
                  f"{bus['operation_clocks']:g} idle clocks x {bus['idle_clock_pj']:.1f} pJ + 6 writes x "
                  f"{bus['write_pj']:.1f} pJ + 3 reads x {bus['read_pj']:.1f} pJ + the operation "
                  f"{ia['operation_model_pj']:.0f} pJ (the model's mean over the same operands) = "
                  f"{ia['charged_pj']:.0f} pJ against {ia['gate_level_pj']:.0f} pJ at gate level: "
                  f"{100 * ia['error']:+.1f} %.", ""]
        open(a.report, "w").write("\n".join(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
