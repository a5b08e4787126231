"""One Liberty reader for the flows' scripts: the file's groups, its cells (pins, their
direction and capacitance, internal power tables, leakage, area) and the table lookup
OpenSTA does. Enough of Liberty for the OSU 0.18 um library and the ROM macros'
(scripts/flows/synthesis/rom_model.py); not a validator."""
import re


def tokens(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = text.replace("\\\n", " ")
    return re.findall(r'"[^"]*"|[A-Za-z0-9_.\-+\[\]!\'&|^*]+|[{}();:,]', text)


def parse(tokens):
    """Groups as dicts: {'type', 'args', 'attrs', 'groups'}."""
    root = {"type": "root", "args": [], "attrs": {}, "groups": []}
    stack = [root]
    i, n = 0, len(tokens)
    while i < n:
        t = tokens[i]
        if t == "}":
            stack.pop()
            i += 1
            continue
        if i + 1 < n and tokens[i + 1] == ":":
            j = i + 2
            val = []
            while j < n and tokens[j] != ";" and tokens[j] != "}":
                val.append(tokens[j])
                j += 1
            stack[-1]["attrs"][t] = " ".join(val).strip('"')
            i = j + 1 if j < n and tokens[j] == ";" else j
            continue
        if i + 1 < n and tokens[i + 1] == "(":
            j = i + 2
            args = []
            while tokens[j] != ")":
                if tokens[j] != ",":
                    args.append(tokens[j].strip('"'))
                j += 1
            j += 1
            if j < n and tokens[j] == "{":
                g = {"type": t, "args": args, "attrs": {}, "groups": []}
                stack[-1]["groups"].append(g)
                stack.append(g)
                i = j + 1
            else:  # complex attribute: name (args);
                stack[-1]["attrs"][t] = args
                i = j + 1 if j < n and tokens[j] == ";" else j
            continue
        i += 1
    return root


def floats(s):
    return [float(x) for x in re.split(r"[,\s]+", s.strip()) if x]


class Table:
    """A Liberty table with its template's variables; lookup(load=, slew=) bilinear,
    extrapolated linearly beyond the index (as OpenSTA does)."""

    def __init__(self, group, templates):
        tpl = templates.get(group["args"][0] if group["args"] else "", {})
        self.vars = []
        self.index = []
        for k in (1, 2):
            var = tpl.get(f"variable_{k}")
            idx = group["attrs"].get(f"index_{k}") or tpl.get(f"index_{k}")
            if var is None:
                continue
            self.vars.append(var)
            self.index.append(floats(idx[0] if isinstance(idx, list) else idx))
        vals = group["attrs"].get("values")
        rows = [floats(v) for v in (vals if isinstance(vals, list) else [vals])]
        self.values = rows

    @staticmethod
    def _seg(index, x):
        if len(index) == 1:
            return 0, 0, 0.0
        k = 0
        while k < len(index) - 2 and x > index[k + 1]:
            k += 1
        f = (x - index[k]) / (index[k + 1] - index[k])
        return k, k + 1, f

    def lookup(self, load=0.0, slew=0.0):
        x = [load if "capacitance" in v else slew for v in self.vars]
        if len(self.vars) == 0:
            return self.values[0][0]
        if len(self.vars) == 1:
            row = self.values[0] if len(self.values) == 1 else [r[0] for r in self.values]
            a, b, f = self._seg(self.index[0], x[0])
            return row[a] + f * (row[b] - row[a])
        a, b, f = self._seg(self.index[0], x[0])
        c, d, g = self._seg(self.index[1], x[1])
        v = self.values
        top = v[a][c] + g * (v[a][d] - v[a][c])
        bot = v[b][c] + g * (v[b][d] - v[b][c])
        return top + f * (bot - top)


class Library:
    """Cells: pins (direction, capacitance, bus width), internal power, leakage."""

    def __init__(self, paths):
        self.cells = {}
        for path in paths:
            root = parse(tokens(open(path).read()))
            for lib in root["groups"]:
                templates = {}
                for g in lib["groups"]:
                    if g["type"] in ("lu_table_template", "power_lut_template"):
                        templates[g["args"][0]] = {k: v for k, v in g["attrs"].items()}
                for g in lib["groups"]:
                    if g["type"] == "cell":
                        self.cells[g["args"][0]] = self._cell(g, templates)

    @staticmethod
    def _cell(g, templates):
        cell = {"leakage_nw": float(g["attrs"].get("cell_leakage_power", 0.0)),
                "area": float(g["attrs"].get("area", 0.0)), "pins": {}}
        pins = []
        for p in g["groups"]:
            if p["type"] == "pin":
                pins.append((p["args"][0], p, None))
            elif p["type"] == "bus":
                pins.append((p["args"][0], p, True))
                for q in p["groups"]:
                    if q["type"] == "pin":
                        pins.append((q["args"][0], q, None))
        for name, p, is_bus in pins:
            entry = cell["pins"].setdefault(name, {"direction": None, "cap": 0.0, "power": []})
            if "direction" in p["attrs"]:
                entry["direction"] = p["attrs"]["direction"]
            if "capacitance" in p["attrs"]:
                entry["cap"] = float(p["attrs"]["capacitance"])
            for ip in p["groups"]:
                if ip["type"] != "internal_power":
                    continue
                tabs = {t["type"]: Table(t, templates) for t in ip["groups"]
                        if t["type"] in ("rise_power", "fall_power")}
                entry["power"].append({"related": ip["attrs"].get("related_pin"),
                                       "rise": tabs.get("rise_power"), "fall": tabs.get("fall_power")})
        # bus bits inherit the bus's direction and capacitance
        for name, p, is_bus in pins:
            if is_bus:
                for q in p["groups"]:
                    if q["type"] == "pin":
                        bit = cell["pins"][q["args"][0]]
                        bit["direction"] = bit["direction"] or cell["pins"][name]["direction"]
                        bit["cap"] = bit["cap"] or cell["pins"][name]["cap"]
        return cell

    def pin(self, cell, pin):
        """The pin entry of cell.pin (a bus bit A[3] falls back to the bus A)."""
        c = self.cells[cell]["pins"]
        if pin in c:
            return c[pin]
        return c.get(re.sub(r"\[\d+\]$", "", pin))


def cell_areas(text):
    """{cell name: area} of every cell in a Liberty text (one with no area: 0.0)."""
    areas = {}
    for lib in parse(tokens(text))["groups"]:
        for g in lib["groups"]:
            if g["type"] == "cell":
                areas[g["args"][0]] = float(g["attrs"].get("area", 0.0))
    return areas
