#!/usr/bin/env python3
"""Energy per result of a mapped netlist from its gate-level activity (issue 36).

Why a calculator of its own: Debian 12's OpenSTA (2.0.17, a 2019 snapshot) cannot take
per-pin activity (`set_power_activity -pins` fails in its Tcl wrapper, and `-activity` is
spelt `-activiity` in its help) and reads no VCD or SAIF. So the toggles come from the
Icarus replay's VCD and the energy from the same Liberty tables OpenSTA reads:

  - switching: 1/2 C V^2 per toggle of a net, C the Liberty input capacitances of every
    cell pin (and ROM macro address pin) on the net (no wire-load model in the OSU
    library, as for the timing);
  - internal: per output transition of a cell, the Liberty rise_power / fall_power table
    (pJ) at the net's load and the related input pin's transition time (OpenSTA's slews
    at the design's own SDC, dumped once), the related pins weighted by their toggles;
    per transition of an input pin with an internal_power group (the flip-flops' CLK, D),
    its table at its own slew;
  - leakage: the cells' cell_leakage_power (nW) times the time;
  - ROM macros: reads times the energy per read of scripts/flows/synthesis/rom_model.py; a read
    is a simulation time step at which any address bit of the macro moved (a glitching
    address is a read too).
OpenSTA's report_power is the check on a design small enough to work by hand
(tests/silicon_energy_*): its switching equals ours; its internal power charges
rise_power + fall_power per unit of activity, twice ours per toggle (the Liberty convention
this file keeps: rise_power per rising output transition, fall_power per falling).

  energy.py dumper NETLIST_ICARUS TB_TOP VCD_FILE OUT_V
      a Verilog module `energy_dump` that writes only the netlist's own scopes (the DUT
      and every non-cell instance below it, one level each) into VCD_FILE.
  energy.py compute --lib LIB [--lib LIB ...] --netlist MAPPED_V --top TOP
                    --tb-top TB_TOP --vcd VCD --slews SLEWS --rom-model ROM_MODEL_JSON
                    --results-strobe NET --results-mode rise|fall|clk_valid [--clock NET]
                    [--t-begin NS] [--counter PATH] --out JSON
      per-net toggles (rises, falls), the energy split, ROM reads and, at every result,
      the cumulative energy (convergence) into JSON.
  energy.py sta-slews TCL_OUT OUT
      the Tcl OpenSTA runs after the design's constraints to write every cell input
      pin's rise and fall transition time into OUT.
"""
import argparse
import json
import os
import re
import sys
from collections import defaultdict

VDD = 1.8


# ---------------------------------------------------------------- Liberty, VCD, runner
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))  # scripts/
from specular_flows.liberty import Library  # noqa: E402
from specular_flows.run import run  # noqa: E402
from specular_flows import vcd  # noqa: E402


# ---------------------------------------------------------------- netlist (Yosys output)
_VTOK = re.compile(r"\\\S+|[A-Za-z_][A-Za-z0-9_$]*|\d+'[sS]?[bhdoBHDO][0-9a-fA-FxXzZ_]+|\d+|\S")


def _vname(t):
    """An identifier as the simulator names it: escaped names without the backslash."""
    return t[1:] if t.startswith("\\") else t


class Module:
    def __init__(self, name):
        self.name = name
        self.ports = []
        self.widths = {}       # net -> (msb, lsb)
        self.cells = []        # (type, instance, {port: [bits]})
        self.assigns = []      # ([lhs bits], [rhs bits])


def _const_bits(tok):
    m = re.match(r"(\d+)'[sS]?([bhdoBHDO])([0-9a-fA-FxXzZ_]+)", tok)
    width, base, digits = int(m.group(1)), m.group(2).lower(), m.group(3).replace("_", "")
    if base == "d":
        v = bin(int(digits))[2:]
    elif base == "h":
        v = "".join("xxxx" if c in "xX" else "zzzz" if c in "zZ" else bin(int(c, 16))[2:].zfill(4)
                    for c in digits)
    elif base == "o":
        v = "".join(bin(int(c, 8))[2:].zfill(3) for c in digits)
    else:
        v = digits
    v = v.rjust(width, "0")[-width:]
    return [("const", c) for c in v]   # MSB first


def parse_netlist(path):
    toks = _VTOK.findall(open(path).read())
    modules = {}
    i = 0
    n = len(toks)
    mod = None

    def expr(i, m):
        """Bits of an expression, MSB first: (net, bit) or ('const', c)."""
        t = toks[i]
        if t == "{":
            bits = []
            i += 1
            while toks[i] != "}":
                if toks[i] == ",":
                    i += 1
                    continue
                b, i = expr(i, m)
                bits += b
            return bits, i + 1
        if re.match(r"\d+'", t):
            return _const_bits(t), i + 1
        name = _vname(t)
        i += 1
        if i < n and toks[i] == "[":
            hi = int(toks[i + 1])
            if toks[i + 2] == ":":
                lo = int(toks[i + 3])
                i += 5
            else:
                lo = hi
                i += 3
            step = -1 if hi >= lo else 1
            return [(name, k) for k in range(hi, lo + step, step)], i
        if name not in m.widths:  # an implicit net (qflow's flat netlist declares none): one bit
            m.widths[name] = (None, None)
        msb, lsb = m.widths[name]
        if (msb, lsb) == (None, None):
            return [(name, None)], i
        step = -1 if msb >= lsb else 1
        return [(name, k) for k in range(msb, lsb + step, step)], i

    while i < n:
        t = toks[i]
        if t == "module":
            mod = Module(_vname(toks[i + 1]))
            modules[mod.name] = mod
            i += 2
            while toks[i] != ";":
                i += 1
            i += 1
        elif t == "endmodule":
            mod = None
            i += 1
        elif t in ("input", "output", "inout", "wire", "reg") and mod is not None:
            i += 1
            rng = (None, None)
            if toks[i] == "signed":
                i += 1
            if toks[i] == "[":
                rng = (int(toks[i + 1]), int(toks[i + 3]))
                i += 5
            while toks[i] != ";":
                if toks[i] != ",":
                    name = _vname(toks[i])
                    mod.widths[name] = rng
                    if t in ("input", "output", "inout"):
                        mod.ports.append((name, t))
                i += 1
            i += 1
        elif t == "assign" and mod is not None:
            lhs, i = expr(i + 1, mod)
            assert toks[i] == "=", (path, i, toks[i])
            rhs, i = expr(i + 1, mod)
            mod.assigns.append((lhs, rhs))
            i += 1  # ;
        elif mod is not None and i + 2 < n and toks[i + 2] == "(":
            ctype, inst = _vname(t), _vname(toks[i + 1])
            i += 3
            conns = {}
            while toks[i] != ")":
                if toks[i] == ",":
                    i += 1
                    continue
                assert toks[i] == ".", (path, toks[i - 3:i + 3])
                port = _vname(toks[i + 1])
                i += 3
                if toks[i] == ")":
                    bits = []
                else:
                    bits, i = expr(i, mod)
                conns[port] = bits
                i += 1  # )
            mod.cells.append((ctype, inst, conns))
            i += 2  # ) ;
        else:
            i += 1
    return modules


def _bitname(net, bit):
    return net if bit is None else f"{net}[{bit}]"


def flatten(modules, top, lib):
    """Global nets by union-find over (instance path, net bit); leaf cells with their pin
    bits. Returns (find, leaves, scopes): leaves = [(path, cell type, inst, {pin: key})]."""
    parent = {}

    def find(x):
        while parent.get(x, x) != x:
            parent[x] = parent.get(parent[x], parent[x])
            x = parent[x]
        return x

    def union(a, b):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb

    leaves, scopes = [], []

    def key(path, b):
        if b[0] == "const":
            return ("const", b[1])
        return (path, _bitname(*b))

    def walk(mname, path):
        m = modules[mname]
        scopes.append(path)
        for lhs, rhs in m.assigns:
            for a, b in zip(reversed(lhs), reversed(rhs)):
                union(key(path, a), key(path, b))
        for ctype, inst, conns in m.cells:
            if ctype in modules:
                sub = modules[ctype]
                cpath = path + (inst,)
                for port, bits in conns.items():
                    msb, lsb = sub.widths.get(port, (None, None))
                    if msb is None:
                        inner = [(port, None)]
                    else:
                        step = -1 if msb >= lsb else 1
                        inner = [(port, k) for k in range(msb, lsb + step, step)]
                    for a, b in zip(reversed(bits), reversed(inner)):
                        union(key(path, a), key(cpath, b))
                walk(ctype, cpath)
            else:
                if ctype not in lib.cells:
                    raise SystemExit(f"energy.py: cell type '{ctype}' of {'/'.join(path + (inst,))} "
                                     "is in no Liberty file given")
                pins = {}
                for port, bits in conns.items():
                    if len(bits) == 1:
                        pins[port] = key(path, bits[0])
                    else:
                        for k, b in enumerate(reversed(bits)):
                            pins[f"{port}[{k}]"] = key(path, b)
                leaves.append((path, ctype, inst, pins))

    walk(top, ())
    return find, leaves, scopes


# ---------------------------------------------------------------- VCD
def read_vcd(path, wanted, weights, strobe, mode, clock, groups, t_begin):
    """Toggles of the VCD's signals, per (scope path, bit name) in `wanted` (a dict from
    such a name to a global net). Counts a change only between time steps (the value at
    the end of a step against the previous step's), 0<->1 only (x and z are not toggles).

    weights: global net -> (pJ per rise, pJ per fall), for the running energy; strobe,
    clock: global nets of the result strobe and clock; groups: {name: set of nets}, a read
    counted per time step at which any net of the group moves.
    Returns rises, falls (per global net), reads (per group), the checkpoints (time ps,
    results, cumulative pJ), the end time (ps), the timescale in ps."""
    ids = {}          # vcd id -> [(global net, bit index or None)]
    widths = {}       # vcd id -> declared width
    f = open(path)
    timescale_ps, variables = vcd.read_header(f)
    for var in variables:
        width, vid, name, rng, base = var.width, var.id, var.name, var.range, var.scope
        targets = []
        if rng is None or width == 1:
            bitn = name if rng is None else f"{name}{rng}"
            targets.append((wanted.get((base, bitn)), None))
        else:
            m = re.match(r"\[(\d+):(\d+)\]", rng)
            hi, lo = int(m.group(1)), int(m.group(2))
            step = -1 if hi >= lo else 1
            for pos, k in enumerate(range(hi, lo + step, step)):
                targets.append((wanted.get((base, f"{name}[{k}]")), pos))
        targets = [(g, pos) for g, pos in targets if g is not None]
        if targets:
            ids.setdefault(vid, []).extend(targets)
            widths[vid] = width
    value = {}        # global net -> '0'/'1'/'x'
    rises = defaultdict(int)
    falls = defaultdict(int)
    reads = {g: 0 for g in groups}
    net_group = defaultdict(list)
    for g, nets in groups.items():
        for net in nets:
            net_group[net].append(g)
    pending = {}      # vcd id -> raw value string (the last of this time step)
    last_read = {}
    energy = 0.0
    results = 0
    checkpoints = []
    t_ps = 0.0
    begin_ps = t_begin * 1e3
    clock_val = "x"
    strobe_val = "x"

    def flush():
        nonlocal energy, results, clock_val, strobe_val
        counting = t_ps >= begin_ps
        moved_groups = set()
        new_clock, new_strobe = clock_val, strobe_val
        for vid, raw in pending.items():
            for net, pos in ids[vid]:
                if pos is None:
                    v = raw[-1]
                else:
                    v = raw[pos] if pos < len(raw) else "0"
                old = value.get(net, "x")
                if v == old:
                    continue
                value[net] = v
                if net == clock:
                    new_clock = v
                if net == strobe:
                    new_strobe = v
                if not counting or old not in "01" or v not in "01":
                    continue
                if v == "1":
                    rises[net] += 1
                    w = weights.get(net)
                    if w:
                        energy += w[0]
                else:
                    falls[net] += 1
                    w = weights.get(net)
                    if w:
                        energy += w[1]
                for g in net_group.get(net, ()):
                    moved_groups.add(g)
        for g in moved_groups:
            # one read per address transition, the transitions within one access time
            # of the read they follow merged into it (the macro's address-transition
            # detector restarts the same read; an address glitch is a read of its own
            # only when it outlasts the access time)
            if counting and t_ps - last_read.get(g, -1e30) >= read_vcd.groups_access_ps.get(g, 0.0):
                reads[g] += 1
                last_read[g] = t_ps
                energy += groups_energy.get(g, 0.0)
        if counting:
            if (mode == "rise" and strobe_val == "0" and new_strobe == "1"
                    or mode == "fall" and strobe_val == "1" and new_strobe == "0"):
                results += 1
                checkpoints.append((t_ps, results, energy))
            elif mode == "clk_valid" and clock_val == "0" and new_clock == "1" and strobe_val == "1":
                results += 1
                checkpoints.append((t_ps, results, energy))
        clock_val, strobe_val = new_clock, new_strobe
        pending.clear()

    groups_energy = read_vcd.groups_energy
    changes = vcd.Changes(f, timescale_ps, widths)
    for t_ps, pending in changes:
        flush()
    t_ps = changes.end_ps
    # a variant's testbench stops just before the edge after its last valid: the result
    # held when the replay ends is one (rtl/tb/specular_variant_tb.v)
    if mode == "clk_valid" and strobe_val == "1" and t_ps >= begin_ps:
        results += 1
        checkpoints.append((t_ps, results, energy))
    return rises, falls, reads, checkpoints, t_ps, timescale_ps


read_vcd.groups_energy = {}
read_vcd.groups_access_ps = {}


def count_with_tool(tool, out, vcd_path, wanted, weights, strobe, mode, clock, groups, t_begin):
    """read_vcd's answer from tools/vcd_activity/specular_vcd_activity (the same rules,
    about 20 times as fast on a VCD of hundreds of MB): the map of global nets, their
    weights, the ROM groups and the strobe written beside OUT, the counts read back."""
    nets = sorted(set(wanted.values()) | set(weights) | {n for g in groups.values() for n in g}
                  | ({strobe} if strobe is not None else set()) | ({clock} if clock is not None else set()), key=str)
    index = {net: k for k, net in enumerate(nets)}
    map_file, counts_file = out + ".map", out + ".counts"
    with open(map_file, "w") as f:
        f.write(f"nets\t{len(nets)}\n")
        for net, (r, fa) in weights.items():
            f.write(f"weight\t{index[net]}\t{r!r}\t{fa!r}\n")
        for (scope, bit), net in wanted.items():
            f.write(f"sig\t{scope}\t{bit}\t{index[net]}\n")
        for g, members in groups.items():
            f.write(f"group\t{g}\t{read_vcd.groups_energy[g]!r}\t{read_vcd.groups_access_ps[g]!r}\t"
                    + ",".join(str(index[n]) for n in sorted(members, key=str)) + "\n")
        f.write(f"strobe\t{index[strobe]}\t{mode}\n")
        if clock is not None:
            f.write(f"clock\t{index[clock]}\n")
        f.write(f"begin\t{t_begin * 1e3!r}\n")
    run([tool, map_file, vcd_path, counts_file], "energy.py")
    rises, falls = defaultdict(int), defaultdict(int)
    reads = {g: 0 for g in groups}
    checkpoints = []
    t_end_ps = timescale_ps = 0.0
    for line in open(counts_file):
        p = line.rstrip("\n").split("\t")
        if p[0] == "toggles":
            rises[nets[int(p[1])]] = int(p[2])
            falls[nets[int(p[1])]] = int(p[3])
        elif p[0] == "reads":
            reads[p[1]] = int(p[2])
        elif p[0] == "checkpoint":
            checkpoints.append((float(p[1]), int(p[2]), float(p[3])))
        elif p[0] == "end":
            t_end_ps, timescale_ps = float(p[1]), float(p[2])
    os.remove(map_file)
    os.remove(counts_file)
    return rises, falls, reads, checkpoints, t_end_ps, timescale_ps


# ---------------------------------------------------------------- the energy
def cell_energy_weights(lib, leaves, find, load, slews):
    """Per global net driven by a cell output: (pJ per rise, pJ per fall) of internal
    energy with the related pins equally weighted (for the running figure only)."""
    w = {}
    for path, ctype, inst, pins in leaves:
        for pin, k in pins.items():
            e = lib.pin(ctype, pin)
            if e is None or e["direction"] != "output" or not e["power"]:
                continue
            net = find(k)
            rs, fs = [], []
            for grp in e["power"]:
                sl = slew_of(slews, path, inst, grp["related"])
                if grp["rise"]:
                    rs.append(grp["rise"].lookup(load.get(net, 0.0), sl[0]))
                if grp["fall"]:
                    fs.append(grp["fall"].lookup(load.get(net, 0.0), sl[1]))
            half_cv2 = 0.5 * load.get(net, 0.0) * VDD * VDD
            w[net] = (sum(rs) / max(len(rs), 1) + half_cv2, sum(fs) / max(len(fs), 1) + half_cv2)
    return w


def slew_of(slews, path, inst, pin):
    """(rise, fall) transition time of a pin (OpenSTA's, ns); (0, 0) if unknown. The
    rise_power table is looked up at the related pin's rise slew and fall_power at its
    fall slew, as OpenSTA 2.0.17 does (tests/silicon_energy_openSTA)."""
    if pin is None:
        return (0.0, 0.0)
    return slews.get("/".join(path + (inst, pin)), (0.0, 0.0))


def compute(args):
    lib = Library(args.lib)
    modules = parse_netlist(args.netlist)
    find, leaves, scopes = flatten(modules, args.top, lib)
    # loads: every input pin's capacitance on its net
    load = defaultdict(float)
    for path, ctype, inst, pins in leaves:
        for pin, k in pins.items():
            e = lib.pin(ctype, pin)
            if e and e["direction"] == "input":
                load[find(k)] += e["cap"]
    # after layout (scripts/flows/layout/layout.sh): each net's routed wire capacitance on top of its
    # pins' (a file of "NET PF" lines, NET a top-level net of the flat netlist or
    # a/b/net through instances, bus bits as net[3])
    wire_pf, wire_nets, wire_unknown = 0.0, 0, []
    wire_load, wire_name = defaultdict(float), {}   # per global net: its wire alone, a name
    if args.wire_cap:
        known = set(parent_keys_of(modules, args.top))
        for line in open(args.wire_cap):
            p = line.split()
            if len(p) != 2 or p[0].startswith("#"):
                continue
            *path, bit = p[0].split("/")
            k = (tuple(path), bit)
            if k not in known:
                wire_unknown.append(p[0])
                continue
            load[find(k)] += float(p[1])
            wire_load[find(k)] += float(p[1])
            wire_name.setdefault(find(k), p[0])
            wire_pf += float(p[1])
            wire_nets += 1
    slews = {}
    if args.slews:
        for line in open(args.slews):
            p = line.split()
            if len(p) == 3 and "inf" not in p[1] + p[2]:
                slews[p[0].replace(".", "__")] = (float(p[1]), float(p[2]))
    # the VCD's names of every global net: scope path + net bit (Icarus' names: the
    # testbench top, the DUT instance `dut`, dots in escaped names as double underscores)
    wanted = {}
    parent_keys = {}
    for x in list(_all_keys(modules, args.top)):
        path, bit = x
        scope = ".".join((args.tb_top, "dut") + tuple(p.replace(".", "__") for p in path))
        wanted[(scope, bit.replace(".", "__") if "[" not in bit else
                _fix_bit(bit))] = find(x)
        parent_keys[x] = True
    rom = json.load(open(args.rom_model)) if args.rom_model else {"macros": []}
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "synthesis"))
    import rom_model  # the synthesis flow's ROM macro model
    rom_energy = {m["name"]: rom_model.read_energy(m)["energy_read_pj"] for m in rom["macros"]}
    groups = {}
    group_cell = {}
    for path, ctype, inst, pins in leaves:
        if ctype in rom_energy:
            name = "/".join(path + (inst,))
            groups[name] = {find(k) for p, k in pins.items() if re.match(r"A(\[\d+\])?$", p)}
            group_cell[name] = ctype
    read_vcd.groups_energy = {g: rom_energy[group_cell[g]] for g in groups}
    rom_access = {m["name"]: m["access_ns"] * 1e3 for m in rom["macros"]}
    read_vcd.groups_access_ps = {g: rom_access[group_cell[g]] for g in groups}
    weights = cell_energy_weights(lib, leaves, find, load, slews)
    strobe = wanted.get(_split_name(args.tb_top, args.results_strobe))
    clock = wanted.get(_split_name(args.tb_top, args.clock)) if args.clock else None
    if strobe is None:
        raise SystemExit(f"energy.py: result strobe '{args.results_strobe}' is no net of the netlist")
    if args.counter:
        rises, falls, reads, checkpoints, t_end_ps, _ = count_with_tool(
            args.counter, args.out, args.vcd, wanted, weights, strobe, args.results_mode, clock, groups, args.t_begin)
    else:
        rises, falls, reads, checkpoints, t_end_ps, _ = read_vcd(
            args.vcd, wanted, weights, strobe, args.results_mode, clock, groups, args.t_begin)
    # exact energy per driven net
    internal = 0.0
    internal_seq = 0.0
    toggles_by_net = {}
    for path, ctype, inst, pins in leaves:
        seq = ctype.startswith("DFF") or ctype.startswith("LATCH")
        for pin, k in pins.items():
            e = lib.pin(ctype, pin)
            if e is None or not e["power"]:
                continue
            net = find(k)
            if e["direction"] == "output":
                rel = [g for g in e["power"]]
                tog = [rises[find(pins[g["related"]])] + falls[find(pins[g["related"]])]
                       if g["related"] in pins else 0 for g in rel]
                tot = sum(tog)
                wts = [t / tot for t in tog] if tot else [1.0 / len(rel)] * len(rel)
                en = 0.0
                for g, wt in zip(rel, wts):
                    sl = slew_of(slews, path, inst, g["related"])
                    if g["rise"]:
                        en += wt * rises[net] * g["rise"].lookup(load[net], sl[0])
                    if g["fall"]:
                        en += wt * falls[net] * g["fall"].lookup(load[net], sl[1])
            else:  # an input pin's own internal power (a flip-flop's CLK, D)
                sl = slews.get("/".join(path + (inst, pin)).replace(".", "__"), (0.0, 0.0))
                en = 0.0
                for g in e["power"]:
                    if g["rise"]:
                        en += rises[net] * g["rise"].lookup(0.0, sl[0])
                    if g["fall"]:
                        en += falls[net] * g["fall"].lookup(0.0, sl[1])
            internal += en
            if seq:
                internal_seq += en
    switching = 0.0
    toggles = 0
    nets = set(find(k) for k in parent_keys)
    for net in nets:
        t = rises[net] + falls[net]
        toggles += t
        switching += t * 0.5 * load[net] * VDD * VDD
    # the wires' own share of the switching (issue 48: which nets' share grew), per net by
    # the layout's name, so that aliases (a port and the net it joins) count once
    wire_switching = {net: (rises[net] + falls[net]) * 0.5 * c * VDD * VDD for net, c in wire_load.items()}
    leak_nw = sum(lib.cells[c]["leakage_nw"] for _, c, _, _ in leaves)
    rom_reads = {g: reads[g] for g in groups}
    rom_pj = sum(reads[g] * read_vcd.groups_energy[g] for g in groups)
    t_begin_ps = args.t_begin * 1e3
    span_ns = (t_end_ps - t_begin_ps) / 1e3
    results = checkpoints[-1][1] if checkpoints else 0
    out = {
        "vcd": args.vcd, "top": args.top, "results": results, "span_ns": span_ns,
        "nets": len(nets), "toggles": toggles,
        "internal_pj": internal, "internal_sequential_pj": internal_seq,
        "switching_pj": switching, "leakage_nw": leak_nw,
        "rom_reads": rom_reads, "rom_pj": rom_pj,
        "rom_energy_per_read_pj": {g: read_vcd.groups_energy[g] for g in groups},
        "checkpoints": [(round(t / 1e3, 3), r, round(e, 4)) for t, r, e in checkpoints],
        "cells": len(leaves),
        "wire_cap_pf": wire_pf, "wire_cap_nets": wire_nets,
        "wire_cap_unknown_nets": len(wire_unknown),
        "wire_switching_pj": sum(wire_switching.values()),
    }
    if args.wire_out:
        with open(args.wire_out, "w") as f:
            f.write("# net wire_pf toggles wire_switching_pj (the whole run; the largest first)\n")
            for net in sorted(wire_switching, key=lambda n: (-wire_switching[n], wire_name[n])):
                f.write(f"{wire_name[net]} {wire_load[net]:.6g} {rises[net] + falls[net]} {wire_switching[net]:.6g}\n")
    if args.toggles_out:
        with open(args.toggles_out, "w") as f:
            for net in sorted(nets, key=str):
                if rises[net] or falls[net]:
                    f.write(f"{_netname(net)} {rises[net]} {falls[net]}\n")
    json.dump(out, open(args.out, "w"), indent=1)
    return 0


def parent_keys_of(modules, top):
    return list(_all_keys(modules, top))


def _fix_bit(bit):
    name, rest = bit.split("[", 1)
    return name.replace(".", "__") + "[" + rest


def _netname(net):
    path, bit = net
    if path == "const":
        return f"const_{bit}"
    return "/".join(path + (bit,))


def _split_name(tb_top, dotted):
    """`dut.NET` or `NET` (in the DUT's top scope) as a VCD key."""
    name = dotted[4:] if dotted.startswith("dut.") else dotted
    return (f"{tb_top}.dut", name)


def _all_keys(modules, top):
    """Every (instance path, net bit) of the hierarchy."""
    def walk(mname, path):
        m = modules[mname]
        for net, (msb, lsb) in m.widths.items():
            if msb is None:
                yield (path, net)
            else:
                step = -1 if msb >= lsb else 1
                for k in range(msb, lsb + step, step):
                    yield (path, f"{net}[{k}]")
        for ctype, inst, conns in m.cells:
            if ctype in modules:
                yield from walk(ctype, path + (inst,))
    yield from walk(top, ())


def dumper(args):
    """The VCD dumper: $dumpvars(1, scope) for the DUT and every non-cell instance."""
    modules = parse_netlist(args.netlist)
    tops = [m for m in modules if m == args.top] or [None]
    if tops[0] is None:
        raise SystemExit(f"energy.py: top '{args.top}' not in {args.netlist}")
    paths = []

    def walk(mname, path):
        paths.append(path)
        for ctype, inst, conns in modules[mname].cells:
            if ctype in modules:
                walk(ctype, path + (inst,))
    walk(args.top, ())

    def ref(path):
        parts = [args.tb_top, "dut"] + [p if re.match(r"^[A-Za-z_][A-Za-z0-9_$]*$", p) else f"\\{p} "
                                        for p in path]
        return ".".join(parts)

    lines = ["// Written by scripts/flows/energy/energy.py: the netlist's scopes only, one level each.",
             "module energy_dump;", "  initial begin", f'    $dumpfile("{args.vcd}");']
    for p in paths:
        lines.append(f"    $dumpvars(1, {ref(p)});")
    lines += ["  end", "endmodule", ""]
    open(args.out, "w").write("\n".join(lines))
    return 0


STA_SLEWS = r"""
# energy.py: every leaf cell input pin's transition time (ns), rise and fall, at the SDC.
set f [open {%s} w]
foreach pin [get_pins -hierarchical *] {
  if {[get_property $pin direction] != "input"} { continue }
  if {[catch {set r [get_property $pin actual_rise_transition_max]
              set fl [get_property $pin actual_fall_transition_max]}]} { continue }
  puts $f "[get_full_name $pin] $r $fl"
}
close $f
"""


def sta_slews(args):
    open(args.tcl, "w").write(STA_SLEWS % args.out)
    return 0


def report(args):
    """energy.json and energy.md of OUT_DIR from energy_sdf.json (and energy_zero.json)."""
    d = args.dir
    sdf = json.load(open(f"{d}/energy_sdf.json"))
    zero = json.load(open(f"{d}/energy_zero.json")) if os.path.exists(f"{d}/energy_zero.json") else None
    n = sdf["results"]
    if n == 0:
        raise SystemExit("energy.py: the replay produced no result (no strobe seen)")

    def per(x):
        return x / n
    cpr = args.clocks_per_result
    leak_pj = lambda T: sdf["leakage_nw"] * cpr * T * 1e-6  # nW x ns = 1e-6 pJ
    logic = per(sdf["internal_pj"] + sdf["switching_pj"])
    rom = per(sdf["rom_pj"])
    out = {"top": args.top, "results": n, "period_ns": args.period, "t_sim_ns": args.t_sim,
           "clocks_per_result": cpr,
           "internal_pj": per(sdf["internal_pj"]), "switching_pj": per(sdf["switching_pj"]),
           "internal_sequential_pj": per(sdf["internal_sequential_pj"]),
           "leakage_pj_at_period": leak_pj(args.period), "rom_pj": rom,
           "rom_reads_per_result": {k: v / n for k, v in sdf["rom_reads"].items()},
           "rom_energy_per_read_pj": sdf["rom_energy_per_read_pj"],
           "toggles_per_result": per(sdf["toggles"]), "leakage_nw": sdf["leakage_nw"],
           "cells": sdf["cells"], "nets": sdf["nets"]}
    out["total_pj_at_period"] = logic + rom + leak_pj(args.period)
    if args.t_sim:
        out["leakage_pj_at_t_sim"] = leak_pj(args.t_sim)
        out["total_pj_at_t_sim"] = logic + rom + leak_pj(args.t_sim)
    if zero:
        zn = zero["results"]
        out["zero_delay_results"] = zn
        zl = (zero["internal_pj"] + zero["switching_pj"]) / max(zn, 1)
        out["zero_delay_logic_pj"] = zl
        out["zero_delay_rom_pj"] = zero["rom_pj"] / max(zn, 1)
        out["zero_delay_toggles_per_result"] = zero["toggles"] / max(zn, 1)
        out["glitch_toggle_share"] = 1 - out["zero_delay_toggles_per_result"] / out["toggles_per_result"]
        out["glitch_logic_energy_share"] = 1 - zl / logic
        out["glitch_energy_share"] = 1 - (zl + out["zero_delay_rom_pj"]) / (logic + rom)
    # convergence: dynamic energy (logic, equal related-pin weights, + ROM) per result
    cps = sdf["checkpoints"]
    conv = []
    final = cps[-1][2] / cps[-1][1]
    for frac in (0.125, 0.25, 0.5, 0.75, 1.0):
        k = max(1, int(round(frac * len(cps)))) - 1
        t, r, e = cps[k]
        conv.append({"results": r, "pj_per_result": e / r, "vs_final": e / r / final - 1})
    half = [e / r / final - 1 for t, r, e in cps[len(cps) // 2:]]
    out["convergence"] = conv
    out["convergence_max_dev_second_half"] = max(abs(x) for x in half)
    # The random operands after the edge cases (the first RANDOM_FROM results): their mean
    # per result, its spread and standard error, and how the running mean settles.
    k0 = min(args.random_from, len(cps) - 1)
    base = cps[k0 - 1][2] if k0 > 0 else 0.0
    inc = [cps[k][2] - (cps[k - 1][2] if k > 0 else 0.0) for k in range(k0, len(cps))]
    if len(inc) >= 4:
        m = sum(inc) / len(inc)
        sd = (sum((x - m) ** 2 for x in inc) / (len(inc) - 1)) ** 0.5
        run = []
        acc = 0.0
        for j, x in enumerate(inc, 1):
            acc += x
            run.append(acc / j)
        scale = (logic + rom) / final  # the exact energy / the running figure's weights
        out["random_from"] = k0
        out["random_results"] = len(inc)
        out["random_dynamic_pj"] = m * scale
        out["random_dynamic_sd_pj"] = sd * scale
        out["random_dynamic_sem_rel"] = sd / m / len(inc) ** 0.5
        out["random_running_max_dev_second_half"] = max(abs(x / m - 1) for x in run[len(run) // 2:])
        out["random_results_for_1pct_sem"] = int((sd / m / 0.01) ** 2) + 1
        # the design's figure: the mean over the random operands (the same distribution for
        # every design, whatever its stream's length), settled when its standard error is 1 %
        out["random_total_pj_at_period"] = m * scale + leak_pj(args.period)
        if args.t_sim:
            out["random_total_pj_at_t_sim"] = m * scale + leak_pj(args.t_sim)
        out["settled_1pct"] = out["random_dynamic_sem_rel"] <= 0.01
        out["random_running"] = [{"results": j, "pj_per_result": run[j - 1] * scale}
                                 for j in sorted({max(1, len(run) // 8), len(run) // 4, len(run) // 2,
                                                  3 * len(run) // 4, len(run)})]
    if args.per_result_out:
        # each result's own energy, for the transaction-level model's fit (issue 61): the
        # running energy's increment from the previous result's strobe to its own, scaled
        # as random_dynamic_pj is, plus the leakage over that interval; the results before
        # the stream's (lead_results: a testbench's own operations) left out, so that line
        # k is the stimulus's k-th operation.
        scale = (logic + rom) / final
        lead = args.lead_results
        if len(cps) <= lead:
            raise SystemExit(f"energy.py: {len(cps)} results, not more than the {lead} before the stream")
        with open(args.per_result_out, "w") as fo:
            fo.write("# index\tpj\tclocks\n")
            for k in range(lead, len(cps)):
                t0, _, e0 = cps[k - 1] if k > 0 else (0.0, 0, 0.0)
                t, _, e = cps[k]
                dt_ns = t - t0  # energy_*.json's checkpoints are in ns
                pj = (e - e0) * scale + sdf["leakage_nw"] * dt_ns * 1e-6
                fo.write(f"{k - lead}\t{pj:.3f}\t{dt_ns / args.period:.2f}\n")
    json.dump(out, open(f"{d}/energy.json", "w"), indent=1)
    f = lambda x: f"{x:.1f}"
    lines = [f"# Energy per result: {args.top}", "",
             f"{n} results replayed at {args.period} ns (SDF delays); pJ per result.", "",
             "| part | pJ |", "|---|---:|",
             f"| logic internal | {f(out['internal_pj'])} |",
             f"| logic switching | {f(out['switching_pj'])} |",
             f"| ROM reads | {f(rom)} |",
             f"| leakage at {args.period} ns | {out['leakage_pj_at_period']:.3f} |",
             f"| **total at {args.period} ns** | **{f(out['total_pj_at_period'])}** |"]
    if args.t_sim:
        lines += [f"| leakage at T_sim {args.t_sim} ns | {out['leakage_pj_at_t_sim']:.3f} |",
                  f"| **total at T_sim** | **{f(out['total_pj_at_t_sim'])}** |"]
    lines += ["", "ROM reads per result: " + ", ".join(
        f"{k} {v:.2f} (x {sdf['rom_energy_per_read_pj'][k]:.1f} pJ)" for k, v in out["rom_reads_per_result"].items())]
    if zero:
        lines += ["", f"Zero-delay replay ({zn} results): logic {f(zl)} pJ, ROM {f(out['zero_delay_rom_pj'])} pJ, "
                  f"toggles {out['zero_delay_toggles_per_result']:.0f} against {out['toggles_per_result']:.0f}: "
                  f"glitches {100 * out['glitch_toggle_share']:.1f} % of the toggles, "
                  f"{100 * out['glitch_logic_energy_share']:.1f} % of the logic energy, "
                  f"{100 * out['glitch_energy_share']:.1f} % of logic + ROM."]
    lines += ["", "Convergence (dynamic pJ per result over the first k results, against all):", "",
              "| k | pJ / result | against the whole run |", "|---:|---:|---:|"]
    lines += [f"| {c['results']} | {c['pj_per_result']:.1f} | {100 * c['vs_final']:+.2f} % |" for c in conv]
    lines += ["", f"Largest deviation over the second half of the run: "
              f"{100 * out['convergence_max_dev_second_half']:.2f} %.", ""]
    if "random_results" in out:
        lines += [f"The random operands (results {out['random_from'] + 1} to {n}, after the edge cases): "
                  f"{out['random_dynamic_pj']:.1f} pJ per result (logic + ROM), standard deviation "
                  f"{out['random_dynamic_sd_pj']:.1f} pJ, standard error of the mean "
                  f"{100 * out['random_dynamic_sem_rel']:.2f} %; the running mean stays within "
                  f"{100 * out['random_running_max_dev_second_half']:.2f} % of it over the second half; "
                  f"a 1 % standard error needs {out['random_results_for_1pct_sem']} random results: "
                  f"{'settled' if out['settled_1pct'] else 'NOT settled to 1 % (a longer stream: --random)'}. "
                  f"Energy per result over the random operands: "
                  f"{out['random_total_pj_at_period']:.1f} pJ at {args.period} ns.", "",
                  "| random results | pJ / result (running mean) |", "|---:|---:|"]
        lines += [f"| {r['results']} | {r['pj_per_result']:.1f} |" for r in out["random_running"]]
        lines.append("")
    open(f"{d}/energy.md", "w").write("\n".join(lines))
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    d = sub.add_parser("dumper")
    d.add_argument("netlist")
    d.add_argument("top")
    d.add_argument("tb_top")
    d.add_argument("vcd")
    d.add_argument("out")
    c = sub.add_parser("compute")
    c.add_argument("--lib", action="append", required=True)
    c.add_argument("--netlist", required=True)
    c.add_argument("--top", required=True)
    c.add_argument("--tb-top", required=True)
    c.add_argument("--vcd", required=True)
    c.add_argument("--slews")
    c.add_argument("--rom-model")
    c.add_argument("--results-strobe", required=True)
    c.add_argument("--results-mode", choices=["rise", "fall", "clk_valid"], default="rise")
    c.add_argument("--clock")
    c.add_argument("--t-begin", type=float, default=0.0)
    c.add_argument("--toggles-out")
    c.add_argument("--wire-cap", help="NET PF lines: routed wire capacitance per net (scripts/flows/layout/layout.sh)")
    c.add_argument("--wire-out", help="write each wired net's wire, toggles and the wire's own switching energy")
    c.add_argument("--counter", help="tools/vcd_activity/specular_vcd_activity: count with it "
                   "(the same rules as this file's reader, which counts without it)")
    c.add_argument("--out", required=True)
    s = sub.add_parser("sta-slews")
    s.add_argument("tcl")
    s.add_argument("out")
    r = sub.add_parser("report")
    r.add_argument("--top", required=True)
    r.add_argument("--dir", required=True)
    r.add_argument("--period", type=float, required=True)
    r.add_argument("--t-sim", type=float)
    r.add_argument("--clocks-per-result", type=float, required=True)
    r.add_argument("--random-from", type=int, default=0,
                   help="results before the random operands (edge cases): 10 x groups, or 18")
    r.add_argument("--per-result-out", help="write each result's energy (TSV: index in the stimulus, "
                   "pJ dynamic as random_dynamic_pj plus the leakage over its interval, clocks)")
    r.add_argument("--lead-results", type=int, default=0,
                   help="results before the stimulus's first (the testbench's own): left out of --per-result-out")
    args = ap.parse_args()
    return {"dumper": dumper, "compute": compute, "sta-slews": sta_slews,
            "report": report}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
