"""The draft: the bounded JSON the model writes instead of XML (ARCHITECTURE.md section 5).

    {"groups": [{"label": "patients", "count": 10, "spawn": "pharmacy",
                 "tree": {"node": "Sequence", "children": [
                     {"node": "GoTo", "target": "pharmacy_counter"},
                     {"node": "Queue", "service_point": "pharmacy_counter"}]}}]}

`build_draft_schema` makes the JSON schema for one request: only the retrieved node types, only the
selected RoI names for `target` ports, and every number, string, list and the tree depth bounded, so
the grammar built from it (models/grammar.py) always finishes. `parse_draft` is the strict check of
the text that comes back, whether it was grammar-constrained or not.

What the model writes per node: the node type and the non-auto input ports of that node in the
manifest, except ports typed agent/agents/point_list (ids and point lists are post-processing's
job: the model never writes ids). Ports without a manifest default are required; the others are
optional and post-processing fills the manifest default. Numbers are chosen from a short list of
sensible values inside the port's bounds (the grammar cannot bound free digits); parse_draft
accepts any number within the bounds, so a hand-written draft is not held to that list.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from grove_tui.errors import DraftError
from grove_tui.limits import MAX_GROUP_COUNT

LABEL_MAX_LENGTH = 24
STRING_PORT_MAX_LENGTH = 48
MAX_CHILDREN = 4
# Mirrors models.grammar.SAFE_STRING_CHARS: what the grammar lets through is what we accept here.
SAFE_STRING_CHARS = "A-Za-z0-9 _.,'()/:-"
SAFE_STRING_PATTERN = f"^[{SAFE_STRING_CHARS}]*$"
_SAFE_STRING = re.compile(SAFE_STRING_PATTERN)
# Port types the model never writes: agent ids and point lists come from post-processing.
POST_PROCESSED_TYPES = frozenset({"agent", "agents", "point_list"})
WRITTEN_TYPES = frozenset({"int", "float", "bool", "string", "target"})
BRANCH_CATEGORIES = frozenset({"control", "decorator"})

_SENSIBLE_FLOATS = (0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.6, 0.75, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0,
                    8.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 90.0, 120.0, 180.0, 300.0, 600.0, 1800.0, 3600.0)
_SENSIBLE_INTS = (-1, 0, 1, 2, 3, 4, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 3000, 5000, 10000, 20000,
                  30000, 60000, 120000, 300000, 600000, 1800000, 3600000)
_ENUMERATE_ALL_INTS_UP_TO = 24


@dataclass(frozen=True)
class DraftNode:
    node: str
    ports: dict[str, Any] = field(default_factory=dict)  # only the ports the model wrote
    children: tuple[DraftNode, ...] = ()

    def walk(self) -> Iterable[DraftNode]:
        yield self
        for child in self.children:
            yield from child.walk()


@dataclass(frozen=True)
class DraftGroup:
    label: str
    count: int
    spawn: str
    tree: DraftNode


@dataclass(frozen=True)
class Draft:
    groups: tuple[DraftGroup, ...]

    def node_types(self) -> set[str]:
        return {node.node for group in self.groups for node in group.tree.walk()}

    def places(self, nodes: Mapping[str, Any] | None = None) -> set[str]:
        """Every RoI name the draft uses: spawns and the values of target-typed ports."""
        table = _manifest() if nodes is None else nodes
        names = {group.spawn for group in self.groups}
        for group in self.groups:
            for node in group.tree.walk():
                spec = table.get(node.node)
                for port in spec.ports if spec is not None else ():
                    if port.type == "target" and port.name in node.ports:
                        names.add(node.ports[port.name])
        return names


def _manifest() -> Mapping[str, Any]:
    from grove_tui.bt.manifest import NODES

    return NODES


def _specs(node_names: Iterable[str], nodes: Mapping[str, Any] | None) -> dict[str, Any]:
    table = _manifest() if nodes is None else nodes
    names = list(dict.fromkeys(node_names))
    unknown = [name for name in names if name not in table]
    if unknown:
        raise DraftError(f"unknown node type(s) {', '.join(unknown)}; the manifest has {', '.join(sorted(table))}")
    if not names:
        raise DraftError("no node types given for the draft")
    return {name: table[name] for name in names}


def written_ports(spec: Any) -> tuple[Any, ...]:
    """The ports of a node the model writes in a draft, in manifest order."""
    return tuple(port for port in spec.ports
                 if port.direction == "in" and not port.auto and port.type in WRITTEN_TYPES)


def _sensible_ints(port: Any) -> list[int]:
    low = int(port.min) if port.min is not None else 0
    high = int(port.max) if port.max is not None else 100
    if high - low <= _ENUMERATE_ALL_INTS_UP_TO:
        return list(range(low, high + 1))
    values = {low, high} | {value for value in _SENSIBLE_INTS if low <= value <= high}
    if isinstance(port.default, int) and not isinstance(port.default, bool) and low <= port.default <= high:
        values.add(port.default)
    return sorted(values)


def _sensible_floats(port: Any) -> list[float]:
    low = float(port.min) if port.min is not None else 0.0
    high = float(port.max) if port.max is not None else 3600.0
    values = {round(low, 4), round(high, 4)} | {value for value in _SENSIBLE_FLOATS if low <= value <= high}
    if isinstance(port.default, (int, float)) and not isinstance(port.default, bool) and low <= port.default <= high:
        values.add(round(float(port.default), 4))
    return sorted(values)


def port_schema(port: Any, roi_names: list[str]) -> dict[str, Any]:
    """The JSON schema of one written port value."""
    if port.choices:
        return {"enum": list(port.choices)}
    if port.type == "target":
        return {"enum": list(roi_names)}
    if port.type == "bool":
        return {"type": "boolean"}
    if port.type == "int":
        return {"enum": _sensible_ints(port)}
    if port.type == "float":
        return {"enum": _sensible_floats(port)}
    if port.type == "string":
        return {"type": "string", "maxLength": STRING_PORT_MAX_LENGTH, "pattern": SAFE_STRING_PATTERN}
    raise DraftError(f"port {port.name!r} has type {port.type!r}, which a draft never writes")


def _node_schema(spec: Any, roi_names: list[str], children_ref: str | None, max_children: int) -> dict[str, Any]:
    properties: dict[str, Any] = {"node": {"const": spec.name}}
    required = ["node"]
    for port in written_ports(spec):
        properties[port.name] = port_schema(port, roi_names)
        if port.default is None:
            required.append(port.name)
    if children_ref is not None:
        most = 1 if spec.category == "decorator" else max_children
        properties["children"] = {"type": "array", "items": {"$ref": children_ref}, "minItems": 1, "maxItems": most}
        required.append("children")
    return {"type": "object", "properties": properties, "required": required, "additionalProperties": False}


def build_draft_schema(node_names: Iterable[str], roi_names: Iterable[str], max_groups: int = 6,
                       max_count: int = 60, max_depth: int = 3, max_children: int = MAX_CHILDREN,
                       nodes: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """JSON schema of a draft for one request; recursion is unrolled into one `$defs` entry per tree level."""
    specs = _specs(node_names, nodes)
    rois = list(dict.fromkeys(roi_names))
    if not rois:
        raise DraftError("no RoI names given: a draft needs at least one place to spawn")
    if not (1 <= max_groups <= 16 and 1 <= max_count <= MAX_GROUP_COUNT and 1 <= max_depth <= 6 and 1 <= max_children <= 8):
        raise DraftError(f"draft limits out of range: max_groups={max_groups} (1..16), max_count={max_count} "
                         f"(1..{MAX_GROUP_COUNT}), "
                         f"max_depth={max_depth} (1..6), max_children={max_children} (1..8)")
    leaves = [name for name, spec in specs.items() if spec.category not in BRANCH_CATEGORIES]
    branches = [name for name, spec in specs.items() if spec.category in BRANCH_CATEGORIES]
    if not leaves:
        raise DraftError(f"the node types {', '.join(specs)} include no action or condition, so no tree can end")
    defs: dict[str, Any] = {}
    for name in leaves:
        defs[name] = _node_schema(specs[name], rois, None, max_children)
    for level in range(max_depth, 0, -1):
        options = [{"$ref": f"#/$defs/{name}"} for name in leaves]
        if level < max_depth:
            for name in branches:
                defs[f"{name}_{level}"] = _node_schema(specs[name], rois, f"#/$defs/level_{level + 1}", max_children)
                options.append({"$ref": f"#/$defs/{name}_{level}"})
        defs[f"level_{level}"] = {"anyOf": options}
    group = {
        "type": "object",
        "properties": {
            "label": {"type": "string", "minLength": 1, "maxLength": LABEL_MAX_LENGTH, "pattern": SAFE_STRING_PATTERN},
            "count": {"type": "integer", "minimum": 1, "maximum": max_count},
            "spawn": {"enum": rois},
            "tree": {"$ref": "#/$defs/level_1"},
        },
        "required": ["label", "count", "spawn", "tree"],
        "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {"groups": {"type": "array", "items": group, "minItems": 1, "maxItems": max_groups}},
        "required": ["groups"],
        "additionalProperties": False,
        "$defs": defs,
    }


def _reject_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    result: dict[str, Any] = {}
    for key, value in pairs:
        if key in result:
            raise DraftError(f"key {key!r} appears twice in one object")
        result[key] = value
    return result


def _reject_constant(name: str) -> Any:
    raise DraftError(f"{name} is not valid JSON")


class _Parser:
    def __init__(self, specs: dict[str, Any], rois: list[str], max_groups: int, max_count: int, max_depth: int,
                 max_children: int):
        self.specs, self.rois = specs, rois
        self.roi_set = set(rois)
        self.max_groups, self.max_count, self.max_depth = max_groups, max_count, max_depth
        self.max_children = max_children

    def fail(self, path: str, problem: str) -> DraftError:
        return DraftError(f"draft {path}: {problem}")

    def expect_keys(self, value: Any, path: str, allowed: list[str], required: list[str]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(path, f"expected an object, got {json.dumps(value)[:60]}")
        extra = [key for key in value if key not in allowed]
        if extra:
            raise self.fail(path, f"unexpected key(s) {', '.join(extra)}; allowed: {', '.join(allowed)}")
        missing = [key for key in required if key not in value]
        if missing:
            raise self.fail(path, f"missing key(s) {', '.join(missing)}")
        return value

    def draft(self, data: Any) -> Draft:
        data = self.expect_keys(data, "(top level)", ["groups"], ["groups"])
        groups = data["groups"]
        if not isinstance(groups, list) or not 1 <= len(groups) <= self.max_groups:
            raise self.fail("groups", f"expected a list of 1..{self.max_groups} groups")
        return Draft(tuple(self.group(item, f"groups[{index}]") for index, item in enumerate(groups)))

    def group(self, value: Any, path: str) -> DraftGroup:
        keys = ["label", "count", "spawn", "tree"]
        value = self.expect_keys(value, path, keys, keys)
        label = self.safe_string(value["label"], f"{path}.label", LABEL_MAX_LENGTH)
        if not label.strip():
            raise self.fail(f"{path}.label", "must not be empty")
        count = value["count"]
        if not isinstance(count, int) or isinstance(count, bool) or not 1 <= count <= self.max_count:
            raise self.fail(f"{path}.count", f"{json.dumps(count)} is not a whole number in 1..{self.max_count}")
        spawn = self.roi(value["spawn"], f"{path}.spawn")
        return DraftGroup(label, count, spawn, self.node(value["tree"], f"{path}.tree", 1))

    def roi(self, value: Any, path: str) -> str:
        if not isinstance(value, str) or value not in self.roi_set:
            raise self.fail(path, f"{json.dumps(value)} is not one of the selected places: {', '.join(self.rois)}")
        return value

    def safe_string(self, value: Any, path: str, most: int) -> str:
        if not isinstance(value, str):
            raise self.fail(path, f"expected a string, got {json.dumps(value)}")
        if len(value) > most:
            raise self.fail(path, f"longer than {most} characters")
        if not _SAFE_STRING.match(value):
            raise self.fail(path, f"{json.dumps(value)} uses characters outside [{SAFE_STRING_CHARS}]")
        return value

    def node(self, value: Any, path: str, level: int) -> DraftNode:
        if not isinstance(value, dict):
            raise self.fail(path, f"expected a node object, got {json.dumps(value)[:60]}")
        kind = value.get("node")
        if kind not in self.specs:
            raise self.fail(f"{path}.node", f"{json.dumps(kind)} is not one of the allowed node types: {', '.join(self.specs)}")
        spec = self.specs[kind]
        ports = written_ports(spec)
        branch = spec.category in BRANCH_CATEGORIES
        allowed = ["node", *(port.name for port in ports), *(["children"] if branch else [])]
        required = ["node", *(port.name for port in ports if port.default is None), *(["children"] if branch else [])]
        self.expect_keys(value, f"{path} ({kind})", allowed, required)
        values = {port.name: self.port_value(port, value[port.name], f"{path}.{port.name}")
                  for port in ports if port.name in value}
        children: tuple[DraftNode, ...] = ()
        if branch:
            if level >= self.max_depth:
                raise self.fail(path, f"{kind} needs children, but the tree may only be {self.max_depth} levels deep")
            most = 1 if spec.category == "decorator" else self.max_children
            items = value["children"]
            if not isinstance(items, list) or not 1 <= len(items) <= most:
                raise self.fail(f"{path}.children", f"{kind} takes {'exactly 1 child' if most == 1 else f'1..{most} children'}")
            children = tuple(self.node(item, f"{path}.children[{index}]", level + 1) for index, item in enumerate(items))
        return DraftNode(kind, values, children)

    def port_value(self, port: Any, value: Any, path: str) -> Any:
        if port.choices:
            if value not in port.choices:
                raise self.fail(path, f"{json.dumps(value)} is not one of {', '.join(map(str, port.choices))}")
            return value
        if port.type == "target":
            return self.roi(value, path)
        if port.type == "bool":
            if not isinstance(value, bool):
                raise self.fail(path, f"expected true or false, got {json.dumps(value)}")
            return value
        if port.type == "string":
            return self.safe_string(value, path, STRING_PORT_MAX_LENGTH)
        numeric = isinstance(value, (int, float)) and not isinstance(value, bool)
        if port.type == "int" and not (numeric and float(value).is_integer()):
            raise self.fail(path, f"expected a whole number, got {json.dumps(value)}")
        if port.type == "float" and not (numeric and math.isfinite(value)):
            raise self.fail(path, f"expected a number, got {json.dumps(value)}")
        if (port.min is not None and value < port.min) or (port.max is not None and value > port.max):
            raise self.fail(path, f"{json.dumps(value)} is outside {port.min}..{port.max}")
        return int(value) if port.type == "int" else float(value)


def parse_draft(text: str, node_names: Iterable[str], roi_names: Iterable[str], max_groups: int = 6,
                max_count: int = 60, max_depth: int = 3, max_children: int = MAX_CHILDREN,
                nodes: Mapping[str, Any] | None = None) -> Draft:
    """Strictly parse and validate the model's JSON; DraftError names the offending JSON path."""
    specs = _specs(node_names, nodes)
    rois = list(dict.fromkeys(roi_names))
    try:
        data = json.loads(text, object_pairs_hook=_reject_duplicates, parse_constant=_reject_constant)
    except json.JSONDecodeError as error:
        snippet = text[max(0, error.pos - 30):error.pos + 30].replace("\n", " ")
        raise DraftError(f"draft is not valid JSON ({error.msg} at character {error.pos}: ...{snippet}...)") from None
    return _Parser(specs, rois, max_groups, max_count, max_depth, max_children).draft(data)


def node_to_dict(node: DraftNode) -> dict[str, Any]:
    result: dict[str, Any] = {"node": node.node, **node.ports}
    if node.children:
        result["children"] = [node_to_dict(child) for child in node.children]
    return result


def draft_to_json(draft: Draft, indent: int | None = None) -> str:
    """The draft as JSON in the same key order the model writes (parse_draft(draft_to_json(d)) == d)."""
    data = {"groups": [{"label": group.label, "count": group.count, "spawn": group.spawn, "tree": node_to_dict(group.tree)}
                       for group in draft.groups]}
    return json.dumps(data, indent=indent, separators=None if indent else (",", ":"))
