"""Blocking the robot at a place: "a steward blocks the robot at the rinkside", "two guards stand in the
doorway and block the robot".

Without a place, BlockRobot sends a person to the front of the robot wherever it is (reconcile's
ROBOT_ACTIVITIES). With one, the people hold that place and block the robot there when it comes to or
through it:

    ReactiveFallback[
        ReactiveSequence[IsRobotClose(BLOCK_REACH), IsAtPosition(post, HOLD_RADIUS), BlockRobot],
        Sequence[GoTo(place), Wait(seconds)] ]

They stand at their post; when the robot is near they step in front of it, but never further than
HOLD_RADIUS from the post (IsAtPosition fails, the block is halted and they walk back). The pattern is a
reaction around a routine, so they keep holding the place once the wait is over (bt/format/after_task.py).
Planning puts each post where the robot's route passes the place (`posts_on_the_route`), and the report
checks the block at the place (analysis/outcomes.py, a block claim with a place).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Protocol

import numpy as np
import shapely

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.generation.draft import DraftNode
from grove_tui.language.reading import GroupReading
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.scenario.report import FAILS, Claim
from grove_tui.world.model import Zone, World

BLOCK_REACH = 5.0  # metres: the robot this near a person at their post sets the block off
HOLD_RADIUS = 2.5  # metres from the post a blocker goes at most
START_CLEAR = 1.5  # metres: a post nearer the robot's start is on top of the robot
PLACE_RADIUS = HOLD_RADIUS + 1.0  # metres from a door or thing the report counts as "there"
POST_SPACING = 0.9  # metres between the posts of a group, across the robot's way
Point = tuple[float, float]


class _Planned(Protocol):
    @property
    def tree(self) -> DraftNode: ...


def blocking_at(place: str, seconds: float, front_dist: float, together: bool = False) -> DraftNode:
    """The tree of people who block the robot at `place` (module doc)."""
    block = DraftNode("ReactiveSequence", {}, (
        DraftNode("IsRobotClose", {"threshold": BLOCK_REACH}),
        DraftNode("IsAtPosition", {"tolerance": HOLD_RADIUS}),
        DraftNode("BlockRobot", {"front_dist": front_dist, "duration": 0.0}),
    ))
    routine: tuple[DraftNode, ...] = ((DraftNode("JoinGroup", {}),) if together else ()) + (
        DraftNode("GoTo", {"target": place}), DraftNode("Wait", {"duration": seconds}))
    return DraftNode("ReactiveFallback", {}, (block, DraftNode("Sequence", {}, routine)))


def _is_block(ids: Sequence[str]) -> bool:
    return list(ids) == ["IsRobotClose", "IsAtPosition", "BlockRobot"]


def blocked_place(tree: DraftNode) -> str | None:
    """The place a group's tree blocks the robot at (its post: where it walks to), or None when it blocks
    it wherever it is."""
    if not any(n.node == "ReactiveSequence" and _is_block([c.node for c in n.children]) for n in tree.walk()):
        return None
    goto = next((n for n in tree.walk() if n.node == "GoTo" and "target" in n.ports), None)
    return None if goto is None else str(goto.ports["target"])


def _block(document: TreeDocument) -> tuple[TreeElement, TreeElement | None] | None:
    """(the IsAtPosition of the block, the GoTo to the post) of a block-at-place tree, else None."""
    block = next((e for e in document.nodes() if e.id == "ReactiveSequence"
                  and _is_block([c.id for c in e.children])), None)
    if block is None:
        return None
    check = block.children[1]
    goto = next((e for e in document.nodes() if e.id == "GoTo" and e.get("x") is not None), None)
    return check, goto


def _set_post(document: TreeDocument, post: Point) -> None:
    found = _block(document)
    if found is not None:
        point_post(*found, post)


def point_post(check: TreeElement, goto: TreeElement | None, post: Point) -> None:
    """Point a held post's IsAtPosition and the GoTo that takes the person there at `post`, in place."""
    check.set("target_x", f"{post[0]:.3f}")
    check.set("target_y", f"{post[1]:.3f}")
    check.attributes.pop("goal_id", None)
    if goto is not None:
        goto.set("x", f"{post[0]:.3f}")
        goto.set("y", f"{post[1]:.3f}")
        for port, value in (("target_x", post[0]), ("target_y", post[1])):
            if goto.get(port) is not None:
                goto.set(port, f"{value:.3f}")
        goto.attributes.pop("goal_id", None)  # the export numbers it from its point


def post_of(document: TreeDocument) -> Point | None:
    """Where a written block-at-place tree holds: its GoTo's point."""
    found = _block(document)
    if found is None or found[1] is None:
        return None
    goto = found[1]
    return float(goto.get("x") or 0.0), float(goto.get("y") or 0.0)


def posts_on_the_route(world: World, place: str, route: Sequence[Point] | None, count: int) -> list[Point] | None:
    """Posts for `count` people where the robot's route passes `place` (a zone it crosses, a door or thing it
    passes within PLACE_RADIUS of), side by side across its way; None when the route does not pass there."""
    if not route or len(route) < 2:
        return None
    path = np.asarray(route, dtype=float)
    seg = np.diff(path, axis=0)
    arcs = np.concatenate([[0.0], np.cumsum(np.hypot(seg[:, 0], seg[:, 1]))])
    if arcs[-1] <= 1e-6:
        return None
    samples = np.array([_along(path, arcs, s) for s in np.arange(0.0, arcs[-1], 0.25)])
    from_start = np.hypot(samples[:, 0] - path[0, 0], samples[:, 1] - path[0, 1])
    # past the robot's start: a post on top of where it starts blocks nothing; a route that passes the place
    # only as it sets off (the robot starts by the desk) passes it all the same, and the post is by the start
    for clear in (BLOCK_REACH, START_CLEAR):
        posts = _posts_past(world, place, samples, from_start > clear, count)
        if posts is not None:
            return posts
    return None


def route_gap(world: World, place: str, route: Sequence[Point] | None) -> str:
    """How near the robot's whole route comes to `place`, in words for a note (" (it comes within 7.2 m)")."""
    found = world.find(place)
    point = None if isinstance(found, Zone) else _point(world, place)
    if not route or (point is None and not isinstance(found, Zone)):
        return ""
    line = shapely.LineString(np.asarray(route, dtype=float)) if len(route) > 1 else shapely.Point(route[0])
    gap = line.distance(found.polygon if isinstance(found, Zone) else shapely.Point(point))
    return f" (its whole route comes within {gap:.1f} m of it)"


def _posts_past(world: World, place: str, samples: np.ndarray, away: np.ndarray, count: int) -> list[Point] | None:
    """`posts_on_the_route` on the route's samples where `away` holds."""
    found = world.find(place)
    if isinstance(found, Zone):
        inside = shapely.contains_xy(found.polygon, samples[:, 0], samples[:, 1]) & away
        if not inside.any():
            return None
        k = np.flatnonzero(inside)
        j = int(k[len(k) // 2])
    else:
        point = _point(world, place)
        if point is None:
            return None
        gap = np.hypot(samples[:, 0] - point[0], samples[:, 1] - point[1])
        gap[~away] = np.inf
        j = int(np.argmin(gap))
        if not gap[j] <= PLACE_RADIUS:
            return None
    centre = samples[j]
    ahead = samples[min(j + 2, len(samples) - 1)] - samples[max(j - 2, 0)]
    norm = math.hypot(float(ahead[0]), float(ahead[1])) or 1.0
    across = (-float(ahead[1]) / norm, float(ahead[0]) / norm)
    offsets = [(i - (count - 1) / 2.0) * POST_SPACING for i in range(count)]
    return [(float(centre[0]) + o * across[0], float(centre[1]) + o * across[1]) for o in offsets]


def _along(path: np.ndarray, arcs: np.ndarray, s: float) -> np.ndarray:
    i = min(int(np.searchsorted(arcs, s, side="right")) - 1, len(path) - 2)
    span = arcs[i + 1] - arcs[i]
    f = 0.0 if span <= 1e-9 else (s - arcs[i]) / span
    return np.asarray(path[i] + f * (path[i + 1] - path[i]))


def _point(world: World, place: str) -> Point | None:
    found = world.find(place)
    position = getattr(found, "position", None) or getattr(found, "interaction_point", None)
    if position is None:
        return None
    return float(position[0]), float(position[1])


def point_goal_ids(document: TreeDocument, id_of: object) -> None:
    """For a HuNavSim export: an IsAtPosition written with target_x/target_y gets the global goal id of its
    point (HuNavSim 2.0 declares goal_id only), in place."""
    if not callable(id_of):
        return
    for element in document.nodes():
        if element.id != "IsAtPosition":
            continue
        x, y = element.get("target_x"), element.get("target_y")
        if x is None or y is None:
            continue
        element.set("goal_id", str(id_of((float(x), float(y)))))


def at_the_blocked_place(claim: Claim, reading: GroupReading, group: _Planned, world: World) -> Claim:
    """A robot_block claim with the place the sentence blocks it at, checked there; unchanged when the
    sentence names no place. FAILS (planned) when the trees block it wherever it is instead."""
    place = reading.location
    if not place or claim.status == FAILS:
        return claim
    asked = f"block the robot at {place}"
    if blocked_place(group.tree) != place:
        return replace(claim, asked=asked, status=FAILS, evidence=f"the trees block it wherever it is, not at {place}")
    plan = f"{claim.plan}, holding {place}"
    if isinstance(world.find(place), Zone):
        return replace(claim, asked=asked, plan=plan, zone=place, place=place)
    point = _point(world, place)
    if point is None:
        return replace(claim, asked=asked, plan=plan, zone=world.zone_of_place(place), place=place)
    return replace(claim, asked=asked, plan=plan, place=place, point=(round(point[0], 3), round(point[1], 3)),
                   radius=PLACE_RADIUS)


class PostedAgent(Protocol):
    """An agent as the post placers read it (reconcile's agents)."""

    @property
    def id(self) -> int: ...
    @property
    def group_index(self) -> int: ...
    @property
    def document(self) -> TreeDocument | None: ...


class PostedGroup(Protocol):
    """A draft group as the post placers read it."""

    @property
    def index(self) -> int: ...
    @property
    def label(self) -> str: ...
    @property
    def tree(self) -> DraftNode: ...


def posts_for_blockers(world: World, grid: OccupancyGrid, groups: Sequence[PostedGroup], agents: Sequence[PostedAgent],
                       route: Sequence[Point] | None, notes: list[str]) -> dict[int, Point]:
    """Agent id -> the post each person who blocks the robot at a place holds: where the robot's route passes
    the place, else the place's own point (a note says the robot does not come by)."""
    out: dict[int, Point] = {}
    for g in groups:
        place = blocked_place(g.tree)
        if place is None:
            continue
        members = [a for a in agents if a.group_index == g.index]
        posts = posts_on_the_route(world, place, route, len(members))
        if posts is None:
            notes.append(f"group '{g.label}': the robot's route does not pass {place}"
                         f"{route_gap(world, place, route)}; they hold it and block "
                         f"the robot only if it comes")
            for a in members:
                own = post_of(a.document) if a.document is not None else None
                if own is not None:
                    out[a.id] = own
            continue
        for a, p in zip(members, posts):
            out[a.id] = grid.nearest_free(p[0], p[1], max_dist=2.0) or p
    return out


def set_post(document: TreeDocument, post: Point | None) -> None:
    """Point a block-at-place tree's post (its GoTo and the IsAtPosition that keeps it there), in place."""
    if post is not None:
        _set_post(document, post)


def rooms_to_pass(world: World, groups: Sequence[PostedGroup], route: Sequence[Point] | None) -> list[str]:
    """The zones of the places people block the robot at that its route does not pass: "a steward blocks
    the robot at the rinkside" has it come by the rinkside, or there is nothing to block there."""
    rooms: list[str] = []
    for g in groups:
        place = blocked_place(g.tree)
        if place is None or posts_on_the_route(world, place, route, 1) is not None:
            continue
        zone = world.zone_of_place(place)
        if zone and zone not in rooms:
            rooms.append(zone)
    return rooms
