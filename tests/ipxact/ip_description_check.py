#!/usr/bin/python3
"""The IP's descriptions for SoC tools (ip/, docs/ipxact.md) against their sources.

  ip_description_check.py ipxact  EXPORT SOURCE_DIR SCRATCH
      ip/specular_unit.xml, read with lxml, against the C++ register map: every
      register, register file, array and field (offset, width, access, reset,
      enumerated values). Validated against IEEE 1685-2014's index.xsd when
      SPECULAR_IPXACT_SCHEMA names it; otherwise well-formedness and the structure
      walked here (the schema is not in the project: docs/ipxact.md, "Validating").
  ip_description_check.py systemrdl EXPORT SOURCE_DIR SCRATCH
      ip/specular_unit.rdl, read with systemrdl_subset (tokeniser + recursive
      descent), against the same map.
  ip_description_check.py rtl-ports EXPORT SOURCE_DIR SCRATCH YOSYS ROM_DIR
      the component's Verilog ports, module parameters and file sets against Yosys's
      reading of rtl/device/specular_device.v and rtl/device/specular_device_sync.v;
      every file a Verilog file set or rom_images names exists in the source tree, each
      ROM image beside the Verilog that reads it.
  ip_description_check.py resets EXPORT SOURCE_DIR SCRATCH IVERILOG VVP ROM_DIR
      specular_ip_axi.xml's resets of CONFIG, PIN19_H and PIN20_A, evaluated with
      parameter values other than the defaults, against what the IP reads back when
      Icarus elaborates it with those values (ip_reset_readback_tb.v).
  ip_description_check.py resolved EXPORT SOURCE_DIR SCRATCH
      `specular_ip_export --ipxact-resolved --set ...` (numbers for tools that evaluate no
      expression): every number in it equal to specular_ip_axi.xml's expression evaluated
      with the same values; bad --set values refused with exit 2 and the allowed range.
  ip_description_check.py current EXPORT SOURCE_DIR SCRATCH
      the committed ip/ files equal what specular_ip_export writes now.

The C++ map comes from `specular_ip_export --json`: a dump of register_map and
register_fields (map_json.cpp) that shares no code with the XML and RDL writers; the
expected IP-XACT and SystemRDL words for each C++ access are this file's own tables.
Exit 0 pass, 1 a difference (each one listed), 2 bad use.
"""
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

NS = "http://www.accellera.org/XMLSchema/IPXACT/1685-2014"
Q = "{%s}" % NS

# C++ Access -> (IP-XACT access, modifiedWriteValue or None)
IPXACT_ACCESS = {
    "read_only": ("read-only", None),
    "read_write": ("read-write", None),
    "write_1_to_clear": ("read-write", "oneToClear"),
    "self_clearing": ("write-only", None),
}
# C++ Access -> SystemRDL properties that must hold
RDL_ACCESS = {
    "read_only": {"sw": "r", "hw": "w"},  # the device writes it
    "read_write": {"sw": "rw", "hw": "r"},  # storage the device reads
    "write_1_to_clear": {"sw": "rw", "hw": "r", "onwrite": "woclr", "hwset": True},
    "self_clearing": {"sw": "w", "hw": "r", "singlepulse": True},
}
RDL_WRITE_EFFECTS = ("onwrite", "singlepulse", "onread", "hwset", "hwclr", "woclr", "woset")


class Failures:
    def check(self, ok, what):
        if not ok:
            self.items.append(what)

    def __init__(self, truth="the C++ map"):
        self.items = []
        self.truth = truth

    def equal(self, got, want, what):
        self.check(got == want, f"{what}: {got!r}, {self.truth} says {want!r}")

    def finish(self, name):
        if self.items:
            for item in self.items:
                print(f"{name}: FAIL: {item}")
            print(f"{name}: {len(self.items)} difference(s)")
            return 1
        print(f"{name}: PASS")
        return 0


def cpp_map(export, scratch):
    path = os.path.join(scratch, "map.json")
    subprocess.run([export, "--json", path], check=True)
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def sv_number(text):
    """An IP-XACT 2014 constant expression as written: decimal or 'hXX / 32'hXX."""
    t = text.strip().replace("_", "")
    m = re.fullmatch(r"(\d*)'([hHdDbBoO])([0-9a-fA-F]+)", t)
    if m:
        return int(m.group(3), {"h": 16, "d": 10, "b": 2, "o": 8}[m.group(2).lower()])
    return int(t, 10)


def sv_expression(text, parameters):
    """An IP-XACT 2014 expression (SystemVerilog operators, literals as sv_number takes,
    parameters by their parameterId) evaluated with `parameters` {id: int}. This test's
    own evaluator: + - * / % ** << >> & | ^ ~ and parentheses, nothing else."""
    import ast
    literal = r"\d*'[hHdDbBoO][0-9a-fA-F_]+"
    python = re.sub(literal, lambda m: str(sv_number(m.group(0))), text.strip())
    tree = ast.parse(python, mode="eval")
    operators = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
                 ast.Mult: lambda a, b: a * b, ast.Div: lambda a, b: a // b,
                 ast.Mod: lambda a, b: a % b, ast.Pow: lambda a, b: a ** b,
                 ast.LShift: lambda a, b: a << b, ast.RShift: lambda a, b: a >> b,
                 ast.BitAnd: lambda a, b: a & b, ast.BitOr: lambda a, b: a | b,
                 ast.BitXor: lambda a, b: a ^ b}

    def value(node):
        if isinstance(node, ast.Expression):
            return value(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, int):
            return node.value
        if isinstance(node, ast.Name):
            if node.id not in parameters:
                raise ValueError(f"{text!r}: no parameter with id {node.id!r}")
            return parameters[node.id]
        if isinstance(node, ast.BinOp) and type(node.op) in operators:
            return operators[type(node.op)](value(node.left), value(node.right))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.Invert)):
            v = value(node.operand)
            return -v if isinstance(node.op, ast.USub) else ~v & 0xFFFFFFFF
        raise ValueError(f"{text!r}: not an expression this test evaluates")
    return value(tree)


def component_parameters(root, overrides=None):
    """The component's parameters {parameterId: value}, `overrides` {name: value} set."""
    values = {}
    for p in root.findall(f"{Q}parameters/{Q}parameter"):
        name = text_of(p, "name")
        v = text_of(p, "value")
        if overrides and name in overrides:
            values[p.get("parameterId")] = overrides[name]
        elif p.get("type") == "string":
            values[p.get("parameterId")] = v
        else:
            values[p.get("parameterId")] = sv_expression(v, values)
    return values


def field_reset(word, f):
    return (word >> f["shift"]) & ((1 << f["width"]) - 1)


# ---- IP-XACT -------------------------------------------------------------------------


def text_of(element, tag):
    child = element.find(Q + tag)
    return None if child is None else child.text


def check_ipxact_fields(fail, where, xml_register, cpp_fields, reset_word, parameters=None):
    fields = xml_register.findall(Q + "field")
    fail.equal([text_of(f, "name") for f in fields], [f["name"] for f in cpp_fields],
               f"{where}: fields")
    for xf, cf in zip(fields, cpp_fields):
        at = f"{where}.{cf['name']}"
        fail.equal(sv_number(text_of(xf, "bitOffset")), cf["shift"], f"{at} bitOffset")
        fail.equal(sv_number(text_of(xf, "bitWidth")), cf["width"], f"{at} bitWidth")
        resets = xf.findall(f"{Q}resets/{Q}reset/{Q}value")
        # a memory window's words (reset_word None) have no reset
        fail.equal([sv_expression(r.text, parameters or {}) for r in resets],
                   [] if reset_word is None else [field_reset(reset_word, cf)], f"{at} reset")
        access, mwv = IPXACT_ACCESS[cf["access"]]
        fail.equal(text_of(xf, "access"), access, f"{at} access")
        fail.equal(text_of(xf, "modifiedWriteValue"), mwv, f"{at} modifiedWriteValue")
        fail.equal(text_of(xf, "volatile"), "true" if cf["volatile"] else None, f"{at} volatile")
        values = [(text_of(v, "name"), sv_number(text_of(v, "value")))
                  for v in xf.findall(f"{Q}enumeratedValues/{Q}enumeratedValue")]
        fail.equal(values, [(v["name"], v["value"]) for v in cf["values"]], f"{at} enumeratedValues")


BUS_FILES = ("tlm2_generic_payload.busdef.xml", "tlm2_generic_payload.absdef.xml")


def vlnv_of(root):
    return tuple(text_of(root, t) for t in ("vendor", "library", "name", "version"))


def vlnv_ref(element):
    return tuple(element.get(a) for a in ("vendor", "library", "name", "version"))


def check_bus_interface(fail, root, bus_trees, names):
    """The socket's bus type and abstraction resolve to the definitions in ip/, and its
    port map joins a logical port of the abstraction to a port of the model; `names`:
    the component's interfaces (["socket"] for the SystemC targets, ["s_axi"] for the IP)."""
    bus_def = bus_trees[BUS_FILES[0]].getroot()
    abs_def = bus_trees[BUS_FILES[1]].getroot()
    fail.equal(bus_def.tag, Q + "busDefinition", BUS_FILES[0])
    fail.equal(abs_def.tag, Q + "abstractionDefinition", BUS_FILES[1])
    def same(got, want, what):
        fail.check(got == want, f"{what}: {got!r}, the definition in ip/ is {want!r}")
    same(vlnv_ref(abs_def.find(Q + "busType")), vlnv_of(bus_def), "the abstraction's busType")
    interfaces = root.findall(f"{Q}busInterfaces/{Q}busInterface")
    fail.equal([text_of(bi, "name") for bi in interfaces], names, "bus interfaces")
    physical = {text_of(p, "name") for p in root.findall(f"{Q}model/{Q}ports/{Q}port")}
    # done_irq: Xilinx's interrupt bus type, a master, level high, mapped to the port
    for bi in [i for i in interfaces if text_of(i, "name") == "done_irq"]:
        fail.equal(vlnv_ref(bi.find(Q + "busType")), ("xilinx.com", "signal", "interrupt", "1.0"),
                   "done_irq busType")
        refs = bi.findall(f"{Q}abstractionTypes/{Q}abstractionType/{Q}abstractionRef")
        fail.equal([vlnv_ref(r) for r in refs], [("xilinx.com", "signal", "interrupt_rtl", "1.0")],
                   "done_irq abstractionRef")
        fail.check(bi.find(Q + "master") is not None, "done_irq: not a master (the IP drives it)")
        fail.equal({text_of(p, "name"): text_of(p, "value") for p in bi.findall(f"{Q}parameters/{Q}parameter")},
                   {"SENSITIVITY": '"LEVEL_HIGH"'}, "done_irq parameters")
        mapped = [(pm.find(f"{Q}logicalPort/{Q}name").text, pm.find(f"{Q}physicalPort/{Q}name").text)
                  for pm in bi.iter(Q + "portMap")]
        fail.equal(mapped, [("INTERRUPT", "done_irq")], "done_irq portMap")
        fail.check("done_irq" in physical, "done_irq: no port done_irq in the model")
    for bi in [i for i in interfaces if text_of(i, "name") == "socket"]:
        same(vlnv_ref(bi.find(Q + "busType")), vlnv_of(bus_def), "busType")
        refs = bi.findall(f"{Q}abstractionTypes/{Q}abstractionType/{Q}abstractionRef")
        same([vlnv_ref(r) for r in refs], [vlnv_of(abs_def)], "abstractionRef")
        logical = {text_of(p, "logicalName") for p in abs_def.findall(f"{Q}ports/{Q}port")}
        for pm in bi.iter(Q + "portMap"):
            lp = pm.find(f"{Q}logicalPort/{Q}name").text
            pp = pm.find(f"{Q}physicalPort/{Q}name").text
            fail.check(lp in logical, f"portMap: no logical port {lp} in {BUS_FILES[1]}")
            fail.check(pp in physical, f"portMap: no port {pp} in the model")
    # The Verilog view of the whole IP: ARM's AXI4-Lite definitions, every signal of
    # AXI4-Lite's RTL abstraction (AMBA AXI and ACE spec., B1.1) mapped to a port of it.
    for bi in [i for i in interfaces if text_of(i, "name") == "s_axi"]:
        same(vlnv_ref(bi.find(Q + "busType")), ("amba.com", "AMBA4", "AXI4-Lite", "r0p0_0"), "s_axi busType")
        refs = bi.findall(f"{Q}abstractionTypes/{Q}abstractionType/{Q}abstractionRef")
        same([vlnv_ref(r) for r in refs], [("amba.com", "AMBA4", "AXI4-Lite_rtl", "r0p0_0")],
             "s_axi abstractionRef")
        mapped = {pm.find(f"{Q}logicalPort/{Q}name").text: pm.find(f"{Q}physicalPort/{Q}name").text
                  for pm in bi.iter(Q + "portMap")}
        fail.equal(sorted(mapped), sorted(AXI4_LITE_SIGNALS), "s_axi logical ports")
        for lp, pp in mapped.items():
            fail.check(pp in physical, f"s_axi portMap {lp}: no port {pp} in the model")


# specular_ip_axi's registers that read a parameter (specular_ip_axi.v passes them to
# specular_reg_block.v), and the defaults the C++ map's resets are
CONFIGURED = {"CONFIG": "CONFIG_VALUE", "PIN19_H": "PIN19_H_VALUE", "PIN20_A": "PIN20_A_VALUE"}

AXI4_LITE_SIGNALS = ("ACLK", "ARESETn", "AWVALID", "AWREADY", "AWADDR", "AWPROT", "WVALID",
                     "WREADY", "WDATA", "WSTRB", "BVALID", "BREADY", "BRESP", "ARVALID",
                     "ARREADY", "ARADDR", "ARPROT", "RVALID", "RREADY", "RDATA", "RRESP")


# The components, one per Verilog top (no port needs a parameter to say which top it is
# of): their file, top, view, bus interfaces, and whether their map has the batch windows.
COMPONENTS = {
    "specular_unit.xml": ("specular_device", "rtl", ["socket", "done_irq"], True),
    "specular_device_sync.xml": ("specular_device_sync", "rtl_sync", [], None),
    "specular_ip_axi.xml": ("specular_ip_axi", "rtl_axi", ["s_axi", "done_irq"], False),
}


def check_ipxact(export, source, scratch):
    from lxml import etree
    fail = Failures()
    cpp = cpp_map(export, scratch)
    bus_trees = {name: etree.parse(os.path.join(source, "ip", name)) for name in BUS_FILES}
    trees = {name: etree.parse(os.path.join(source, "ip", name)) for name in COMPONENTS}  # raises if not well-formed
    schema = os.environ.get("SPECULAR_IPXACT_SCHEMA", "")
    if schema:
        xsd = etree.XMLSchema(etree.parse(schema))
        for name, t in list(trees.items()) + list(bus_trees.items()):
            ok = xsd.validate(t)
            fail.check(ok, f"{name} not valid against {schema}: " +
                       "; ".join(str(e) for e in list(xsd.error_log)[:5]))
            print(f"ipxact: {name} validated against {schema}: {'valid' if ok else 'INVALID'}")
    else:
        print("ipxact: SPECULAR_IPXACT_SCHEMA not set: well-formedness and structure only")
    names = set()
    for file, (top, view, interfaces, windows) in COMPONENTS.items():
        root = trees[file].getroot()
        fail.equal(root.tag, Q + "component", f"{file}: root element")
        for tag in ("vendor", "library", "name", "version"):
            fail.check(bool(text_of(root, tag)), f"{file}: VLNV: no {tag}")
        fail.equal(text_of(root, "name"), file[:-4], f"{file}: the component's name")
        names.add(text_of(root, "name"))
        check_bus_interface(fail, root, bus_trees, interfaces)
        # no parameter chooses a top: every port is present, no RTL_TOP
        ports = root.findall(f"{Q}model/{Q}ports/{Q}port")
        fail.equal([text_of(p, "name") for p in ports if p.find(Q + "isPresent") is not None], [],
                   f"{file}: ports with isPresent")
        fail.equal(len({text_of(p, "name") for p in ports}), len(ports), f"{file}: port names unique")
        params = [text_of(p, "name") for p in root.findall(f"{Q}parameters/{Q}parameter")]
        fail.check("RTL_TOP" not in params, f"{file}: a parameter RTL_TOP")
        maps = root.findall(f"{Q}memoryMaps/{Q}memoryMap")
        fail.equal(len(maps), 0 if windows is None else 1, f"{file}: memory maps")
        if maps:
            check_memory_map(fail, file, root, maps[0], cpp, windows)
    fail.equal(len(names), len(COMPONENTS), "component names distinct")
    return fail.finish("ipxact")


def check_memory_map(fail, file, root, memory_map, cpp, windows):
    """The memory map against the C++ map; `windows` False: specular_ip_axi's, without
    the batch windows and with BATCH_CAPACITY 0 (docs/decisions.md)."""
    by_name = {r["name"]: r for r in cpp["registers"]}
    rows = [r for r in cpp["registers"] if windows or r["name"] not in ("BATCH_COS", "BATCH_OUT")]
    blocks = memory_map.findall(Q + "addressBlock")
    fail.equal(len(blocks), 1, f"{file}: address blocks")
    if not blocks:
        return
    block = blocks[0]
    fail.equal(sv_number(text_of(block, "baseAddress")), 0, f"{file}: baseAddress")
    parameters = component_parameters(root)
    fail.equal(sv_expression(text_of(block, "range"), parameters), cpp["map_size"], f"{file}: range")
    if not windows:
        # the IP answers (DECERR above its registers) in its whole ADDR_WIDTH window
        for width in (15, 16, 32):
            fail.equal(sv_expression(text_of(block, "range"), dict(parameters, ADDR_WIDTH=width)),
                       1 << width, f"{file}: range at ADDR_WIDTH {width}")
    fail.equal(sv_number(text_of(block, "width")), 32, f"{file}: width")
    # the bus interface names this memory map
    refs = root.findall(f"{Q}busInterfaces/{Q}busInterface/{Q}slave/{Q}memoryMapRef")
    fail.equal([r.get("memoryMapRef") for r in refs], [text_of(memory_map, "name")],
               f"{file}: slave memoryMapRef")
    entries = [e for e in block if e.tag in (Q + "register", Q + "registerFile")]
    fail.equal([text_of(e, "name") for e in entries], [r["name"] for r in rows],
               f"{file}: registers, register files and arrays in order")
    for xe, row in zip(entries, rows):
        name = row["name"]
        resets = row["reset_of_word"]
        if name == "BATCH_CAPACITY" and not windows:
            resets = [0]  # the IP's BATCH_CAPACITY_VALUE
        fail.equal(sv_number(text_of(xe, "addressOffset")), row["offset"], f"{file}: {name} addressOffset")
        if not windows and name in CONFIGURED:
            # specular_ip_axi reads the parameter: each field's reset is an expression of it
            for xf in xe.findall(Q + "field"):
                for r in xf.findall(f"{Q}resets/{Q}reset/{Q}value"):
                    fail.check(CONFIGURED[name] in r.text,
                               f"{file}: {name}.{text_of(xf, 'name')} reset {r.text!r} is not an "
                               f"expression of {CONFIGURED[name]}")
        if "aliases" in row:
            fail.equal(xe.tag, Q + "registerFile", f"{name}: an alias window is a registerFile")
            fail.equal(sv_number(text_of(xe, "range") or "0"), 4 * row["words"], f"{name} range")
            inner = xe.findall(Q + "register")
            fail.equal([text_of(r, "name") for r in inner], row["aliases"], f"{name} registers")
            for w, (xr, alias) in enumerate(zip(inner, row["aliases"])):
                fail.equal(sv_number(text_of(xr, "addressOffset")), 4 * w, f"{name}.{alias} addressOffset")
                fail.equal(sv_number(text_of(xr, "size")), 32, f"{name}.{alias} size")
                check_ipxact_fields(fail, f"{file}: {name}.{alias}", xr, by_name[alias]["fields"],
                                    resets[w], parameters)
        else:
            fail.equal(xe.tag, Q + "register", f"{name}: a register")
            dims = [sv_number(d.text) for d in xe.findall(Q + "dim")]
            fail.equal(dims, [] if row["words"] == 1 else [row["words"]], f"{name} dim")
            fail.equal(sv_number(text_of(xe, "size")), 32, f"{name} size")
            fail.check(len(set(resets)) == 1,
                       f"{name}: words with different resets cannot be one register array")
            check_ipxact_fields(fail, f"{file}: {name}", xe, row["fields"],
                                None if row["words"] > 1 else resets[0], parameters)


# ---- SystemRDL -----------------------------------------------------------------------


def rdl_identifier(name):
    return name.replace("-", "_")


def check_rdl_fields(fail, where, comp, cpp_fields, reset_word, enums):
    fields = [(c, i) for c, i in comp.children if c.kind == "field"]
    fail.equal([i.name for _, i in fields], [f["name"] for f in cpp_fields], f"{where}: fields")
    for (fc, fi), cf in zip(fields, cpp_fields):
        at = f"{where}.{cf['name']}"
        msb, lsb = fi.dims if fi.dims and len(fi.dims) == 2 else (None, None)
        fail.equal(lsb, cf["shift"], f"{at} lsb")
        fail.equal(None if msb is None else msb - lsb + 1, cf["width"], f"{at} width")
        fail.equal(fi.reset, field_reset(reset_word, cf), f"{at} reset")
        want = dict(RDL_ACCESS[cf["access"]])
        if not cf["hardware_writes"]:
            want["hw"] = "na"  # a constant: no hardware input
        got = {k: fc.properties.get(k) for k in want}
        fail.equal(got, want, f"{at} access")
        extra = [k for k in RDL_WRITE_EFFECTS if k in fc.properties and k not in want]
        fail.check(not extra, f"{at}: side effects {extra} the C++ map does not have")
        encode = fc.properties.get("encode")
        if cf["values"]:
            entries = enums[encode].entries if encode in enums else []
            fail.equal([(e[0], e[1]) for e in entries],
                       [(rdl_identifier(v["name"]), v["value"]) for v in cf["values"]], f"{at} encode")
        else:
            fail.equal(encode, None, f"{at} encode")


def check_systemrdl(export, source, scratch):
    import systemrdl_subset
    fail = Failures()
    cpp = cpp_map(export, scratch)
    with open(os.path.join(source, "ip", "specular_unit.rdl"), encoding="utf-8") as f:
        rdl = systemrdl_subset.parse(f.read())
    fail.equal(sorted(rdl.addrmaps), ["specular_unit"], "root addrmaps (no wrapper)")
    top = rdl.addrmaps.get("specular_unit")
    if top is None:
        return fail.finish("systemrdl")
    fail.equal(top.defaults.get("regwidth"), 32, "default regwidth")
    desc = str(top.properties.get("desc", ""))
    for word in ("done_irq", "LEVEL_HIGH", "ADDR_WIDTH", "BATCH_CAPACITY reads 0"):
        fail.check(word in desc, f"the addrmap's desc does not say {word!r}")
    by_name = {r["name"]: r for r in cpp["registers"]}
    # the rows in order; OPERANDS and RESULTS as WINDOW_REG aliases of their registers;
    # then MAP_END, a register not present at the map's last word: SystemRDL sizes an
    # addrmap by its last child, so the top is the map's size with no wrapper
    want = []
    for row in cpp["registers"]:
        if "aliases" in row:
            want += [(f"{row['name']}_{a}", row, w) for w, a in enumerate(row["aliases"])]
        else:
            want.append((row["name"], row, None))
    children = top.children
    fail.equal([i.name for _, i in children], [n for n, _, _ in want] + ["MAP_END"],
               "registers, aliases and windows in order")
    instances = {i.name: (c, i) for c, i in children}
    for (comp, inst), (name, row, word) in zip(children, want):
        if word is not None:
            alias = row["aliases"][word]
            fail.equal(inst.address, row["offset"] + 4 * word, f"{name} address")
            fail.equal(inst.alias_of, alias, f"{name}: an alias of")
            primary = instances.get(alias, (None, None))[0]
            fail.check(comp is primary, f"{name}: not of its primary's type")
            fail.equal(comp.kind, "reg", f"{name} kind")
            check_rdl_fields(fail, name, comp, by_name[alias]["fields"], row["reset_of_word"][word],
                             rdl.enums)
            continue
        fail.equal(inst.address, row["offset"], f"{name} address")
        fail.equal(inst.alias_of, None, f"{name}: an alias")
        if row["words"] > 1:
            # a window is an external memory of 32-bit words, no reset per word (issue 46)
            fail.equal((comp.kind, comp.external), ("mem", True), f"{name}: an external mem")
            fail.equal(inst.dims, None, f"{name}: one mem, not an array")
            fail.equal(comp.properties.get("mementries"), row["words"], f"{name} mementries")
            fail.equal(comp.properties.get("memwidth"), 32, f"{name} memwidth")
            fail.equal(comp.properties.get("sw"), "r" if row["access"] == "read_only" else "rw", f"{name} sw")
            fail.check("specular_ip_axi" in str(comp.properties.get("desc", "")),
                       f"{name}: its desc does not say specular_ip_axi lacks it")
        else:
            fail.equal(comp.kind, "reg", f"{name}: a reg")
            fail.equal(inst.dims, None, f"{name} array")
            check_rdl_fields(fail, name, comp, row["fields"], row["reset_of_word"][0], rdl.enums)
    comp, inst = instances.get("MAP_END", (None, None))
    if comp is not None:
        fail.equal((comp.kind, inst.address, comp.properties.get("ispresent")),
                   ("reg", cpp["map_size"] - 4, False), "MAP_END: a reg not present at the last word")
    capacity = instances.get("BATCH_CAPACITY", (None, None))[0]
    fail.check(capacity is not None and "0 on specular_ip_axi" in str(capacity.properties.get("desc")),
               "BATCH_CAPACITY: its desc does not say what specular_ip_axi reads")
    # the last register ends inside the map
    last = cpp["registers"][-1]
    fail.check(last["offset"] + 4 * last["words"] <= cpp["map_size"], "map size")
    return fail.finish("systemrdl")


# ---- the Verilog tops ----------------------------------------------------------------

TOP_FOLDER = {"specular_device": "device", "specular_device_sync": "device", "specular_ip_axi": "ip"}
RTL_FOLDERS = ("device", "primitives", "design_space", "ip")  # rtl/sources.cmake


def yosys_json(yosys, rom_dir, script, out):
    subprocess.run([yosys, "-q", "-p", script + f"; write_json {out}"], cwd=rom_dir, check=True,
                   stdout=subprocess.DEVNULL)
    with open(out, encoding="utf-8") as f:
        return json.load(f)["modules"]


def yosys_parameter(text):
    """Yosys writes integers as bit strings and strings as themselves."""
    if text and set(text) <= {"0", "1"}:
        return int(text, 2), len(text)
    return text, None


def check_rtl_ports(export, source, scratch, yosys, rom_dir):
    from lxml import etree
    fail = Failures("Yosys")
    rtl = os.path.join(source, "rtl")
    sources = sorted(os.path.join(rtl, d, f) for d in RTL_FOLDERS
                     for f in os.listdir(os.path.join(rtl, d)) if f.endswith(".v"))
    for file, (top, view, _, _) in COMPONENTS.items():
        root = etree.parse(os.path.join(source, "ip", file)).getroot()
        model = root.find(Q + "model")
        xml_ports = {text_of(p, "name"): p for p in model.findall(f"{Q}ports/{Q}port")}
        instantiations = {text_of(i, "name"): i
                          for i in model.findall(f"{Q}instantiations/{Q}componentInstantiation")}
        file_sets = {text_of(s, "name"): s for s in root.findall(f"{Q}fileSets/{Q}fileSet")}
        parameters = component_parameters(root)
        modules = yosys_json(yosys, rom_dir, f"read_verilog {rtl}/{TOP_FOLDER[top]}/{top}.v; proc",
                             os.path.join(scratch, f"{top}.json"))
        ports = modules[top]["ports"]
        # every Verilog port, in order, with its direction, width and signedness
        in_view = [name for name, p in xml_ports.items()
                   if view in [v.text for v in p.iter(Q + "viewRef")]]
        # (IP-XACT's port order has no meaning; the component lists each name once)
        fail.equal(sorted(in_view), sorted(ports), f"{top}: the ports of view {view}")
        for name, yp in ports.items():
            xp = xml_ports.get(name)
            if xp is None:
                continue
            wire = xp.find(Q + "wire")
            fail.equal(text_of(wire, "direction"), {"input": "in", "output": "out"}[yp["direction"]],
                       f"{top}.{name} direction")
            vector = wire.find(f"{Q}vectors/{Q}vector")
            width = 1 if vector is None else \
                abs(sv_expression(text_of(vector, "left"), parameters) -
                    sv_expression(text_of(vector, "right"), parameters)) + 1
            fail.equal(width, len(yp["bits"]), f"{top}.{name} width")
            type_names = [t.text for t in wire.iter(Q + "typeName")]
            fail.equal(type_names, ["wire signed" if yp.get("signed") else "wire"], f"{top}.{name} type")
            fail.check(xp.find(Q + "isPresent") is None, f"{top}.{name}: isPresent (every port is its top's)")
        # a component with parameters of its own (specular_ip_axi): its ports' widths
        # evaluated at another value of each integer parameter that sizes a port, against
        # Yosys elaborating the top with that value (chparam)
        for pid, other in (("ADDR_WIDTH", 32),) if "ADDR_WIDTH" in parameters else ():
            changed = yosys_json(yosys, rom_dir, f"read_verilog {rtl}/{TOP_FOLDER[top]}/{top}.v; "
                                 f"chparam -set {pid} {other} {top}; proc",
                                 os.path.join(scratch, f"{top}_{pid}_{other}.json"))[top]["ports"]
            for name, yp in changed.items():
                vector = xml_ports[name].find(f"{Q}wire/{Q}vectors/{Q}vector") if name in xml_ports else None
                if vector is None:
                    continue
                values = dict(parameters, **{pid: other})
                width = abs(sv_expression(text_of(vector, "left"), values) -
                            sv_expression(text_of(vector, "right"), values)) + 1
                fail.equal(width, len(yp["bits"]), f"{top}.{name} width at {pid}={other}")
        # the module parameters, in order, with their defaults
        inst = instantiations.get(view)
        fail.check(inst is not None, f"no componentInstantiation {view}")
        if inst is None:
            continue
        fail.equal(text_of(inst, "moduleName"), top, f"{view} moduleName")
        xml_params = [(text_of(p, "name"), text_of(p, "value"), p)
                      for p in inst.findall(f"{Q}moduleParameters/{Q}moduleParameter")]
        defaults = modules[top]["parameter_default_values"]
        fail.equal(sorted(n for n, _, _ in xml_params), sorted(defaults), f"{top} parameters")
        for name, value, element in xml_params:
            want, bits = yosys_parameter(defaults.get(name, ""))
            # a module parameter that follows a component parameter (specular_ip_axi) names it
            if isinstance(want, str):
                got = value[1:-1] if value.startswith('"') else str(parameters.get(value, ""))[1:-1]
            else:
                got = sv_expression(value, parameters)
            fail.equal(got, want, f"{top} parameter {name}")
            vector = element.find(f"{Q}vectors/{Q}vector")
            if bits is not None and bits != 32:  # a sized parameter
                fail.check(vector is not None and sv_number(text_of(vector, "left")) == bits - 1,
                           f"{top} parameter {name}: [{bits - 1}:0] expected")
        # the file set: the files of the modules Yosys elaborates under this top
        hierarchy = yosys_json(yosys, rom_dir,
                               f"read_verilog -defer {' '.join(sources)}; hierarchy -top {top}; proc",
                               os.path.join(scratch, f"{top}_hierarchy.json"))
        files = sorted({os.path.basename(m["attributes"]["src"].split(":")[0])
                        for m in hierarchy.values()})
        file_set = file_sets.get(f"verilog_{view}")
        listed = [] if file_set is None else \
            [os.path.basename(text_of(f, "name")) for f in file_set.findall(Q + "file")]
        fail.equal(sorted(listed), files, f"file set verilog_{view}")
        for f in ([] if file_set is None else file_set.findall(Q + "file")):
            rel = text_of(f, "name")  # relative to ip/, as installed beside share/SpecularUnit/rtl
            fail.check(os.path.isfile(os.path.join(source, "ip", rel)), f"{rel}: no such file")
        # the ROM images the top reads ($readmemh), in their own file set, named by its view
        roms = file_sets.get("rom_images")
        named = [] if roms is None else [text_of(f, "name") for f in roms.findall(Q + "file")]
        fail.equal(sorted(os.path.basename(n) for n in named), ["rom38.hex", "rom5.hex"],
                   f"{file}: file set rom_images")
        # each image beside a file of the top's set that reads it with $readmemh (and names it
        # as its default): where Yosys finds it after its working folder, in both trees
        readers = [os.path.join(source, "ip", text_of(f, "name"))
                   for f in ([] if file_set is None else file_set.findall(Q + "file"))]
        for rel in named:
            image = os.path.basename(rel)
            beside = [v for v in readers if os.path.dirname(v) == os.path.dirname(os.path.join(source, "ip", rel))
                      and os.path.isfile(v) and "$readmemh" in open(v, encoding="utf-8").read()
                      and f'"{image}"' in open(v, encoding="utf-8").read()]
            fail.check(beside, f"{file}: rom_images {rel} is not beside the Verilog that reads {image}")
        refs = [] if inst is None else [text_of(r, "localName") for r in inst.findall(Q + "fileSetRef")]
        fail.check("rom_images" in refs, f"{view}: no fileSetRef rom_images")
        # every file a file set names relative to ip/ exists in the source tree (the install
        # mirrors ip/ and rtl/); ../../../ names the installed SystemC package (headers below)
        for fs in file_sets.values():
            for f in fs.findall(Q + "file"):
                rel = text_of(f, "name")
                if not rel.startswith("../../../"):
                    fail.check(os.path.isfile(os.path.join(source, "ip", rel)),
                               f"{file}: file set {text_of(fs, 'name')} names {rel}, not in the source tree")
    root = etree.parse(os.path.join(source, "ip", "specular_unit.xml")).getroot()
    file_sets = {text_of(s, "name"): s for s in root.findall(f"{Q}fileSets/{Q}fileSet")}
    # the SystemC headers listed are headers of the package
    headers = file_sets.get("systemc_headers")
    for f in ([] if headers is None else headers.findall(Q + "file")):
        rel = text_of(f, "name").split("include/", 1)[1]
        fail.check(any(os.path.isfile(os.path.join(source, base, rel))
                       for base in ("modules/include", "twin/include")), f"{rel}: no such header")
    return fail.finish("rtl-ports")


# Parameter sets other than the defaults: every field of CONFIG changed (normalisation
# energy / device-energy, saturation literal, constants minimax / minimax-half, other
# widths), h and a other than the patent's (a negative), and ADDR_WIDTH at 16 and 32.
RESET_CASES = (
    {},
    {"CONFIG_VALUE": 0x080D1051, "PIN19_H_VALUE": 0x66, "PIN20_A_VALUE": 0x3F0000, "ADDR_WIDTH": 16},
    {"CONFIG_VALUE": 0x0A0C0E33, "PIN19_H_VALUE": 0x2AB, "PIN20_A_VALUE": 0xFFC00000, "ADDR_WIDTH": 32},
)


def check_resets(export, source, scratch, iverilog, vvp, rom_dir):
    from lxml import etree
    fail = Failures("the RTL's read-back")
    root = etree.parse(os.path.join(source, "ip", "specular_ip_axi.xml")).getroot()
    block = root.find(f"{Q}memoryMaps/{Q}memoryMap/{Q}addressBlock")
    registers = {text_of(r, "name"): r for r in block.findall(Q + "register")}
    rtl = os.path.join(source, "rtl")
    sources = sorted(os.path.join(rtl, d, f) for d in ("device", "primitives", "ip")
                     for f in os.listdir(os.path.join(rtl, d))
                     if f.endswith(".v") and not f.endswith("_props.v"))
    bench = os.path.join(HERE, "ip_reset_readback_tb.v")
    for n, case in enumerate(RESET_CASES):
        where = ", ".join(f"{k}={v:#x}" if k != "ADDR_WIDTH" else f"{k}={v}" for k, v in case.items()) \
            or "defaults"
        out = os.path.join(scratch, f"case{n}.vvp")
        args = [iverilog, "-g2005", "-Wall", "-Wno-timescale", "-o", out, "-s", "ip_reset_readback_tb",
                f'-Pip_reset_readback_tb.ROM5_IMAGE="{rom_dir}/rom5.hex"',
                f'-Pip_reset_readback_tb.ROM38_IMAGE="{rom_dir}/rom38.hex"']
        args += [f"-Pip_reset_readback_tb.{k}={v}" for k, v in case.items()]
        built = subprocess.run(args + sources + [bench], capture_output=True, text=True)
        if built.returncode != 0:
            fail.check(False, f"{where}: iverilog failed: {built.stderr.strip()[:400]}")
            continue
        ran = subprocess.run([vvp, "-n", out], capture_output=True, text=True, cwd=scratch)
        read = {m.group(1): (int(m.group(2), 16), int(m.group(3)))
                for m in re.finditer(r"READ (\w+) 0x([0-9a-fA-F]+) resp (\d+)", ran.stdout)}
        fail.equal(sorted(read), sorted(CONFIGURED), f"{where}: registers read")
        parameters = component_parameters(root, case)
        for name, (value, response) in read.items():
            fail.equal(response, 0, f"{where}: {name} response")
            xr = registers.get(name)
            if xr is None:
                fail.check(False, f"no register {name} in specular_ip_axi.xml")
                continue
            described, mask = 0, 0
            for xf in xr.findall(Q + "field"):
                shift = sv_number(text_of(xf, "bitOffset"))
                width = sv_number(text_of(xf, "bitWidth"))
                reset = sv_expression(xf.find(f"{Q}resets/{Q}reset/{Q}value").text, parameters)
                fail.check(0 <= reset < 1 << width,
                           f"{where}: {name}.{text_of(xf, 'name')} reset {reset:#x} wider than {width} bits")
                described |= reset << shift
                mask |= ((1 << width) - 1) << shift
            fail.check(described == value & mask,
                       f"{where}: {name} reset in the XML {described:#010x} (its fields' bits "
                       f"{mask:#010x}), the RTL reads {value:#010x}")
            print(f"resets: {where}: {name} XML {described:#010x} RTL {value:#010x}")
    return fail.finish("resets")


def check_resolved(export, source, scratch):
    from lxml import etree
    fail = Failures("specular_ip_axi.xml evaluated")
    expressions = etree.parse(os.path.join(source, "ip", "specular_ip_axi.xml")).getroot()
    for n, case in enumerate(RESET_CASES):
        out = os.path.join(scratch, f"resolved{n}.xml")
        args = [export, "--source-dir", source, "--ipxact-resolved", out]
        if case:
            args += ["--set", ",".join(f"{k}={v:#x}" for k, v in case.items())]
        subprocess.run(args, check=True)
        resolved = etree.parse(out).getroot()
        parameters = component_parameters(expressions, case)
        # the same elements in the same order: every place an expression may stand
        places = {"reset": "resets/{0}reset/{0}value", "range": "range", "left": "vectors/{0}vector/{0}left"}
        for label, place in places.items():
            path = ".//" + Q + place.format(Q)
            want = [sv_expression(e.text, parameters) for e in expressions.iterfind(path)]
            got = []
            for e in resolved.iterfind(path):
                try:
                    got.append(sv_number(e.text))
                except ValueError:
                    got.append(f"not a number: {e.text!r}")
            fail.equal(got, want, f"case {n}: every {label}")
        values = {text_of(p, "name"): text_of(p, "value")
                  for p in resolved.iterfind(f".//{Q}moduleParameter")}
        for name, v in case.items():
            fail.equal(sv_number(values.get(name, "0")), v, f"case {n}: moduleParameter {name}")
    # bad values: refused, the range named
    for setting, words in (("ADDR_WIDTH=14", "15..32"), ("ADDR_WIDTH=33", "15..32"),
                           ("CONFIG_VALUE=0x100000000", "0..4294967295"), ("NO_SUCH=1", "NO_SUCH")):
        run = subprocess.run([export, "--source-dir", source, "--ipxact-resolved",
                              os.path.join(scratch, "bad.xml"), "--set", setting],
                             capture_output=True, text=True)
        fail.check(run.returncode == 2 and words in run.stderr,
                   f"--set {setting}: exit {run.returncode}, {run.stderr.strip()!r}; expected 2 naming {words}")
    return fail.finish("resolved")


def check_current(export, source, scratch):
    fail = Failures()
    fresh = {"specular_unit.xml": "--ipxact", "specular_unit.rdl": "--systemrdl"}
    args = [export, "--source-dir", source, "--bus-dir", scratch]
    for name, option in fresh.items():
        args += [option, os.path.join(scratch, name)]
    subprocess.run(args, check=True)
    for name in list(fresh) + [c for c in COMPONENTS if c not in fresh] + list(BUS_FILES):
        with open(os.path.join(scratch, name), "rb") as f:
            now = f.read()
        committed_path = os.path.join(source, "ip", name)
        committed = open(committed_path, "rb").read() if os.path.exists(committed_path) else b""
        fail.check(now == committed,
                   f"ip/{name} differs from what specular_ip_export writes now; run "
                   f"specular_ip_export --source-dir . --ipxact ip/specular_unit.xml "
                   f"--systemrdl ip/specular_unit.rdl --bus-dir ip")
    return fail.finish("current")


def main(argv):
    commands = {"ipxact": (check_ipxact, 3), "systemrdl": (check_systemrdl, 3),
                "rtl-ports": (check_rtl_ports, 5), "current": (check_current, 3),
                "resets": (check_resets, 6), "resolved": (check_resolved, 3)}
    if len(argv) < 2 or argv[1] not in commands or len(argv) - 2 != commands[argv[1]][1]:
        print(__doc__, file=sys.stderr)
        return 2
    function, _ = commands[argv[1]]
    args = [os.path.abspath(a) if i in (1, 2) else a for i, a in enumerate(argv[2:])]
    os.makedirs(args[2], exist_ok=True)
    return function(*args)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
