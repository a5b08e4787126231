#!/usr/bin/env python3
"""flows_shared_readers: scripts/specular_flows' VCD reader, Liberty reader and runner on
snippets written here, against values worked out by hand (issue 62).

  shared_readers_test.py PROJECT_DIR SCRATCH

Exit 0 all as expected, 1 a difference (each named).
"""
import os
import subprocess
import sys

VCD = """$date today $end
$timescale
  10 ps
$end
$scope module tb $end
$scope module dut $end
$var wire 1 ! clk $end
$var wire 4 " q [3:0] $end
$var wire 1 # \\a.b $end
$upscope $end
$var reg 1 $ unused $end
$upscope $end
$enddefinitions $end
#0
$dumpvars
0!
bx "
0#
$end
#5
1!
b101 "
#7
1$
#12
0!
b1 "
#20
"""

LIBERTY = """library (tiny) {
  /* a comment */
  lu_table_template (power2) {
    variable_1 : input_transition_time;
    variable_2 : total_output_net_capacitance;
    index_1 ("0.1, 0.3");
    index_2 ("0.01, 0.05");
  }
  cell (NAND2X1) {
    area : 32;
    cell_leakage_power : 0.5;
    pin (A) { direction : input; capacitance : 0.0122; }
    pin (Y) {
      direction : output;
      function : "(!(A B))";
      internal_power () {
        related_pin : "A";
        rise_power (power2) { values ("1.0, 3.0", \\
                                      "2.0, 8.0"); }
        fall_power (power2) { values ("0.5, 0.5", "0.5, 0.5"); }
      }
    }
    bus (D) { bus_type : bus4; direction : input; capacitance : 0.02; pin (D[1]) { } }
  }
  cell (FILL) { }
}
"""


def main(argv):
    if len(argv) != 3:
        print("usage: shared_readers_test.py PROJECT_DIR SCRATCH", file=sys.stderr)
        return 2
    project, scratch = argv[1], argv[2]
    os.makedirs(scratch, exist_ok=True)
    sys.path.insert(0, os.path.join(project, "scripts"))
    from specular_flows import liberty, vcd
    fails = []

    def expect(what, got, want):
        if got != want:
            fails.append(f"{what}: {got!r}, want {want!r}")

    def close(what, got, want):  # interpolation in binary floating point: within 1e-12
        if abs(got - want) > 1e-12:
            fails.append(f"{what}: {got!r}, want {want!r}")

    # ---- VCD: 10 ps a tick; scopes dotted, the escaped name without its backslash
    path = os.path.join(scratch, "tiny.vcd")
    open(path, "w").write(VCD)
    with open(path) as f:
        scale, variables = vcd.read_header(f)
        expect("timescale", scale, 10.0)
        expect("variables", variables, [vcd.Var("tb.dut", "clk", "!", 1, None),
                                        vcd.Var("tb.dut", "q", '"', 4, "[3:0]"),
                                        vcd.Var("tb.dut", "a.b", "#", 1, None),
                                        vcd.Var("tb", "unused", "$", 1, None)])
        changes = vcd.Changes(f, scale, {"!": 1, '"': 4, "#": 1})
        # #7 changes only the unwanted '$': no step; b101 and b1 padded with 0 to 4 bits, bx with x
        expect("steps", list(changes), [(0.0, {"!": "0", '"': "xxxx", "#": "0"}),
                                        (50.0, {"!": "1", '"': "0101"}),
                                        (120.0, {"!": "0", '"': "0001"})])
        expect("end", changes.end_ps, 200.0)
    expect("timescale 1ns", vcd.timescale_ps("1ns"), 1000.0)
    try:
        vcd.timescale_ps("ten ps")
        fails.append("timescale 'ten ps' accepted")
    except ValueError as e:
        expect("bad timescale", str(e), "timescale 'ten ps': not a number and a unit (s, ms, us, ns, ps, fs)")

    # ---- Liberty
    lib_path = os.path.join(scratch, "tiny.lib")
    open(lib_path, "w").write(LIBERTY)
    expect("areas", liberty.cell_areas(LIBERTY), {"NAND2X1": 32.0, "FILL": 0.0})
    lib = liberty.Library([lib_path])
    nand = lib.cells["NAND2X1"]
    expect("leakage", nand["leakage_nw"], 0.5)
    expect("A", (lib.pin("NAND2X1", "A")["direction"], lib.pin("NAND2X1", "A")["cap"]), ("input", 0.0122))
    # a bus bit declared inherits the bus's direction and capacitance; one not declared falls back to the bus
    expect("D[1]", (lib.pin("NAND2X1", "D[1]")["direction"], lib.pin("NAND2X1", "D[1]")["cap"]), ("input", 0.02))
    expect("D[3]", lib.pin("NAND2X1", "D[3]")["cap"], 0.02)
    power = lib.pin("NAND2X1", "Y")["power"]
    expect("internal_power groups", [p["related"] for p in power], ["A"])
    rise = power[0]["rise"]
    # slew 0.2 is half-way along 0.1..0.3, load 0.03 half-way along 0.01..0.05:
    # rows 1 + (3-1)/2 = 2 and 2 + (8-2)/2 = 5, then 2 + (5-2)/2 = 3.5
    close("rise(0.03 pF, 0.2 ns)", rise.lookup(load=0.03, slew=0.2), 3.5)
    # beyond the index, linear: slew 0.5 is 2 steps of 0.2 past 0.1 at load 0.01: 1 + 2*(2-1) = 3
    close("rise(0.01 pF, 0.5 ns)", rise.lookup(load=0.01, slew=0.5), 3.0)
    close("fall", power[0]["fall"].lookup(load=0.04, slew=0.15), 0.5)

    # ---- runner: output back; a failure one line in the house's spelling, exit 1
    code = ("import sys; sys.path.insert(0, sys.argv[1]); from specular_flows.run import run; "
            "r = run(['sh', '-c', sys.argv[2]], 'demo.py'); print('got ' + r.stdout.strip())")
    ok = subprocess.run([sys.executable, "-c", code, os.path.join(project, "scripts"), "echo out"],
                        capture_output=True, text=True)
    expect("run ok", (ok.returncode, ok.stdout, ok.stderr), (0, "got out\n", ""))
    bad = subprocess.run([sys.executable, "-c", code, os.path.join(project, "scripts"),
                          "echo out; echo oops >&2; exit 3"], capture_output=True, text=True)
    expect("run failing", (bad.returncode, bad.stdout, bad.stderr), (1, "", "demo.py: sh failed (3): oops\n"))

    for f in fails:
        print(f)
    print(f"flows_shared_readers: {'FAIL' if fails else 'PASS'}")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
