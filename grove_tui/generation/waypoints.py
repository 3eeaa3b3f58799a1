"""Waypoint injection: plan every leg between consecutive navigation goals of a behavior tree.

The paper's operational layer: each navigation node (`navigates=True` in the node manifest: GoTo,
Converse, ...) carries its resolved target in the `x`, `y` ports; the legs start -> first target,
first -> second, ... are planned with Theta* and the intermediate points land in the node's
`waypoints` port ("x1,y1;x2,y2", start and target excluded). Nodes that move the agent without a
waypoints port (Queue, FollowVelocityField: resolved `x`, `y` but `navigates=False`) are not planned
but move the start of the next leg to their point. The tree keeps its structure and every
other attribute; the result depends only on the targets and the start, so injecting twice changes
nothing.
"""

from __future__ import annotations

from lxml import etree

from grove_tui.bt.manifest import NODES
from grove_tui.navigation.theta_star import PlanningError

WAYPOINTS_PORT = "waypoints"


def navigation_tags() -> frozenset[str]:
    return frozenset(name for name, spec in NODES.items() if spec.navigates)


def relocating_tags() -> frozenset[str]:
    """Nodes that leave the agent at their resolved x, y without planned waypoints (Queue, FollowVelocityField)."""
    return frozenset(name for name, spec in NODES.items()
                     if not spec.navigates and spec.port("x") is not None and spec.port("y") is not None)


def _safe_parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False,
                           remove_blank_text=False)


def format_waypoints(points) -> str:
    """'x1,y1;x2,y2' with 2 decimals; an empty list gives ''."""
    return ";".join(f"{_fixed(x)},{_fixed(y)}" for x, y in points)


def parse_waypoints(text: str) -> list[tuple[float, float]]:
    """Inverse of `format_waypoints`; raises PlanningError on malformed text."""
    points = []
    for item in (text or "").split(";"):
        if not item.strip():
            continue
        try:
            x, y = item.split(",")
            points.append((float(x), float(y)))
        except ValueError:
            raise PlanningError(f"waypoints {text!r}: {item!r} is not an 'x,y' pair") from None
    return points


def _fixed(value: float) -> str:
    text = f"{value:.2f}"
    return "0.00" if text == "-0.00" else text


def _describe(element) -> str:
    name = element.get("name")
    target = element.get("target")
    parts = [f"<{element.tag}>"]
    if name:
        parts.append(f"name={name!r}")
    if target:
        parts.append(f"target={target!r}")
    if element.sourceline is not None:
        parts.append(f"line {element.sourceline}")
    return " ".join(parts)


def _target_point(element) -> tuple[float, float]:
    values = []
    for port in ("x", "y"):
        raw = element.get(port)
        if raw is None:
            raise PlanningError(f"{_describe(element)} has no resolved '{port}' port; post-processing must write "
                                f"the target point before planning")
        try:
            values.append(float(raw))
        except ValueError:
            raise PlanningError(f"{_describe(element)} port {port}={raw!r} is not a number (a blackboard "
                                f"pointer cannot be planned; post-processing must resolve it)") from None
    return values[0], values[1]


def _target_label(element) -> str:
    for port in ("target", "service_point", "exit", "zone", "name"):
        value = element.get(port)
        if value:
            return value
    return element.tag


def inject_waypoints(xml: str, start, planner, start_label: str = "start") -> str:
    """Fill the `waypoints` port of every navigation node of every BehaviorTree in `xml`.

    `planner` is anything with `plan(start, goal, start_label=..., goal_label=...) -> (K, 2)` (a
    ThetaStarPlanner, or a wrapper going through a PlanCache). Unplannable legs raise PlanningError
    naming both ends.
    """
    text = xml.lstrip()
    declaration = text.startswith("<?xml")
    try:
        root = etree.fromstring(text.encode("utf-8"), _safe_parser())
    except etree.XMLSyntaxError as exc:
        raise PlanningError(f"behavior-tree XML does not parse: {exc}") from None
    navigating = navigation_tags()
    relocating = relocating_tags()
    trees = [root] if root.tag == "BehaviorTree" else root.iter("BehaviorTree")
    for tree in trees:
        position = (float(start[0]), float(start[1]))
        position_label = start_label
        for element in tree.iter():
            if not isinstance(element.tag, str):
                continue
            if element.tag in relocating:
                # The next leg starts where this node leaves the agent (e.g. at the queue's counter).
                if element.get("x") is not None and element.get("y") is not None:
                    position, position_label = _target_point(element), _target_label(element)
                continue
            if element.tag not in navigating:
                continue
            target = _target_point(element)
            label = _target_label(element)
            path = planner.plan(position, target, start_label=position_label, goal_label=label)
            element.set(WAYPOINTS_PORT, format_waypoints(path[1:-1]))
            position, position_label = target, label
    body = etree.tostring(root.getroottree(), encoding="unicode")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n' + body) if declaration else body
