"""What every export says about a bundle's scene: one function per quantity, asked by every writer.

The agents YAML and trees (exports/hunav.py), the Gazebo world (gazebo_world.py), the nav2 map
(nav2_map.py), the ROS 2 bag (rosbag.py) and the Foxglove MCAP (foxglove.py) all name the same
quantities. Each comes from here, so the files cannot disagree:

- `goal_radius(agent)`: agents YAML `goal_radius`, the `tolerance` of every GoTo a tree is lowered to,
  hunav_msgs/Agent `goal_radius`, the goal spheres of the bag's and the MCAP's markers;
- `agent_radius(agent)`: agents YAML `radius`, hunav_msgs/Agent `radius`, the bodies drawn;
- `skin(agent)`, `behavior_block(agent)` / `behavior_values(agent)`: agents YAML and hunav_msgs 2.0;
- `muster_points(...)`: where each evacuee ends outside its exit (HuNavSim never removes agents);
- `Scene.extent`: the rectangle every file covers: the world, every start, goal, global goal, robot
  pose and muster point, plus SCENE_MARGIN. The Gazebo world's ground plane, the nav2 map, the bag's
  `/map` and the MCAP's `/map` span exactly it;
- `scene_boxes(world)`: walls (door gaps cut), furniture and obstacles as the boxes the Gazebo world
  holds; `Scene.static_map()` rasterises those same boxes, nothing inflated: the map a robot's planner
  needs (nav2 inflates by its own footprint), written as the nav2 map and published as `/map`.

GROVE's own planning grid (grid.npz: the building only, inflated by the largest body radius) is a
different thing, and the exports that carry it name it so (`/grove/planning_grid`).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from grove_tui.bt.format.document import TreeDocument
from grove_tui.errors import ExportError, GroveError
from grove_tui.navigation.grid import OccupancyGrid, check_grid_shape
from grove_tui.scenario.model import AgentSpec, HunavBehavior, Scenario
from grove_tui.world import Door, World

if TYPE_CHECKING:
    from shapely.geometry import Polygon

Point = tuple[float, float]

BEHAVIOR_NUMBERS = {"Regular": 1, "Impassive": 2, "Surprised": 3, "Scared": 4, "Curious": 5, "Threatening": 6}
SKINS = 5  # hunav_gazebo_wrapper 1.0's actor meshes (WorldGenerator.cpp skin_filename)
SCENE_MARGIN = 1.0  # metres of ground beyond the farthest wall, goal or pose
# Evacuees' points outside their exit: rows across the door, this far apart (more than two bodies
# plus HuNavSim's 0.2 m reach, so nobody stands on anybody's goal), first row this far out.
MUSTER_SPACING = 1.0
MUSTER_FIRST_ROW = 2.0
MUSTER_PER_ROW = 5
WALL_HEIGHT = 2.5
WALL_THICKNESS = 0.1
FURNITURE_HEIGHT = {"table": 0.75, "desk": 0.75, "counter": 1.05, "reception_desk": 1.05, "bed": 0.6,
                    "sofa": 0.8, "chair": 0.9, "vending_machine": 1.8, "coffee_machine": 1.2, "shelf": 1.8}
DEFAULT_FURNITURE_HEIGHT = 1.0
OBSTACLE_HEIGHT = WALL_HEIGHT
# HuNavSim's loader defaults for keys an agents YAML leaves out (hunav_loader.cpp, 2.0).
LOADER_BEHAVIOR_DEFAULTS = {"configuration": 0, "duration": 40.0, "once": True, "vel": 1.0, "dist": 0.0,
                            "goal_force_factor": 2.0, "obstacle_force_factor": 10.0, "social_force_factor": 5.0,
                            "other_force_factor": 20.0}


# --------------------------------------------------------------------------------------------- agents

def goal_radius(agent: AgentSpec) -> float:
    """The radius of the agent's goals (reached within it + 0.1 m): one value in every file."""
    return float(agent.goal_radius)


def agent_radius(agent: AgentSpec) -> float:
    return float(agent.radius)


def skin(agent: AgentSpec) -> int:
    """The Gazebo actor mesh: the imported file's, else one of HuNavSim's five by id."""
    if agent.hunav is not None and agent.hunav.skin is not None:
        return int(agent.hunav.skin)
    return agent.id % SKINS


def behavior_block(agent: AgentSpec, numbers: bool = False) -> dict[str, object]:
    """The agents YAML `behavior` block: an imported agent's keys as its file had them, a generated
    agent's from its robot reaction (the tree carries the reaction; these mirror its values for the
    tools that read them). `numbers`: `type` as 1..6 (the 1.0 layout) instead of "Regular"..."""
    kind = agent.behavior if agent.behavior in BEHAVIOR_NUMBERS else "Regular"
    block: dict[str, object] = {"type": BEHAVIOR_NUMBERS[kind] if numbers else kind}
    if agent.hunav is not None and agent.hunav.behavior is not None:
        given = agent.hunav.behavior
        block.update({name: getattr(given, name) for name in HunavBehavior.__dataclass_fields__
                      if getattr(given, name) is not None})
        return block
    from grove_tui.simulation.simulation import REACTION_DEFAULTS

    _, distance, duration, once = REACTION_DEFAULTS.get(kind, ("", 0.0, 40.0, True))
    block.update({"configuration": 0, "duration": float(duration), "once": bool(once),
                  "vel": min(max(float(agent.max_vel), 0.0), 1.8), "dist": float(distance),
                  "goal_force_factor": 2.0, "obstacle_force_factor": 10.0, "social_force_factor": 5.0,
                  "other_force_factor": 20.0})
    return block


def behavior_values(agent: AgentSpec) -> dict[str, float | int | bool]:
    """hunav_msgs/AgentBehavior's fields for the agent: its block, HuNavSim's loader defaults where the
    block leaves a key out, `type` as the message's number."""
    block = behavior_block(agent, numbers=True)
    values: dict[str, float | int | bool] = dict(LOADER_BEHAVIOR_DEFAULTS)
    values.update({key: value for key, value in block.items() if isinstance(value, (int, float, bool))})
    return values


# ------------------------------------------------------------------------------------------ evacuees

def tag_ranks(scenario: Scenario, trees: Mapping[int, TreeDocument], tag: str,
              key: str) -> dict[tuple[int, str], int]:
    """Sequential allocation: the members of each `tag` node's place (its `key` port), in agent-id order."""
    members: dict[str, list[int]] = {}
    for agent in sorted(scenario.agents, key=lambda a: a.id):
        for el in trees[agent.id].nodes():
            if el.id != tag:
                continue
            name = el.get(key, "") or ""
            if agent.id not in members.setdefault(name, []):
                members[name].append(agent.id)
    return {(a, name): rank for name, ids in members.items() for rank, a in enumerate(ids)}


def muster_point(world: World, door_name: str, rank: int) -> Point | None:
    """The rank-th evacuee's point outside exit `door_name`: rows across the door, MUSTER_SPACING apart,
    skipping any that land inside a zone (another part of the building); None for an unknown door."""
    try:
        door = world.find(door_name)
    except GroveError:
        return None
    if not isinstance(door, Door):
        return None
    nx, ny = -door.normal[0], -door.normal[1]
    ax, ay = door.along
    slot = 0
    for _ in range(10000):
        row, column = divmod(slot, MUSTER_PER_ROW)
        lateral = (column - (MUSTER_PER_ROW - 1) / 2.0) * MUSTER_SPACING
        out = MUSTER_FIRST_ROW + row * MUSTER_SPACING
        point = (door.position[0] + nx * out + ax * lateral, door.position[1] + ny * out + ay * lateral)
        slot += 1
        if world.zone_at(*point) is not None:
            continue
        if rank == 0:
            return point
        rank -= 1
    return None


def muster_points(world: World, scenario: Scenario, trees: Mapping[int, TreeDocument]) -> dict[tuple[int, str], Point]:
    """(agent id, exit) -> the point outside that exit where the agent ends, for every evacuee."""
    points: dict[tuple[int, str], Point] = {}
    for (agent_id, exit_name), rank in tag_ranks(scenario, trees, "FollowVelocityField", "exit").items():
        point = muster_point(world, exit_name, rank) if exit_name else None
        if point is not None:
            points[(agent_id, exit_name)] = point
    return points


# ---------------------------------------------------------------------------------------- geometry

@dataclass(frozen=True)
class SceneBox:
    """A static box of the scene: centre, yaw, length along yaw, width across, height."""

    name: str
    kind: str  # "wall", "furniture" or "obstacle"
    x: float
    y: float
    yaw: float
    length: float
    width: float
    height: float


def _rectangle(polygon: Polygon) -> tuple[float, float, float, float, float]:
    """(centre x, centre y, yaw, side along yaw, side across) of a footprint's minimum rotated rectangle."""
    rectangle = polygon.minimum_rotated_rectangle
    (ax, ay), (bx, by), (cx, cy) = list(rectangle.exterior.coords)[:3]
    centre = rectangle.centroid
    return centre.x, centre.y, math.atan2(by - ay, bx - ax), math.hypot(bx - ax, by - ay), math.hypot(cx - bx, cy - by)


def scene_boxes(world: World) -> list[SceneBox]:
    """Every static thing of the world as a box: each building wall segment (zone boundaries with the
    door openings cut out), WALL_THICKNESS thick; each piece of furniture and obstacle as its
    footprint's minimum rotated rectangle, as tall as its type suggests."""
    boxes = []
    for k, (x1, y1, x2, y2) in enumerate(np.asarray(world.room_walls(), dtype=float).tolist()):
        length = math.hypot(x2 - x1, y2 - y1)
        if length > 1e-9:
            boxes.append(SceneBox(f"wall_{k}", "wall", (x1 + x2) / 2, (y1 + y2) / 2, math.atan2(y2 - y1, x2 - x1),
                                  length, WALL_THICKNESS, WALL_HEIGHT))
    for entity in world.entities():
        x, y, yaw, along, across = _rectangle(entity.polygon)
        boxes.append(SceneBox(f"furniture_{entity.name}", "furniture", x, y, yaw, along, across,
                              FURNITURE_HEIGHT.get(entity.type, DEFAULT_FURNITURE_HEIGHT)))
    for obstacle in world.obstacles:
        x, y, yaw, along, across = _rectangle(obstacle.polygon)
        boxes.append(SceneBox(f"obstacle_{obstacle.name}", "obstacle", x, y, yaw, along, across, OBSTACLE_HEIGHT))
    return boxes


def rasterize_boxes(boxes: Iterable[SceneBox], origin: Point, resolution: float, shape: tuple[int, int]) -> np.ndarray:
    """(H, W) bool, row 0 the smallest y: cells whose centre lies in a box, each box grown to at least
    half a cell diagonal around its centre line, so a 0.1 m wall is an unbroken 4-connected chain."""
    height, width = shape
    occupied = np.zeros(shape, dtype=bool)
    floor = resolution * math.sqrt(0.5)
    for box in boxes:
        half_l = max(box.length / 2, floor) + (floor if box.kind == "wall" else 0.0)
        half_w = max(box.width / 2, floor)
        c, s = math.cos(box.yaw), math.sin(box.yaw)
        reach = math.hypot(half_l, half_w)
        c0 = max(int(math.floor((box.x - reach - origin[0]) / resolution)), 0)
        c1 = min(int(math.ceil((box.x + reach - origin[0]) / resolution)) + 1, width)
        r0 = max(int(math.floor((box.y - reach - origin[1]) / resolution)), 0)
        r1 = min(int(math.ceil((box.y + reach - origin[1]) / resolution)) + 1, height)
        if c0 >= c1 or r0 >= r1:
            continue
        dx = (origin[0] + (np.arange(c0, c1) + 0.5) * resolution)[None, :] - box.x
        dy = (origin[1] + (np.arange(r0, r1) + 0.5) * resolution)[:, None] - box.y
        along = dx * c + dy * s
        across = -dx * s + dy * c
        occupied[r0:r1, c0:c1] |= (np.abs(along) <= half_l) & (np.abs(across) <= half_w)
    return occupied


# ------------------------------------------------------------------------------------------- scene

@dataclass(frozen=True)
class Scene:
    """A bundle's scene as every export describes it (see the module docstring)."""

    world: World
    scenario: Scenario
    muster: dict[tuple[int, str], Point] = field(default_factory=dict)
    extra_points: tuple[Point, ...] = ()  # more places the scene must cover (an export's own goals)

    def points(self) -> list[Point]:
        """Every place an agent or the robot stands or heads for."""
        scenario = self.scenario
        points: list[Point] = []
        for agent in scenario.agents:
            points.append(agent.start)
            points.extend(agent.goals)
        points.extend(scenario.global_goals.values())
        if scenario.robot is not None:
            points += [scenario.robot.start, scenario.robot.goal, *scenario.robot.path]
        points.extend(self.muster.values())
        points.extend(self.extra_points)
        return [(float(p[0]), float(p[1])) for p in points]

    @property
    def resolution(self) -> float:
        return float(self.scenario.resolution)

    @cached_property
    def extent(self) -> tuple[float, float, float, float]:
        """xmin, ymin, xmax, ymax: the world and every point, plus SCENE_MARGIN, on the map's lattice."""
        x0, y0, x1, y1 = self.world.bounds()
        points = self.points()
        if points:
            xs, ys = [p[0] for p in points], [p[1] for p in points]
            x0, y0, x1, y1 = min(x0, *xs), min(y0, *ys), max(x1, *xs), max(y1, *ys)
        r = self.resolution
        return (math.floor((x0 - SCENE_MARGIN) / r) * r, math.floor((y0 - SCENE_MARGIN) / r) * r,
                math.ceil((x1 + SCENE_MARGIN) / r) * r, math.ceil((y1 + SCENE_MARGIN) / r) * r)

    def covers(self, point: Sequence[float]) -> bool:
        x0, y0, x1, y1 = self.extent
        return x0 <= float(point[0]) <= x1 and y0 <= float(point[1]) <= y1

    def with_points(self, points: Iterable[Sequence[float]]) -> Scene:
        """This scene, grown to also cover `points` (what an export adds, such as its global goals)."""
        extra = tuple((float(p[0]), float(p[1])) for p in points)
        if all(self.covers(p) for p in extra):
            return self
        return Scene(self.world, self.scenario, self.muster, self.extra_points + extra)

    @cached_property
    def boxes(self) -> list[SceneBox]:
        return scene_boxes(self.world)

    @cached_property
    def static_map(self) -> OccupancyGrid:
        """The scene's boxes on a grid spanning `extent`, nothing inflated, free everywhere else
        (Gazebo's ground plane, outside the building too): the nav2 map and `/map`."""
        x0, y0, x1, y1 = self.extent
        r = self.resolution
        shape = (int(round((y1 - y0) / r)), int(round((x1 - x0) / r)))
        try:
            check_grid_shape(shape, f" at {r} m")
        except ValueError as exc:
            raise ExportError(f"the scene of world {self.world.name!r} is too large for one map: {exc}") from None
        occupied = rasterize_boxes(self.boxes, (x0, y0), r, shape)
        occupied.flags.writeable = False
        return OccupancyGrid(origin=(x0, y0), resolution=r, occupied=occupied, inflation=0.0,
                             world_name=self.world.name)


def scene_of(world: World, scenario: Scenario, trees: Mapping[int, TreeDocument] | None = None) -> Scene:
    """The scene of a scenario in its world; with its trees, the evacuees' muster points are in it."""
    return Scene(world, scenario, muster_points(world, scenario, trees) if trees is not None else {})
