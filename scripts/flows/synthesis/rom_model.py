#!/usr/bin/env python3
"""Every read-only memory of a top as a memory macro of the OSU 0.18 um flow
(scripts/flows/synthesis/silicon.sh): ROM 5 and ROM 38 of the device, and any table of a design variant
(exp2, reciprocal, a second ROM 5, ...), each sized by its words and width.

No public area or access-time figure of a 0.18 um mask ROM (or ROM compiler) of these
sizes could be found, so this is the issue's fallback, a first-principles model:
  - the bit array: a contact-programmed NOR ROM cell, one NMOS per bit, of BIT_CELL_UM2
    (8 x 8 lambda at the SCMOS SUBM rules' lambda = 0.1 um of the OSU library);
  - the periphery as library cells at their Liberty areas: a NAND3X1 + INVX4 row driver
    per row, a MUX2X1 tree (WAYS - 1 per output bit) as column multiplexer, a BUFX4 per
    output, an INVX1 per column as precharge and sense;
  - the access time as the sum of stated stages: decoder (DECODER_LEVELS gate delays),
    word line (INVX8 driver into the gate capacitance of a row), bit line (cell current
    into the bit line capacitance of a column down to the sense swing) and column
    multiplexer + output buffer (MUX_LEVELS gate delays).
The constants below are the whole model; docs/silicon.md quotes them.

  rom_model.py OUT_DIR [MEMORIES_JSON]
      writes rom_macros.lib (Liberty), rom_macros_bb.v (blackboxes for Yosys),
      rom_macros_sim.v (behavioural models with the access time for the gate-level
      simulation) and rom_model.json (the figures).
      MEMORIES_JSON: Yosys `write_json` of the top after `memory -nomap` (silicon.sh's
      probe). Every $mem_v2 there must be read-only with asynchronous read ports (else
      exit 1, naming it); one macro per distinct (words, width, contents): ROM5_MACRO
      (32768 x 22) and ROM38_MACRO (16384 x 25, plus ROM38_BANK_MACRO, the one bank, for
      the report) keep their names and figures, any other is ROM_<words>X<width>_MACRO
      (a letter after it when two tables share a size). Also writes rom_macros.lef, the
      macros' abstracts for placement and routing (scripts/flows/layout/layout.sh), and each macro's words
      (NAME.hex, from the memory's INIT, read by its simulation model), a techmap per
      macro (rom_macro_map_NAME.v, from rom_macro_map.v) and rom_macro_map.ys (the
      techmap commands, each selecting its memories by module/cell).
      Without MEMORIES_JSON: the device's three macros (images rom5.hex, rom38.hex).

  rom_model.py --lef ROM_MODEL_JSON OUT_LEF [NAME ...]
      the LEF abstracts alone, from the figures of an earlier run's rom_model.json; with
      NAMEs only those macros (qflow 1.3.17's blif2cel.tcl, reading a hard-macro LEF,
      never finds the end of a macro the netlist does not use and skips every one after it).
"""
import json
import math
import os
import sys

LAMBDA_UM = 0.1
BIT_CELL_UM2 = (8 * LAMBDA_UM) * (8 * LAMBDA_UM)  # 0.64 um^2
GATE_DELAY_NS = 0.2          # one library gate at fanout 4 (NAND3X1/INVX1 tables, ~0.15-0.25)
DECODER_LEVELS = 3           # predecode NAND3, decode NAND3, word-line driver INVX8
MUX_LEVELS = 3               # column pass gate, sense inverter, BUFX4
DRIVER_KOHM = 1.5            # INVX8 output resistance
WORDLINE_FF_PER_CELL = 1.0   # gate + metal-strapped poly per bit cell
BITLINE_FF_PER_CELL = 0.5    # shared drain junction + metal per bit cell
CELL_CURRENT_UA = 100.0      # a minimum NMOS at Vgs = 1.8 V
SENSE_SWING_V = 0.3          # bit-line swing the sense inverter needs
OUTPUT_KOHM = 1.0            # BUFX4 output resistance: delay per pF of load
INPUT_PF = 0.02              # an address pin drives two NAND3 predecoder inputs
# Energy per read (issue 36), the same organisation at VDD; a read is an address change
# (scripts/flows/energy/energy.py counts them in the gate-level replay):
VDD_V = 1.8
WIRE_FF_PER_UM = 0.2         # metal at 0.18 um, area + fringe, a line over the array
ROW_PITCH_UM = 8 * LAMBDA_UM  # a bit cell's height: a predecode line's length per row
NAND3_INPUT_PF = 0.0158812   # NAND3X1 input (Liberty): a row decoder's input
MUX2_SELECT_PF = 0.0173455   # MUX2X1 input (Liberty): the column multiplexer's select
BITLINE_SWING_V = 2 * SENSE_SWING_V  # self-timed word-line pulse: the mean bit-line
                             # swing, twice the sense swing the slowest column needs
ONES_FRACTION = 0.5          # columns of the selected row whose cell discharges its line
SENSE_PJ = 0.05              # a sense inverter + output buffer transition (INVX1/BUFX4
                             # internal_power tables, 0.02-0.05 pJ at their loads)
AREA = {"NAND3X1": 36, "INVX4": 24, "INVX1": 16, "MUX2X1": 48, "BUFX4": 32}  # lib areas

# name, words, width, address bits, column ways (words per row): the device's ROMs. The
# column ways of any other table: the power of two that makes its array the squarest
# (rows closest to columns), the rule these three follow.
MACROS = [
    ("ROM5_MACRO", 32768, 22, 15, 32),
    ("ROM38_MACRO", 16384, 25, 14, 32),       # the 16 banks rtl/device/rom38.v holds
    ("ROM38_BANK_MACRO", 1024, 25, 10, 8),    # one bank: a device built for one policy
]


def squarest_ways(words, width):
    best = None
    for k in range(0, 11):
        ways = 1 << k
        rows = -(-words // ways)
        score = abs(rows - ways * width)
        if best is None or score < best[0]:
            best = (score, ways)
    return best[1]


def model(name, words, width, abits, ways):
    rows = -(-words // ways)
    columns = ways * width
    bits = words * width
    array = bits * BIT_CELL_UM2
    periphery = (rows * (AREA["NAND3X1"] + AREA["INVX4"])
                 + width * (ways - 1) * AREA["MUX2X1"]
                 + width * AREA["BUFX4"] + columns * AREA["INVX1"])
    t_decoder = DECODER_LEVELS * GATE_DELAY_NS
    t_wordline = 0.69 * DRIVER_KOHM * columns * WORDLINE_FF_PER_CELL * 1e-3  # kohm x pF = ns
    t_bitline = rows * BITLINE_FF_PER_CELL * 1e-3 * SENSE_SWING_V / CELL_CURRENT_UA * 1e3  # pF V / uA = us
    t_output = MUX_LEVELS * GATE_DELAY_NS
    access = t_decoder + t_wordline + t_bitline + t_output
    return {"name": name, "words": words, "width": width, "address_bits": abits,
            "rows": rows, "columns": columns, "bits": bits,
            "array_um2": round(array, 1), "periphery_um2": round(periphery, 1),
            "area_um2": round(array + periphery, 1),
            "t_decoder_ns": round(t_decoder, 3), "t_wordline_ns": round(t_wordline, 3),
            "t_bitline_ns": round(t_bitline, 3), "t_output_ns": round(t_output, 3),
            "access_ns": round(access, 3)}


def model_with_energy(*args):
    m = model(*args)
    m.update(read_energy(m))
    return m


def read_energy(m):
    """Energy per read (pJ) of a macro of model(): the parts in a dict, pJ.

    - decoders: the row address in three predecode groups (a NAND3 row decoder takes one
      line of each); per read one line of each group falls and one rises, each line the
      inputs of its rows/lines decoders and a wire the array's height: C V^2 per group;
    - word line: the old row falls, the new one rises: C_wl V^2, C_wl = columns x
      WORDLINE_FF_PER_CELL (the access-time model's figure);
    - bit lines: precharged; the selected row's cells that conduct (ONES_FRACTION of the
      columns) discharge their line by BITLINE_SWING_V and the precharge restores it:
      C_bl V_DD dV each, C_bl = rows x BITLINE_FF_PER_CELL;
    - column multiplexer: its log2(ways) select lines toggle with probability 1/2, each
      into width x ways/2^(k+1) MUX2X1 selects: 1/2 C V^2 x 1/2;
    - sense and output: half the output bits change, SENSE_PJ each."""
    rows, columns, ways, width = m["rows"], m["columns"], m["columns"] // m["width"], m["width"]
    v2 = VDD_V * VDD_V
    rbits = max(1, (rows - 1).bit_length())
    sizes = [rbits // 3 + (1 if k < rbits % 3 else 0) for k in range(3)]
    wire_pf = rows * ROW_PITCH_UM * WIRE_FF_PER_UM * 1e-3
    decoder = sum((rows / (1 << g)) * NAND3_INPUT_PF * v2 + wire_pf * v2 for g in sizes if g > 0)
    wordline = columns * WORDLINE_FF_PER_CELL * 1e-3 * v2
    bitlines = columns * ONES_FRACTION * rows * BITLINE_FF_PER_CELL * 1e-3 * VDD_V * BITLINE_SWING_V
    selects = width * (ways - 1) * MUX2_SELECT_PF
    column_mux = 0.5 * 0.5 * selects * v2
    sense = 0.5 * width * SENSE_PJ
    parts = {"decoder_pj": decoder, "wordline_pj": wordline, "bitlines_pj": bitlines,
             "column_mux_pj": column_mux, "sense_output_pj": sense}
    parts = {k: round(v, 3) for k, v in parts.items()}
    parts["energy_read_pj"] = round(sum(parts.values()), 3)
    return parts


def liberty(models):
    out = ["/* ROM macros of the specular device: first-principles model, scripts/flows/synthesis/rom_model.py */",
           "library(specular_rom_macros) {",
           "  delay_model : table_lookup;",
           '  time_unit : "1ns"; voltage_unit : "1V"; current_unit : "1uA";',
           '  pulling_resistance_unit : "1kohm"; leakage_power_unit : "1nW";',
           "  capacitive_load_unit (1,pf);",
           "  slew_upper_threshold_pct_rise : 80; slew_lower_threshold_pct_rise : 20;",
           "  slew_upper_threshold_pct_fall : 80; slew_lower_threshold_pct_fall : 20;",
           "  input_threshold_pct_rise : 50; input_threshold_pct_fall : 50;",
           "  output_threshold_pct_rise : 50; output_threshold_pct_fall : 50;",
           "  nom_process : 1; nom_voltage : 1.8; nom_temperature : 25;",
           "  operating_conditions (typical) { process : 1; voltage : 1.8; temperature : 25; }",
           "  default_operating_conditions : typical;",
           "  lu_table_template(rom_load) { variable_1 : total_output_net_capacitance; index_1 (\"0.0, 1.0\"); }"]
    widths = sorted({m["width"] for m in models} | {m["address_bits"] for m in models})
    for w in widths:
        out.append(f"  type (bus{w}) {{ base_type : array; data_type : bit; bit_width : {w}; "
                   f"bit_from : {w - 1}; bit_to : 0; downto : true; }}")
    for m in models:
        t = m["access_ns"]
        delay = f'index_1 ("0.0, 1.0"); values ("{t:.3f}, {t + OUTPUT_KOHM:.3f}");'
        slew = f'index_1 ("0.0, 1.0"); values ("0.100, {0.1 + 2.2 * OUTPUT_KOHM:.3f}");'
        out += [f"  cell ({m['name']}) {{",
                f"    area : {m['area_um2']};",
                "    dont_use : true;",
                f"    bus (A) {{ bus_type : bus{m['address_bits']}; direction : input; capacitance : {INPUT_PF}; }}",
                f"    bus (Q) {{ bus_type : bus{m['width']}; direction : output; max_capacitance : 1.0;"]
        # One timing group per output bit, related to every address bit (a bus-to-bus
        # timing group of unequal widths is refused by OpenSTA).
        for bit in range(m["width"]):
            out += [f"      pin (Q[{bit}]) {{",
                    '        timing () { related_pin : "A"; timing_sense : non_unate;',
                    f"          cell_rise (rom_load) {{ {delay} }}",
                    f"          cell_fall (rom_load) {{ {delay} }}",
                    f"          rise_transition (rom_load) {{ {slew} }}",
                    f"          fall_transition (rom_load) {{ {slew} }}",
                    "        }", "      }"]
        out += ["    }", "  }"]
    out.append("}")
    return "\n".join(out) + "\n"


def blackboxes(models):
    out = ["// ROM macros as blackboxes for Yosys (scripts/flows/synthesis/rom_model.py)."]
    for m in models:
        out += ["(* blackbox *)",
                f"module {m['name']} (input wire [{m['address_bits'] - 1}:0] A, "
                f"output wire [{m['width'] - 1}:0] Q);", "endmodule"]
    return "\n".join(out) + "\n"


def behavioural(models, images=None):
    out = ["// ROM macros for the gate-level simulation (scripts/flows/gatelevel/gatesim.sh): the words of the",
           "// image, valid the Liberty access time after the address settles (an inertial",
           "// delay: an address held shorter than the access time never reaches Q).",
           "`timescale 1ns / 10ps"]
    if images is None:
        images = {"ROM5_MACRO": "rom5.hex", "ROM38_MACRO": "rom38.hex"}
    for m in models:
        if m["name"] not in images:
            continue  # one bank: area and timing only (the netlist holds all 16 banks)
        a, w = m["address_bits"], m["width"]
        out += [f"module {m['name']} (A, Q);",
                f'  parameter IMAGE = "{images[m["name"]]}";',
                f"  parameter real ACCESS = {m['access_ns']:.3f};",
                f"  input wire [{a - 1}:0] A;",
                f"  output wire [{w - 1}:0] Q;",
                f"  reg [{w - 1}:0] words [0:{m['words'] - 1}];",
                "  initial $readmemh(IMAGE, words);",
                "  assign #(ACCESS) Q = words[A];",
                "endmodule"]
    return "\n".join(out) + "\n"


# The LEF abstract of a macro (scripts/flows/layout/layout.sh): an outline of the model's area with the
# bit array's aspect (columns wide, rows high, the same bit cell), its pins on metal2 along
# the bottom edge, and obstructions on metal1-3 over the rest (the array and its decoders
# use them) but a channel along the pins on metal2 and metal3 (LEF_CHANNEL_UM), where the
# router reaches them even when the placer puts that edge against the die's; metal4-6
# stay free for routing over the macro. No power pins: the model has no
# supply network, and the layout does not connect one (docs/silicon.md says so).
LEF_GRID_X_UM = 1.6          # twice the metal2 pitch (0.8 um): pins on every other track
LEF_GRID_Y_UM = 10.0         # the standard-cell row height
LEF_PIN_DEPTH_UM = 1.0       # a pin's length into the macro on metal2
LEF_PIN_WIDTH_UM = 0.4       # a via's metal2 pad (osu018_stdcells.lef: M2_M1, M3_M2): no notch where they meet
LEF_CHANNEL_UM = 8.0         # metal2 and metal3 obstructions start this far above the pins
LEF_OBS_LAYERS = ("metal1", "metal2", "metal3")


def outline(m):
    """Width and height (um) of a macro: its area at the bit array's aspect, rounded up
    to the placement grid."""
    aspect = m["columns"] / m["rows"]   # the bit cell is square
    w = math.sqrt(m["area_um2"] * aspect)
    h = m["area_um2"] / w
    snap = lambda v, g: math.ceil(v / g - 1e-9) * g
    return round(snap(w, LEF_GRID_X_UM), 3), round(snap(h, LEF_GRID_Y_UM), 3)


def lef(models):
    out = ["# ROM macros of the specular device: LEF abstracts of the first-principles model,",
           "# scripts/flows/synthesis/rom_model.py (the same figures as rom_macros.lib)",
           "VERSION 5.4 ;", "NAMESCASESENSITIVE ON ;", 'BUSBITCHARS "[]" ;', 'DIVIDERCHAR "/" ;',
           "UNITS", "  DATABASE MICRONS 1000 ;", "END UNITS", ""]
    for m in models:
        w, h = outline(m)
        pins = [f"A[{k}]" for k in range(m["address_bits"])] + [f"Q[{k}]" for k in range(m["width"])]
        slots = int(w // LEF_GRID_X_UM) - 1
        if slots < len(pins):
            raise SystemExit(f"rom_model.py: macro {m['name']} is {w} um wide, too narrow for "
                             f"{len(pins)} pins at {LEF_GRID_X_UM} um")
        step = slots // (len(pins) + 1)
        out += [f"MACRO {m['name']}", "  CLASS BLOCK ;", f"  FOREIGN {m['name']} 0.000 0.000 ;",
                "  ORIGIN 0.000 0.000 ;", f"  SIZE {w:.3f} BY {h:.3f} ;", "  SYMMETRY X Y ;"]
        for k, pin in enumerate(pins):
            # on a metal2 track when the macro's x is (qflow's tracks: 0.8 um from the die corner)
            x = (k + 1) * step * LEF_GRID_X_UM
            direction = "INPUT" if pin.startswith("A") else "OUTPUT"
            out += [f"  PIN {pin}", f"    DIRECTION {direction} ;", "    USE SIGNAL ;", "    PORT",
                    "      LAYER metal2 ;",
                    f"        RECT {x - LEF_PIN_WIDTH_UM / 2:.3f} 0.000 {x + LEF_PIN_WIDTH_UM / 2:.3f} {LEF_PIN_DEPTH_UM:.3f} ;",
                    "    END", f"  END {pin}"]
        out.append("  OBS")
        for layer in LEF_OBS_LAYERS:
            y0 = 0.0 if layer == "metal1" else LEF_PIN_DEPTH_UM + LEF_CHANNEL_UM
            out += [f"    LAYER {layer} ;", f"      RECT 0.000 {y0:.3f} {w:.3f} {h:.3f} ;"]
        out += ["  END", f"END {m['name']}", ""]
    out.append("END LIBRARY")
    return "\n".join(out) + "\n"


MAP_TEMPLATE = "rom_macro_map.v"   # beside this file; NAME, ABITS placeholders


def memories(path):
    """The $mem_v2 cells of a Yosys JSON: (module, cell, words, width, init bits)."""
    design = json.load(open(path))
    found = []
    for module, body in design["modules"].items():
        for cell, c in body.get("cells", {}).items():
            if c["type"] != "$mem_v2":
                continue
            p = {k: v for k, v in c["parameters"].items()}
            num = lambda k: int(p[k], 2)
            if num("WR_PORTS") != 0 or num("RD_PORTS") != 1 or set(p["RD_CLK_ENABLE"]) != {"0"}:
                raise SystemExit(f"rom_model.py: memory {module}/{cell} is not a read-only memory "
                                 f"with one asynchronous read port (WR_PORTS {num('WR_PORTS')}, "
                                 f"RD_PORTS {num('RD_PORTS')}, RD_CLK_ENABLE {p['RD_CLK_ENABLE']}); "
                                 "only ROMs become macros")
            found.append((module, cell, num("SIZE"), num("WIDTH"), p["INIT"]))
    return found


def hex_words(init, words, width):
    """INIT (MSB first, word k at bits [k*width +: width]) as $readmemh lines, word 0 first."""
    digits = -(-width // 4)
    lines = []
    for k in range(words):
        end = len(init) - k * width
        bits = init[max(end - width, 0):end] if end > 0 else ""
        bits = bits.rjust(digits * 4, "0")
        line = ""
        for i in range(0, len(bits), 4):
            nib = bits[i:i + 4]
            line += "x" if any(b not in "01" for b in nib) else f"{int(nib, 2):x}"
        lines.append(line)
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) >= 4 and sys.argv[1] == "--lef":
        models = json.load(open(sys.argv[2]))["macros"]
        if len(sys.argv) > 4:   # only these (qflow's blif2cel reads past an unused macro)
            models = [m for m in models if m["name"] in sys.argv[4:]]
        with open(sys.argv[3], "w") as f:
            f.write(lef(models))
        return 0
    if len(sys.argv) not in (2, 3):
        sys.stderr.write("usage: rom_model.py OUT_DIR [MEMORIES_JSON]\n")
        return 2
    out = sys.argv[1]
    images = None
    instances = {}
    if len(sys.argv) == 2:
        models = [model_with_energy(*m) for m in MACROS]
    else:
        known = {(m[1], m[2]): m for m in MACROS[:2]}
        groups = {}   # (words, width, init) -> name
        order = []
        for module, cell, words, width, init in memories(sys.argv[2]):
            key = (words, width, init)
            if key not in groups:
                taken = {groups[k] for k in groups}
                if (words, width) in known and known[(words, width)][0] not in taken:
                    name = known[(words, width)][0]
                else:
                    base = f"ROM_{words}X{width}"
                    name = f"{base}_MACRO"
                    letter = ord("B")
                    while name in taken:
                        name = f"{base}{chr(letter)}_MACRO"
                        letter += 1
                groups[key] = name
                order.append(key)
            instances.setdefault(groups[key], []).append(f"{module}/{cell}")
        models, images = [], {}
        for key in order:
            words, width, init = key
            name = groups[key]
            abits = max(1, (words - 1).bit_length())
            if (words, width) in known and known[(words, width)][0] == name:
                models.append(model_with_energy(*known[(words, width)]))
            else:
                models.append(model_with_energy(name, words, width, abits, squarest_ways(words, width)))
            with open(f"{out}/{name}.hex", "w") as f:
                f.write(hex_words(init, words, width))
            images[name] = f"{out}/{name}.hex"
            if name == "ROM38_MACRO":
                models.append(model_with_energy(*MACROS[2]))
        template = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), MAP_TEMPLATE)).read()
        commands = []
        for m in models:
            if m["name"] not in instances:
                continue
            mapfile = f"{out}/rom_macro_map_{m['name']}.v"
            with open(mapfile, "w") as f:
                f.write(template.replace("MACRO_NAME", m["name"])
                        .replace("MACRO_WORDS", str(m["words"]))
                        .replace("MACRO_WIDTH", str(m["width"]))
                        .replace("MACRO_ABITS", str(m["address_bits"])))
            for inst in instances[m["name"]]:
                commands.append(f"techmap -map {mapfile} {inst}")
        with open(f"{out}/rom_macro_map.ys", "w") as f:
            f.write("\n".join(commands) + "\n")
    with open(f"{out}/rom_macros.lib", "w") as f:
        f.write(liberty(models))
    with open(f"{out}/rom_macros_bb.v", "w") as f:
        f.write(blackboxes(models))
    with open(f"{out}/rom_macros.lef", "w") as f:
        f.write(lef(models))
    with open(f"{out}/rom_macros_sim.v", "w") as f:
        f.write(behavioural(models, images))
    constants = {k: v for k, v in globals().items()
                 if k.isupper() and k not in ("AREA", "MACROS", "MAP_TEMPLATE", "LEF_OBS_LAYERS")}
    with open(f"{out}/rom_model.json", "w") as f:
        json.dump({"constants": constants, "macros": models, "instances": instances}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
