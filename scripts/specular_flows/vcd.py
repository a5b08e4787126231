"""One VCD reader for the flows' scripts: the declarations, then the value changes one time
step at a time (IEEE 1364-2005 section 18; what Icarus and Verilator write)."""
import collections
import re

Var = collections.namedtuple("Var", "scope name id width range")
Var.__doc__ = """A declared variable: its scope (dotted), its name (an escaped name without
the backslash), its VCD id, its width and its bit range ('[7:0]', or None)."""

UNITS_PS = {"s": 1e12, "ms": 1e9, "us": 1e6, "ns": 1e3, "ps": 1.0, "fs": 1e-3}


def timescale_ps(text):
    """'10 ps', '1ns' ... in picoseconds."""
    m = re.match(r"\s*(\d+)\s*([munpf]?s)", text)
    if not m:
        raise ValueError(f"timescale '{text.strip()}': not a number and a unit (s, ms, us, ns, ps, fs)")
    return int(m.group(1)) * UNITS_PS[m.group(2)]


def read_header(f):
    """Reads f (an open VCD file) up to $enddefinitions: (timescale in ps, [Var]). f is
    left at the first value change."""
    variables = []
    scope = []
    scale = 1.0
    for line in f:
        s = line.split()
        if not s:
            continue
        if s[0] == "$timescale":
            txt = " ".join(s[1:])
            while "$end" not in txt:
                txt += " " + f.readline().strip()
            scale = timescale_ps(txt)
        elif s[0] == "$scope":
            scope.append(s[2])
        elif s[0] == "$upscope":
            scope.pop()
        elif s[0] == "$var":
            name = s[4][1:] if s[4].startswith("\\") else s[4]
            rng = s[5] if len(s) > 5 and s[5].startswith("[") else None
            variables.append(Var(".".join(scope), name, s[3], int(s[2]), rng))
        elif s[0] == "$enddefinitions":
            break
    return scale, variables


class Changes:
    """The value changes after read_header, one time step at a time: iterating yields
    (time in ps, {id: value}) for each step with a change of a wanted id (ids: {id: width}),
    in the order of the file; a vector's value is padded to its width as IEEE 1364 says
    (with 0, or with x or z when it starts so), values in lower case. After the
    iteration, end_ps is the last time stamp of the file."""

    def __init__(self, f, scale_ps, ids):
        self.f, self.scale_ps, self.ids = f, scale_ps, ids
        self.end_ps = 0.0

    def __iter__(self):
        ids, t_ps, pending = self.ids, 0.0, {}
        for line in self.f:
            c = line[0] if line else ""
            if c == "#":
                if pending:
                    yield t_ps, pending
                    pending = {}
                t_ps = int(line[1:]) * self.scale_ps
                self.end_ps = t_ps
            elif c in "01xzXZ":
                vid = line[1:].strip()
                if vid in ids:
                    pending[vid] = c.lower()
            elif c in "bB":
                val, vid = line[1:].split()
                if vid in ids:
                    val = val.lower()
                    w = ids[vid]
                    if len(val) < w:  # leading zeros (or x, z) left out: pad to the width
                        val = (val[0] if val[0] in "xz" else "0") * (w - len(val)) + val
                    pending[vid] = val
        if pending:
            yield t_ps, pending
