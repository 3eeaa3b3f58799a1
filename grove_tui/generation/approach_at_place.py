"""Approaching the robot at a place: "children in the playground approach the robot", "a steward approaches
the robot at the entrance", "two kids at the duty free run up to the robot".

Without a place, ApproachRobot sends people to the robot wherever it is, from the first second (reconcile's
ROBOT_ACTIVITIES): they may meet it anywhere, far from where the sentence put them. With one, they wait at the
place and come up to the robot when it comes near:

    ReactiveFallback[
        ReactiveSequence[IsRobotClose(APPROACH_REACH), IsAtPosition(post, HOLD_RADIUS), ApproachRobot],
        Sequence[GoTo(place), Wait(seconds)] ]

Their post is beside the robot's route where it passes the place (SIDE metres off it, so that coming up to it
is a walk of their own, not the robot driving past them); when it is near they walk up to it, never further
than HOLD_RADIUS from the post, and walk back once it has gone. Planning runs the robot's route through the
place (as for block_at_place.py) and puts the posts there; the report checks the approach at the place
(analysis/outcomes.py, an approach claim with a place: only a meeting there counts).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Protocol

import numpy as np
import shapely

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.generation.block_at_place import PostedAgent, PostedGroup, point_post, posts_on_the_route, route_gap
from grove_tui.generation.draft import DraftNode
from grove_tui.language.reading import GroupReading
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.scenario.report import FAILS, Claim
from grove_tui.world.model import World, Zone

APPROACH_REACH = 8.0  # metres: the robot this near a person at their post sets the approach off
HOLD_RADIUS = 5.0  # metres from the post an approacher goes at most
SIDE = 3.5  # metres beside the robot's route a post stands
PLACE_RADIUS = 6.0  # metres from a door or thing the report counts as "there"
SPACING = 0.9  # metres between the posts of a group, along the robot's way
Point = tuple[float, float]
_PATTERN = ["IsRobotClose", "IsAtPosition", "ApproachRobot"]


def approach_place(group: GroupReading) -> str | None:
    """Where a group that only approaches the robot is put by its sentence ("in the playground", "at the
    entrance"), or None (no place, or they go somewhere: today's approach wherever the robot is)."""
    if group.robot_interaction != "approach" or group.destination or group.via:
        return None
    return group.location or group.start


def approaching_at(place: str, seconds: float, ports: dict[str, float], together: bool = False) -> DraftNode:
    """The tree of people who approach the robot at `place` (module doc); `ports` ApproachRobot's."""
    approach = DraftNode("ReactiveSequence", {}, (
        DraftNode("IsRobotClose", {"threshold": APPROACH_REACH}),
        DraftNode("IsAtPosition", {"tolerance": HOLD_RADIUS}),
        DraftNode("ApproachRobot", dict(ports)),
    ))
    routine: tuple[DraftNode, ...] = ((DraftNode("JoinGroup", {}),) if together else ()) + (
        DraftNode("GoTo", {"target": place}), DraftNode("Wait", {"duration": seconds}))
    return DraftNode("ReactiveFallback", {}, (approach, DraftNode("Sequence", {}, routine)))


def approached_place(tree: DraftNode) -> str | None:
    """The place a group's tree approaches the robot at (where it walks to), or None."""
    if not any(n.node == "ReactiveSequence" and [c.node for c in n.children] == _PATTERN for n in tree.walk()):
        return None
    goto = next((n for n in tree.walk() if n.node == "GoTo" and "target" in n.ports), None)
    return None if goto is None else str(goto.ports["target"])


def _approach(document: TreeDocument) -> tuple[TreeElement, TreeElement | None] | None:
    found = next((e for e in document.nodes() if e.id == "ReactiveSequence"
                  and [c.id for c in e.children] == _PATTERN), None)
    if found is None:
        return None
    goto = next((e for e in document.nodes() if e.id == "GoTo" and e.get("x") is not None), None)
    return found.children[1], goto


def set_post(document: TreeDocument, post: Point | None) -> None:
    """Point an approach-at-place tree's post (its GoTo and the IsAtPosition that keeps it near), in place."""
    found = _approach(document) if post is not None else None
    if found is None or post is None:
        return
    point_post(*found, post)


def _on_the_route(world: World, place: str, route: Sequence[Point] | None) -> Point | None:
    """Where the robot's route passes `place` (block_at_place.posts_on_the_route: past its start); for a route
    that starts in the place and soon leaves it, its farthest point in the place."""
    found = posts_on_the_route(world, place, route, 1)
    if found:
        return found[0]
    zone = world.find(place)
    if not route or len(route) < 2 or not isinstance(zone, Zone):
        return None
    line = shapely.LineString(np.asarray(route, dtype=float))
    inside = line.intersection(zone.polygon)
    if inside.is_empty:
        return None
    start = shapely.Point(route[0])
    ends = [p for g in getattr(inside, "geoms", [inside]) for p in shapely.get_coordinates(g)]
    far = max(ends, key=lambda p: start.distance(shapely.Point(p)))
    return float(far[0]), float(far[1])


def _heading(route: Sequence[Point], at: Point) -> tuple[float, float]:
    path = np.asarray(route, dtype=float)
    line = shapely.LineString(path)
    s = line.project(shapely.Point(at))
    a, b = line.interpolate(max(s - 1.0, 0.0)), line.interpolate(min(s + 1.0, line.length))
    dx, dy = b.x - a.x, b.y - a.y
    norm = math.hypot(dx, dy) or 1.0
    return dx / norm, dy / norm


def posts_beside_the_route(world: World, grid: OccupancyGrid, place: str, route: Sequence[Point] | None,
                           count: int) -> list[Point] | None:
    """Posts for `count` people SIDE metres beside where the robot's route passes `place`, in the place
    when it is a zone and on free floor; None when the route does not pass there."""
    centre = _on_the_route(world, place, route)
    if centre is None or route is None:
        return None
    cx, cy = centre
    hx, hy = _heading(route, (cx, cy))
    zone = world.find(place)
    polygon = zone.polygon if isinstance(zone, Zone) else None
    for side in (SIDE, 3.0, 4.5, 2.5):
        for sign in (1.0, -1.0):
            px, py = cx - sign * hy * side, cy + sign * hx * side
            spots = [(px + (i - (count - 1) / 2.0) * SPACING * hx, py + (i - (count - 1) / 2.0) * SPACING * hy)
                     for i in range(count)]
            free = [grid.nearest_free(x, y, max_dist=0.6) for x, y in spots]
            if all(f is not None for f in free) and (polygon is None or all(
                    shapely.contains_xy(polygon, f[0], f[1]) for f in free if f is not None)):
                return [(float(f[0]), float(f[1])) for f in free if f is not None]
    return None


def posts_for_approachers(world: World, grid: OccupancyGrid, groups: Sequence[PostedGroup], agents: Sequence[PostedAgent],
                          route: Sequence[Point] | None, notes: list[str]) -> dict[int, Point]:
    """Agent id -> the post of each person who approaches the robot at a place: beside where the robot's
    route passes the place; people whose place the route misses keep the place's own point (a note says so)."""
    out: dict[int, Point] = {}
    for g in groups:
        place = approached_place(g.tree)
        if place is None:
            continue
        members = [a for a in agents if a.group_index == g.index]
        posts = posts_beside_the_route(world, grid, place, route, len(members))
        if posts is None:
            notes.append(f"group '{g.label}': the robot's route does not pass {place}"
                         f"{route_gap(world, place, route)}; they wait there and "
                         f"approach the robot only if it comes")
            continue
        out.update({a.id: p for a, p in zip(members, posts)})
    return out


def rooms_to_pass(world: World, groups: Sequence[PostedGroup], route: Sequence[Point] | None) -> list[str]:
    """The zones of the places people approach the robot at that its route does not pass."""
    rooms: list[str] = []
    for g in groups:
        place = approached_place(g.tree)
        if place is None or _on_the_route(world, place, route) is not None:
            continue
        zone = world.zone_of_place(place)
        if zone and zone not in rooms:
            rooms.append(zone)
    return rooms


class _Planned(Protocol):
    @property
    def tree(self) -> DraftNode: ...


def at_the_approached_place(claim: Claim, reading: GroupReading, group: _Planned, world: World) -> Claim:
    """An approach claim with the place the sentence puts the approach at, checked there; unchanged when the
    sentence names no place. FAILS (planned) when the trees approach it wherever it is instead."""
    place = approach_place(reading)
    if not place or claim.status == FAILS:
        return claim
    asked = f"approach the robot at {place}"
    if approached_place(group.tree) != place:
        return replace(claim, asked=asked, status=FAILS,
                       evidence=f"the trees approach it wherever it is, not at {place}")
    plan = f"{claim.plan}, waiting at {place} until it comes near"
    if isinstance(world.find(place), Zone):
        return replace(claim, asked=asked, plan=plan, zone=place, place=place)
    found = world.find(place)
    position = getattr(found, "position", None) or getattr(found, "interaction_point", None)
    if position is None:
        return replace(claim, asked=asked, plan=plan, zone=world.zone_of_place(place), place=place)
    return replace(claim, asked=asked, plan=plan, place=place,
                   point=(round(float(position[0]), 3), round(float(position[1]), 3)), radius=PLACE_RADIUS)
