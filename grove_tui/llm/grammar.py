"""JSON schema -> GBNF for llama.cpp, for exactly the bounded subset GROVE's own schemas use (the roi model's answer).

A malformed GBNF crashes llama.cpp inside the C++ sampler, so we never compile a grammar we did not
build here, and this converter refuses anything outside the subset instead of guessing:

- `object` with `properties` in a fixed order, `required`, `additionalProperties: false`; optional
  properties only after the first (required) one, so the comma placement stays unambiguous;
- `enum` / `const` of strings, numbers, booleans and null;
- `string` with `maxLength` (and optional `minLength`) drawn from SAFE_STRING_CHARS;
- `integer` as an enum or a `minimum`..`maximum` range of at most MAX_INTEGER_RANGE values
  (llama.cpp's own converter ignores integer bounds; we enumerate them);
- `number` only as an enum, `boolean`, `null`;
- `array` with `items`, `minItems` and a required `maxItems`;
- `anyOf` / `oneOf`, and `$ref` to `#/$defs/<name>` without cycles (depth is bounded by the caller
  expanding its recursion into one definition per level).

Every repetition is bounded, so a complete output always ends: the model cannot loop on whitespace or
an unterminated string.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from grove_tui.errors import GrammarError

# The characters a free-text value may use: no quotes, backslashes or control characters, so strict
# json.loads always accepts what the grammar allows and nothing can break out of the JSON string.
SAFE_STRING_CHARS = "A-Za-z0-9 _.,'()/:-"
SAFE_STRING_PATTERN = f"^[{SAFE_STRING_CHARS}]*$"
MAX_INTEGER_RANGE = 512
MAX_ARRAY_ITEMS = 32
MAX_STRING_LENGTH = 256

_IGNORED_KEYS = frozenset({"description", "title", "$comment", "default", "examples", "$schema"})
_REF_PREFIX = "#/$defs/"
# A JSON schema as the caller built it: its values are checked as it is converted (hence object).
Schema = Mapping[str, object]


def schema_to_gbnf(schema: Schema) -> str:
    """Return a GBNF grammar (root rule `root`) accepting exactly the compact JSON documents of `schema`."""
    return _Converter(schema).convert()


def gbnf_literal(text: str) -> str:
    """Quote `text` as a GBNF string literal (ASCII only, everything else escaped)."""
    out = ['"']
    for char in text:
        code = ord(char)
        if char == '"':
            out.append('\\"')
        elif char == "\\":
            out.append("\\\\")
        elif 0x20 <= code < 0x7F:
            out.append(char)
        elif code <= 0xFF:
            out.append(f"\\x{code:02X}")
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04X}")
        else:
            out.append(f"\\U{code:08X}")
    out.append('"')
    return "".join(out)


# Optional tails nest up to this depth; a longer bound is written as a counted repetition `x{0,n}`.
# Both engines take both forms (llama.cpp unrolls the count itself), but llguidance refuses grammars
# nested much deeper than this (a 48-character text was "too deeply nested").
MAX_NESTED_TAIL = 8


def bounded_repeat(item: str, low: int, high: int, separator: str = "") -> str:
    """`item` low..high times (low >= 1), `separator` before each one after the first.

    Short tails nest, `a (s a (s a)?)?`, so every length parses one way and ends; longer ones are
    counted, `a (s a){0,n}`, which both llama.cpp and llguidance read the same way.
    """
    extra = high - low
    mandatory = " ".join([item] + [f"{separator}{item}"] * (low - 1))
    if extra > MAX_NESTED_TAIL:
        repeated = f"({separator}{item})" if separator else item
        return f"{mandatory} {repeated}{{0,{extra}}}"
    tail = ""
    for _ in range(extra):
        tail = f"({separator}{item}{(' ' + tail) if tail else ''})?"
    return f"{mandatory} {tail}".strip()


def json_literal(value: object) -> str:
    """The compact JSON text of a scalar, as the model must write it."""
    if isinstance(value, float) and value.is_integer():
        # 2.0 and 2 are the same number; the short form is what tokenizers see most often.
        return json.dumps(int(value))
    if isinstance(value, (str, bool, int, float)) or value is None:
        return json.dumps(value, ensure_ascii=True)
    raise GrammarError(f"enum/const value {value!r} is not a JSON scalar")


class GbnfRules:
    """GBNF rules by name, one rule shared between identical bodies (the JSON-schema grammar here and
    the draft syntax's grammar in generation/draft.py both name their rules this way)."""

    def __init__(self, reserved: Iterable[str] = ("root",)) -> None:
        self.rules: dict[str, str] = {}
        self.by_body: dict[str, str] = {}
        self.reserved = frozenset(reserved)

    def add(self, hint: str, body: str) -> str:
        """Name `body` as a rule (a name made from `hint`), or return the name it already has."""
        existing = self.by_body.get(body)
        if existing is not None:
            return existing
        base = re.sub(r"[^A-Za-z0-9]+", "-", hint).strip("-").lower() or "r"
        name, counter = base, 1
        while name in self.rules or name in self.reserved:
            counter += 1
            name = f"{base}-{counter}"
        self.rules[name] = body
        self.by_body[body] = name
        return name

    def text(self, root: str, extra: Mapping[str, str] | None = None) -> str:
        """The grammar: `root`, the named rules, then `extra` (rules whose names are reserved)."""
        rules = {"root": root, **self.rules, **(extra or {})}
        return "".join(f"{name} ::= {body}\n" for name, body in rules.items())


class _Converter:
    def __init__(self, schema: Schema) -> None:
        if not isinstance(schema, dict):
            raise GrammarError(f"schema must be a JSON object, got {type(schema).__name__}")
        self.schema = schema
        defs = schema.get("$defs", {})
        if not isinstance(defs, dict):
            raise GrammarError(f"$defs must be an object of named schemas, got {type(defs).__name__}")
        self.defs: dict[str, object] = defs
        self.named = GbnfRules(reserved=("root", "ws"))
        self.def_rules: dict[str, str] = {}
        self.resolving: list[str] = []

    def convert(self) -> str:
        root_schema = {key: value for key, value in self.schema.items() if key != "$defs"}
        body = self.expression(root_schema, "root")
        return self.named.text(body, {"ws": '" "?'})

    def add_rule(self, hint: str, body: str) -> str:
        """Name `body` as a rule, sharing one rule between identical bodies."""
        return self.named.add(hint, body)

    def expression(self, schema: object, hint: str) -> str:
        """A GBNF expression matching `schema`; composite parts become named rules."""
        if not isinstance(schema, dict):
            raise GrammarError(f"{hint}: schema must be an object, got {schema!r}")
        keys = set(schema) - _IGNORED_KEYS
        if "$ref" in schema:
            self._only(schema, keys, {"$ref"}, hint)
            return self.reference(schema["$ref"])
        if "const" in schema:
            self._only(schema, keys, {"const", "type"}, hint)
            return gbnf_literal(json_literal(schema["const"]))
        if "enum" in schema:
            self._only(schema, keys, {"enum", "type"}, hint)
            values = schema["enum"]
            if not isinstance(values, list) or not values:
                raise GrammarError(f"{hint}: enum must be a non-empty list")
            literals = list(dict.fromkeys(gbnf_literal(json_literal(value)) for value in values))
            return self.add_rule(hint, " | ".join(literals)) if len(literals) > 1 else literals[0]
        for combinator in ("anyOf", "oneOf"):
            if combinator in schema:
                self._only(schema, keys, {combinator}, hint)
                options = schema[combinator]
                if not isinstance(options, list) or not options:
                    raise GrammarError(f"{hint}: {combinator} must be a non-empty list")
                parts = [self.expression(option, f"{hint}-{index}") for index, option in enumerate(options)]
                return self.add_rule(hint, " | ".join(dict.fromkeys(parts)))
        kind = schema.get("type")
        if kind == "object":
            return self.object(schema, keys, hint)
        if kind == "array":
            return self.array(schema, keys, hint)
        if kind == "string":
            return self.string(schema, keys, hint)
        if kind == "integer":
            return self.integer(schema, keys, hint)
        if kind == "boolean":
            self._only(schema, keys, {"type"}, hint)
            return self.add_rule("boolean", '"true" | "false"')
        if kind == "null":
            self._only(schema, keys, {"type"}, hint)
            return '"null"'
        if kind == "number":
            raise GrammarError(f"{hint}: a number must be an enum of allowed values (unbounded numbers never end)")
        raise GrammarError(f"{hint}: unsupported schema {sorted(keys)} with type {kind!r}")

    @staticmethod
    def _only(schema: Schema, keys: set[str], allowed: set[str], hint: str) -> None:
        extra = keys - allowed
        if extra:
            raise GrammarError(f"{hint}: unsupported keyword(s) {sorted(extra)} next to {sorted(allowed & keys)}")

    def reference(self, ref: object) -> str:
        if not isinstance(ref, str) or not ref.startswith(_REF_PREFIX):
            raise GrammarError(f"$ref {ref!r} must point into #/$defs/")
        name = ref[len(_REF_PREFIX):]
        if name not in self.defs:
            raise GrammarError(f"$ref {ref!r}: no such definition (known: {', '.join(sorted(self.defs)) or 'none'})")
        if name in self.def_rules:
            return self.def_rules[name]
        if name in self.resolving:
            cycle = " -> ".join([*self.resolving[self.resolving.index(name):], name])
            raise GrammarError(f"$ref cycle {cycle}: recursion must be expanded to a bounded depth")
        self.resolving.append(name)
        try:
            expression = self.expression(self.defs[name], name)
        finally:
            self.resolving.pop()
        rule = expression if re.fullmatch(r"[a-z0-9-]+", expression) else self.add_rule(name, expression)
        self.def_rules[name] = rule
        return rule

    def object(self, schema: Schema, keys: set[str], hint: str) -> str:
        self._only(schema, keys, {"type", "properties", "required", "additionalProperties"}, hint)
        if schema.get("additionalProperties", False) is not False:
            raise GrammarError(f"{hint}: objects must set additionalProperties to false")
        properties = schema.get("properties", {})
        required = schema.get("required", [])
        if not isinstance(properties, dict) or not isinstance(required, list):
            raise GrammarError(f"{hint}: properties must be an object and required a list")
        unknown = set(required) - set(properties)
        if unknown:
            raise GrammarError(f"{hint}: required names unknown properties {sorted(unknown)}")
        if not properties:
            return '"{" "}"'
        names = list(properties)
        if names[0] not in required:
            raise GrammarError(f"{hint}: the first property ({names[0]!r}) must be required so commas stay unambiguous")
        parts = []
        for index, name in enumerate(names):
            value = self.expression(properties[name], f"{hint}-{name}")
            pair = f'{gbnf_literal(json.dumps(name) + ":")} ws {value}'
            if index == 0:
                parts.append(pair)
            elif name in required:
                parts.append(f'"," ws {pair}')
            else:
                parts.append(f'("," ws {pair})?')
        return self.add_rule(hint, '"{" ' + " ".join(parts) + ' "}"')

    def array(self, schema: Schema, keys: set[str], hint: str) -> str:
        self._only(schema, keys, {"type", "items", "minItems", "maxItems"}, hint)
        if "items" not in schema:
            raise GrammarError(f"{hint}: arrays need an items schema")
        if "maxItems" not in schema:
            raise GrammarError(f"{hint}: arrays need maxItems (an unbounded array may never end)")
        low, high = schema.get("minItems", 0), schema["maxItems"]
        if not (isinstance(low, int) and isinstance(high, int) and 0 <= low <= high <= MAX_ARRAY_ITEMS):
            raise GrammarError(f"{hint}: need 0 <= minItems <= maxItems <= {MAX_ARRAY_ITEMS}, got {low}..{high}")
        if high == 0:
            return '"[" "]"'
        item = self.expression(schema["items"], f"{hint}-item")
        items = self._bounded_list(item, low, high, '"," ws ')
        return self.add_rule(hint, f'"[" {items} "]"')

    @staticmethod
    def _bounded_list(item: str, low: int, high: int, separator: str) -> str:
        """`item` repeated low..high times, separated (bounded_repeat), optional as a whole when low is 0."""
        sequence = bounded_repeat(item, max(low, 1), high, separator)
        return sequence if low >= 1 else f"({sequence})?"

    def string(self, schema: Schema, keys: set[str], hint: str) -> str:
        self._only(schema, keys, {"type", "maxLength", "minLength", "pattern"}, hint)
        if schema.get("pattern", SAFE_STRING_PATTERN) != SAFE_STRING_PATTERN:
            raise GrammarError(f"{hint}: the only supported string pattern is {SAFE_STRING_PATTERN!r}")
        if "maxLength" not in schema:
            raise GrammarError(f"{hint}: strings need maxLength (an unbounded string may never close)")
        low, high = schema.get("minLength", 0), schema["maxLength"]
        if not (isinstance(low, int) and isinstance(high, int) and 0 <= low <= high <= MAX_STRING_LENGTH):
            raise GrammarError(f"{hint}: need 0 <= minLength <= maxLength <= {MAX_STRING_LENGTH}, got {low}..{high}")
        char = self.add_rule("safe-char", f"[{SAFE_STRING_CHARS}]")
        if high == 0:
            return self.add_rule(f"string-{low}-{high}", '"\\"" "\\""')
        chars = self._bounded_list(char, low, high, "")
        return self.add_rule(f"string-{low}-{high}", f'"\\"" {chars} "\\""')

    def integer(self, schema: Schema, keys: set[str], hint: str) -> str:
        self._only(schema, keys, {"type", "minimum", "maximum"}, hint)
        low, high = schema.get("minimum"), schema.get("maximum")
        if not (isinstance(low, int) and isinstance(high, int)) or isinstance(low, bool) or isinstance(high, bool):
            raise GrammarError(f"{hint}: integers need integer minimum and maximum (or an enum)")
        if not 0 <= high - low < MAX_INTEGER_RANGE:
            raise GrammarError(f"{hint}: integer range {low}..{high} must hold 1..{MAX_INTEGER_RANGE} values")
        # Longest literals first only for readability; GBNF alternatives are not ordered choices.
        values = sorted(range(low, high + 1), key=lambda number: (-len(str(number)), number))
        return self.add_rule(f"int-{low}-{high}", " | ".join(gbnf_literal(str(number)) for number in values))
