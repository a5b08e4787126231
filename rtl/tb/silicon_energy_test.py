#!/usr/bin/env python3
"""silicon_energy: scripts/flows/energy/energy.py on netlists small enough to work by hand
(issue 36, docs/design_space/energy_per_result.md "Energy per result"), through the whole path: the VCD dumper, the
Icarus replay with delays and with zero delay, the VCD-to-toggles step, the energy from
the Liberty tables, OpenSTA's slews and report_power, the report.

  silicon_energy_test.py ENERGY_PY OSU018_DIR SCRATCH CHECK
  CHECK: inverter_chain | wire_cap | wire_cap_implicit | glitch | rom_monotonic | openSTA | arguments
  silicon_energy_test.py ENERGY_PY OSU018_DIR SCRATCH whole_path NETLIST_DIR VECTORS_TOOL
                         SPECULAR_TB ROM_DIR COUNTER
  silicon_energy_test.py ENERGY_PY OSU018_DIR SCRATCH counter COUNTER

- inverter_chain: three INVX1 in a chain, input toggled K = 40 times (20 rises, 20
  falls): the energy equals the hand computation from INVX1's Liberty numbers, read here
  with a regular expression (not energy.py's reader): per stage, 20 x rise_power + 20 x
  fall_power at its load (the next INVX1's input capacitance; the last stage none) and
  the slew the test states (0.06 ns, the table's first column), plus 40 x 1/2 C V^2
  on a, n1 and n2 (one INVX1 input each; y drives nothing);
  leakage 3 x INVX1's cell_leakage_power.
- wire_cap: the chain with 0.010 pF of wire on n1 and 0.005 pF on n2 (energy.py
  --wire-cap, the routed wires of scripts/flows/layout/layout.sh): both loads grow by their wire, in
  the switching energy and in u1's and u2's internal-power lookups; a net the netlist
  lacks is counted as unknown; the wires' own switching (K x 1/2 C_wire V^2 each) is
  wire_switching_pj, and --wire-out lists n1 then n2 with their wire, toggles and share.
- wire_cap_implicit: the same with n1 and n2 not declared, as qflow's flat netlist after
  layout leaves every internal net (Verilog's implicit one-bit wires): the same figures.
  (energy.py once took an undeclared net for bit 0 of a bus and matched 329 of the laid-
  out device's 24 190 nets.)
- glitch: a = XOR(a, a through six INVX1) is 0 in zero delay; with the cells' delays
  (-gspecify) every change of a makes a pulse. The delayed replay counts 2K toggles on
  the XOR's output, the zero-delay replay none; the report's glitch share of the toggles
  is 2K / 11K (a and six inverter outputs K each, clk 2K, the XOR's 2K).
- openSTA: the chain's switching energy equals OpenSTA's report_power at an input
  activity of K (whose 2019 snapshot reports activity x energy; OpenSTA leaves out the
  input port's net a, which the test subtracts), its internal energy
  half OpenSTA's (which charges rise_power + fall_power per unit of activity), both with
  OpenSTA's own slews (energy.py sta-slews).
- rom_monotonic: scripts/flows/synthesis/rom_model.py's energy per read grows with the words
  (width fixed) and with the width (words fixed).
- whole_path: scripts/flows/energy/energy.sh on the drawn device's mapped netlist (silicon_flow's)
  with 4 random operands: 22 results (the common stream's 18 edge cases + 4); the device
  replayed the operands specular_variant_vectors writes for any variant (asked here of
  one_pass, whose model is not the device's) and its testbench expected the pins 24-26
  the patent variant's C++ model gives; the figure is the sum of its parts; the zero-delay
  replay gave as many results; T_sim is the top's row of energy_streams.tsv; the toggle
  counter energy.sh used (tools/vcd_activity) counted the SDF replay's VCD as energy.py's
  own reader does.
- counter: the toggle counter equals energy.py's reader on the glitch generator's
  replays, a result shown four ways (a strobe's rise or fall, clk_valid, from 40 ns on).
Exit 0 pass, 1 fail.
"""
import csv
import json
import os
import re
import subprocess
import sys

K = 40
VDD = 1.8


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        print(f"FAIL: {' '.join(cmd)} exited {r.returncode}\n{r.stdout}\n{r.stderr}")
        sys.exit(1)
    return r.stdout


CHAIN = """module chain (clk, a, y);
  input clk, a; output y;
  wire n1, n2;
  INVX1 u1 (.A(a), .Y(n1));
  INVX1 u2 (.A(n1), .Y(n2));
  INVX1 u3 (.A(n2), .Y(y));
endmodule
"""

GLITCH = """module glitch (clk, a, g);
  input clk, a; output g;
  wire n1, n2, n3, n4, n5, n6;
  INVX1 u1 (.A(a), .Y(n1));
  INVX1 u2 (.A(n1), .Y(n2));
  INVX1 u3 (.A(n2), .Y(n3));
  INVX1 u4 (.A(n3), .Y(n4));
  INVX1 u5 (.A(n4), .Y(n5));
  INVX1 u6 (.A(n5), .Y(n6));
  XOR2X1 ux (.A(a), .B(n6), .Y(g));
endmodule
"""

TB = """`timescale 1ns/10ps
module energy_tb;
  reg a = 0, clk = 0;
  wire o;
  integer k;
  TOP dut (.clk(clk), .a(a), .OUT(o));
  initial begin
    #5;
    for (k = 0; k < K; k = k + 1) begin
      #10 a = ~a;
      #2 clk = 1;
      #2 clk = 0;
    end
    #10 $finish;
  end
endmodule
"""


def replay(energy_py, osu, scratch, top, out_port, netlist_text, delays, tag):
    d = os.path.join(scratch, tag)
    os.makedirs(d, exist_ok=True)
    net = os.path.join(d, "netlist.v")
    open(net, "w").write(netlist_text)
    tb = os.path.join(d, "tb.v")
    open(tb, "w").write(TB.replace("TOP", top).replace("OUT", out_port).replace("< K", f"< {K}"))
    vcd = os.path.join(d, "activity.vcd")
    run(["/usr/bin/python3", energy_py, "dumper", net, top, "energy_tb", vcd, os.path.join(d, "dump.v")])
    vvp = os.path.join(d, "sim.vvp")
    run(["iverilog", "-g2005", "-gspecify" if delays else "-gno-specify", "-o", vvp,
         "-s", "energy_tb", "-s", "energy_dump", os.path.join(osu, "osu018_stdcells.v"), net, tb,
         os.path.join(d, "dump.v")])
    run(["vvp", "-n", vvp], cwd=d)
    return net, vcd, d


def compute(energy_py, osu, net, top, vcd, slews, d, name, results=("--results-strobe", "clk", "--results-mode", "rise"),
            extra=()):
    out = os.path.join(d, f"{name}.json")
    toggles = os.path.join(d, f"{name}_toggles.txt")
    run(["/usr/bin/python3", energy_py, "compute", "--lib", os.path.join(osu, "osu018_stdcells.lib"),
         "--netlist", net, "--top", top, "--tb-top", "energy_tb", "--vcd", vcd, "--slews", slews,
         *results, *extra, "--toggles-out", toggles, "--out", out])
    t = {}
    for line in open(toggles):
        n, r, f = line.split()
        t[n] = (int(r), int(f))
    return json.load(open(out)), t


def liberty_invx1(osu):
    """INVX1's input capacitance, leakage and the slew-0.06 column of its power tables,
    read with regular expressions."""
    text = open(os.path.join(osu, "osu018_stdcells.lib")).read()
    cell = re.search(r"cell \(INVX1\) \{(.*?)\n\}", text, re.S).group(1)
    cap = float(re.search(r"pin\(A\).*?capacitance : ([\d.]+);", cell, re.S).group(1))
    leak = float(re.search(r"cell_leakage_power : ([\d.]+);", cell).group(1))
    power = re.search(r"internal_power\(\) \{(.*)", cell, re.S).group(1)

    def table(kind):
        m = re.search(kind + r"\(energy_template_5x5\) \{\s*index_1 \(\"([^\"]*)\"\);\s*"
                      r"index_2 \(\"([^\"]*)\"\);\s*values \((.*?)\);", power, re.S)
        loads = [float(x) for x in m.group(1).split(",")]
        slews = [float(x) for x in m.group(2).split(",")]
        rows = [[float(x) for x in r.split(",")] for r in re.findall(r"\"([^\"]*)\"", m.group(3))]
        assert slews[0] == 0.06
        return loads, [r[0] for r in rows]
    return cap, leak, table("rise_power"), table("fall_power")


def interpolate(table, x):
    xs, ys = table
    k = 0 if x <= xs[1] else max(i for i in range(len(xs) - 1) if xs[i] <= x)
    k = min(k, len(xs) - 2)
    return ys[k] + (x - xs[k]) / (xs[k + 1] - xs[k]) * (ys[k + 1] - ys[k])


def close(a, b, rel=1e-6, what=""):
    if abs(a - b) > rel * max(abs(a), abs(b), 1e-12):
        print(f"FAIL: {what}: {a} against {b}")
        sys.exit(1)


def fixed_slews(path, instances, pins):
    with open(path, "w") as f:
        for i in instances:
            for p in pins:
                f.write(f"{i}/{p} 0.06 0.06\n")


def check_inverter_chain(energy_py, osu, scratch):
    net, vcd, d = replay(energy_py, osu, scratch, "chain", "y", CHAIN, True, "chain")
    slews = os.path.join(d, "slews.txt")
    fixed_slews(slews, ["u1", "u2", "u3"], ["A"])
    e, t = compute(energy_py, osu, net, "chain", vcd, slews, d, "energy")
    cap, leak, rise, fall = liberty_invx1(osu)
    for n in ("a", "n1", "n2", "y"):
        if t.get(n) != (K // 2, K // 2):
            print(f"FAIL: net {n} toggles {t.get(n)}, want {(K // 2, K // 2)}")
            return 1
    loads = [cap, cap, 0.0]   # u1 drives u2, u2 drives u3, u3 the port y (no load)
    internal = sum(K // 2 * interpolate(rise, c) + K // 2 * interpolate(fall, c) for c in loads)
    # switching: a (u1's input), n1, n2: one INVX1 input each; y none
    switching = 3 * K * 0.5 * cap * VDD * VDD
    close(e["internal_pj"], internal, what="internal energy (pJ)")
    close(e["switching_pj"], switching, what="switching energy (pJ)")
    close(e["leakage_nw"], 3 * leak, what="leakage (nW)")
    if e["results"] != K:
        print(f"FAIL: {e['results']} results counted, want {K}")
        return 1
    print(f"PASS inverter chain: internal {internal:.5f} pJ, switching {switching:.5f} pJ, "
          f"leakage {3 * leak:.5f} nW, as computed by hand from the Liberty")
    return 0


def check_wire_cap(energy_py, osu, scratch, implicit=False):
    """The chain with routed wire on n1 and n2 (--wire-cap, issue 48): each wire's
    capacitance adds to its net's load, so to the switching energy (K toggles x 1/2 C V^2)
    and to the driver's internal-power lookup, computed here by hand. `implicit`: n1 and
    n2 undeclared (qflow's flat netlist)."""
    text = CHAIN.replace("  wire n1, n2;\n", "") if implicit else CHAIN
    net, vcd, d = replay(energy_py, osu, scratch, "chain", "y", text, True, "chain")
    slews = os.path.join(d, "slews.txt")
    fixed_slews(slews, ["u1", "u2", "u3"], ["A"])
    wires = {"n1": 0.010, "n2": 0.005}
    wire_file = os.path.join(d, "wire_cap.txt")
    with open(wire_file, "w") as f:
        f.write("".join(f"{n} {c}\n" for n, c in wires.items()) + "no_such_net 0.5\n")
    wire_out = os.path.join(d, "wire_switching.txt")
    e, t = compute(energy_py, osu, net, "chain", vcd, slews, d, "energy_wire",
                   extra=("--wire-cap", wire_file, "--wire-out", wire_out))
    cap, leak, rise, fall = liberty_invx1(osu)
    loads = [cap + wires["n1"], cap + wires["n2"], 0.0]
    internal = sum(K // 2 * interpolate(rise, c) + K // 2 * interpolate(fall, c) for c in loads)
    switching = 3 * K * 0.5 * cap * VDD * VDD + sum(K * 0.5 * c * VDD * VDD for c in wires.values())
    close(e["internal_pj"], internal, what="internal energy with wires (pJ)")
    close(e["switching_pj"], switching, what="switching energy with wires (pJ)")
    if e["wire_cap_nets"] != 2 or e["wire_cap_unknown_nets"] != 1:
        print(f"FAIL: wire nets matched {e['wire_cap_nets']}, unknown {e['wire_cap_unknown_nets']}; want 2 and 1")
        return 1
    # the wires' own share: K toggles x 1/2 C_wire V^2 per net, n1 (more wire) first
    own = {n: K * 0.5 * c * VDD * VDD for n, c in wires.items()}
    close(e.get("wire_switching_pj", -1.0), sum(own.values()), what="the wires' own switching (pJ)")
    rows = [l.split() for l in open(wire_out) if not l.startswith("#")]
    if [r[0] for r in rows] != ["n1", "n2"] or [int(r[2]) for r in rows] != [K, K]:
        print(f"FAIL: {wire_out}: want n1 then n2 with {K} toggles each, got {rows}")
        return 1
    for r in rows:
        close(float(r[1]), wires[r[0]], what=f"{r[0]}'s wire (pF)")
        close(float(r[3]), own[r[0]], what=f"{r[0]}'s own switching (pJ)")
    print(f"PASS wire capacitance: internal {internal:.5f} pJ, switching {switching:.5f} pJ with "
          f"{sum(wires.values())} pF of wire, as computed by hand")
    return 0


def check_glitch(energy_py, osu, scratch):
    got = {}
    for tag, delays in (("glitch_delays", True), ("glitch_zero", False)):
        net, vcd, d = replay(energy_py, osu, scratch, "glitch", "g", GLITCH, delays, tag)
        slews = os.path.join(d, "slews.txt")
        fixed_slews(slews, [f"u{i}" for i in range(1, 7)] + ["ux"], ["A", "B"])
        e, t = compute(energy_py, osu, net, "glitch", vcd, slews, d, "energy_sdf" if delays else "energy_zero")
        got[tag] = (e, t, d)
    g_delay = sum(got["glitch_delays"][1].get("g", (0, 0)))
    g_zero = sum(got["glitch_zero"][1].get("g", (0, 0)))
    if g_delay != 2 * K or g_zero != 0:
        print(f"FAIL: XOR output toggles {g_delay} with delays (want {2 * K}), {g_zero} in zero delay (want 0)")
        return 1
    # the report on the two: the glitch share of the toggles, 2K of 11K
    d = got["glitch_delays"][2]
    os.replace(os.path.join(got["glitch_zero"][2], "energy_zero.json"), os.path.join(d, "energy_zero.json"))
    run(["/usr/bin/python3", energy_py, "report", "--top", "glitch", "--dir", d, "--period", "18",
         "--clocks-per-result", "1"])
    r = json.load(open(os.path.join(d, "energy.json")))
    close(r["glitch_toggle_share"], 2 / 11, what="glitch share of the toggles")
    if not r["glitch_logic_energy_share"] > 0:
        print(f"FAIL: glitch energy share {r['glitch_logic_energy_share']}, want > 0")
        return 1
    print(f"PASS glitch: {g_delay} toggles of the XOR with delays, {g_zero} in zero delay; "
          f"glitch share {r['glitch_toggle_share']:.4f} of the toggles, "
          f"{r['glitch_logic_energy_share']:.4f} of the logic energy")
    return 0


def check_openSTA(energy_py, osu, scratch):
    net, vcd, d = replay(energy_py, osu, scratch, "chain", "y", CHAIN, True, "chain_sta")
    tcl_slews = os.path.join(d, "slews_dump.tcl")
    slews = os.path.join(d, "slews.txt")
    run(["/usr/bin/python3", energy_py, "sta-slews", tcl_slews, slews])
    tcl = os.path.join(d, "sta.tcl")
    lib = os.path.join(osu, "osu018_stdcells.lib")
    open(tcl, "w").write(f"""read_liberty {{{lib}}}
read_verilog {{{net}}}
link_design chain
create_clock -name clk -period 18 [get_ports clk]
set_input_transition 0.06 [get_ports a]
source {{{tcl_slews}}}
set_power_activity -input -activity {K} -duty 0.5
report_power -digits 8
""")
    out = run(["sta", "-no_splash", "-exit", tcl])
    m = re.search(r"^Total\s+(\S+)\s+(\S+)\s+(\S+)", out, re.M)
    sta_internal, sta_switching = float(m.group(1)) * 1e12, float(m.group(2)) * 1e12  # "W" = J here
    e, t = compute(energy_py, osu, net, "chain", vcd, slews, d, "energy")
    # OpenSTA gives an instance the switching of the net it drives: the input port's net
    # a (u1's input, K toggles) is ours only
    cap = liberty_invx1(osu)[0]
    port_net = K * 0.5 * cap * VDD * VDD
    close(e["switching_pj"] - port_net, sta_switching, rel=1e-4, what="switching against OpenSTA")
    close(e["internal_pj"], sta_internal / 2, rel=1e-3, what="internal against OpenSTA / 2")
    print(f"PASS OpenSTA: switching {e['switching_pj']:.5f} pJ (OpenSTA {sta_switching:.5f}), "
          f"internal {e['internal_pj']:.5f} pJ (OpenSTA {sta_internal:.5f}, rise + fall per unit of activity)")
    return 0


def check_rom_monotonic(energy_py):
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(energy_py)), "synthesis"))
    import rom_model

    def e(words, width):
        abits = max(1, (words - 1).bit_length())
        return rom_model.model_with_energy("X", words, width, abits,
                                           rom_model.squarest_ways(words, width))["energy_read_pj"]
    for width in (1, 8, 22, 25, 40):
        seq = [e(1 << k, width) for k in range(4, 17)]
        if any(b <= a for a, b in zip(seq, seq[1:])):
            print(f"FAIL: energy per read not increasing in words at width {width}: {seq}")
            return 1
    for words in (16, 512, 1024, 16384, 32768):
        seq = [e(words, w) for w in range(1, 41)]
        if any(b <= a for a, b in zip(seq, seq[1:])):
            print(f"FAIL: energy per read not increasing in width at {words} words: {seq}")
            return 1
    print("PASS ROM model: energy per read increases with words and with width")
    return 0


def check_arguments(energy_py, scratch):
    """scripts/flows/energy/energy.sh refuses bad arguments with exit 2, naming the value and the range."""
    script = os.path.join(os.path.dirname(energy_py), "energy.sh")
    out = os.path.join(scratch, "out")
    for args, text in ((["--period", "0"], "'0' is not a period in ns from 1 to 1000"),
                       (["--period", "abc"], "'abc' is not a period in ns from 1 to 1000"),
                       (["--t-sim", "-3"], "'-3' is not a period in ns above 0"),
                       (["--random", "x"], "'x' is not a count from 0 to 5000"),
                       (["--random", "5001"], "'5001' is not a count from 0 to 5000"),
                       (["--top", "no_such_top"], "top 'no_such_top' has no flow pieces"),
                       (["--bogus"], "unknown option '--bogus'"),
                       ([], "usage")):
        r = subprocess.run(["bash", script] + args + ([out] if args else []), capture_output=True, text=True)
        if r.returncode != 2 or text not in r.stderr:
            print(f"FAIL: energy.sh {' '.join(args)}: exit {r.returncode}, stderr {r.stderr!r}; want 2 and {text!r}")
            return 1
    print("PASS arguments: energy.sh refuses bad values with exit 2, naming them")
    return 0


def verdict(fails, passed):
    """Each failure on a line of its own, or the pass line; the exit status."""
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print(passed)
    return 1 if fails else 0


def same_counts(a, b, what):
    """energy.py compute's answers a (its own reader) and b (specular_vcd_activity): the same
    results, toggles, ROM reads and checkpoints; energies to rounding (the order of a sum)."""
    fails = []
    for k in ("results", "toggles", "rom_reads", "nets", "span_ns"):
        if a[k] != b[k]:
            fails.append(f"{what}: {k} {a[k]} (reader) against {b[k]} (counter)")
    for k in ("internal_pj", "switching_pj", "rom_pj"):
        if abs(a[k] - b[k]) > 1e-9 * max(1.0, abs(a[k])):
            fails.append(f"{what}: {k} {a[k]} (reader) against {b[k]} (counter)")
    ca, cb = a["checkpoints"], b["checkpoints"]
    if len(ca) != len(cb) or any(x[:2] != y[:2] or abs(x[2] - y[2]) > 1e-6 * max(1.0, abs(x[2]))
                                 for x, y in zip(ca, cb)):
        fails.append(f"{what}: checkpoints differ ({len(ca)} against {len(cb)})")
    return fails


def check_counter(energy_py, osu, scratch, counter):
    """tools/vcd_activity's counter equals energy.py's reader on the glitch generator's two
    replays, for each way a result shows (a strobe's rise, its fall, a clock edge with n1,
    which ends high, as the strobe) and with counting from 40 ns on."""
    fails = []
    for tag, delays in (("counter_delays", True), ("counter_zero", False)):
        net, vcd, d = replay(energy_py, osu, scratch, "glitch", "g", GLITCH, delays, tag)
        slews = os.path.join(d, "slews.txt")
        fixed_slews(slews, [f"u{i}" for i in range(1, 7)] + ["ux"], ["A", "B"])
        for name, results, extra in (
                ("rise", ("--results-strobe", "clk", "--results-mode", "rise"), ()),
                ("fall", ("--results-strobe", "a", "--results-mode", "fall"), ()),
                ("clk_valid", ("--results-strobe", "n1", "--results-mode", "clk_valid", "--clock", "clk"), ()),
                ("late", ("--results-strobe", "clk", "--results-mode", "rise"), ("--t-begin", "40"))):
            a, ta = compute(energy_py, osu, net, "glitch", vcd, slews, d, f"{name}_reader", results, extra)
            b, tb = compute(energy_py, osu, net, "glitch", vcd, slews, d, f"{name}_counter", results,
                            (*extra, "--counter", counter))
            fails += same_counts(a, b, f"{tag} {name}")
            if ta != tb:
                fails.append(f"{tag} {name}: per-net toggles differ")
            if a["results"] == 0 or a["toggles"] == 0:
                fails.append(f"{tag} {name}: nothing counted ({a['results']} results, {a['toggles']} toggles)")
    return verdict(fails, "PASS counter: specular_vcd_activity counts as energy.py's reader (2 replays x 4 ways)")


def check_whole_path(energy_py, scratch, netlist_dir, vectors_tool, specular_tb, rom_dir, counter):
    scripts = os.path.dirname(os.path.dirname(energy_py))  # scripts/flows
    out = os.path.join(scratch, "energy")
    r = subprocess.run(["bash", os.path.join(scripts, "energy", "energy.sh"), "--top", "specular_device",
                        "--netlist-dir", netlist_dir, "--random", "4", "--vectors-tool", vectors_tool,
                        "--specular-tb", specular_tb, "--counter", counter, "--keep-vcd", out, rom_dir],
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAIL: energy.sh exit {r.returncode}: {r.stderr}")
        return 1
    e = json.load(open(os.path.join(out, "energy.json")))
    fails = []
    if e["results"] != 22 or e.get("zero_delay_results") != 22:
        fails.append(f"results {e['results']} (zero delay {e.get('zero_delay_results')}), want 22: 18 edge cases + 4")
    if e.get("random_from") != 18 or e.get("random_results") != 4:
        fails.append(f"random results {e.get('random_from')}..{e.get('random_results')}, want from 18, 4 of them")
    # the operands: the stream any variant replays (one_pass's), the expected pins: patent's model
    stream = {}
    for name in ("one_pass", "patent"):
        text = subprocess.run([vectors_tool, name, "--count", "22", "--seed", "1"], capture_output=True,
                              text=True, check=True).stdout
        stream[name] = [[int(x, 16) for x in line.split()] for line in text.splitlines()]
    rows = list(csv.DictReader(open(os.path.join(out, "sdf", "vectors_patent_patent_clamp.csv"))))
    replayed = [[int(v["reg1_hex"], 16), int(v["n"]), int(v["r"]), int(v["g"]), int(v["b"])] for v in rows]
    if replayed != [x[:5] for x in stream["one_pass"]]:
        fails.append(f"replayed operands {replayed[:3]}... are not the common stream's {stream['one_pass'][:3]}...")
    pins = [[int(v[f"pin{k}_hex"], 16) for k in (24, 25, 26)] for v in rows]
    if pins != [x[6:9] for x in stream["patent"]]:
        fails.append("the device's expected pins 24-26 differ from the patent variant's model")
    parts = e["internal_pj"] + e["switching_pj"] + e["rom_pj"] + e["leakage_pj_at_period"]
    if min(e["internal_pj"], e["switching_pj"], e["rom_pj"]) <= 0 or abs(parts / e["total_pj_at_period"] - 1) > 1e-9:
        fails.append(f"total {e['total_pj_at_period']} is not the sum of positive parts ({parts})")
    if not 0 < e["glitch_toggle_share"] < 1:
        fails.append(f"glitch share of the toggles {e['glitch_toggle_share']} not in (0, 1)")
    # the counter energy.sh used against energy.py's own reader, on the SDF replay's VCD
    # (ROM macros' reads and a real netlist's names)
    cmd = json.load(open(os.path.join(out, "energy_sdf.json")))
    reader = os.path.join(out, "energy_sdf_reader.json")
    run(["/usr/bin/python3", energy_py, "compute", "--lib", "/usr/share/qflow/tech/osu018/osu018_stdcells.lib",
         "--lib", os.path.join(netlist_dir, "rom_macros.lib"), "--netlist", os.path.join(netlist_dir, "mapped.v"),
         "--top", "specular_device", "--tb-top", "specular_device_tb", "--vcd", os.path.join(out, "sdf", "activity.vcd"),
         "--slews", os.path.join(out, "slews.txt"), "--rom-model", os.path.join(netlist_dir, "rom_model.json"),
         "--results-strobe", "pin35_done", "--results-mode", "rise", "--out", reader])
    fails += same_counts(json.load(open(reader)), cmd, "the device's SDF replay")
    if not cmd["rom_reads"] or min(cmd["rom_reads"].values()) == 0:
        fails.append(f"no ROM read counted: {cmd['rom_reads']}")
    rows_tsv = [l.split() for l in open(os.path.join(scripts, "energy", "energy_streams.tsv"))
                if l.startswith("specular_device ")]
    if not rows_tsv or e["t_sim_ns"] != float(rows_tsv[0][2]):
        fails.append(f"T_sim {e['t_sim_ns']} is not energy_streams.tsv's {rows_tsv}")
    return verdict(fails, f"PASS whole_path: 22 results of the common stream, {e['total_pj_at_period']:.0f} pJ per result")


def main():
    energy_py, osu, scratch, check = sys.argv[1:5]
    if check == "whole_path":
        os.makedirs(scratch, exist_ok=True)
        return check_whole_path(energy_py, scratch, *sys.argv[5:10])
    if check == "counter":
        os.makedirs(scratch, exist_ok=True)
        return check_counter(energy_py, osu, scratch, sys.argv[5])
    os.makedirs(scratch, exist_ok=True)
    if check == "inverter_chain":
        return check_inverter_chain(energy_py, osu, scratch)
    if check == "glitch":
        return check_glitch(energy_py, osu, scratch)
    if check == "wire_cap":
        return check_wire_cap(energy_py, osu, scratch)
    if check == "wire_cap_implicit":
        return check_wire_cap(energy_py, osu, scratch, implicit=True)
    if check == "openSTA":
        return check_openSTA(energy_py, osu, scratch)
    if check == "rom_monotonic":
        return check_rom_monotonic(energy_py)
    if check == "arguments":
        return check_arguments(energy_py, scratch)
    print(f"unknown check '{check}' (inverter_chain, glitch, openSTA, rom_monotonic, arguments, whole_path, counter)")
    return 2


if __name__ == "__main__":
    sys.exit(main())
