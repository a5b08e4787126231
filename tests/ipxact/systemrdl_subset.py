"""A small SystemRDL 2.0 reader for the subset ip/specular_unit.rdl uses.

Debian packages no SystemRDL compiler (and the npm registry has no official one), so
the test reads the file with this: a tokeniser and a recursive-descent parser over
  root      := (enum_def | component_def)*
  enum_def  := 'enum' ID '{' (ID '=' number ['{' assignment* '}'] ';')* '}' ';'
  component := ['external'] ('addrmap'|'regfile'|'reg'|'field'|'mem') [ID] '{' item* '}' [instances] ';'
  item      := component | type_instance | alias | assignment
  type_instance := ID instance ';'     (ID: a root addrmap, or a component defined by name
                                        earlier in this component's body)
  alias     := 'alias' ID ID instance ';'   (primary: an earlier sibling instance; type:
                                        as type_instance)
  assignment:= ['default'] ID ['=' value] ';'
  instances := instance (',' instance)*
  instance  := ID ['[' number [':' number] ']'] ['=' number] ['@' number] ['+=' number]
  value     := string | number | ID
numbers: decimal, 0x hex, Verilog-style sized literals (8'hFF, 'd3). It builds a tree of
components and instances; it does not elaborate SystemRDL's full semantics (no user
properties, no dynamic assignments, no parameters), and refuses what it does not know
with the line and what it expected. docs/ipxact.md says so.
"""
from dataclasses import dataclass, field as dc_field
from typing import Dict, List, Optional, Tuple, Union

KEYWORD_COMPONENTS = ("addrmap", "regfile", "reg", "field", "mem")


class RdlError(Exception):
    pass


@dataclass
class Token:
    kind: str  # "id", "number", "string", "symbol", "end"
    text: str
    line: int
    value: Optional[int] = None


def parse_number(text: str) -> int:
    t = text.replace("_", "")
    if "'" in t:
        size, rest = t.split("'", 1)
        base = {"h": 16, "d": 10, "b": 2, "o": 8}.get(rest[:1].lower())
        if base is None:
            raise ValueError(text)
        value = int(rest[1:], base)
        if size and value >= 1 << int(size):
            raise ValueError(f"{text}: value wider than {size} bits")
        return value
    if t.lower().startswith("0x"):
        return int(t[2:], 16)
    return int(t, 10)


def tokenise(text: str) -> List[Token]:
    tokens: List[Token] = []
    i, line, n = 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif c.isspace():
            i += 1
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            if end < 0:
                raise RdlError(f"line {line}: unterminated comment")
            line += text.count("\n", i, end)
            i = end + 2
        elif c == '"':
            j, out = i + 1, []
            while j < n and text[j] != '"':
                if text[j] == "\\" and j + 1 < n:
                    j += 1
                if text[j] == "\n":
                    line += 1
                out.append(text[j])
                j += 1
            if j >= n:
                raise RdlError(f"line {line}: unterminated string")
            tokens.append(Token("string", "".join(out), line))
            i = j + 1
        elif c.isdigit() or (c == "'" and i + 1 < n and text[i + 1].isalpha()):
            j = i
            while j < n and (text[j].isalnum() or text[j] in "_'"):
                j += 1
            word = text[i:j]
            try:
                tokens.append(Token("number", word, line, parse_number(word)))
            except ValueError as e:
                raise RdlError(f"line {line}: bad number '{word}' ({e})")
            i = j
        elif c.isalpha() or c == "_":
            j = i
            while j < n and (text[j].isalnum() or text[j] == "_"):
                j += 1
            tokens.append(Token("id", text[i:j], line))
            i = j
        elif text.startswith("+=", i):
            tokens.append(Token("symbol", "+=", line))
            i += 2
        elif c in "{}[]:;=@,":
            tokens.append(Token("symbol", c, line))
            i += 1
        else:
            raise RdlError(f"line {line}: unexpected character '{c}'")
    tokens.append(Token("end", "", line))
    return tokens


Value = Union[str, int, bool]


@dataclass
class Instance:
    name: str
    dims: Optional[Tuple[int, ...]] = None  # [N] -> (N,); [msb:lsb] -> (msb, lsb)
    reset: Optional[int] = None
    address: Optional[int] = None
    stride: Optional[int] = None
    alias_of: Optional[str] = None  # `alias PRIMARY TYPE NAME`: the primary's instance name


@dataclass
class Component:
    kind: str
    type_name: Optional[str]
    properties: Dict[str, Value] = dc_field(default_factory=dict)
    defaults: Dict[str, Value] = dc_field(default_factory=dict)
    children: List[Tuple["Component", Instance]] = dc_field(default_factory=list)
    line: int = 0
    external: bool = False  # instantiated `external` (a mem always is, SystemRDL 2.0 §12)


@dataclass
class EnumDef:
    name: str
    entries: List[Tuple[str, int, Dict[str, Value]]]


@dataclass
class RdlFile:
    enums: Dict[str, EnumDef]
    addrmaps: Dict[str, Component]


class Parser:
    def __init__(self, tokens: List[Token]):
        self.tokens, self.pos = tokens, 0
        self.defined: Dict[str, Component] = {}  # root addrmaps, instantiable by name
        self.scopes: List[Dict[str, Component]] = []  # named definitions in open bodies

    def peek(self) -> Token:
        return self.tokens[self.pos]

    def fail(self, expected: str):
        t = self.peek()
        raise RdlError(f"line {t.line}: expected {expected}, found '{t.text or 'end of file'}'")

    def accept(self, text: str) -> bool:
        t = self.peek()
        if t.kind in ("symbol", "id") and t.text == text:
            self.pos += 1
            return True
        return False

    def expect(self, text: str):
        if not self.accept(text):
            self.fail(f"'{text}'")

    def identifier(self) -> str:
        t = self.peek()
        if t.kind != "id":
            self.fail("an identifier")
        self.pos += 1
        return t.text

    def number(self) -> int:
        t = self.peek()
        if t.kind != "number":
            self.fail("a number")
        self.pos += 1
        return t.value

    def value(self) -> Value:
        t = self.peek()
        if t.kind == "string":
            self.pos += 1
            return t.text
        if t.kind == "number":
            self.pos += 1
            return t.value
        if t.kind == "id":
            self.pos += 1
            return {"true": True, "false": False}.get(t.text, t.text)
        self.fail("a string, a number or an identifier")

    def root(self) -> RdlFile:
        enums: Dict[str, EnumDef] = {}
        addrmaps: Dict[str, Component] = {}
        while self.peek().kind != "end":
            if self.accept("enum"):
                e = self.enum_def()
                if e.name in enums:
                    raise RdlError(f"enum '{e.name}' defined twice")
                enums[e.name] = e
            elif self.peek().text == "addrmap":
                comp, instances = self.component()
                if instances or not comp.type_name:
                    raise RdlError(f"line {comp.line}: a root addrmap is a named definition")
                addrmaps[comp.type_name] = comp
                self.defined[comp.type_name] = comp
            else:
                self.fail("'enum' or 'addrmap'")
        return RdlFile(enums, addrmaps)

    def enum_def(self) -> EnumDef:
        name = self.identifier()
        self.expect("{")
        entries = []
        while not self.accept("}"):
            entry = self.identifier()
            self.expect("=")
            value = self.number()
            props: Dict[str, Value] = {}
            if self.accept("{"):
                while not self.accept("}"):
                    key, val, is_default = self.assignment()
                    props[key] = val
            self.expect(";")
            entries.append((entry, value, props))
        self.expect(";")
        return EnumDef(name, entries)

    def assignment(self) -> Tuple[str, Value, bool]:
        is_default = self.accept("default")
        key = self.identifier()
        val: Value = True
        if self.accept("="):
            val = self.value()
        self.expect(";")
        return key, val, is_default

    def component(self) -> Tuple[Component, List[Instance]]:
        t = self.peek()
        external = self.accept("external")
        kind = self.identifier()
        if kind not in KEYWORD_COMPONENTS:
            raise RdlError(f"line {t.line}: expected one of {KEYWORD_COMPONENTS}, found '{kind}'")
        type_name = self.identifier() if self.peek().kind == "id" else None
        comp = Component(kind, type_name, line=t.line, external=external)
        self.expect("{")
        self.scopes.append({})
        while not self.accept("}"):
            if self.peek().kind == "id" and self.peek().text in KEYWORD_COMPONENTS + ("external",):
                child, instances = self.component()
                if not instances and not child.type_name:
                    raise RdlError(f"line {child.line}: a nested {child.kind} without a name or an instance")
                if not instances:
                    self.scopes[-1][child.type_name] = child  # a definition, instantiated below
                for inst in instances:
                    comp.children.append((child, inst))
            elif self.accept("alias"):
                line = self.peek().line
                primary = self.identifier()
                if primary not in [i.name for _, i in comp.children]:
                    raise RdlError(f"line {line}: alias of '{primary}', which is no earlier sibling")
                child = self.defined_type()
                inst = self.instance()
                inst.alias_of = primary
                comp.children.append((child, inst))
                self.expect(";")
            elif self.peek().kind == "id" and self.lookup(self.peek().text) is not None:
                child = self.defined_type()  # an instance of a defined component
                comp.children.append((child, self.instance()))
                self.expect(";")
            else:
                key, val, is_default = self.assignment()
                target = comp.defaults if is_default else comp.properties
                if key in target:
                    raise RdlError(f"line {self.peek().line}: property '{key}' assigned twice")
                target[key] = val
        self.scopes.pop()
        instances = []
        if self.peek().kind == "id":
            instances.append(self.instance())
            while self.accept(","):
                instances.append(self.instance())
        self.expect(";")
        return comp, instances

    def lookup(self, name: str) -> Optional[Component]:
        for scope in reversed(self.scopes):
            if name in scope:
                return scope[name]
        return self.defined.get(name)

    def defined_type(self) -> Component:
        line = self.peek().line
        name = self.identifier()
        comp = self.lookup(name)
        if comp is None:
            raise RdlError(f"line {line}: no component '{name}' defined before")
        return comp

    def instance(self) -> Instance:
        inst = Instance(self.identifier())
        if self.accept("["):
            first = self.number()
            if self.accept(":"):
                inst.dims = (first, self.number())
            else:
                inst.dims = (first,)
            self.expect("]")
        if self.accept("="):
            inst.reset = self.number()
        if self.accept("@"):
            inst.address = self.number()
        if self.accept("+="):
            inst.stride = self.number()
        return inst


def parse(text: str) -> RdlFile:
    return Parser(tokenise(text)).root()
