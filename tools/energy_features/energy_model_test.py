#!/usr/bin/env python3
"""The energy model's tests (issue 61, docs/energy/calibration.md); ctest runs each in its
own scratch folder.

    energy_model_test.py features TOOL SCRATCH
        the feature tool on two operations against Hamming distances counted here from the
        register values (specular_tb --format csv's reg9 and pin columns for the same operands)
    energy_model_test.py calibration_current TOOL SCRATCH SOURCE_DIR
        fit.py on the committed data into SCRATCH: its calibration.h must equal the
        committed modules/include/specular/energy/calibration.h
    energy_model_test.py accuracy TOOL SCRATCH SOURCE_DIR
        the model as compiled (TOOL --model: OperationEnergy with the committed calibration)
        on every test_* stream: its mean within 3 % of the committed gate-level mean, both
        calibrations
"""
import os
import subprocess
import sys

DEVICES = {"specular_device_sync": "pj_synchronous", "specular_device": "pj_drawn"}


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"FAIL: {' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def table(path):
    lines = [l.rstrip("\n").split("\t") for l in open(path) if l.strip()]
    head = [h.lstrip("# ") for h in lines[0]]
    return [dict(zip(head, row)) for row in lines[1:]]


def pop(x):
    return bin(x).count("1")


def features(tool, scratch):
    # 1.0, n 1, R G B ff 00 80; then 0.5, n 2, ff ff ff. Registers after each, from
    # specular_tb --format csv (reg1_hex, reg9_pass1_hex, reg9_pass2_hex, pin24-26_hex):
    #   0x10000, 0x400000, 0x400000, (0x42c23b, 0x0, 0x2182a0)
    #   0x08000, 0xc00000, 0x0d47fc, (0x0a63ec, 0x0a63ec, 0x0a63ec)
    # From the registers after reset (all 0).
    stream = os.path.join(scratch, "two.txt")
    open(stream, "w").write("10000 001 ff 00 80\n08000 002 ff ff ff\n")
    # ROM 5's address of a bus code: its leading one's place and the bits after it, so
    # two codes read the same word only if both match; 1.0 on the bus is 0x400000
    # (register 9's S14.22), cos's U1.16 code shifted 6 places.
    want = [
        {"one": 1, "toggles_reg2": pop(1), "rom38_read": 1, "toggles_rgb": pop(0xff) + pop(0x00) + pop(0x80),
         # pass 1 and pass 2 both 0x400000: the same address
         "end_rom5_read": 0,
         # pass 2 0x400000 back to cos 1.0 << 6 = 0x400000: no read
         "return_rom5_read": 0,
         # from reset: pass 2 0 and cos 0, both the zero entry
         "prev_return_rom5_read": 0,
         # between operations: cos 0 (the zero entry) to 1.0 (0x400000)
         "idle_rom5_read": 1,
         "ones_out": pop(0x42c23b) + pop(0) + pop(0x2182a0)},
        {"one": 1, "toggles_reg2": pop(1 ^ 2), "rom38_read": 1,
         "toggles_rgb": pop(0xff ^ 0xff) + pop(0x00 ^ 0xff) + pop(0x80 ^ 0xff),
         # pass 1 0xc00000 (leading one bit 23), pass 2 0x0d47fc (bit 19)
         "end_rom5_read": 1,
         # pass 2 0x0d47fc back to cos 0.5 << 6 = 0x200000 (bit 21)
         "return_rom5_read": 1,
         "prev_return_rom5_read": 0,
         # cos 1.0 (bit 22) to 0.5 (bit 21)
         "idle_rom5_read": 1,
         "ones_out": 3 * pop(0x0a63ec)},
    ]
    # the same n again, R, G, B to 0: no ROM 38 read, no toggle of register 2
    open(stream, "a").write("08000 002 00 00 00\n")
    want.append({"toggles_reg2": 0, "rom38_read": 0, "toggles_rgb": 3 * 8, "end_rom5_read": 1,
                 "idle_rom5_read": 0, "prev_return_rom5_read": 1, "ones_out": 0})
    # and again: nothing loads
    open(stream, "a").write("08000 002 00 00 00\n")
    want.append({"toggles_reg2": 0, "rom38_read": 0, "toggles_rgb": 0, "idle_rom5_read": 0})
    rows = table_from(run([tool, stream]))
    bad = []
    for k, w in enumerate(want):
        for name, v in w.items():
            if float(rows[k][name]) != v:
                bad.append(f"operation {k} {name}: tool {rows[k][name]}, counted {v}")
    if bad:
        raise SystemExit("FAIL: " + "; ".join(bad))
    print(f"PASS: {sum(len(w) for w in want)} feature values of {len(want)} operations")


def table_from(text):
    lines = [l.split("\t") for l in text.splitlines() if l.strip()]
    return [dict(zip(lines[0], row)) for row in lines[1:]]


def calibration_current(tool, scratch, src):
    header = os.path.join(scratch, "calibration.h")
    run([sys.executable, os.path.join(src, "scripts", "flows", "energy", "model", "fit.py"), "--features-tool", tool,
         "--header", header, "--work", scratch])
    committed = os.path.join(src, "modules", "include", "specular", "energy", "calibration.h")
    if open(header).read() != open(committed).read():
        diff = subprocess.run(["diff", committed, header], capture_output=True, text=True).stdout
        raise SystemExit(f"FAIL: {committed} is not what fit.py makes from the committed data "
                         f"(scripts/flows/energy/model/fit.py --header ...):\n{diff}")
    print("PASS: calibration.h is fit.py's output on the committed data")


def accuracy(tool, scratch, src):
    data = os.path.join(src, "scripts", "flows", "energy", "model", "data")
    streams = sorted(f[:-4] for f in os.listdir(os.path.join(data, "streams")) if f.startswith("test_"))
    if len(streams) < 3:
        raise SystemExit(f"FAIL: {len(streams)} test streams, expected at least 3")
    bad, lines = [], []
    for s in streams:
        out = os.path.join(scratch, s + ".model.tsv")
        run([tool, "--model", os.path.join(data, "streams", s + ".txt"), out])
        model = table(out)
        for top, col in DEVICES.items():
            gate = table(os.path.join(data, top, s + ".tsv"))
            if len(gate) != len(model):
                bad.append(f"{top} {s}: {len(gate)} gate-level operations, {len(model)} in the stream")
                continue
            # the first operation left out, as the fit does (the testbench's registers before it)
            g = sum(float(r["pj"]) for r in gate[1:]) / (len(gate) - 1)
            m = sum(float(r[col]) for r in model[1:]) / (len(model) - 1)
            lines.append(f"{top} {s}: gate level {g:.1f} pJ, model {m:.1f} pJ, {100 * (m / g - 1):+.2f} %")
            if abs(m / g - 1) > 0.03:
                bad.append(lines[-1])
    print("\n".join(lines))
    if bad:
        raise SystemExit("FAIL: more than 3 % off: " + "; ".join(bad))
    print(f"PASS: {len(lines)} workload means within 3 %")


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    cmd, tool, scratch = sys.argv[1:4]
    os.makedirs(scratch, exist_ok=True)
    if cmd == "features":
        features(tool, scratch)
    elif cmd == "calibration_current":
        calibration_current(tool, scratch, sys.argv[4])
    elif cmd == "accuracy":
        accuracy(tool, scratch, sys.argv[4])
    else:
        raise SystemExit(f"unknown test '{cmd}'")
    return 0


if __name__ == "__main__":
    sys.exit(main())
