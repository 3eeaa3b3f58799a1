"""HuNavSim 2.0 hand-off: agents.yaml (`hunav_loader: ros__parameters:`) plus one BT XML per agent.

HuNavSim only runs the nodes its agent manager registers. GROVE-only nodes are either
*lowered* to HuNavSim nodes (the default) or kept, with a TreeNodesModel listing them so Groot2
and a C++ implementation know their ports:

    GoTo(x, y, waypoints)        -> Sequence of HuNavSim GoTo(goal_id) over every waypoint and the target
    Wait(duration)               -> StopAndWaitTimerAction(wait_duration)
    Queue(service point)         -> walk to the agent's slot, then step forward slot by slot, waiting
                                    one service time at each (its rank is its order among the queue's
                                    members, which post-processing allocates sequentially)
    FollowVelocityField(field)   -> the field's streamline from the agent's start, as GoTo waypoints
    Wander(zone, duration)       -> a seeded tour of planned points inside the zone
    JoinGroup(group_id)          -> SetGroupId
    Converse(target, members)    -> walk to the spot, then ConversationFormation on the first member,
                                    StopAndWaitTimerAction on the others

Goals are written once into `global_goals` (ids consecutive from 1) and referenced by id.
"""

from __future__ import annotations

import dataclasses
import math
import os
import shutil
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import yaml

from grove_tui.bt.document import TreeDocument, TreeElement
from grove_tui.bt.manifest import NODES, treenodes_model_xml
from grove_tui.bt.ports import parse_point_list
from grove_tui.bt.xml import check_tree_text, read_tree, write_tree
from grove_tui.errors import BTError, ExportError
from grove_tui.files import atomic_directory, check_output_dir, safe_file_name
from grove_tui.scenario.bundle import load_field, load_grid, load_scenario, read_bundle_text
from grove_tui.scenario.model import AgentSpec, Scenario

if TYPE_CHECKING:
    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.navigation.theta_star import ThetaStarPlanner

Point = tuple[float, float]

BEHAVIOR_TYPES = ("Regular", "Impassive", "Surprised", "Scared", "Curious", "Threatening")
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
GOAL_TOLERANCE = 0.3
STREAMLINE_STEP = 0.2
WANDER_LEG_SECONDS = 12.0


@dataclass
class GoalTable:
    """HuNavSim's `global_goals`: each distinct point once, ids consecutive from 1."""

    points: list[Point] = field(default_factory=list)
    _ids: dict[tuple[float, float], int] = field(default_factory=dict)

    def id_of(self, point: Sequence[float]) -> int:
        key = (round(float(point[0]), 2), round(float(point[1]), 2))
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
    return TreeElement("GoTo", {"agent_id": "{id}", "time_step": "{dt}", "goal_id": str(goal_id),
                                "tolerance": f"{tolerance:g}"})


def _wait(seconds: float) -> TreeElement:
    return TreeElement("StopAndWaitTimerAction", {"agent_id": "{id}", "wait_duration": f"{seconds:g}"})


def _sequence(children: Sequence[TreeElement], name: str) -> TreeElement:
    return TreeElement("Sequence", {"name": name}, list(children))


def _route(points: Sequence[Point], ctx: _AgentContext, tolerance: float = GOAL_TOLERANCE) -> list[TreeElement]:
    return [_hunav_goto(ctx.goals.id_of(p), tolerance) for p in points]


def _queue_slots(service: Point, spacing: float, count: int, ctx: _AgentContext) -> list[Point]:
    """Slots on a line from the service point into the free space in front of it."""
    heading = _free_heading(service, ctx, reach=spacing * (count + 1))
    return [(service[0] + math.cos(heading) * spacing * (k + 1), service[1] + math.sin(heading) * spacing * (k + 1))
            for k in range(count)]


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


def _lower_queue(el: TreeElement, ctx: _AgentContext, where: str) -> TreeElement:
    service = (_attr_float(el, "x", where), _attr_float(el, "y", where))
    spacing = float(el.get("spacing", "0.6"))
    service_time = float(el.get("service_time", "10"))
    name = el.get("service_point", "service point")
    rank = ctx.queue_rank.get((ctx.agent.id, name), 0)
    slots = _queue_slots(service, spacing, rank + 1, ctx)
    steps: list[TreeElement] = []
    # Walk to the slot behind everyone who queued first, then advance one slot per service time.
    steps += _route([slots[rank]], ctx, tolerance=0.2)
    for k in range(rank, 0, -1):
        steps.append(_wait(service_time))
        steps += _route([slots[k - 1]], ctx, tolerance=0.2)
    steps.append(_wait(service_time))  # being served at the head
    return _sequence(steps, f"Queue_{name}")


def _streamline(vf, start: Point, exit_point: Point, ctx: _AgentContext) -> list[Point]:
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
    return _sequence(_route(points, ctx), f"FollowVelocityField_{el.get('exit', 'exit')}")


def _lower_wander(el: TreeElement, ctx: _AgentContext, where: str, world) -> TreeElement:
    zone_name = el.get("zone", "")
    duration = float(el.get("duration", "30"))
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


def _shapely_point(p: Point):
    import shapely

    return shapely.Point(p)


def _planned(a: Point, b: Point, ctx: _AgentContext) -> list[Point]:
    if ctx.planner is None:
        return [b]
    path = ctx.planner.plan(a, b)
    return [(float(q[0]), float(q[1])) for q in path[1:]]


def _lower_element(el: TreeElement, ctx: _AgentContext, where: str, world) -> TreeElement | None:
    """Replacement for a GROVE-only element, or None to keep it."""
    tag = el.id
    if tag == "GoTo" and el.get("x") is not None:  # GROVE's GoTo; HuNavSim's own names only a goal_id
        target = (_attr_float(el, "x", where), _attr_float(el, "y", where))
        waypoints = list(parse_point_list(el.get("waypoints", "")))
        tolerance = float(el.get("tolerance", str(GOAL_TOLERANCE)))
        return _sequence(_route(waypoints + [target], ctx, tolerance), f"GoTo_{el.get('target', 'target')}")
    if tag == "Wait":
        return _wait(float(el.get("duration", "5")))
    if tag == "Queue":
        return _lower_queue(el, ctx, where)
    if tag == "FollowVelocityField":
        return _lower_field(el, ctx, where)
    if tag == "Wander":
        return _lower_wander(el, ctx, where, world)
    if tag == "JoinGroup":
        group = el.get("group_id") or str(ctx.agent.group)
        return TreeElement("SetGroupId", {"agent_id": "{id}", "group_id": group})
    if tag == "Converse":
        target = (_attr_float(el, "x", where), _attr_float(el, "y", where))
        waypoints = list(parse_point_list(el.get("waypoints", "")))
        members = [int(m) for m in (el.get("members") or str(ctx.agent.id)).replace(" ", "").split(",") if m]
        duration = float(el.get("duration", "20"))
        steps = _route(waypoints + [target], ctx)
        if members and members[0] == ctx.agent.id:
            steps.append(TreeElement("ConversationFormation", {
                "main_agent_id": "{id}", "goal_id": str(ctx.goals.id_of(target)),
                "conversation_duration": f"{duration:g}", "time_step": "{dt}",
                "non_main_agent_ids": ",".join(str(m) for m in members[1:]),
            }))
        else:
            steps.append(_wait(duration))
        return _sequence(steps, f"Converse_{el.get('target', 'spot')}")
    return None


def lower_tree(document: TreeDocument, ctx: _AgentContext, where: str, world=None) -> TreeDocument:
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


def _queue_ranks(scenario: Scenario, trees: dict[int, TreeDocument]) -> dict[tuple[int, str], int]:
    """Sequential allocation: each queue's members in agent-id order."""
    members: dict[str, list[int]] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        for el in trees[agent.id].nodes():
            if el.id != "Queue":
                continue
            name = el.get("service_point", "service point")
            if agent.id not in members.setdefault(name, []):
                members[name].append(agent.id)
    return {(a, name): rank for name, ids in members.items() for rank, a in enumerate(ids)}


def _initial_heading(agent: AgentSpec) -> float:
    if not agent.goals:
        return 0.0
    gx, gy = agent.goals[0]
    return math.atan2(gy - agent.start[1], gx - agent.start[0])


def _behavior_block(agent: AgentSpec) -> dict[str, object]:
    kind = agent.behavior if agent.behavior in BEHAVIOR_TYPES else "Regular"
    return {
        "type": kind,
        "configuration": 0,
        "duration": 40.0,
        "once": True,
        "vel": round(min(max(agent.max_vel, 0.0), 1.8), 3),
        "dist": 0.0,
        "goal_force_factor": 2.0,
        "obstacle_force_factor": 10.0,
        "social_force_factor": 5.0,
        "other_force_factor": 20.0,
    }


def _renumber_goal_ids(document: TreeDocument, goals: GoalTable) -> TreeDocument:
    """Point every node's `goal_id` at this export's global_goals entry for its (x, y), in place."""
    for el in document.nodes():
        if el.get("goal_id") is not None and el.get("x") and el.get("y"):
            el.set("goal_id", str(goals.id_of((float(el.get("x")), float(el.get("y"))))))
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
                 simulator: str = "Gazebo Classic", base_name: str | None = None,
                 overwrite: bool = False, trajectories: bool = False) -> HunavExport:
    """Write `<base>.yaml` and `<base>__agent_<id>_bt.xml` files for HuNavSim 2.0 into `out_dir`.

    With `trajectories`, a simulated bundle's trajectory files are copied beside them, in the same
    atomic step. `out_dir` may be new, empty or an earlier export; another folder only with `overwrite`.
    """
    bundle = Path(bundle_dir)
    out = check_output_dir(out_dir, owned=is_hunav_export, what="GROVE HuNavSim export", overwrite=overwrite)
    if base_name is not None:
        safe_file_name(base_name, "--base-name")
    scenario = load_scenario(bundle)
    world_name = Path(scenario.world).stem
    base = base_name or f"agents_{world_name}"

    trees: dict[int, TreeDocument] = {}
    for agent in scenario.agents:
        # Inside the bundle, a regular file, bounded: a tree linked to /dev/zero once read 7.5 GB here.
        text = read_bundle_text(bundle, agent.tree, f"tree file of agent {agent.id}")
        try:
            trees[agent.id] = read_tree(text, str(bundle / agent.tree))
        except BTError as exc:
            raise ExportError(f"tree of agent {agent.id}: {exc}") from None

    world = grid = planner = None
    if lower:
        from grove_tui.navigation.grid import build_grid
        from grove_tui.navigation.theta_star import ThetaStarPlanner
        from grove_tui.world import load_world

        world = load_world(scenario.world)
        grid_path = bundle / "grid.npz"
        grid = load_grid(bundle) if os.path.lexists(grid_path) else build_grid(world, scenario.resolution)
        planner = ThetaStarPlanner(grid)

    goals = GoalTable()
    ranks = _queue_ranks(scenario, trees) if lower else {}
    written: dict[str, str] = {}
    agent_entries: dict[str, dict[str, object]] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        where = str(bundle / agent.tree)
        ctx = _AgentContext(agent, scenario, bundle, goals, ranks, grid, planner, scenario.seed)
        goal_ids = [goals.id_of(g) for g in agent.goals]
        tree = lower_tree(trees[agent.id], ctx, where, world) if lower else _renumber_goal_ids(trees[agent.id], goals)
        xml = write_tree(_rename_main_tree(tree, "DefaultTree"))
        problems = check_tree_text(xml, source=where, nodes=HUNAV_NODES if lower else NODES)
        if problems:
            raise ExportError(f"{where}: exported tree does not validate: " + "; ".join(str(p) for p in problems))
        written[f"{base}__agent_{agent.id}_bt.xml"] = xml
        agent_entries[f"agent{agent.id}"] = {
            "id": agent.id,
            "skin": agent.id % 5,
            "group_id": agent.group,
            "max_vel": round(agent.max_vel, 3),
            "radius": round(agent.radius, 3),
            "goal_radius": GOAL_TOLERANCE,
            "cyclic_goals": False,
            "init_pose": {"x": round(agent.start[0], 3), "y": round(agent.start[1], 3), "z": SPAWN_HEIGHT,
                          "h": round(_initial_heading(agent), 3)},
            "behavior": _behavior_block(agent),
            "goals": goal_ids,
        }

    params: dict[str, object] = {
        "yaml_base_name": base,
        "simulator": simulator,
        "map": world_name,
        "publish_people": True,
        "global_goals": goals.to_yaml(),
        "agents": list(agent_entries),
    }
    params.update(agent_entries)
    document = {"hunav_loader": {"ros__parameters": params}}
    nodes_model = None if lower else treenodes_model_xml()

    copied: list[str] = []
    with atomic_directory(out, owned=is_hunav_export, what="GROVE HuNavSim export", overwrite=overwrite) as staging:
        if trajectories:
            copied = copy_trajectories(bundle, staging)
        (staging / EXPORT_MARKER).write_text("written by grove export hunav\n", encoding="utf-8")
        (staging / f"{base}.yaml").write_text(yaml.safe_dump(document, sort_keys=False, width=120), encoding="utf-8")
        for name, xml in written.items():
            (staging / name).write_text(xml, encoding="utf-8")
        if nodes_model is not None:
            (staging / "grove_nodes_model.xml").write_text(nodes_model, encoding="utf-8")
    return HunavExport(
        directory=out,
        agents_yaml=out / f"{base}.yaml",
        trees=tuple(out / name for name in written),
        nodes_model=None if nodes_model is None else out / "grove_nodes_model.xml",
        lowered=lower,
        trajectories=tuple(out / name for name in copied),
    )


def copy_trajectories(bundle_dir: Path, out_dir: Path) -> list[str]:
    """Names of the trajectory files of a simulated bundle, copied into `out_dir`."""
    copied = []
    for name in ("trajectories.csv", "trajectories.sqlite", "trajectories.txt"):
        src = bundle_dir / name
        if src.is_file() and not src.is_symlink():
            shutil.copy2(src, out_dir / name)
            copied.append(name)
    return copied


