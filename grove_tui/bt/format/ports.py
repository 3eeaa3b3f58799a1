"""Port values as text: the one codec for blackboard pointers, literals, agent lists and point lists.

Every stage that reads or writes a port value (post-processing, waypoint injection, the runtime,
exports, evaluation, the app) goes through these functions, so a point list is written with one
precision and read by one parser everywhere.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Container, Iterable, Sequence

from grove_tui.bt.format.manifest import NodeSpec, PortSpec

Point = tuple[float, float]
# A port's value once read (convert_literal), by port type: int/agent, float, bool, string/target,
# agents (ids), point_list.
PortValue = int | float | bool | str | tuple[int, ...] | tuple[Point, ...]

# Centimetres: finer than the planner's 0.1 m grid and the SFM's 0.35 m body radius, and short
# enough that a tree with hundreds of waypoints stays readable.
POINT_DECIMALS = 2
MAX_COORDINATE = 1e6  # metres; anything larger is a typo or an attack, not a place in a building
MAX_TEXT_PORT = 1000

_BLACKBOARD_POINTER = re.compile(r"^\{([A-Za-z_@][A-Za-z0-9_.@:-]*)\}$")


def blackboard_pointer(value: str) -> str | None:
    """The key of a "{key}" port value, else None."""
    m = _BLACKBOARD_POINTER.match(value.strip())
    return m.group(1) if m else None


def format_number(value: float) -> str:
    """A port literal for a number: at most 3 decimals, no trailing zeros, never '-0'."""
    text = f"{float(value):.3f}".rstrip("0").rstrip(".")
    return text if text not in ("", "-0") else "0"


def format_port_value(value: PortValue) -> str:
    """Any Python port value as BT.CPP text (booleans as true/false, floats by `format_number`)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return format_number(value)
    return str(value)


def _coordinate(value: float) -> str:
    text = f"{float(value):.{POINT_DECIMALS}f}"
    # "-0.00" and "0.00" are the same place; one spelling keeps re-planned trees byte-identical
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def format_point_list(points: Iterable[Sequence[float]]) -> str:
    """'x1,y1;x2,y2' with POINT_DECIMALS decimals; no points give ''."""
    return ";".join(f"{_coordinate(x)},{_coordinate(y)}" for x, y in points)


def parse_point_list(text: str) -> tuple[tuple[float, float], ...]:
    """Inverse of `format_point_list`; ValueError names the malformed pair."""
    points = []
    for part in (text or "").split(";"):
        if not part.strip():
            continue
        xy = part.split(",")
        try:
            if len(xy) != 2:
                raise ValueError
            x, y = float(xy[0]), float(xy[1])
        except ValueError:
            raise ValueError(f"expected points like 'x1,y1;x2,y2', got {part.strip()!r}") from None
        if not (math.isfinite(x) and math.isfinite(y) and abs(x) < MAX_COORDINATE and abs(y) < MAX_COORDINATE):
            raise ValueError(f"point {part.strip()!r} is not finite or not within {MAX_COORDINATE:g} m")
        points.append((x, y))
    return tuple(points)


def parse_agent_list(text: str) -> tuple[int, ...]:
    if not text.strip():
        return ()
    try:
        return tuple(int(part) for part in text.replace(";", ",").split(",") if part.strip())
    except ValueError:
        raise ValueError(f"expected comma-separated agent ids like '2,3', got {text!r}") from None


def convert_literal(port: PortSpec, text: str) -> PortValue:
    """Convert a port literal to its Python value; ValueError says what is expected."""
    t = port.type
    s = text.strip()
    value: PortValue
    if t in ("int", "agent"):
        try:
            value = int(s)
        except ValueError:
            raise ValueError(f"expected an integer, got {text!r}") from None
    elif t == "float":
        try:
            value = float(s)
        except ValueError:
            raise ValueError(f"expected a number, got {text!r}") from None
        if not math.isfinite(value):
            raise ValueError(f"expected a finite number, got {text!r}")
    elif t == "bool":
        low = s.lower()
        if low in ("true", "1"):
            value = True
        elif low in ("false", "0"):
            value = False
        else:
            raise ValueError(f"expected true or false, got {text!r}")
    elif t == "agents":
        value = parse_agent_list(s)
    elif t == "point_list":
        value = parse_point_list(s)
    else:  # string, target
        value = text
        if len(value) > MAX_TEXT_PORT:
            raise ValueError(f"text longer than {MAX_TEXT_PORT} characters")
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if port.min is not None and value < port.min:
            raise ValueError(f"{value} is below the minimum {port.min}")
        if port.max is not None and value > port.max:
            raise ValueError(f"{value} is above the maximum {port.max}")
    if port.choices is not None and value not in port.choices:
        raise ValueError(f"{value!r} is not one of {', '.join(port.choices)}")
    return value


def checked_port(spec: NodeSpec, port: PortSpec) -> PortSpec:
    """The port as GROVE checks a literal for it: HuNavSim's own nodes get no bounds.

    HuNavSim declares its ports without limits (BT::InputPort<double>(...) in bt_node.cpp and the node
    headers), and its shipped trees use values such as ThreateningNav goal_dist="20"; a tree HuNavSim
    runs must not be refused here. The manifest's bounds still shape what the language model may write.
    """
    if spec.origin != "hunavsim" or (port.min is None and port.max is None):
        return port
    return dataclasses.replace(port, min=None, max=None)


def satisfied_by_goal_id(port: PortSpec, given_ports: Container[str]) -> bool:
    """A navigation `target` given instead as HuNavSim's `goal_id` (a global goal of the scenario).

    HuNavSim 2.0's GoTo names its destination only by goal_id (go_to_node.hpp); GROVE's GoTo accepts
    that form too (the runtime resolves the id in the scenario's global goals), so a HuNavSim tree and
    an exported GROVE tree validate without a `target`.
    """
    return port.type == "target" and ("goal_id" in given_ports or "target_x" in given_ports)
