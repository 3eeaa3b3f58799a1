"""JSON as Python holds it: the shared names for data the project writes as JSON and reads back.

    JSONValue   any JSON document, recursively: what json.dumps writes and json.loads returns
    JSONObject  a JSON object we build (a report, a worker message, a payload) before json.dumps
    JSONMapping a JSON object we only read (a parameter: dict is invariant, Mapping is not)

Data straight from json.loads or YAML, before a reader has checked it, is not JSONValue but `Any`
(with its reason on the line): checking it is the reader's job, narrowing with isinstance as it goes.
Shapes the project defines itself (a grounding report, a worker's reply) get their own TypedDict or
dataclass beside the code that writes them; these aliases are for what is free-form by design.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TypeAlias

JSONScalar: TypeAlias = str | int | float | bool | None
JSONValue: TypeAlias = JSONScalar | list["JSONValue"] | dict[str, "JSONValue"]
JSONObject: TypeAlias = dict[str, JSONValue]
JSONMapping: TypeAlias = Mapping[str, JSONValue]
