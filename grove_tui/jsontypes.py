"""JSON as Python holds it: the shared names for data the project writes as JSON and reads back.

    JSONValue   any JSON document, recursively: what json.dumps writes
    JSONObject  a JSON object we build (a report, a worker message, a payload) before json.dumps
    JSONMapping a JSON object we only read (a parameter: dict is invariant, Mapping is not)
    Parsed      a JSON or YAML object as parsed, read back by code that checks or defaults each value
                where it reads it (generation.json, a suite file): the one named boundary left `Any`

Data straight from json.loads or YAML, before a reader has checked it, is not JSONValue: a reader that
validates takes `object` and narrows with isinstance as it goes; one that reads key by key with
defaults takes `Parsed`.
Shapes the project defines itself (a grounding report, a worker's reply) get their own TypedDict or
dataclass beside the code that writes them; these aliases are for what is free-form by design.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, TypeAlias

JSONScalar: TypeAlias = str | int | float | bool | None
# Sequence and Mapping, not list and dict: they are covariant, so a list[str] or a dict[str, float] is
# JSON as it stands (json.dumps writes a tuple as a list).
JSONValue: TypeAlias = JSONScalar | Sequence["JSONValue"] | Mapping[str, "JSONValue"]
JSONObject: TypeAlias = dict[str, JSONValue]
JSONMapping: TypeAlias = Mapping[str, JSONValue]
Parsed: TypeAlias = Mapping[str, Any]  # Any: parsed JSON/YAML, each value checked or defaulted where it is read
