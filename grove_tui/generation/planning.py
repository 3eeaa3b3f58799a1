"""Operational layer: collision-free geometry for the post-processed trees, and the robot's task.

Normal and queuing presets plan every leg between consecutive navigation goals with Theta* and
inject the waypoints into the trees; the emergency preset plans each group's centroid to its exit
(per person the nearest allowed one; a group split over exits plans one field per exit) and turns
that path into the velocity field. The robot gets a start and a goal
(the user's, or chosen across the scene so that its path runs through where people are) and a
planned path.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from grove_tui.bt.document import TreeDocument
from grove_tui.bt.manifest import NODES
from grove_tui.bt.ports import parse_point_list
from grove_tui.bt.xml import write_tree
from grove_tui.errors import Cancelled
from grove_tui.navigation.theta_star import PlanCache, ThetaStarPlanner
from grove_tui.generation.formations import (
    PASSING_MARGIN,
    block_formations,
    formations_at,
    nearest_formation_gap,
    predict_formations,
)
from grove_tui.generation.postprocess import FreeSpace, PostProcessed
from grove_tui.errors import GenerationError, PlanningError
from grove_tui.generation.presets import Preset
from grove_tui.scenario.model import AgentSpec, RobotSpec
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.generation.waypoints import plan_waypoints
from grove_tui.world.model import Door, Entity, World
from grove_tui.navigation.grid import OccupancyGrid

Point = tuple[float, float]

ROBOT_CLEARANCE = 2.0  # metres between the robot's start/goal and anybody's spawn
ROBOT_CANDIDATES = 48


@dataclass(frozen=True)
class RobotRequest:
    """What the user asked of the robot; None parts are chosen by the pipeline. Strings are RoI names."""

    start: Point | str | None = None
    goal: Point | str | None = None
    enabled: bool = True


@dataclass
class OperationalPlan:
    agents: list[AgentSpec]
    trees: dict[str, str]  # relative path -> XML with waypoints
    fields: dict[str, VelocityField]  # field id -> field
    robot: RobotSpec | None
    notes: list[str] = field(default_factory=list)


class CachedPlanner:
    """Theta* behind a PlanCache: legs shared by many agents (same goal slot) are planned once."""

    def __init__(self, world_name: str, planner: ThetaStarPlanner, cache: PlanCache | None = None) -> None:
        self.world_name = world_name
        self.planner = planner
        self.cache = cache or PlanCache()

    def plan(self, start: Point, goal: Point, start_label: str = "start", goal_label: str = "goal") -> np.ndarray:
        path: np.ndarray = self.cache.plan(self.world_name, self.planner, start, goal, start_label=start_label,
                                           goal_label=goal_label)
        return path


def goals_from_tree(document: TreeDocument) -> list[Point]:
    """Every point the agent is sent to, in tick order: injected waypoints then the node's target."""
    goals: list[Point] = []
    for element in document.nodes():
        spec = NODES.get(element.id)
        x, y = element.get("x"), element.get("y")
        if spec is None or x is None or y is None:
            continue
        waypoints = element.get("waypoints")
        if waypoints:
            try:
                goals.extend(parse_point_list(waypoints))
            except ValueError as exc:
                raise PlanningError(f"{element.describe()}: waypoints: {exc}") from None
        goals.append((float(x), float(y)))
    return goals


def plan_operational(world: World, grid: OccupancyGrid, preset: Preset, post: PostProcessed, seed: int,
                     robot: RobotRequest | None = None, planner: ThetaStarPlanner | None = None,
                     cache: PlanCache | None = None, cancel: threading.Event | None = None) -> OperationalPlan:
    planner = planner or ThetaStarPlanner(grid)
    cached = CachedPlanner(world.name, planner, cache)
    notes: list[str] = []
    fields: dict[str, VelocityField] = {}
    group_paths: dict[str, np.ndarray] = {}
    if preset.velocity == "field":
        if post.exit is None:
            raise GenerationError("the preset follows velocity fields to an exit, but the world has no exit")
        # One field per group and exit: a group whose members' nearest exits differ gets one per exit.
        followers: dict[str, list[Any]] = {}
        for a in post.agents:
            if a.field_id is not None:
                followers.setdefault(a.field_id, []).append(a)
        labels = {g.index: g for g in post.groups}
        for field_id, members in followers.items():
            _check_cancel(cancel)
            g = labels[members[0].group_index]
            exit_name = members[0].exit or post.exit
            exit_door = world.find(exit_name)
            assert isinstance(exit_door, Door), exit_name  # fields lead to exits, which are doors
            centroid = _free_centroid(grid, [a.start for a in members], g.spawn)
            try:
                built = cached.cache.field(world.name, planner, centroid, exit_door.position,
                                           start_label=f"group '{g.label}' in {g.spawn}", exit_label=exit_name)
            except PlanningError as exc:
                raise GenerationError(f"group '{g.label}' cannot reach exit {exit_name}: {exc}") from None
            fields[field_id] = built
            group_paths[field_id] = built.path

    agents: list[AgentSpec] = []
    trees: dict[str, str] = {}
    for a in post.agents:
        _check_cancel(cancel)
        assert a.document is not None  # post-processing gives every agent its tree document
        document = a.document.copy()  # planning edits its own copy: a re-plan starts from the same trees
        if preset.velocity == "waypoints" and preset.planner.enabled:
            try:
                plan_waypoints(document, a.start, cached, start_label=f"agent {a.id} in {a.spawn_zone}")
            except PlanningError as exc:
                raise GenerationError(f"agent {a.id} ({a.label}) cannot reach its goal: {exc}") from None
        goals = goals_from_tree(document)
        if a.field_id is not None and a.field_id in group_paths:
            # Field followers head along their group's path: record it as their goals.
            goals = [(float(p[0]), float(p[1])) for p in group_paths[a.field_id][1:]]
        rel = f"trees/agent_{a.id}.xml"
        trees[rel] = write_tree(document)
        agents.append(AgentSpec(
            id=a.id, group=a.sfm_group, start=a.start, goals=tuple((round(x, 3), round(y, 3)) for x, y in goals),
            zone=a.zone, tree=rel, radius=preset.agent_radius, max_vel=a.max_vel, label=a.label,
            behavior=a.behavior))
    robot_spec = None
    if robot is None or robot.enabled:
        robot_spec = plan_robot(world, grid, cached, post, robot or RobotRequest(), seed, notes)
    return OperationalPlan(agents, trees, fields, robot_spec, notes)


def _check_cancel(cancel: threading.Event | None) -> None:
    if cancel is not None and cancel.is_set():
        raise Cancelled("generation cancelled during planning")


def _free_centroid(grid: OccupancyGrid, points: Sequence[Point], zone: str) -> Point:
    if not points:
        # A group with no members has no centre; the prompt checks refuse "zero people" before this.
        raise GenerationError(f"a group in {zone} has no people to lead to the exit")
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    q = grid.nearest_free(cx, cy)
    if q is None:
        raise GenerationError(f"no free floor near the centre of the group in {zone}")
    # Snap to the nearest spawn when the centroid's free cell lies in another room (an L-shaped group).
    nearest = min(points, key=lambda p: math.dist(p, (cx, cy)))
    return (float(q[0]), float(q[1])) if math.dist(q, (cx, cy)) < 1.0 else nearest


def _resolve_point(world: World, grid: OccupancyGrid, value: Point | str, what: str) -> Point:
    if isinstance(value, str):
        try:
            obj = world.find(value)
        except Exception as exc:
            raise GenerationError(f"robot {what} {value!r}: {exc}") from None
        if isinstance(obj, Entity):
            p = obj.interaction_point
        elif isinstance(obj, Door):
            p = obj.inward_point(0.8)
        else:
            p = obj.anchor
    else:
        p = (float(value[0]), float(value[1]))
    q = grid.nearest_free(p[0], p[1], max_dist=1.0)
    if q is None:
        raise GenerationError(f"robot {what} ({p[0]:.2f}, {p[1]:.2f}) is not on free floor")
    return (round(float(q[0]), 3), round(float(q[1]), 3))


def plan_robot(world: World, grid: OccupancyGrid, planner: Any, post: PostProcessed, request: RobotRequest, seed: int,
               notes: list[str]) -> RobotSpec:
    """The robot crosses the scene: from one side of the crowd to the other, through where people are.

    Candidates are free points of the zones people start in or head for and of the zones next to
    them, at least ROBOT_CLEARANCE from every spawn. The pair chosen maximises its straight-line
    length minus three times its distance from the crowd's centre, so the robot has to pass the crowd.
    Queues and conversation circles the trees will form are obstacles for the robot's planner
    (`formations.py`): it passes them with PASSING_MARGIN to spare, or through them only when there
    is no other way (a note says so).
    """
    starts = [a.start for a in post.agents]
    robot_radius = RobotSpec((0.0, 0.0), (0.0, 0.0)).radius
    clearance = robot_radius + PASSING_MARGIN
    formations = predict_formations(world, grid, [a.document for a in post.agents if a.document is not None],
                                    post.goals)
    fixed = [_resolve_point(world, grid, p, what) for p, what in ((request.start, "start"), (request.goal, "goal"))
             if p is not None]
    # A start or goal the user put inside a formation (the robot delivers to the counter): that one is not an obstacle.
    formations = [f for f in formations if not any(f in formations_at(formations, q, clearance) for q in fixed)]
    robot_planner = ThetaStarPlanner(block_formations(grid, formations, clearance)) if formations else None

    def plan_path(a: Point, b: Point, may_cross: bool = True) -> np.ndarray:
        if robot_planner is not None:
            try:
                return robot_planner.plan(a, b, start_label="robot start", goal_label="robot goal")
            except PlanningError:
                if not may_cross:
                    raise
        path: np.ndarray = planner.plan(a, b, start_label="robot start", goal_label="robot goal")
        if robot_planner is not None:
            crossed = [f.describe() for f in formations
                       if nearest_formation_gap([f], [tuple(p) for p in path]) < clearance]
            if crossed:
                notes.append(f"the robot's path passes close to {', '.join(crossed)}: there is no way around")
        return path

    if request.start is not None and request.goal is not None:
        start, goal = fixed
    else:
        fixed_start = fixed[0] if request.start is not None else None
        fixed_goal = fixed[-1] if request.goal is not None else None
        candidates = _robot_candidates(world, grid, post, starts, seed)
        if robot_planner is not None:
            # Not inside a queue or circle, unless nothing else is left.
            candidates = [c for c in candidates if robot_planner.grid.is_free(*c)] or candidates
        centre = (sum(p[0] for p in starts) / len(starts), sum(p[1] for p in starts) / len(starts))
        pairs = []
        firsts = [fixed_start] if fixed_start else candidates
        seconds = [fixed_goal] if fixed_goal else candidates
        for a in firsts:
            for b in seconds:
                if a == b:
                    continue
                length = math.dist(a, b)
                if length < 4.0:
                    continue
                # Crossing the crowd matters more than length; beyond 20 m a longer walk adds nothing.
                pairs.append((min(length, 20.0) - 3.0 * _point_segment_distance(centre, a, b), a, b))
        pairs.sort(key=lambda t: (-t[0], t[1], t[2]))
        if not pairs:
            raise GenerationError("no room for the robot: no two free points 4 m apart near the scene")
        # Every pair around the formations first; through one only when no pair can go around.
        for may_cross in (False, True) if robot_planner is not None else (True,):
            for _, a, b in pairs[:20]:
                try:
                    path = plan_path(a, b, may_cross)
                    return RobotSpec(start=a, goal=b,
                                     path=tuple((round(float(x), 3), round(float(y), 3)) for x, y in path))
                except PlanningError:
                    continue
        raise GenerationError("no reachable start/goal pair for the robot near the scene")
    try:
        path = plan_path(start, goal)
    except PlanningError as exc:
        raise GenerationError(f"the robot cannot reach its goal: {exc}") from None
    return RobotSpec(start=start, goal=goal, path=tuple((round(float(x), 3), round(float(y), 3)) for x, y in path))


def _robot_candidates(world: World, grid: OccupancyGrid, post: PostProcessed, starts: Sequence[Point], seed: int) -> list[Point]:
    zones: list[str] = []
    for a in post.agents:
        for z in (a.spawn_zone, a.zone):
            if z and z not in zones:
                zones.append(z)
    for z in list(zones):
        for d in world.doors_of(z):
            other = d.leads_to if d.zone == z else d.zone
            if other in [zz.name for zz in world.zones] and other not in zones:
                zones.append(other)
    rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, 0x3C6EF372])
    space = FreeSpace(world, grid)
    found: list[Point] = []
    per_zone = max(4, ROBOT_CANDIDATES // max(len(zones), 1))
    spawn_arr = np.asarray(starts, dtype=float).reshape(-1, 2)
    for z in zones:
        pts = space.cells(z)
        if len(pts) == 0:
            continue
        d = np.min(np.hypot(pts[:, None, 0] - spawn_arr[None, :, 0], pts[:, None, 1] - spawn_arr[None, :, 1]), axis=1)
        pts = pts[d >= ROBOT_CLEARANCE]
        if len(pts) == 0:
            continue
        pick = rng.choice(len(pts), size=min(per_zone, len(pts)), replace=False)
        found += [(round(float(pts[i, 0]), 3), round(float(pts[i, 1]), 3)) for i in sorted(pick)]
    return found


def _point_segment_distance(p: Point, a: Point, b: Point) -> float:
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)
