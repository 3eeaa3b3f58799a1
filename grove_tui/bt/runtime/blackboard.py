"""The blackboard: key/value store of one tree scope, as BT.CPP's Blackboard.

A SubTree gets its own blackboard whose ports remap keys to its parent's ("{key}"), or that sees every
parent entry with `_autoremap="true"`. Entries get a type family the first time a typed port uses
them, so two ports of incompatible types sharing one entry are refused when the tree is built.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from grove_tui.bt.format.manifest import PortSpec
from grove_tui.bt.format.ports import PortValue, convert_literal
from grove_tui.errors import BTError

_MISSING = object()
_ABSENT = object()  # what BlackboardRef asks for, distinct from Blackboard.get's "no default" marker
_TYPE_FAMILY = {"int": "int", "agent": "int", "float": "float", "bool": "bool"}  # everything else: text


class Blackboard:
    """Key/value store of one tree scope, with SubTree remapping ({key}) and `_autoremap` to the parent."""

    __slots__ = ("_values", "_types", "_remap", "_parent", "_autoremap")

    def __init__(self, parent: Blackboard | None = None, autoremap: bool = False,
                 values: Mapping[str, PortValue] | None = None):
        self._values: dict[str, PortValue] = dict(values or {})
        self._types: dict[str, str] = {}
        self._remap: dict[str, str] = {}
        self._parent = parent
        self._autoremap = autoremap

    def add_remapping(self, internal: str, external: str) -> None:
        self._remap[internal] = external

    def _owner(self, key: str) -> tuple[Blackboard, str]:
        bb = self
        while True:
            parent = bb._parent
            if key in bb._remap and parent is not None:
                key = bb._remap[key]
                bb = parent
                continue
            if key in bb._values or parent is None or not bb._autoremap or key.startswith("_"):
                return bb, key
            bb = parent

    def get(self, key: str, default: object = _MISSING) -> object:
        """The entry's value; `default` when it is not set, KeyError without a default."""
        bb, k = self._owner(key)
        value = bb._values.get(k, _MISSING)
        if value is _MISSING:
            if default is _MISSING:
                raise KeyError(key)
            return default
        return value

    def set(self, key: str, value: PortValue) -> None:
        bb, k = self._owner(key)
        bb._values[k] = value

    def __contains__(self, key: str) -> bool:
        bb, k = self._owner(key)
        return k in bb._values

    def declare(self, key: str, port_type: str, where: str) -> None:
        """Give an entry a type; BTError when two ports of incompatible types share it (as BT.CPP does)."""
        bb, k = self._owner(key)
        family = _TYPE_FAMILY.get(port_type, "text")
        known = bb._types.get(k)
        if known is None or known == "text":
            bb._types[k] = family
        elif family != "text" and family != known:
            raise BTError(f"{where}: blackboard entry {{{key}}} is used as {family} here but as {known} elsewhere")

    def keys(self) -> list[str]:
        return list(self._values)


class BlackboardRef:
    """A port bound to a blackboard entry ("{key}"); values are converted to the port type when read."""

    __slots__ = ("blackboard", "key", "port", "where")

    def __init__(self, blackboard: Blackboard, key: str, port: PortSpec, where: str):
        self.blackboard = blackboard
        self.key = key
        self.port = port
        self.where = where

    def get(self) -> Any:  # Any: the port's type is the manifest's, known at run time (convert_literal)
        value = self.blackboard.get(self.key, _ABSENT)
        if value is _ABSENT:
            raise BTError(f"{self.where}: port {self.port.name!r} reads blackboard entry {{{self.key}}}, "
                          "which is not set")
        if isinstance(value, str) and self.port.type not in ("string", "target"):
            try:
                return convert_literal(self.port, value)
            except ValueError as exc:
                raise BTError(f"{self.where}: port {self.port.name!r} from {{{self.key}}}: {exc}") from None
        if self.port.type == "float" and isinstance(value, int) and not isinstance(value, bool):
            return float(value)
        return value
