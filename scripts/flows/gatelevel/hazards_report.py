#!/usr/bin/env python3
"""Fig. 2's hazards from the gate-level runs of scripts/flows/gatelevel/gatesim.sh --hazards.

  hazards_report.py OUT_DIR T_SIM_NS

Reads OUT_DIR/hazards/T<period>/ (sweep.txt: start offset in periods and 1 pass / 0 fail;
boundaries.txt: each pass/fail boundary refined to 0.1 ns; x<offset>.log: the
testbench's and the hazard probe's output) and OUT_DIR/icarus.sdf (flip-flop 41's
recovery, removal and reset pulse width checks, the DFFPOSX1 clock pulse width), and
writes OUT_DIR/hazards.md and OUT_DIR/hazards.json.
"""
import glob
import json
import os
import re
import sys


def sdf_check(sdf, instance, pattern):
    """The (typ) value of the first TIMINGCHECK line matching pattern in instance's CELL."""
    start = sdf.find(f"(INSTANCE {instance})")
    if start < 0:
        return None
    end = sdf.find("(CELL", start)
    m = re.search(pattern + r"\s*\((-?[\d.]+):(-?[\d.]+):(-?[\d.]+)\)", sdf[start:end])
    return float(m.group(3)) if m else None


def hazard_line(log_path):
    lines = [l for l in open(log_path).read().splitlines() if l.startswith("HAZARD")]
    if not lines:
        return None
    f = lines[-1].split()[1:]
    return {
        "select36_after_clk_fall_ns": [float(f[1]), float(f[2])],
        "reset41_pulses": int(f[6]), "reset41_narrowest_ns": float(f[8]),
        "reset41_widest_ns": float(f[10]), "reset41_not_cleared": int(f[12]),
        "recovery_margin_ns": float(f[14]), "removal_margin_ns": float(f[16]),
        "setup42_margin_ns": float(f[18]), "reg9_d_settle_ns": float(f[20]),
    }


def first_failure(log_path):
    for line in open(log_path).read().splitlines():
        if re.search(r"MISMATCH|fatal|FATAL|specular_device_tb:", line) and "PASS" not in line:
            return re.sub(r"^.*?specular_device_tb: ", "", line).strip()
    return "no result"


def main():
    out, t_sim = sys.argv[1], float(sys.argv[2])
    sdf = open(f"{out}/icarus.sdf").read()
    inst = r"cu16/dff41__cell"
    checks = {
        "dffsr_recovery_ns": sdf_check(sdf, inst, r"RECOVERY \(COND D\\&S \(posedge R\)\) \(COND D\\&S \(posedge CLK\)\)"),
        "dffsr_removal_ns": sdf_check(sdf, inst, r"REMOVAL \(COND D\\&S \(posedge R\)\) \(COND D\\&S \(posedge CLK\)\)"),
        "dffsr_reset_min_width_ns": sdf_check(sdf, inst, r"WIDTH \(negedge R\)"),
    }
    periods = {}
    for d in sorted(glob.glob(f"{out}/hazards/T*"), key=lambda p: float(p.rsplit("T", 1)[1])):
        T = float(d.rsplit("T", 1)[1])
        sweep = {}
        for line in open(f"{d}/sweep.txt"):
            x, ok = line.split()
            sweep[float(x)] = ok == "1"
        bounds = []
        if os.path.exists(f"{d}/boundaries.txt"):
            for line in open(f"{d}/boundaries.txt"):
                _, a, b, a_ok = line.split()
                bounds.append((float(a), float(b), a_ok == "1"))
        # Failing windows: runs of failing offsets in offset order, widened to the refined
        # boundary on each side (the last passing offset of the refinement).
        xs = sorted(sweep)
        windows, run = [], None
        for x in xs:
            if not sweep[x]:
                run = [x, x] if run is None else [run[0], x]
            elif run is not None:
                windows.append(run)
                run = None
        if run is not None:
            windows.append(run)
        result = []
        for lo, hi in windows:
            # The refinement keeps a on its own side: a pass->fail boundary (a passes)
            # ends in the window's first failing offset b, a fail->pass one starts at
            # its last failing offset a.
            lo_ref = min([b for a, b, a_ok in bounds
                          if a_ok and lo - 1 / 16 - 1e-9 <= a and b <= lo + 1e-9] or [lo])
            hi_ref = max([a for a, b, a_ok in bounds
                          if not a_ok and hi - 1e-9 <= a and b <= hi + 1 / 16 + 1e-9] or [hi])
            result.append({
                "from_periods": round(lo_ref, 4), "to_periods": round(hi_ref, 4),
                "from_ns": round(lo_ref * T, 2), "to_ns": round(hi_ref * T, 2),
                "first_failure": first_failure(f"{d}/x{lo:.6f}.log"),
            })
        # The 16 offsets of the sweep (multiples of T/16); the rest are refinements.
        coarse = [x for x in sweep if abs(x * 16 - round(x * 16)) < 1e-6]
        base = f"{d}/x0.000000.log"
        strobes = re.search(r"strobes: 37 (\d+) pulses \(narrowest ([\d.]+) ns\), 35 (\d+) pulses \(narrowest ([\d.]+) ns\)",
                            open(base).read())
        periods[f"{T:g}"] = {
            "period_ns": T,
            "offsets_run": len(coarse),
            "offsets_failing": sum(1 for x in coarse if not sweep[x]),
            "failing_windows": result,
            "at_offset_0": hazard_line(base),
            "strobe37_pulses": int(strobes.group(1)) if strobes else None,
            "strobe37_narrowest_ns": float(strobes.group(2)) if strobes else None,
            "pin35_pulses": int(strobes.group(3)) if strobes else None,
            "pin35_narrowest_ns": float(strobes.group(4)) if strobes else None,
        }
    summary = {"t_sim_ns": t_sim, "flip_flop41_checks": checks, "periods": periods}
    with open(f"{out}/hazards.json", "w") as f:
        json.dump(summary, f, indent=1)

    with open(f"{out}/hazards.md", "w") as f:
        w = f.write
        w("# Fig. 2's hazards in the gate-level simulation\n\n")
        w(f"scripts/flows/gatelevel/gatesim.sh --hazards {t_sim:g}: the mapped netlist with the SDF delays, "
          "start (27) swept over a whole period around the rising clock edge it is timed "
          "from (16 offsets from -T/2 to 7T/16 and 0.499 T, each pass/fail boundary refined to 0.1 ns).\n\n")
        w("Flip-flop 41 (DFFSR) from the SDF: recovery %.3f ns, removal %.3f ns, "
          "minimum reset pulse %.3f ns.\n\n" % (checks["dffsr_recovery_ns"] or 0,
                                                  checks["dffsr_removal_ns"] or 0,
                                                  checks["dffsr_reset_min_width_ns"] or 0))
        w("| period (ns) | start offsets failing | failing window (start after its edge) | first failure there |\n")
        w("|---:|---:|---|---|\n")
        for key, p in periods.items():
            wins = "; ".join(f"{r['from_ns']:+.2f} to {r['to_ns']:+.2f} ns" for r in p["failing_windows"]) or "none"
            fails = "; ".join(r["first_failure"] for r in p["failing_windows"][:1]) or ""
            w(f"| {p['period_ns']:g} | {p['offsets_failing']} of 16 | {wins} | {fails} |\n")
        w("\n| period (ns) | reset pulses of 41 | narrowest (ns) | Q41 not cleared | recovery margin (ns) | removal margin (ns) | select 36 after clk fall (ns) | setup margin Q41 -> 42 (ns) | register 9's D settled after clk fall (ns) |\n")
        w("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for key, p in periods.items():
            h = p["at_offset_0"]
            if h:
                w(f"| {p['period_ns']:g} | {h['reset41_pulses']} | {h['reset41_narrowest_ns']:.2f} | "
                  f"{h['reset41_not_cleared']} | {h['recovery_margin_ns']:.2f} | {h['removal_margin_ns']:.2f} | "
                  f"{h['select36_after_clk_fall_ns'][0]:.2f} | {h['setup42_margin_ns']:.2f} | {h['reg9_d_settle_ns']:.2f} |\n")
        w("\n| period (ns) | pulses of 37 | narrowest 37 (ns) | pulses of 35 | narrowest 35 (ns) |\n")
        w("|---:|---:|---:|---:|---:|\n")
        for key, p in periods.items():
            w(f"| {p['period_ns']:g} | {p['strobe37_pulses']} | {p['strobe37_narrowest_ns']} | "
              f"{p['pin35_pulses']} | {p['pin35_narrowest_ns']} |\n")
    print(open(f"{out}/hazards.md").read())
    return 0


if __name__ == "__main__":
    sys.exit(main())
