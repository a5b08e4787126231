#!/usr/bin/env python3
"""The operand streams of the transaction-level energy model's fit and of its check (issue 61).

    scripts/flows/energy/model/streams.py [--vectors-tool PATH] [--check] OUT_DIR

Writes OUT_DIR/NAME.txt per stream: one operation a line, `cos n r g b` in hex (the format
of gatesim.sh --stimulus and of specular_variant_vectors: cos a 17-bit code, 0x10000 = 1;
n 1-1000; R, G, B 0-255). Deterministic: the same files every run (--check compares
against OUT_DIR's and exits 1 on a difference).

  train_common   the common energy stream: specular_variant_vectors patent --count 318
                 --seed 1 (18 edge cases, 300 random operands); the one stream that needs
                 the tool
  train_walk     low activity: cos random walks with steps of 2^0 to 2^12 codes, n and
                 R, G, B held over runs of 25-60 operations
  train_lobes    the lobe lit: cos random walks (steps of 2^0 to 2^10 codes) from cos^n
                 uniform on (0.05, 1), n log-uniform on 1-300, n and R, G, B held over runs
                 of 20-50 operations (non-zero results that change a little at a time)
  train_cos      cos only: n (log-uniform on 1-1000) and R, G, B held over runs of 30-60
                 operations, cos uniform or p^(1/n) for p uniform (half each)
  train_changes  one kind of change at a time: the same operation repeated, cos only, n
                 only, R, G, B only (all or one channel), cos 0 and 1
  test_random    random operands of another seed (specular_variant_vectors --seed 2, its
                 300 random operands: its 18 edge cases are train_common's)
  test_sphere    two shaded spheres in raster order: cos = N.H over each disc (radius 8.5
                 pixels), a fixed n and colour per sphere, 432 pixels
  test_sweep     constant n (60) and colour, cos = cos(theta) with theta swept from -0.5
                 to 0.5 rad through the highlight, 300 operations
  grid           16 cos x 16 n (cos k/15, n 1000^(j/15)), each point preceded by the same
                 reference operation (cos 0.5, n 32) at the same colour: a point's energy
                 depends on (cos, n) only

The fit (fit.py) reads the train_* streams only; the test_* streams and grid are never fitted.
"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))))  # scripts/
from specular_flows.run import run  # noqa: E402

ONE = 1 << 16


def code(c):
    return max(0, min(ONE, int(round(c * ONE))))


def line(cos_code, n, r, g, b):
    return f"{cos_code:05x} {n:03x} {r:02x} {g:02x} {b:02x}"


def from_tool(tool, seed, count, skip):
    r = run([tool, "patent", "--count", str(count), "--seed", str(seed), "--out", "/dev/stdout"], "streams.py")
    rows = [" ".join(l.split()[:5]) for l in r.stdout.splitlines() if l.strip()]
    if len(rows) != count:
        raise SystemExit(f"streams.py: {tool} wrote {len(rows)} operations, not {count}")
    return rows[skip:]


def walk(rng, count):
    out = []
    while len(out) < count:
        n = rng.randint(1, 1000)
        rgb = [rng.randint(0, 255) for _ in range(3)]
        c = rng.randint(0, ONE)
        for _ in range(rng.randint(25, 60)):
            if len(out) == count:
                break
            c = max(0, min(ONE, c + rng.choice((-1, 1)) * (1 << rng.randint(0, 12))))
            out.append(line(c, n, *rgb))
    return out


def lobe_walk(rng, count):
    out = []
    while len(out) < count:
        n = int(round(math.exp(rng.uniform(0.0, math.log(300.0)))))
        rgb = [rng.randint(0, 255) for _ in range(3)]
        c = code(rng.uniform(0.05, 1.0) ** (1.0 / n))
        for _ in range(rng.randint(20, 50)):
            if len(out) == count:
                break
            c = max(0, min(ONE, c + rng.choice((-1, 1)) * (1 << rng.randint(0, 10))))
            out.append(line(c, n, *rgb))
    return out


def cos_jumps(rng, count):
    out = []
    while len(out) < count:
        n = int(round(math.exp(rng.uniform(0.0, math.log(1000.0)))))
        rgb = [rng.randint(0, 255) for _ in range(3)]
        for _ in range(rng.randint(30, 60)):
            if len(out) == count:
                break
            c = rng.randint(0, ONE) if rng.random() < 0.5 else code(rng.random() ** (1.0 / n))
            out.append(line(c, n, *rgb))
    return out


def changes(rng, count):
    out = []
    c, n, rgb = rng.randint(0, ONE), rng.randint(1, 1000), [rng.randint(0, 255) for _ in range(3)]
    kinds = ["repeat", "cos", "n", "rgb", "channel", "cos0", "cos1", "all"]
    while len(out) < count:
        kind = kinds[len(out) // 5 % len(kinds)] if len(out) < 80 else rng.choice(kinds)
        if kind == "cos":
            c = rng.randint(0, ONE)
        elif kind == "n":
            n = rng.randint(1, 1000)
        elif kind == "rgb":
            rgb = [rng.randint(0, 255) for _ in range(3)]
        elif kind == "channel":
            rgb[rng.randint(0, 2)] = rng.randint(0, 255)
        elif kind == "cos0":
            c = 0
        elif kind == "cos1":
            c = ONE
        elif kind == "all":
            c, n, rgb = rng.randint(0, ONE), rng.randint(1, 1000), [rng.randint(0, 255) for _ in range(3)]
        out.append(line(c, n, *rgb))
    return out


def sphere():
    h = (0.3, 0.4, 1.0)
    norm = math.sqrt(sum(x * x for x in h))
    h = tuple(x / norm for x in h)
    radius, width, height = 8.5, 36, 18
    materials = [((9, 9), 20, (230, 80, 40)), ((27, 9), 200, (60, 140, 255))]
    out = []
    for y in range(height):
        for x in range(width):
            for (cx, cy), n, rgb in materials:
                dx, dy = (x + 0.5 - cx) / radius, (cy - y - 0.5) / radius
                d2 = dx * dx + dy * dy
                if d2 <= 1.0:
                    nz = math.sqrt(1.0 - d2)
                    cos = max(0.0, dx * h[0] + dy * h[1] + nz * h[2])
                    out.append(line(code(cos), n, *rgb))
    return out


def sweep():
    return [line(code(math.cos(-0.5 + k / 299)), 60, 255, 200, 160) for k in range(300)]


def grid():
    out = []
    ref = line(code(0.5), 32, 200, 150, 100)
    for j in range(16):
        n = int(round(1000 ** (j / 15)))
        for k in range(16):
            out.append(ref)
            out.append(line(code(k / 15), n, 200, 150, 100))
    return out


def streams(tool):
    return {
        "train_common": from_tool(tool, 1, 318, 0),
        "train_walk": walk(random.Random(61), 250),
        "train_changes": changes(random.Random(62), 250),
        "train_lobes": lobe_walk(random.Random(63), 250),
        "train_cos": cos_jumps(random.Random(64), 250),
        "test_random": from_tool(tool, 2, 318, 18),
        "test_sphere": sphere(),
        "test_sweep": sweep(),
        "grid": grid(),
    }


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out_dir")
    ap.add_argument("--vectors-tool", default=os.path.join(
        here, "..", "..", "..", "..", "build", "tools", "variant_vectors", "specular_variant_vectors"))
    ap.add_argument("--check", action="store_true", help="compare with OUT_DIR's files, write nothing")
    a = ap.parse_args()
    if not os.access(a.vectors_tool, os.X_OK):
        sys.stderr.write(f"streams.py: specular_variant_vectors not found at '{a.vectors_tool}' (--vectors-tool PATH)\n")
        return 2
    differ = []
    for name, rows in streams(a.vectors_tool).items():
        text = "\n".join(rows) + "\n"
        path = os.path.join(a.out_dir, name + ".txt")
        if a.check:
            if not os.path.exists(path) or open(path).read() != text:
                differ.append(name)
        else:
            os.makedirs(a.out_dir, exist_ok=True)
            open(path, "w").write(text)
            print(f"{name}: {len(rows)} operations")
    if differ:
        sys.stderr.write("streams.py: differ from the committed streams: " + ", ".join(differ) + "\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
