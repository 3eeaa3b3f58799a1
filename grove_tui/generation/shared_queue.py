"""A queue claim's time counts the people of other groups in the same queue.

"Twenty passengers queue at check-in counter A and a few of them glance at the robot": the subset is
a group of its own that queues at the same counter as the rest, behind them. Its queue claim was timed
as if its three people had the counter to themselves, so the run (sized by the longest claim) ended
before any of them was served and the claim read ✗ "served 0". Every queue claim's `needs_seconds`
adds one service time for each person of the other groups queueing at the same service point (the
worst case: all of them ahead), so the run length covers it, and a shorter run says "not checked".

The service time is the trees': the `service_time` of the Queue nodes at that service point (the
longest of them: the simulation's line keeps the one its first joiner brought), or the Queue node's
documented default where a tree leaves it unset (`queue_service_times`). A fixed 10 s made a 40 s
counter's run end before the people behind were served.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace

from grove_tui.bt.format.manifest import NODES
from grove_tui.generation.draft import DraftNode, DraftValue
from grove_tui.scenario.report import GroupGrounding


def default_service_time() -> float:
    """The Queue node's documented service_time default (bt/format/manifest.py)."""
    port = NODES["Queue"].port("service_time")
    return float(port.default) if port is not None and isinstance(port.default, (int, float)) else 10.0


def service_time_of(node: DraftNode) -> float:
    """A Queue node's service time: its port, or the documented default when the tree leaves it unset."""
    value = node.ports.get("service_time")
    try:
        return float(value) if value is not None else default_service_time()
    except (TypeError, ValueError):
        return default_service_time()


def with_drafted_service_time(core: DraftNode, drafted: DraftNode) -> DraftNode:
    """`core` (the tree written for the reading) with its Queue nodes served for the time the model's tree
    gives its Queue at the same service point ("queue at the pharmacy, 30 s each"), else as `core` says;
    the reading's tree left every queue at the default, whatever the model wrote."""
    times = {str(n.ports.get("service_point", n.ports.get("target"))): n.ports["service_time"]
             for n in drafted.walk() if n.node == "Queue" and n.ports.get("service_time") is not None}
    if not times:
        return core
    only = next(iter(times.values())) if len(set(map(str, times.values()))) == 1 else None
    return _served(core, times, only)


def _served(node: DraftNode, times: Mapping[str, DraftValue], only: DraftValue | None) -> DraftNode:
    """`node` with each Queue lacking a service time given the drafted one at its service point (or the
    only one the model wrote, at a place it named otherwise: "pharmacy" for the pharmacy counter)."""
    if node.node == "Queue" and "service_time" not in node.ports:
        value = times.get(str(node.ports.get("service_point")), only)
        return node if value is None else replace(node, ports={**node.ports, "service_time": value})
    if not node.children:
        return node
    return replace(node, children=tuple(_served(c, times, only) for c in node.children))


def one_service_time_per_queue(trees: Sequence[DraftNode]) -> list[DraftNode]:
    """`trees` with every Queue node at one service point served for the longest time any of them gives
    it: the simulation's line serves everyone for the time its first joiner brought, so a subset's default
    10 s beside its group's 30 s made the line's pace depend on who arrived first."""
    times = queue_service_times(trees, set_only=True)
    return [_served(_unserved(tree), times, None) if any(n.node == "Queue" for n in tree.walk()) else tree
            for tree in trees]


def _unserved(node: DraftNode) -> DraftNode:
    if node.node == "Queue":
        return replace(node, ports={k: v for k, v in node.ports.items() if k != "service_time"})
    if not node.children:
        return node
    return replace(node, children=tuple(_unserved(c) for c in node.children))


def queue_service_times(trees: Iterable[DraftNode], set_only: bool = False) -> dict[str, float]:
    """Service point -> the longest service time of the Queue nodes at it in `trees` (`set_only`: of those
    that set one; a default beside a set time is no choice)."""
    out: dict[str, float] = {}
    for tree in trees:
        for node in tree.walk():
            place = node.ports.get("service_point") if node.node == "Queue" else None
            if place and not (set_only and node.ports.get("service_time") is None):
                out[str(place)] = max(out.get(str(place), 0.0), service_time_of(node))
    return out


def with_shared_queues(groups: Sequence[GroupGrounding],
                       service_times: Mapping[str, float] | None = None) -> list[GroupGrounding]:
    """`groups` with every queue claim's needs_seconds covering the other groups' people in its queue, each
    served for its service point's time in `service_times` (`queue_service_times` of the trees)."""
    times = service_times or {}
    queued: Counter[str] = Counter()
    for g in groups:
        for place in {c.place for c in g.claims if c.kind == "queue" and c.place}:
            queued[place] += len(g.members)
    out = []
    for g in groups:
        claims = tuple(replace(c, needs_seconds=c.needs_seconds + (queued[c.place] - len(g.members))
                               * times.get(c.place, default_service_time()))
                       if c.kind == "queue" and c.place and c.needs_seconds is not None
                       and queued[c.place] > len(g.members) else c for c in g.claims)
        out.append(replace(g, claims=claims))
    return out
