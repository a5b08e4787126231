#!/usr/bin/env python3
"""Vectors of scripts/flows/gatelevel/gatesim.sh, as rtl/tb/run_icarus.cmake writes them for the RTL tests.

  gatesim_vectors.py SPECULAR_TB OUT_DIR POLICIES GROUPS RANDOM [STIMULUS]

POLICIES: `all` or comma-separated constants/normalisation/saturation triples. For each
policy specular_tb writes the expected values of GROUPS groups of 10 operations (n, R, G,
B unchanged: back to back at 2 T; the cos edge cases of run_icarus.cmake) and RANDOM
random operations (a reload each). Writes OUT_DIR/vectors_<policy>.csv and
OUT_DIR/policies.txt (name, constants value, normalisation value, literal, file); a
combination the model refuses is left out, as the RTL tests skip it.

STIMULUS (scripts/flows/energy/energy.sh's common stream, issue 36): a file of lines `cos n r g b`, cos
register 1's code (hex U1.16), n, r, g, b hex, as specular_variant_vectors writes them
(its first five columns): these operations, in this order, replace the groups (GROUPS is
then unused and RANDOM must be 0), so that a device top replays a variant's operands.
"""
import subprocess
import sys

CONSTANTS = ["patent", "minimax-half", "minimax"]
NORMALISATIONS = ["patent", "energy", "none", "device-energy"]
SATURATIONS = ["clamp", "literal"]
GROUPS = ["1,255,255,255", "2,0,128,255", "3,1,2,3", "10,255,0,17", "64,200,100,50",
          "500,255,255,255", "999,7,77,177", "1000,255,254,253"]
COSINES = ["0", "1", "0.5", "1.52587890625e-05", "0.9999847412109375", "0.70710678", "0.25",
           "0.999", "0.05", "0.9"]


def main():
    tb, out, policies, groups, random = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
    if policies == "all":
        triples = [(c, n, s) for c in CONSTANTS for n in NORMALISATIONS for s in SATURATIONS]
    else:
        triples = []
        for item in policies.split(","):
            parts = item.split("/")
            if (len(parts) != 3 or parts[0] not in CONSTANTS or parts[1] not in NORMALISATIONS
                    or parts[2] not in SATURATIONS):
                sys.stderr.write(f"gatesim_vectors.py: policy '{item}' is not constants/normalisation/"
                                 f"saturation with constants in {CONSTANTS}, normalisation in "
                                 f"{NORMALISATIONS}, saturation in {SATURATIONS}\n")
                return 2
            triples.append(tuple(parts))
    stimulus = "cos,n,r,g,b\n"
    if len(sys.argv) > 6:
        if random != 0:
            sys.stderr.write(f"gatesim_vectors.py: RANDOM '{random}' with a STIMULUS file: must be 0\n")
            return 2
        for number, line in enumerate(open(sys.argv[6]), 1):
            fields = line.split()
            try:
                cos, n, r, g, b = (int(x, 16) for x in fields[:5])
            except ValueError:
                fields = []
            if len(fields) < 5 or not (0 <= cos <= 1 << 16 and 1 <= n <= 1000 and max(r, g, b) <= 255):
                sys.stderr.write(f"gatesim_vectors.py: {sys.argv[6]}:{number}: '{line.strip()}' is not "
                                 "'cos n r g b' in hex (cos 0..10000, n 1..3e8, r, g, b 0..ff)\n")
                return 2
            # the code as an exact real (a multiple of 2^-16): specular_tb takes it back to the code
            stimulus += f"{cos / 65536!r},{n},{r},{g},{b}\n"
    else:
        for group in GROUPS[:groups]:
            n, rgb = group.split(",", 1)
            for cos in COSINES:
                stimulus += f"{cos},{n},{rgb}\n"
    with open(f"{out}/stimulus.csv", "w") as f:
        f.write(stimulus)
    listing = []
    for constants, normalisation, saturation in triples:
        name = f"{constants}_{normalisation}_{saturation}"
        options = ["--constants", constants, "--policy", normalisation, "--saturation", saturation]
        r = subprocess.run([tb, *options, "--input", f"{out}/stimulus.csv", "--format", "csv",
                            "--output", f"{out}/groups_{name}.csv"], capture_output=True, text=True)
        if r.returncode == 2 and "saturation literal with normalisation" in r.stderr:
            print(f"{name}: refused by the model, left out")
            continue
        if r.returncode not in (0, 1):
            sys.stderr.write(f"specular_tb --input failed ({r.returncode}): {r.stderr}")
            return 1
        lines = open(f"{out}/groups_{name}.csv").read().splitlines()
        if random > 0:
            seed = len(saturation) * 16 + CONSTANTS.index(constants) * 4 + NORMALISATIONS.index(normalisation)
            r = subprocess.run([tb, *options, "--random", str(random), "--seed", str(seed), "--format",
                                "csv", "--output", f"{out}/random_{name}.csv"], capture_output=True, text=True)
            if r.returncode not in (0, 1):
                sys.stderr.write(f"specular_tb --random failed ({r.returncode}): {r.stderr}")
                return 1
            lines += open(f"{out}/random_{name}.csv").read().splitlines()[1:]
        with open(f"{out}/vectors_{name}.csv", "w") as f:
            f.write("\n".join(lines) + "\n")
        listing.append(f"{name} {CONSTANTS.index(constants)} {NORMALISATIONS.index(normalisation)} "
                       f"{1 if saturation == 'literal' else 0} {out}/vectors_{name}.csv")
        print(f"{name}: {len(lines) - 1} vectors")
    with open(f"{out}/policies.txt", "w") as f:
        f.write("\n".join(listing) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
