"""HuNavSim 2.0 hand-off: agents.yaml (`hunav_loader: ros__parameters:`) plus one BT XML per agent,
the world as Gazebo SDF (worlds/) and a nav2 map (maps/), and a README saying where each goes.

HuNavSim only runs the nodes its agent manager registers. GROVE-only nodes are either
*lowered* to HuNavSim nodes (the default) or kept as Grove<Node>, with a TreeNodesModel listing
them so Groot2 and a C++ implementation know their ports:

    GoTo(x, y, waypoints)        -> SequenceWithMemory of HuNavSim GoTo(goal_id) over every waypoint and the target
    Wait(duration)               -> StopAndWaitTimerAction(wait_duration)
    Queue(service point)         -> walk to the agent's slot; move up a slot once the person ahead (the agent one
                                    rank before) has moved on (IsAgentClose on that agent); served one service time
                                    at the head; step aside to a spot of one's own, as GROVE's Queue does
    FollowVelocityField(field)   -> the field's streamline from the agent's start, through the exit door, to the
                                    evacuee's own point outside (rows across the door, 1 m apart)
    Wander(zone, duration)       -> a seeded tour of planned points inside the zone
    JoinGroup(group_id)          -> SetGroupId
    Converse(target, members)    -> walk to one's own spot on GROVE's conversation circle, wait for the other
                                    members (IsAgentClose, at most 60 s), LookAtPoint(centre), StopAndWaitTimerAction

Goals are written once into `global_goals` (ids consecutive from 1) and referenced by id.

What HuNavSim 2.0 needs beyond node names. Sources: robotics-upo/hunav_sim, the 2.0 code under
`namespace hunav` (newer than the humble/1.0 commit afa9743 the rosbag export pins). The public code
index stores these 2.0 files without one common commit; each is cited with the commit the index gives,
or by file and function where it gives none:
- hunav_loader.cpp (2.0, `HunavLoader::HunavLoader`, "Handle new goals structure"): `<agent>.goals` is
  declared PARAMETER_INTEGER_ARRAY; an empty YAML list has no type and aborts the loader, so every agent
  lists at least one goal (its tree's goals, else its start). exports/hunav_loader_check.py emulates it.
- bt_node.cpp (2.0, `tree_tick`) ticks every root on each ComputeAgents call and BT.CPP 4 resets a
  completed root, so each tree runs once and then holds its final state (bt/format/hunav_compat.wrap_for_hunav).
- go_to_node.cpp@306ec99c4451165c9322ab057ad00a0b6fabdbf8:49 sets the temporary goal's radius to 0.1 and
  :71 finishes on `goalReached` (radius + 0.1 m), whatever `tolerance` says: every GoTo is written with
  the 0.2 m HuNavSim applies.
- Agents are never removed (agent_manager has no removal): evacuees walk out to points of their own.
- 2.0 reacts to the robot only through the tree: a Surprised/Scared/Curious/Threatening agent gets
  the reaction GROVE's simulation wraps around its tree.
- conversation_formation_node.cpp (2.0, onStart step 11 `setAgentGoal`, onRunning step 2 `.front()`):
  why conversations are not lowered to ConversationFormation.
- bt_node.cpp (2.0, BTnode constructor): the simulator names and the wrapper package trees load from,
  `<src of the wrapper>/behavior_trees/<yaml_base_name>__agent_<id>_bt.xml` (`share_to_src_path`).
- hunav_gazebo_wrapper launch/simulation.launch.py@3e5219ed1f78370bbb78c9168aa7325a76fda976: the robot
  pose arguments gzpose_x/y/Y, `worlds/<environment_name>.world`, `maps/<environment_name>.yaml`,
  `scenarios/<configuration_file>`.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import shutil
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import yaml

from grove_tui.files import atomic_directory, check_output_dir, refuse_overlap, safe_file_name
from grove_tui.bt.format.hunav_compat import (
    hunav_loading_problems, label_clocks, prefix_node_ids, restrict_to_hunav_ports, wrap_for_hunav,
)
from grove_tui.bt.format.manifest import NODES, treenodes_model_xml
from grove_tui.bt.format.document import TreeDocument, TreeElement, node
from grove_tui.bt.format.ports import parse_point_list
from grove_tui.bt.format.xml import check_document, read_tree, write_tree
from grove_tui.errors import BTError, ExportError
from grove_tui.exports.gazebo_world import world_sdf
from grove_tui.generation.block_at_place import point_goal_ids
from grove_tui.exports.nav2_map import write_nav2_map
from grove_tui.exports.scene import Scene, agent_radius, behavior_block, goal_radius, scene_of, skin
from grove_tui.scenario.bundle import load_bundle_world, load_field, load_grid, load_scenario, read_bundle_text
from grove_tui.scenario.model import AgentSpec, Scenario
from grove_tui.world.model import Door, World

if TYPE_CHECKING:
    import shapely

    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.navigation.velocity_field import VelocityField

Point = tuple[float, float]
# A conversation: its centre rounded to the centimetre and its members' ids, as every member's tree names it.
ConversationKey = tuple[float, float, tuple[int, ...]]
# A robot reaction as the simulation wraps it: (reaction node, trigger distance m, duration s, only once).
Reaction = tuple[str, float, float, bool]

GROVE_ONLY = frozenset(name for name, spec in NODES.items() if spec.origin == "grove")
_HUNAV_GOTO_PORTS = ("agent_id", "time_step", "goal_id", "tolerance")
# What a lowered tree may contain: BT.CPP built-ins, HuNavSim's nodes, and HuNavSim's own GoTo(goal_id).
HUNAV_NODES = {name: spec for name, spec in NODES.items() if spec.origin != "grove"} | {
    "GoTo": dataclasses.replace(
        NODES["GoTo"],
        origin="hunavsim",
        ports=tuple(dataclasses.replace(p, auto=False, default=None) if p.name == "goal_id" else p
                    for p in NODES["GoTo"].ports if p.name in _HUNAV_GOTO_PORTS),
    )
}
EXPORT_MARKER = ".grove-hunav-export"
SPAWN_HEIGHT = 1.25  # HuNavSim's Gazebo actors stand on z = 1.25
# GROVE's own line at the top of an agents YAML it writes: what HuNavSim has no parameter for (prompt,
# preset, seed, robot, labels), as JSON in a comment the loader skips; `grove import hunav` reads it back.
GROVE_LINE_PREFIX = "# grove: "
DEFAULT_SIMULATOR = "Gazebo Classic"
# HuNavSim's loader defaults (hunav_loader.cpp): a value GROVE holds that a file left out is written
# only when it differs from what the loader would take anyway.
LOADER_AGENT_DEFAULTS: dict[str, object] = {"skin": -1, "group_id": -1, "max_vel": 1.0, "radius": 0.35,
                                            "goal_radius": 0.0, "cyclic_goals": True, "init_pose.x": 0.0,
                                            "init_pose.y": 0.0, "init_pose.z": 0.0, "init_pose.h": 0.0}
# Simulators as HuNavSim 2.0's agent manager names them (bt_node.cpp: the wrapper package it loads
# trees from depends on the loader's `simulator` parameter).
SIMULATOR_PACKAGES = {
    "Gazebo Classic": "hunav_gazebo_wrapper",
    "Gazebo Fortress": "hunav_gazebo_fortress_wrapper",
    "Isaac Sim": "hunav_isaac_wrapper",
    "Webots": "hunav_webots_wrapper",
}
HOLD_WAIT_SECONDS = 60.0
CONVERSATION_PATIENCE = 60.0  # GROVE's ConversationRegistry.PATIENCE: start anyway after this long
KEPT_NODE_PREFIX = "Grove"
STREAMLINE_STEP = 0.2
WANDER_LEG_SECONDS = 12.0


@dataclass
class GoalTable:
    """HuNavSim's `global_goals`: each distinct point once, ids consecutive from 1, at full precision
    (an imported file's 3.360 comes back as 3.36, the same double). An imported file's table comes
    first with its own ids (`keep`), duplicates included."""

    points: list[Point] = field(default_factory=list)
    _ids: dict[tuple[float, float], int] = field(default_factory=dict)

    def keep(self, table: dict[int, Point]) -> None:
        """Start from an imported file's global_goals: ids 1..n as they were."""
        for goal_id in sorted(table):
            if goal_id != len(self.points) + 1:
                raise ExportError(f"global_goals must be numbered 1, 2, ...: goal {goal_id} follows "
                                  f"{len(self.points)}")
            point = (float(table[goal_id][0]), float(table[goal_id][1]))
            self.points.append(point)
            self._ids.setdefault(point, goal_id)

    def id_of(self, point: Sequence[float]) -> int:
        key = (float(point[0]), float(point[1]))
        if key not in self._ids:
            self.points.append(key)
            self._ids[key] = len(self.points)
        return self._ids[key]

    def to_yaml(self) -> dict[int, dict[str, float]]:
        return {i + 1: {"x": p[0], "y": p[1]} for i, p in enumerate(self.points)}


@dataclass(frozen=True)
class HunavExport:
    directory: Path
    agents_yaml: Path
    trees: tuple[Path, ...]
    nodes_model: Path | None
    lowered: bool
    trajectories: tuple[Path, ...] = ()
    readme: Path | None = None
    world_file: Path | None = None  # Gazebo SDF (exports/gazebo_world.py)
    map_yaml: Path | None = None  # nav2 map description beside its .pgm (exports/nav2_map.py)
    layout: str = "2.0"  # the agents YAML's layout: "2.0", or "1.0" for a bundle imported from one


@dataclass
class _AgentContext:
    agent: AgentSpec
    scenario: Scenario
    bundle: Path
    goals: GoalTable
    queue_rank: dict[tuple[int, str], int]
    grid: OccupancyGrid | None
    planner: ThetaStarPlanner | None
    seed: int
    muster: dict[tuple[int, str], Point] = field(default_factory=dict)
    world: World | None = None
    conversations: dict[ConversationKey, dict[int, Point]] = field(default_factory=dict)


def _attr(el: TreeElement, name: str, default: str) -> str:
    """The element's `name` attribute, or `default` when the tree does not set it."""
    value = el.get(name)
    return default if value is None else value


def _attr_float(el: TreeElement, name: str, where: str) -> float:
    value = el.get(name)
    if value is None:
        raise ExportError(f"{where}: <{el.id}> on line {el.line} has no `{name}` port; "
                          "export needs post-processed trees (generate the bundle with grove)")
    try:
        return float(value)
    except ValueError:
        raise ExportError(f"{where}: <{el.id}> on line {el.line}: `{name}`={value!r} is not a number") from None


def _hunav_goto(goal_id: int, tolerance: float) -> TreeElement:
    return node("GoTo", agent_id="{id}", time_step="{dt}", goal_id=str(goal_id), tolerance=repr(float(tolerance)))


def _wait(seconds: float) -> TreeElement:
    return node("StopAndWaitTimerAction", agent_id="{id}", wait_duration=f"{seconds:g}")


def _sequence(children: Sequence[TreeElement], name: str) -> TreeElement:
    # With memory: when a robot reaction halts the route, the agent resumes at the leg it was on
    # instead of walking back to the first point (BT.CPP 4 keeps the index across halt()).
    return TreeElement("SequenceWithMemory", {"name": name}, list(children))


def _route(points: Sequence[Point], ctx: _AgentContext) -> list[TreeElement]:
    """HuNavSim GoTo nodes over `points`, each with the agent's goal radius as tolerance (scene.goal_radius:
    the agents YAML and the bag say the same; HuNavSim 2.0's GoTo itself always uses 0.1)."""
    return [_hunav_goto(ctx.goals.id_of(p), goal_radius(ctx.agent)) for p in points]


def _free_heading(origin: Point, ctx: _AgentContext, reach: float) -> float:
    """The direction from `origin` with the longest free run on the grid (up to `reach`)."""
    grid = ctx.grid
    if grid is None:
        return math.atan2(ctx.agent.start[1] - origin[1], ctx.agent.start[0] - origin[0])
    best_angle, best_run = 0.0, -1.0
    step = max(grid.resolution, 0.05)
    for k in range(32):
        angle = 2 * math.pi * k / 32
        run = 0.0
        while run < reach:
            x = origin[0] + math.cos(angle) * (run + step)
            y = origin[1] + math.sin(angle) * (run + step)
            if not grid.is_free(x, y):
                break
            run += step
        if run > best_run + 1e-9:
            best_angle, best_run = angle, run
    return best_angle


def _wait_until(condition: TreeElement, name: str) -> TreeElement:
    """RUNNING until `condition` succeeds, then SUCCESS (BT.CPP built-ins only: HuNavSim has no wait-until)."""
    return TreeElement("Inverter", {"name": name}, [node("KeepRunningUntilFailure", [node("Inverter", [condition])])])


def _at_most(seconds: float, child: TreeElement) -> TreeElement:
    """`child`, given up (successfully) after `seconds` (BT.CPP Timeout: wall clock in HuNavSim)."""
    return node("ForceSuccess", [node("Timeout", [child], msec=str(int(round(seconds * 1000))))])


def _agent_close(other: int, threshold: float) -> TreeElement:
    return node("IsAgentClose", observer_id="{id}", target_agent_id=str(other), threshold=f"{threshold:.2f}")


def _far_from(other: int, threshold: float) -> TreeElement:
    return node("Inverter", [_agent_close(other, threshold)])


def _aside_spot(service: Point, heading: float, rank: int, ctx: _AgentContext) -> Point:
    """Where the rank-th served person steps to: GROVE's rule (crowd/leaves/grove.py `_aside`), one spot each."""
    from grove_tui.crowd.leaves.grove import ASIDE_SPACING, STEP_ASIDE

    dx, dy = math.cos(heading), math.sin(heading)
    spots: list[Point] = []
    for ring in range(12):
        out = STEP_ASIDE + ASIDE_SPACING * ring
        for back in (0.0, ASIDE_SPACING):
            for sign in (1.0, -1.0):
                x = service[0] - sign * dy * out + dx * back
                y = service[1] + sign * dx * out + dy * back
                if ctx.grid is None or ctx.grid.is_free(x, y):
                    spots.append((x, y))
    if not spots:
        return service
    return spots[rank % len(spots)]


def _lower_queue(el: TreeElement, ctx: _AgentContext, where: str) -> TreeElement:
    """HuNavSim has no queue node: each person walks to its slot and moves up only once the person
    ahead of it (the agent one rank before) has moved on, then is served and steps aside, as GROVE's
    Queue does. Waiting on the person ahead instead of on a timer keeps two people off one slot."""
    service = (_attr_float(el, "x", where), _attr_float(el, "y", where))
    spacing = float(_attr(el, "spacing", "0.6"))
    service_time = float(_attr(el, "service_time", "10"))
    name = _attr(el, "service_point", "service point")
    rank = ctx.queue_rank.get((ctx.agent.id, name), 0)
    heading = _free_heading(service, ctx, reach=spacing * (rank + 2))
    slots = [(service[0] + math.cos(heading) * spacing * (k + 1), service[1] + math.sin(heading) * spacing * (k + 1))
             for k in range(rank + 1)]
    ahead = next((a for (a, n), r in ctx.queue_rank.items() if n == name and r == rank - 1), None)
    steps: list[TreeElement] = []
    steps += _route([slots[rank]], ctx)
    for k in range(rank, 0, -1):
        if ahead is not None:
            # the person ahead is in line in front of me (given up after one service time: it may have
            # moved on before I arrived), then has moved on out of the slot I step into
            steps.append(_at_most(service_time, _wait_until(_agent_close(ahead, 1.2 * spacing), "ahead_in_line")))
            steps.append(_wait_until(_far_from(ahead, 1.5 * spacing), "ahead_moved_on"))
        steps += _route([slots[k - 1]], ctx)
    steps.append(_wait(service_time))  # being served at the head
    steps += _route([_aside_spot(service, heading, rank, ctx)], ctx)
    return _sequence(steps, f"Queue_{name}")


def _streamline(vf: VelocityField, start: Point, exit_point: Point, ctx: _AgentContext) -> list[Point]:
    from grove_tui.navigation.velocity_field import sample_field

    ox, oy = float(vf.origin[0]), float(vf.origin[1])
    pos = np.array(start, dtype=float)
    points = [tuple(pos)]
    for _ in range(20000):
        if math.hypot(pos[0] - exit_point[0], pos[1] - exit_point[1]) < 0.5:
            break
        vx, vy = sample_field(vf.vectors, ox, oy, float(vf.resolution), float(pos[0]), float(pos[1]))
        norm = math.hypot(vx, vy)
        if norm < 1e-6:
            break
        pos = pos + STREAMLINE_STEP * np.array([vx, vy]) / norm
        points.append((float(pos[0]), float(pos[1])))
    points.append(exit_point)
    return _simplify_free(points, ctx)


def _simplify_free(points: list[Point], ctx: _AgentContext) -> list[Point]:
    """Fewest points whose straight legs stay in free space (greedy line-of-sight string pulling)."""
    if len(points) <= 2:
        return points[1:]
    grid = ctx.grid

    def visible(a: Point, b: Point) -> bool:
        if grid is None:
            return math.hypot(b[0] - a[0], b[1] - a[1]) < 3.0
        n = max(2, int(math.hypot(b[0] - a[0], b[1] - a[1]) / (grid.resolution * 0.5)))
        return all(grid.is_free(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t) for t in np.linspace(0, 1, n))

    out: list[Point] = []
    anchor = 0
    while anchor < len(points) - 1:
        nxt = anchor + 1
        for j in range(len(points) - 1, anchor, -1):
            if visible(points[anchor], points[j]):
                nxt = j
                break
        out.append(points[nxt])
        anchor = nxt
    return out


def _lower_field(el: TreeElement, ctx: _AgentContext, where: str) -> TreeElement:
    exit_point = (_attr_float(el, "x", where), _attr_float(el, "y", where))
    field_id = el.get("field")
    rel = ctx.scenario.fields.get(field_id or "")
    if rel is None:
        raise ExportError(f"{where}: FollowVelocityField on line {el.line} names field {field_id!r}, "
                          f"which the scenario does not list (fields: {sorted(ctx.scenario.fields)})")
    points = _streamline(load_field(ctx.bundle, field_id or "", rel), ctx.agent.start, exit_point, ctx)
    points += _beyond_exit(_attr(el, "exit", ""), ctx)
    return _sequence(_route(points, ctx), f"FollowVelocityField_{el.get('exit', 'exit')}")


def _beyond_exit(door_name: str, ctx: _AgentContext) -> list[Point]:
    """Through the door and on to this evacuee's own point outside, apart from everyone else's
    (scene.muster_points: the Gazebo world and the map cover it).

    GROVE removes an evacuee at the door; HuNavSim never removes agents and a GoTo goal holds only
    0.2 m, so without this every evacuee would end on the same point in the doorway.
    """
    world = ctx.world
    point = ctx.muster.get((ctx.agent.id, door_name))
    if world is None or point is None:
        return []
    door = world.find(door_name)
    if not isinstance(door, Door):  # the muster lists doors only: find() also knows zones and entities
        return []
    return [door.outward_point(1.0), point]


def _lower_wander(el: TreeElement, ctx: _AgentContext, where: str, world: World | None) -> TreeElement:
    zone_name = _attr(el, "zone", "")
    duration = float(_attr(el, "duration", "30"))
    if world is None:
        raise ExportError(f"{where}: Wander on line {el.line} needs the world to sample points")
    zone = world.zone(zone_name) if zone_name in {z.name for z in world.zones} else world.zone_at(*ctx.agent.start)
    if zone is None:
        raise ExportError(f"{where}: Wander on line {el.line}: unknown zone {zone_name!r}")
    rng = np.random.default_rng([ctx.seed, ctx.agent.id])
    minx, miny, maxx, maxy = zone.polygon.bounds
    legs = max(1, int(math.ceil(duration / WANDER_LEG_SECONDS)))
    stops: list[Point] = []
    tries = 0
    while len(stops) < legs and tries < 500:
        tries += 1
        p = (float(rng.uniform(minx, maxx)), float(rng.uniform(miny, maxy)))
        if (ctx.grid is None or ctx.grid.is_free(*p)) and zone.polygon.contains(_shapely_point(p)):
            stops.append(p)
    route: list[Point] = []
    here = ctx.agent.start
    for stop in stops:
        route += _planned(here, stop, ctx)
        here = stop
    return _sequence(_route(route, ctx), f"Wander_{zone.name}")


def _shapely_point(p: Point) -> shapely.Point:
    import shapely

    return shapely.Point(p)


def _planned(a: Point, b: Point, ctx: _AgentContext) -> list[Point]:
    if ctx.planner is None:
        return [b]
    path = ctx.planner.plan(a, b)
    return [(float(q[0]), float(q[1])) for q in path[1:]]


def _lower_element(el: TreeElement, ctx: _AgentContext, where: str, world: World | None) -> TreeElement | None:
    """Replacement for a GROVE-only element, or None to keep it."""
    tag = el.id
    if tag == "GoTo" and el.get("x") is not None:  # GROVE's GoTo; HuNavSim's own names only a goal_id
        target = (_attr_float(el, "x", where), _attr_float(el, "y", where))
        waypoints = list(parse_point_list(_attr(el, "waypoints", "")))
        return _sequence(_route(waypoints + [target], ctx), f"GoTo_{el.get('target', 'target')}")
    if tag == "Wait":
        return _wait(float(_attr(el, "duration", "5")))
    if tag == "Queue":
        return _lower_queue(el, ctx, where)
    if tag == "FollowVelocityField":
        return _lower_field(el, ctx, where)
    if tag == "Wander":
        return _lower_wander(el, ctx, where, world)
    if tag == "JoinGroup":
        group = el.get("group_id") or str(ctx.agent.group)
        return node("SetGroupId", agent_id="{id}", group_id=group)
    if tag == "Converse":
        return _lower_converse(el, ctx, where)
    return None


def _members(el: TreeElement, agent_id: int) -> tuple[int, ...]:
    return tuple(sorted({int(m) for m in (el.get("members") or str(agent_id)).replace(" ", "").split(",") if m}
                        | {agent_id}))


def _approach(el: TreeElement, start: Point) -> Point:
    """Where an agent comes from when it reaches a conversation: its last waypoint, else its start."""
    waypoints = list(parse_point_list(_attr(el, "waypoints", "")))
    return waypoints[-1] if waypoints else start


def _conversation_spots(scenario: Scenario, trees: dict[int, TreeDocument],
                        grid: OccupancyGrid | None) -> dict[ConversationKey, dict[int, Point]]:
    """Each conversation's spots, as GROVE's ConversationRegistry gives them (crowd/coordination.py):
    evenly around a circle of radius 0.5 + 0.2 per extra member, starting toward the first member,
    each member taking the closest free spot, closest pair first. Computed once for all members, from
    where each arrives, so every member's tree names the same circle."""
    from grove_tui.crowd.coordination import conversation_radius

    arrivals: dict[ConversationKey, dict[int, Point]] = {}
    centres: dict[ConversationKey, Point] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        for el in trees[agent.id].nodes():
            x_attr, y_attr = el.get("x"), el.get("y")
            if el.id != "Converse" or x_attr is None or y_attr is None:
                continue
            centre = (float(x_attr), float(y_attr))
            key = (round(centre[0], 2), round(centre[1], 2), _members(el, agent.id))
            centres[key] = centre
            arrivals.setdefault(key, {})[agent.id] = _approach(el, agent.start)
    plans: dict[ConversationKey, dict[int, Point]] = {}
    for key, arriving in arrivals.items():
        members = key[2]
        cx, cy = centres[key]
        n = len(members)
        radius = conversation_radius(n)
        first = arriving.get(members[0], next(iter(arriving.values())))
        start = math.atan2(first[1] - cy, first[0] - cx)
        spots = []
        for k in range(n):
            x, y = cx + radius * math.cos(start + 2 * math.pi * k / n), cy + radius * math.sin(start + 2 * math.pi * k / n)
            if grid is not None and not grid.is_free(x, y):
                x, y = grid.nearest_free(x, y) or (x, y)
            spots.append((float(x), float(y)))
        pairs = sorted((math.dist(arriving.get(m, (cx, cy)), spot), m, k) for m in members for k, spot in enumerate(spots))
        assigned: dict[int, Point] = {}
        used: set[int] = set()
        for _, m, k in pairs:
            if m not in assigned and k not in used:
                assigned[m] = spots[k]
                used.add(k)
        plans[key] = assigned
    return plans


def _lower_converse(el: TreeElement, ctx: _AgentContext, where: str) -> TreeElement:
    """GROVE's conversation in HuNavSim nodes: walk to one's own spot on the circle, wait until every
    other member is at theirs (at most CONVERSATION_PATIENCE s, as GROVE's registry), face the
    centre, talk for the duration.

    Not HuNavSim's ConversationFormation: it pushes the spots behind the agent's existing goals and
    then reads the goal list's front() (conversation_formation_node.cpp, onStart step 11 and onRunning
    step 2), so an agent that has any goal (every agent does: the loader needs one) never walks to its
    spot and the conversation never starts.
    """
    target = (_attr_float(el, "x", where), _attr_float(el, "y", where))
    waypoints = list(parse_point_list(_attr(el, "waypoints", "")))
    members = _members(el, ctx.agent.id)
    duration = float(_attr(el, "duration", "20"))
    key = (round(target[0], 2), round(target[1], 2), members)
    spots = ctx.conversations.get(key, {})
    mine = spots.get(ctx.agent.id, target)
    steps = _route(waypoints + [mine], ctx)
    for other in members:
        if other == ctx.agent.id:
            continue
        reach = math.dist(mine, spots.get(other, target)) + 0.5
        steps.append(_at_most(CONVERSATION_PATIENCE, _wait_until(_agent_close(other, reach), f"wait_for_{other}")))
    steps.append(node("LookAtPoint", agent_id="{id}", goal_id=str(ctx.goals.id_of(target))))
    steps.append(_wait(duration))
    return _sequence(steps, f"Converse_{el.get('target', 'spot')}")


def lower_tree(document: TreeDocument, ctx: _AgentContext, where: str, world: World | None = None) -> TreeDocument:
    """Rewrite one agent's tree, in place, so it uses only HuNavSim-registered and BT.CPP built-in nodes."""
    for tree in document.trees.values():
        # Depth-first over a snapshot, so goal ids are allocated in tick order and replacements
        # do not disturb the walk.
        for parent, index, el in list(tree.walk_with_parents()):
            if parent is None or el.id not in GROVE_ONLY:
                continue
            replacement = _lower_element(el, ctx, where, world)
            if replacement is not None:
                parent.children[index] = replacement
    return document


def _queue_ranks(scenario: Scenario, trees: dict[int, TreeDocument], tag: str = "Queue",
                 key: str = "service_point") -> dict[tuple[int, str], int]:
    """Sequential allocation: the members of each `tag` node's place (`key`), in agent-id order."""
    members: dict[str, list[int]] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        for el in trees[agent.id].nodes():
            if el.id != tag:
                continue
            name = _attr(el, key, "service point")
            if agent.id not in members.setdefault(name, []):
                members[name].append(agent.id)
    return {(a, name): rank for name, ids in members.items() for rank, a in enumerate(ids)}


def _renumber_goal_ids(document: TreeDocument, goals: GoalTable) -> TreeDocument:
    """Point every node's `goal_id` at this export's global_goals entry for its (x, y), in place."""
    for el in document.nodes():
        x, y = el.get("x"), el.get("y")
        if el.get("goal_id") is not None and x and y:
            el.set("goal_id", str(goals.id_of((float(x), float(y)))))
    return document


def _rename_main_tree(document: TreeDocument, new_id: str) -> TreeDocument:
    """The document with its main tree (and every SubTree call of it) renamed `new_id`."""
    old = document.main_tree_id
    for el in document.nodes():
        if el.subtree_id == old:
            el.set("ID", new_id)
    renamed: dict[str, TreeElement] = {}
    for tree_id, tree in document.trees.items():
        if tree_id == old:
            tree.set("ID", new_id)
            tree_id = new_id
        renamed[tree_id] = tree
    return TreeDocument(new_id, renamed, document.source, document.models)


def is_hunav_export(path: Path) -> bool:
    """A folder `export_hunav` wrote (the only kind of non-empty folder it replaces without --overwrite)."""
    return (path / EXPORT_MARKER).is_file()


def export_hunav(bundle_dir: str | Path, out_dir: str | Path, *, lower: bool = True,
                 simulator: str | None = None, base_name: str | None = None,
                 overwrite: bool = False, trajectories: bool = False) -> HunavExport:
    """Write `<base>.yaml` and `<base>__agent_<id>_bt.xml` files for HuNavSim into `out_dir`.

    A generated bundle gives HuNavSim 2.0's layout. A bundle imported from HuNavSim gives its file
    back: the same layout (1.0 while every tree is the one import made, since 1.0 loads no tree files),
    every key in its place with its value, and each tree file verbatim while GROVE's tree made from it
    is unchanged. `simulator` and `base_name` default to the imported file's, else Gazebo Classic and
    agents_<world>. With `trajectories`, a simulated bundle's trajectory files are copied beside them,
    in the same atomic step. `out_dir` may be new, empty or an earlier export; another folder only with
    `overwrite`.
    """
    bundle = Path(bundle_dir)
    if simulator is not None and simulator not in SIMULATOR_PACKAGES:
        raise ExportError(f"--simulator {simulator!r}: HuNavSim 2.0 knows " + ", ".join(map(repr, SIMULATOR_PACKAGES))
                          + " (the names its agent manager compares the loader's `simulator` parameter with)",
                          hint="Pass --simulator \"Gazebo Classic\", \"Gazebo Fortress\", \"Isaac Sim\" or \"Webots\".")
    out = check_output_dir(out_dir, owned=is_hunav_export, what="GROVE HuNavSim export", overwrite=overwrite)
    refuse_overlap(out, bundle_dir, "the bundle being exported")
    if base_name is not None:
        safe_file_name(base_name, "--base-name")
    scenario = load_scenario(bundle)
    source = scenario.hunav
    world_name = Path(scenario.world).stem
    simulator = simulator or (source.simulator if source is not None else None) or DEFAULT_SIMULATOR
    if simulator not in SIMULATOR_PACKAGES:  # an imported file's own name for its wrapper
        simulator = DEFAULT_SIMULATOR
    base = base_name or (source.base_name or Path(source.file).stem if source is not None else f"agents_{world_name}")
    safe_file_name(base, "yaml_base_name")
    map_name = source.map if source is not None and source.map else world_name

    texts: dict[int, str] = {}
    trees: dict[int, TreeDocument] = {}
    for agent in scenario.agents:
        # Inside the bundle, a regular file, bounded: a tree linked to /dev/zero once read 7.5 GB here.
        texts[agent.id] = read_bundle_text(bundle, agent.tree, f"tree file of agent {agent.id}")
        try:
            trees[agent.id] = read_tree(texts[agent.id], str(bundle / agent.tree))
        except BTError as exc:
            raise ExportError(f"tree of agent {agent.id}: {exc}") from None
    from grove_tui.exports.hunav_import import tree_digest

    # What import made of HuNavSim's file, untouched since: written back as it came.
    kept = {a.id for a in scenario.agents
            if a.hunav is not None and a.hunav.tree_digest and tree_digest(texts[a.id]) == a.hunav.tree_digest}
    layout = "1.0" if source is not None and source.layout == "1.0" and len(kept) == len(scenario.agents) else "2.0"
    as_given = source is not None and source.layout == layout

    from grove_tui.navigation.grid import build_grid

    world = load_bundle_world(bundle, scenario)
    scene = scene_of(world, scenario, trees)
    grid = planner = None
    if lower:
        from grove_tui.navigation.theta_star import ThetaStarPlanner

        grid_path = bundle / "grid.npz"
        grid = load_grid(bundle) if os.path.lexists(grid_path) else build_grid(world, scenario.resolution, scenario.grid_inflation)
        planner = ThetaStarPlanner(grid)

    from grove_tui.simulation.simulation import HUNAV_LOOPING_NODES, REACTION_DEFAULTS

    goals = GoalTable()
    # An imported HuNavSim scenario's trees name goals by id: keep those ids (1..n) as they were.
    try:
        goals.keep(scenario.global_goals)
    except ExportError as exc:
        raise ExportError(f"{bundle / 'scenario.yaml'}: {exc}") from None
    ranks = _queue_ranks(scenario, trees) if lower else {}
    conversations = _conversation_spots(scenario, trees, grid) if lower else {}
    written: dict[str, str] = {}
    agent_entries: dict[str, dict[str, object]] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        where = str(bundle / agent.tree)
        name = agent.hunav.name if agent.hunav is not None else f"agent{agent.id}"
        tree_name = f"{base}__agent_{agent.id}_bt.xml"
        goal_ids = [goals.id_of(g) for g in agent.goals]
        verbatim = agent.hunav.tree_file if agent.id in kept and agent.hunav is not None else ""
        if agent.id in kept and layout == "1.0":
            pass  # HuNavSim 1.0 loads no tree file: it runs its own tree for the agent's behavior
        elif verbatim:
            written[tree_name] = read_bundle_text(bundle, verbatim, f"HuNavSim tree of agent {agent.id}")
        else:
            xml, tree = _hunav_tree(agent, trees[agent.id], scenario, bundle, goals, ranks, grid, planner, scene,
                                    world, conversations, lower, where, REACTION_DEFAULTS, HUNAV_LOOPING_NODES)
            written[tree_name] = xml
            if not goal_ids:
                # hunav_loader.cpp: `goals` is an INTEGER_ARRAY parameter, and an empty list has no type.
                goal_ids = _tree_goal_ids(tree) or [goals.id_of(agent.start)]
        # hunav_loader.cpp: `goals` is an INTEGER_ARRAY parameter, and an empty list has no type: an agent
        # that stays where it is lists its start (the import reads that back as no goals).
        goal_ids = goal_ids or [goals.id_of(agent.start)]
        if as_given and source is not None and agent.hunav is not None:
            agent_entries[name] = _entry_as_given(agent, layout, goal_ids, source.behavior_type == "number")
        else:
            agent_entries[name] = _entry(agent, goal_ids)
    includes: dict[str, str] = {}
    if source is not None and layout == "2.0" and any(a.hunav is not None and a.hunav.tree_file
                                                      for a in scenario.agents if a.id in kept):
        for rel in source.includes:
            includes[rel] = read_bundle_text(bundle, f"hunav/{rel}", "HuNavSim tree a tree includes")
    if source is not None:  # the file's own order of agents
        order = {n: k for k, n in enumerate(source.agents)}
        agent_entries = dict(sorted(agent_entries.items(), key=lambda item: order.get(item[0], len(order))))

    top: dict[str, object] = {"yaml_base_name": base, "simulator": simulator, "map": map_name,
                              "publish_people": source.publish_people if source is not None and
                              source.publish_people is not None else True,
                              "global_goals": goals.to_yaml(), "agents": list(agent_entries)}
    if layout == "1.0":
        del top["global_goals"]
    keys = list(top)
    if as_given and source is not None:
        # the file's keys in its order, what it left out only where GROVE needs it (its agents, goals)
        keys = [k for k in source.keys if k in top] + [k for k in ("global_goals", "agents")
                                                        if k in top and k not in source.keys]
        if source.publish_people is None:
            keys = [k for k in keys if k != "publish_people"]
    params: dict[str, object] = {key: top[key] for key in keys}
    params.update(agent_entries)
    document = {"hunav_loader": {"ros__parameters": params}}
    from grove_tui.exports.hunav_loader_check import check_loader_parameters

    loader_problems = check_loader_parameters(yaml.safe_load(yaml.safe_dump(document)), f"{base}.yaml")
    if loader_problems:
        raise ExportError("HuNavSim's loader would refuse the export: " + "; ".join(loader_problems))
    nodes_model = None if lower or not written else treenodes_model_xml(
        renamed={name: KEPT_NODE_PREFIX + name for name in GROVE_ONLY})
    readme = export_readme(scenario, base, map_name, simulator, sorted(written), lower, layout)
    agents_text = yaml.safe_dump(document, sort_keys=False, width=120)
    if source is None or source.grove_comment:
        agents_text = grove_line(scenario) + agents_text
    # The world file and the map cover every goal the export names (scene.extent).
    scene = scene.with_points(goals.points)

    copied: list[str] = []
    with atomic_directory(out, owned=is_hunav_export, what="GROVE HuNavSim export", overwrite=overwrite) as staging:
        if trajectories:
            copied = copy_trajectories(bundle, staging)
        (staging / EXPORT_MARKER).write_text("written by grove export hunav\n", encoding="utf-8")
        (staging / f"{base}.yaml").write_text(agents_text, encoding="utf-8")
        for tree_name, xml in written.items():
            (staging / tree_name).write_text(xml, encoding="utf-8")
        for rel, text in includes.items():  # what HuNavSim's own trees <include>, beside them as they were
            (staging / rel).parent.mkdir(parents=True, exist_ok=True)
            (staging / rel).write_text(text, encoding="utf-8")
        if nodes_model is not None:
            (staging / "grove_nodes_model.xml").write_text(nodes_model, encoding="utf-8")
        (staging / "README.md").write_text(readme, encoding="utf-8")
        # hunav_gazebo_wrapper's layout: worlds/<environment_name>.world, maps/<environment_name>.yaml
        (staging / "worlds").mkdir()
        (staging / "worlds" / f"{map_name}.world").write_text(world_sdf(scene), encoding="utf-8")
        write_nav2_map(scene.static_map, staging / "maps", map_name)
    return HunavExport(
        directory=out,
        agents_yaml=out / f"{base}.yaml",
        trees=tuple(out / name for name in written),
        nodes_model=None if nodes_model is None else out / "grove_nodes_model.xml",
        lowered=lower,
        trajectories=tuple(out / name for name in copied),
        readme=out / "README.md",
        world_file=out / "worlds" / f"{map_name}.world",
        map_yaml=out / "maps" / f"{map_name}.yaml",
        layout=layout,
    )


def _hunav_tree(agent: AgentSpec, document: TreeDocument, scenario: Scenario, bundle: Path, goals: GoalTable,
                ranks: dict[tuple[int, str], int], grid: OccupancyGrid | None, planner: ThetaStarPlanner | None,
                scene: Scene, world: World | None, conversations: dict[ConversationKey, dict[int, Point]], lower: bool,
                where: str, reactions: dict[str, Reaction], looping: frozenset[str]) -> tuple[str, TreeDocument]:
    """An agent's GROVE tree as HuNavSim 2.0 loads it: GROVE-only nodes lowered (or kept as Grove<Node>),
    run once then hold, the robot reaction inside; the XML and the tree it was written from."""
    ctx = _AgentContext(agent, scenario, bundle, goals, ranks, grid, planner, scenario.seed,
                        muster=scene.muster, world=world if lower else None, conversations=conversations)
    tree = lower_tree(document, ctx, where, world) if lower else _renumber_goal_ids(document, goals)
    point_goal_ids(tree, goals.id_of)  # IsAtPosition(target_x, target_y): HuNavSim knows it by goal id
    tree = _rename_main_tree(tree, "DefaultTree")
    problems = check_document(tree, HUNAV_NODES if lower else NODES, source=where)
    if problems:
        raise ExportError(f"{where}: exported tree does not validate: " + "; ".join(str(p) for p in problems))
    wrap_for_hunav(tree, reaction=reactions.get(agent.behavior), hold_seconds=HOLD_WAIT_SECONDS, looping=looping)
    if not lower:
        # Kept GROVE nodes get their own IDs, so GROVE's GoTo(target, x, y) never clashes with
        # HuNavSim's registered GoTo(goal_id); a C++ plugin must register them under these names.
        prefix_node_ids(tree, GROVE_ONLY, KEPT_NODE_PREFIX)
    xml = write_tree(label_clocks(restrict_to_hunav_ports(tree)))
    if lower:
        refusals = hunav_loading_problems(xml)
        if refusals:
            raise ExportError(f"{where}: HuNavSim 2.0 would refuse the exported tree: " + "; ".join(refusals),
                              hint="Export with --keep-grove-nodes to see the tree as GROVE wrote it.")
    return xml, tree


def _entry(agent: AgentSpec, goal_ids: list[int]) -> dict[str, object]:
    """An agent in HuNavSim 2.0's layout, every key the loader reads (exports/scene.py gives the values)."""
    z = agent.hunav.z if agent.hunav is not None and agent.hunav.z is not None else SPAWN_HEIGHT
    return {
        "id": agent.id,
        "skin": skin(agent),
        "group_id": agent.group,
        "max_vel": float(agent.max_vel),
        "radius": agent_radius(agent),
        "goal_radius": goal_radius(agent),
        "cyclic_goals": bool(agent.cyclic_goals),
        "init_pose": {"x": float(agent.start[0]), "y": float(agent.start[1]), "z": z, "h": agent.initial_heading()},
        "behavior": behavior_block(agent),
        "goals": goal_ids,
    }


def _set(entry: dict[str, object], dotted: str, value: object) -> None:
    node = entry
    *parents, last = dotted.split(".")
    for part in parents:
        child = node.setdefault(part, {})
        if not isinstance(child, dict):
            raise ExportError(f"agents yaml: {dotted} sits under a value, not a mapping")
        node = child
    node[last] = value


def _entry_as_given(agent: AgentSpec, layout: str, goal_ids: list[int], numbers: bool) -> dict[str, object]:
    """An imported agent as its file had it: its keys in their order with GROVE's values (so an edit in
    GROVE shows), a value GROVE holds that the file left out only when the loader would read another."""
    given = agent.hunav
    assert given is not None
    values: dict[str, object] = {
        "id": agent.id, "skin": given.skin, "group_id": agent.group, "max_vel": float(agent.max_vel),
        "radius": agent_radius(agent), "goal_radius": goal_radius(agent), "cyclic_goals": bool(agent.cyclic_goals),
        "init_pose.x": float(agent.start[0]), "init_pose.y": float(agent.start[1]), "init_pose.z": given.z,
        "init_pose.h": agent.initial_heading(),
    }
    block = behavior_block(agent, numbers=numbers)
    if given.behavior is None:
        values["behavior"] = block["type"]  # HuNavSim 1.0's flat `behavior: <number>`
    else:
        values.update({f"behavior.{key}": value for key, value in block.items()})
    if layout == "2.0":
        same = len(given.goal_ids) == len(goal_ids) and all(a == b for a, b in zip(given.goal_ids, goal_ids))
        values["goals"] = list(given.goal_ids) if same or not goal_ids else goal_ids
    else:
        names = list(given.goal_names) if len(given.goal_names) == len(agent.goals) else \
            [f"g{k}" for k in range(len(agent.goals))]
        headings = list(given.goal_headings) if len(given.goal_headings) == len(agent.goals) else [None] * len(names)
        values["goals"] = names
        for goal_name, (x, y), h in zip(names, agent.goals, headings):
            values[f"{goal_name}.x"], values[f"{goal_name}.y"] = float(x), float(y)
            if h is not None:
                values[f"{goal_name}.h"] = h
    order = [key for key in given.keys if key in values] + [key for key in values if key not in given.keys]
    entry: dict[str, object] = {}
    for key in order:
        value = values[key]
        if value is None:
            continue
        if key not in given.keys and LOADER_AGENT_DEFAULTS.get(key, object()) == value:
            continue
        _set(entry, key, value)
    return entry


def grove_line(scenario: Scenario) -> str:
    """The comment lines an agents YAML starts with: GROVE's own data, as `grove import hunav` reads it."""
    data: dict[str, object] = {"prompt": scenario.prompt, "preset": scenario.preset, "seed": scenario.seed,
                               "world": scenario.world, "resolution": scenario.resolution}
    if scenario.robot is not None:
        data["robot"] = scenario.to_dict()["robot"]
    data["agents"] = {str(a.id): {"label": a.label, "zone": a.zone} for a in scenario.agents}
    return ("# Written by GROVE (grove export hunav); `grove import hunav` reads the next line back. HuNavSim's\n"
            "# loader skips comments.\n" + GROVE_LINE_PREFIX + json.dumps(data, separators=(",", ":")) + "\n")


def _tree_goal_ids(document: TreeDocument) -> list[int]:
    """The literal global goal ids a tree's nodes name, first use first."""
    ids: list[int] = []
    for el in document.nodes():
        value = el.get("goal_id")
        if value is not None and value.isdigit() and int(value) not in ids:
            ids.append(int(value))
    return ids


def robot_launch_arguments(scenario: Scenario) -> dict[str, str]:
    """hunav_gazebo_wrapper's robot pose launch arguments (launch/simulation.launch.py: gzpose_x/y/Y)."""
    robot = scenario.robot
    if robot is None:
        return {}
    heading = 0.0
    if robot.path and len(robot.path) > 1:
        (x0, y0), (x1, y1) = robot.path[0][:2], robot.path[1][:2]
        heading = math.atan2(y1 - y0, x1 - x0)
    elif robot.goal is not None:
        heading = math.atan2(robot.goal[1] - robot.start[1], robot.goal[0] - robot.start[0])
    return {"gzpose_x": f"{robot.start[0]:.3f}", "gzpose_y": f"{robot.start[1]:.3f}", "gzpose_Y": f"{heading:.3f}"}


def export_readme(scenario: Scenario, base: str, world_name: str, simulator: str, tree_files: list[str],
                  lowered: bool, layout: str = "2.0") -> str:
    """Where each exported file goes and how to start the scenario, for the README beside them."""
    package = SIMULATOR_PACKAGES[simulator]
    launch = robot_launch_arguments(scenario)
    args = " ".join([f"configuration_file:={base}.yaml", f"environment_name:={world_name}"]
                    + [f"{k}:={v}" for k, v in launch.items()])
    if layout == "1.0":
        version = ("For HuNavSim 1.0, the layout this scenario was imported in (goals named per agent with "
                   "x, y, h; the behavior a number). HuNavSim 1.0 runs a fixed tree per behavior, so there are no "
                   "tree files. ROS 2 bags of a run (`grove export rosbag --hunav-msgs 1.0`) carry 1.0's "
                   "`hunav_msgs/Agent` (`uint8 behavior`).")
        trees = ["- No tree files: HuNavSim 1.0's agent manager picks BT<Behavior>Nav.xml by each agent's behavior."]
    else:
        version = ("For HuNavSim 2.0 (robotics-upo/hunav_sim master: behavior trees in BehaviorTree.CPP 4, "
                   "`global_goals`, `hunav_msgs/Agent` with a nested `AgentBehavior`). ROS 2 bags of the same run "
                   "(`grove export rosbag`) carry hunav_msgs 2.0 by default; `--hunav-msgs 1.0` writes HuNavSim "
                   "1.0's messages.")
        trees = [f"- `{base}__agent_<id>_bt.xml` ({len(tree_files)} files) -> `<ws>/src/{package}/behavior_trees/`: "
                 "the agent manager loads `<yaml_base_name>__agent_<id>_bt.xml` from the *source* folder of the "
                 "wrapper (bt_node.cpp `share_to_src_path`), not from `install/`. A tree that `<include>`s "
                 "HuNavSim's own files (BTRegularNav.xml) needs them beside it, as in HuNavSim's folder."]
    lines = [
        f"# HuNavSim {layout} scenario exported by GROVE ({simulator})",
        "",
        f"World `{world_name}`, {len(scenario.agents)} agents, prompt: {scenario.prompt!r}.",
        "",
        version,
        "",
        "## Where the files go",
        "",
        f"- `{base}.yaml` -> `<ws>/src/{package}/scenarios/` (read by `hunav_loader`; the launch file takes it "
        "as `configuration_file`).",
        *trees,
        f"- `worlds/{world_name}.world` (Gazebo SDF: walls with the door gaps, furniture as boxes, a ground plane "
        f"under every goal) -> `<ws>/src/{package}/worlds/`, and `maps/{world_name}.yaml` + "
        f"`maps/{world_name}.pgm` (nav2 map of the same walls and boxes over the same extent, not inflated) -> "
        f"`<ws>/src/{package}/maps/`: the launch loads `worlds/<environment_name>.world` and "
        "`maps/<environment_name>.yaml`. (Isaac Sim and Webots build their scenes from USD/Webots files; the SDF "
        "is for Gazebo.)",
        "",
        "## Build, then run",
        "",
        f"The launch file finds the scenario, the world and the map in the *installed* share folder of "
        f"`{package}` (`FindPackageShare`), so rebuild the workspace after copying the files:",
        "",
        "```bash",
        f"cd <ws> && colcon build --packages-select {package} && source install/setup.bash",
        f"ros2 launch {package} simulation.launch.py {args}",
        "```",
        "",
    ]
    if scenario.robot is not None and scenario.robot.goal is not None:
        gx, gy = scenario.robot.goal
        lines += [
            "The robot's goal, for your navigation stack and HuNavSim's evaluator (which starts recording when a "
            "goal arrives on `goal_pose`):",
            "",
            "```bash",
            "ros2 topic pub --once /goal_pose geometry_msgs/msg/PoseStamped "
            f"\"{{header: {{frame_id: map}}, pose: {{position: {{x: {gx:.3f}, y: {gy:.3f}}}, orientation: {{w: 1.0}}}}}}\"",
            "```",
            "",
        ]
    lines += [
        "## How GROVE's behaviors became HuNavSim's",
        "",
        "- Each tree runs once, then the agent holds where it ended (HuNavSim ticks every root each step and "
        "BehaviorTree.CPP restarts a finished root).",
        "- Every GoTo's `tolerance` is its agent's `goal_radius` (GROVE's agents: 0.1 m, the radius HuNavSim 2.0's "
        "GoTo applies whatever `tolerance` says); a goal counts as reached within goal_radius + 0.1 m.",
        "- Timed nodes: StopAndWaitTimerAction, ConversationFormation, TimeDelay, Delay, Timeout and the `duration` "
        "of HuNavSim's stateful nodes count wall-clock seconds in HuNavSim (GROVE counts simulation seconds); "
        "TimeExpiredCondition and the *Nav reactions count simulation time. Run Gazebo at real time factor 1 "
        "for the two to agree.",
        "- Evacuees walk through their exit to their own point outside (HuNavSim never removes agents).",
        "- Surprised, Scared, Curious and Threatening agents carry their robot reaction in the tree "
        "(IsRobotVisible then the *Nav node), as HuNavSim 2.0 reacts only through trees.",
        "- People who react to the robot keep reacting once their task is over: the hold sits inside the "
        "reaction (ReactiveFallback[robot cue, run_once_then_hold]), as in GROVE's simulation.",
    ]
    if not lowered:
        lines += ["- Kept GROVE nodes are named `Grove<Node>` (see `grove_nodes_model.xml`); HuNavSim loads these "
                  "trees only with a plugin that registers them."]
    return "\n".join(lines) + "\n"


def copy_trajectories(bundle_dir: Path, out_dir: Path) -> list[str]:
    """Names of the trajectory files of a simulated bundle, copied into `out_dir`."""
    copied = []
    for name in ("trajectories.csv", "trajectories.sqlite", "trajectories.txt"):
        src = bundle_dir / name
        if src.is_file() and not src.is_symlink():
            shutil.copy2(src, out_dir / name)
            copied.append(name)
    return copied


