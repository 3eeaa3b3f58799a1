"""The Scenario: what generation produces and simulation, exports and evaluation consume.

A scenario lives on disk as a bundle directory (see grove_tui.scenario.bundle):
    scenario.yaml      this model
    trees/*.xml        one BehaviorTree.CPP v4 file per agent (Agent.tree is its relative path)
    fields/*.npz       velocity fields referenced by FollowVelocityField nodes (emergency preset)
    grid.npz           the occupancy grid used for planning
    generation.json    per-stage timings, tokens, selected RoIs, retrieved nodes
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

import yaml

from grove_tui.errors import ScenarioError
from grove_tui.files import write_text_atomic
from grove_tui.limits import MAX_COORDINATE, InputLimitError, load_yaml_bounded, read_text_bounded

Point = tuple[float, float]
# A mapping as scenario.yaml holds it: what to_dict writes and from_dict reads, its values checked one by one.
YamlDict = dict[str, Any]  # Any: YAML values, each checked (or written) where its key is read


# HuNavSim's behavior types (hunav_msgs/Agent): what a bundle's `behavior` may name.
BEHAVIOR_TYPES = ("Regular", "Impassive", "Surprised", "Scared", "Curious", "Threatening")
# Physical bounds: beyond these a bundle was edited by hand into nonsense (radius 1e6, max_vel 1e308)
# and the simulation would produce garbage rather than fail.
RADIUS_RANGE = (0.05, 2.0)  # metres
MAX_VEL_RANGE = (0.0, 10.0)  # m/s; 0 is a person who stands
MAX_SEED = 2**32 - 1  # numpy's seed range
MAX_SCENARIO_BYTES = 64 * 1024 * 1024
MAX_AGENTS = 100_000
# A person's body radius when nothing says otherwise: generation gives it to everyone, and the
# planner's grid is inflated by it (a centre that far from a wall keeps the body off it). A 0.5 m
# wide body, about an adult's shoulder breadth; JuPedSim's RiMEA runs in issue 19 used it too. With
# bodies that no longer overlap, 0.35 (a 0.7 m disc) wedged in 1 m doors: 0.4-0.8 persons/s where
# people pass 1.3-1.9 (RiMEA 12, analysis/rimea.py).
DEFAULT_AGENT_RADIUS = 0.25
# The radius of an agent's goals, one value in every file that names it (agents YAML, exported tree
# tolerances, ROS 2 bag, MCAP): HuNavSim 2.0's GoTo gives every goal it walks to this radius
# (go_to_node.cpp), and a goal counts as reached within radius + 0.1 m (AgentManager::goalReached, and
# GROVE's GoTo). An imported agent keeps its file's `goal_radius`.
DEFAULT_GOAL_RADIUS = 0.1
HUNAV_LAYOUTS = ("1.0", "2.0")  # agents YAML layouts: goals named per agent / global_goals ids
HUNAV_BEHAVIOR_TYPES = ("name", "number")  # behavior.type written as "Regular"... / as 1..6


@dataclass(frozen=True)
class HunavBehavior:
    """An agent's `behavior` block as a HuNavSim agents YAML gave it (hunav_msgs/AgentBehavior's
    parameters). None: the file left the key out, HuNavSim's loader default applies, and the export
    leaves it out again."""

    configuration: int | None = None  # 0 default, 1 custom, 2 random normal, 3 random uniform
    duration: float | None = None
    once: bool | None = None
    vel: float | None = None
    dist: float | None = None
    goal_force_factor: float | None = None
    obstacle_force_factor: float | None = None
    social_force_factor: float | None = None
    other_force_factor: float | None = None


@dataclass(frozen=True)
class HunavAgent:
    """What a HuNavSim agents YAML says of an agent beyond GROVE's own fields, kept by `grove import
    hunav` so `grove export hunav` writes it back; None (or empty) where the file had nothing."""

    name: str  # the agent's key in the file (`agent7` may have id 3)
    skin: int | None = None
    z: float | None = None  # init_pose.z (Gazebo's actors stand at 1.25)
    behavior: HunavBehavior | None = None  # None: HuNavSim 1.0's `behavior: <type number>`, no block
    goal_names: tuple[str, ...] = ()  # 1.0 layout: the key of each goal (g0, g1, ...)
    goal_headings: tuple[float | None, ...] = ()  # 1.0 layout: each goal's h
    goal_ids: tuple[int, ...] = ()  # 2.0 layout: the global_goals ids, as listed
    tree_file: str = ""  # 2.0 layout: HuNavSim's tree file, kept verbatim in the bundle
    tree_digest: str = ""  # SHA-256 of the GROVE tree import made; while equal, the export writes tree_file
    keys: tuple[str, ...] = ()  # the agent's keys in the file, in order ("init_pose.x", "g0.h", ...)


@dataclass(frozen=True)
class HunavSource:
    """The HuNavSim agents YAML a bundle was imported from: its layout and top-level parameters
    (None where the file had none), so the export writes the same file back."""

    layout: str  # "1.0" or "2.0" (HUNAV_LAYOUTS)
    file: str  # the agents YAML's file name
    agents: tuple[str, ...]  # its `agents` list, in its order
    behavior_type: str = "name"  # HUNAV_BEHAVIOR_TYPES
    base_name: str | None = None  # yaml_base_name
    simulator: str | None = None
    map: str | None = None
    publish_people: bool | None = None
    keys: tuple[str, ...] = ()  # the top-level keys of `ros__parameters`, in order
    grove_comment: bool = False  # the file carried GROVE's own line (an earlier `grove export hunav`)
    includes: tuple[str, ...] = ()  # files its trees <include>, kept verbatim under hunav/ (relative paths)


@dataclass(frozen=True)
class AgentSpec:
    id: int  # 1-based; 0 is the robot
    group: int  # -1 for none
    start: Point
    goals: tuple[Point, ...]  # every navigation target in order, injected waypoints included
    zone: str  # name of the zone the agent is headed for
    tree: str  # path of its BT XML file, relative to the bundle
    radius: float = DEFAULT_AGENT_RADIUS
    max_vel: float = 1.0  # SFM desired speed (HuNavSim `max_vel`)
    label: str = ""  # the draft group label the agent came from ("patients", "family")
    behavior: str = "Regular"  # HuNavSim reaction to the robot: Regular, Impassive, Surprised, Scared, Curious, Threatening
    goal_radius: float = DEFAULT_GOAL_RADIUS  # metres; reached within goal_radius + 0.1 (HuNavSim's rule)
    cyclic_goals: bool = True  # HuNavSim trees (RegularNav, UpdateGoal) walk `goals` round and round (the loader's default)
    heading: float | None = None  # initial yaw in radians; None: facing the first goal
    hunav: HunavAgent | None = None  # set by `grove import hunav`

    def initial_heading(self) -> float:
        """The yaw it starts with, in the simulation and every export: `heading`, else facing its first
        goal (0 without one, or when that goal is where it stands)."""
        if self.heading is not None:
            return float(self.heading)
        if self.goals:
            dx, dy = self.goals[0][0] - self.start[0], self.goals[0][1] - self.start[1]
            if math.hypot(dx, dy) > 1e-9:
                return math.atan2(dy, dx)
        return 0.0


@dataclass(frozen=True)
class RobotSpec:
    start: Point
    goal: Point
    radius: float = 0.3
    max_vel: float = 0.8
    path: tuple[Point, ...] = ()  # planned path start..goal (empty when not planned)
    # What the robot does with its path (ROBOT_TASKS): "cross" drives it once (the default), "wait"
    # stays at start, "patrol" drives it there and back again and again, "follow" keeps behind the
    # people in `follows` (agent ids).
    task: str = "cross"
    follows: tuple[int, ...] = ()
    # Where on its path a "cross" stops on the way, and for how long: (x, y, seconds), a point of `path`
    # ("carries books from the returns desk to the reading room": it stands at the desk to pick them up)
    stops: tuple[tuple[float, float, float], ...] = ()


@dataclass(frozen=True)
class Scenario:
    world: str  # shipped world name or path to the world YAML
    preset: str
    prompt: str
    seed: int
    models: dict[str, str]  # role -> model file name ("roi", "bt")
    agents: tuple[AgentSpec, ...]
    robot: RobotSpec | None
    fields: dict[str, str] = field(default_factory=dict)  # field id -> relative .npz path
    resolution: float = 0.1  # grid resolution used for planning (m)
    # HuNavSim global goals (id -> point) that trees name by `goal_id` alone: set when a scenario is
    # imported from HuNavSim (`grove import hunav`); generated scenarios write x/y beside every goal_id.
    global_goals: dict[int, Point] = field(default_factory=dict)
    hunav: HunavSource | None = None  # the HuNavSim file an imported scenario came from

    @property
    def grid_inflation(self) -> float:
        """How far the planner's grid keeps centres off walls: the largest body radius of its people."""
        return max((a.radius for a in self.agents), default=DEFAULT_AGENT_RADIUS)

    def to_dict(self) -> YamlDict:
        data = asdict(self)
        data["agents"] = [_agent_to_dict(a) for a in self.agents]
        data["robot"] = None if self.robot is None else _robot_to_dict(self.robot)
        if self.global_goals:
            data["global_goals"] = {int(k): [float(v[0]), float(v[1])] for k, v in self.global_goals.items()}
        else:
            del data["global_goals"]  # generated bundles stay as they were
        if self.hunav is None:
            del data["hunav"]
        else:
            data["hunav"] = _present(asdict(self.hunav))
        return data

    def dump_yaml(self) -> str:
        return yaml.safe_dump(self.to_dict(), sort_keys=False, default_flow_style=None, width=120)

    def save(self, path: str | Path) -> Path:
        return write_text_atomic(path, self.dump_yaml())

    @classmethod
    def load(cls, path: str | Path) -> Scenario:
        path = Path(path)
        if not path.exists() and not path.is_symlink():
            raise ScenarioError(f"{path}: no such scenario file; is this a bundle folder?")
        try:
            text = read_text_bounded(path, MAX_SCENARIO_BYTES, "scenario file")
            data = load_yaml_bounded(text, str(path))
        except InputLimitError as exc:
            raise ScenarioError(str(exc)) from None
        return cls.from_dict(data, source=str(path))

    @classmethod
    def from_dict(cls, data: object, source: str = "<scenario>") -> Scenario:
        if not isinstance(data, dict):
            raise ScenarioError(f"{source}: expected a mapping at the top level")
        try:
            raw_agents = data["agents"]
            if not isinstance(raw_agents, list):
                raise ScenarioError(f"{source}: agents must be a list, got {type(raw_agents).__name__}")
            if len(raw_agents) > MAX_AGENTS:
                raise ScenarioError(f"{source}: {len(raw_agents):,} agents; at most {MAX_AGENTS:,} are supported")
            agents = tuple(_agent_from_dict(a, f"{source}: agents[{i}]") for i, a in enumerate(raw_agents))
            _check_unique_ids(agents, source)
            robot = None if data.get("robot") is None else _robot_from_dict(data["robot"], f"{source}: robot")
            models = data.get("models") or {}
            fields = data.get("fields") or {}
            if not isinstance(models, dict) or not isinstance(fields, dict):
                raise ScenarioError(f"{source}: models and fields must be mappings")
            return cls(
                world=_text(data["world"], f"{source}: world"),
                preset=_text(data["preset"], f"{source}: preset"),
                prompt=str(data["prompt"]),
                seed=_integer(data["seed"], f"{source}: seed", 0, MAX_SEED),
                models={str(k): str(v) for k, v in models.items()},
                agents=agents,
                robot=robot,
                fields={str(k): bundle_relative(v, f"{source}: fields.{k}") for k, v in fields.items()},
                resolution=_number(data.get("resolution", 0.1), f"{source}: resolution", 0.01, 2.0),
                global_goals={int(k): _point(v, f"{source}: global_goals[{k}]")
                              for k, v in (data.get("global_goals") or {}).items()},
                hunav=None if data.get("hunav") is None else _hunav_source(data["hunav"], f"{source}: hunav"),
            )
        except KeyError as exc:
            raise ScenarioError(f"{source}: missing key {exc.args[0]!r}") from None
        except (TypeError, ValueError) as exc:
            if isinstance(exc, ScenarioError):
                raise
            raise ScenarioError(f"{source}: {exc}") from None


def _short(value: object) -> str:
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _number(value: object, where: str, low: float, high: float) -> float:
    """A finite float in [low, high]; bools and strings are refused (YAML 'yes' is not a number)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ScenarioError(f"{where}: expected a number, got {_short(value)}")
    if isinstance(value, int) and not (low <= value <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low:g}..{high:g}")
    number = float(value)
    if not math.isfinite(number) or not (low <= number <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low:g}..{high:g}")
    return number


def _integer(value: object, where: str, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ScenarioError(f"{where}: expected a whole number, got {_short(value)}")
    if not (low <= value <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low}..{high}")
    return value


def _text(value: object, where: str) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ScenarioError(f"{where}: expected a non-empty string, got {_short(value)}")
    return value


def bundle_relative(value: object, where: str) -> str:
    """A path inside the bundle: relative, no '..' parts, no backslashes or drive letters.

    Symbolic links are checked where the file is opened (scenario.bundle.open_member): the text alone
    cannot tell where a link points."""
    text = _text(value, where)
    candidate = PurePosixPath(text)
    if candidate.is_absolute() or "\\" in text or ":" in text or ".." in candidate.parts or "\0" in text:
        raise ScenarioError(f"{where}: {_short(text)} must be a relative path inside the bundle "
                            f"(no leading /, no '..')")
    return text


def _point(value: object, where: str) -> Point:
    if not (isinstance(value, (list, tuple)) and len(value) == 2):
        raise ScenarioError(f"{where}: expected [x, y], got {_short(value)}")
    return (_number(value[0], where, -MAX_COORDINATE, MAX_COORDINATE),
            _number(value[1], where, -MAX_COORDINATE, MAX_COORDINATE))


def _check_unique_ids(agents: tuple[AgentSpec, ...], source: str) -> None:
    # Trajectories, exports and metrics key everything by agent id; two agents with one id corrupt them all.
    seen: set[int] = set()
    for index, agent in enumerate(agents):
        if agent.id in seen:
            raise ScenarioError(f"{source}: agents[{index}]: id {agent.id} is used by another agent; ids must be unique")
        seen.add(agent.id)


def _present(data: YamlDict) -> YamlDict:
    """`data` without its None values and empty sequences, nested mappings likewise."""
    out: YamlDict = {}
    for key, value in data.items():
        if isinstance(value, dict):
            value = _present(value)
        if value is None or value == () or value == [] or value == "":
            continue
        out[key] = list(value) if isinstance(value, tuple) else value
    return out


def _agent_to_dict(agent: AgentSpec) -> YamlDict:
    data = asdict(agent)
    data["start"] = list(agent.start)
    data["goals"] = [list(g) for g in agent.goals]
    # What HuNavSim's files carry: written only when it differs from a generated agent's, so generated
    # bundles stay as they were.
    if agent.goal_radius == DEFAULT_GOAL_RADIUS:
        del data["goal_radius"]
    if agent.cyclic_goals:
        del data["cyclic_goals"]
    if agent.heading is None:
        del data["heading"]
    if agent.hunav is None:
        del data["hunav"]
    else:
        data["hunav"] = _present(data["hunav"])
    return data


def _optional(data: YamlDict, key: str, kind: type, where: str) -> Any:  # Any: of `kind`, which the caller names
    """`data[key]` checked to be of `kind` (a float also takes an int), or None when absent."""
    value = data.get(key)
    if value is None:
        return None
    if kind is float:
        return _number(value, f"{where}.{key}", -MAX_COORDINATE, MAX_COORDINATE)
    if kind is int:
        return _integer(value, f"{where}.{key}", -(2**31), 2**31 - 1)
    if kind is bool and not isinstance(value, bool):
        raise ScenarioError(f"{where}.{key}: expected true or false, got {_short(value)}")
    if kind is str and not isinstance(value, str):
        raise ScenarioError(f"{where}.{key}: expected a string, got {_short(value)}")
    return value


def _mapping(data: object, where: str) -> YamlDict:
    if not isinstance(data, dict):
        raise ScenarioError(f"{where}: expected a mapping")
    return data


def _hunav_behavior(data: object, where: str) -> HunavBehavior:
    data = _mapping(data, where)
    kinds = {"configuration": int, "once": bool}
    return HunavBehavior(**{name: _optional(data, name, kinds.get(name, float), where)
                            for name in HunavBehavior.__dataclass_fields__})


def _hunav_agent(data: object, where: str) -> HunavAgent:
    data = _mapping(data, where)
    name = _optional(data, "name", str, where)
    if not name:
        raise ScenarioError(f"{where}.name: the agent's key in the HuNavSim file is missing")
    headings = data.get("goal_headings") or []
    names = data.get("goal_names") or []
    ids = data.get("goal_ids") or []
    if not all(isinstance(v, list) for v in (headings, names, ids)):
        raise ScenarioError(f"{where}: goal_names, goal_headings and goal_ids must be lists")
    return HunavAgent(
        name=name,
        skin=_optional(data, "skin", int, where),
        z=_optional(data, "z", float, where),
        behavior=None if data.get("behavior") is None else _hunav_behavior(data["behavior"], f"{where}.behavior"),
        goal_names=tuple(_text(n, f"{where}.goal_names[{j}]") for j, n in enumerate(names)),
        goal_headings=tuple(None if h is None else _number(h, f"{where}.goal_headings[{j}]", -1e3, 1e3)
                            for j, h in enumerate(headings)),
        goal_ids=tuple(_integer(g, f"{where}.goal_ids[{j}]", -(2**31), 2**31 - 1) for j, g in enumerate(ids)),
        tree_file="" if not data.get("tree_file") else bundle_relative(data["tree_file"], f"{where}.tree_file"),
        tree_digest=str(data.get("tree_digest", "")),
        keys=_texts(data.get("keys"), f"{where}.keys"),
    )


def _texts(value: object, where: str) -> tuple[str, ...]:
    if value is None:
        return ()
    if not isinstance(value, list):
        raise ScenarioError(f"{where}: expected a list of names")
    return tuple(_text(v, f"{where}[{j}]") for j, v in enumerate(value))


def _hunav_source(data: object, where: str) -> HunavSource:
    data = _mapping(data, where)
    layout = data.get("layout")
    if layout not in HUNAV_LAYOUTS:
        raise ScenarioError(f"{where}.layout: {_short(layout)} is not a HuNavSim layout ({', '.join(HUNAV_LAYOUTS)})")
    behavior_type = data.get("behavior_type", "name")
    if behavior_type not in HUNAV_BEHAVIOR_TYPES:
        raise ScenarioError(f"{where}.behavior_type: {_short(behavior_type)} is not one of "
                            f"{', '.join(HUNAV_BEHAVIOR_TYPES)}")
    agents = data.get("agents") or []
    if not isinstance(agents, list):
        raise ScenarioError(f"{where}.agents: expected the list of agent names")
    return HunavSource(layout=layout, file=_text(data.get("file"), f"{where}.file"),
                       agents=tuple(_text(a, f"{where}.agents[{j}]") for j, a in enumerate(agents)),
                       behavior_type=behavior_type, base_name=_optional(data, "base_name", str, where),
                       simulator=_optional(data, "simulator", str, where), map=_optional(data, "map", str, where),
                       publish_people=_optional(data, "publish_people", bool, where),
                       keys=_texts(data.get("keys"), f"{where}.keys"),
                       grove_comment=_optional(data, "grove_comment", bool, where) or False,
                       includes=tuple(bundle_relative(v, f"{where}.includes") for v in _texts(data.get("includes"),
                                                                                                  f"{where}.includes")))


def _agent_from_dict(data: object, where: str) -> AgentSpec:
    if not isinstance(data, dict):
        raise ScenarioError(f"{where}: expected a mapping")
    try:
        behavior = data.get("behavior", "Regular")
        if behavior not in BEHAVIOR_TYPES:
            raise ScenarioError(f"{where}.behavior: {_short(behavior)} is not a HuNavSim behavior; "
                                f"use one of {', '.join(BEHAVIOR_TYPES)}")
        goals = data.get("goals") or []
        if not isinstance(goals, list):
            raise ScenarioError(f"{where}.goals: expected a list of [x, y] points")
        return AgentSpec(
            id=_integer(data["id"], f"{where}.id", 1, 10 * MAX_AGENTS),
            group=_integer(data.get("group", -1), f"{where}.group", -1, 10 * MAX_AGENTS),
            start=_point(data["start"], f"{where}.start"),
            goals=tuple(_point(g, f"{where}.goals[{j}]") for j, g in enumerate(goals)),
            zone=str(data.get("zone", "")),
            tree=bundle_relative(data["tree"], f"{where}.tree"),
            radius=_number(data.get("radius", DEFAULT_AGENT_RADIUS), f"{where}.radius", *RADIUS_RANGE),
            max_vel=_number(data.get("max_vel", 1.0), f"{where}.max_vel", *MAX_VEL_RANGE),
            label=str(data.get("label", "")),
            behavior=behavior,
            goal_radius=_number(data.get("goal_radius", DEFAULT_GOAL_RADIUS), f"{where}.goal_radius", 0.0, 100.0),
            cyclic_goals=_optional(data, "cyclic_goals", bool, where) is not False,
            heading=_optional(data, "heading", float, where),
            hunav=None if data.get("hunav") is None else _hunav_agent(data["hunav"], f"{where}.hunav"),
        )
    except KeyError as exc:
        raise ScenarioError(f"{where}: missing key {exc.args[0]!r}") from None


def _robot_to_dict(robot: RobotSpec) -> YamlDict:
    data = asdict(robot)
    data["start"] = list(robot.start)
    data["goal"] = list(robot.goal)
    data["path"] = [list(p) for p in robot.path]
    # A robot that just crosses is written as before, so earlier bundles stay byte for byte the same.
    if robot.task == "cross":
        del data["task"]
    if not robot.follows:
        del data["follows"]
    else:
        data["follows"] = list(robot.follows)
    if not robot.stops:
        del data["stops"]
    else:
        data["stops"] = [list(s) for s in robot.stops]
    return data


def _robot_from_dict(data: object, where: str) -> RobotSpec:
    if not isinstance(data, dict):
        raise ScenarioError(f"{where}: expected a mapping")
    try:
        path = data.get("path") or []
        if not isinstance(path, list):
            raise ScenarioError(f"{where}.path: expected a list of [x, y] points")
        return RobotSpec(
            start=_point(data["start"], f"{where}.start"),
            goal=_point(data["goal"], f"{where}.goal"),
            radius=_number(data.get("radius", 0.3), f"{where}.radius", *RADIUS_RANGE),
            max_vel=_number(data.get("max_vel", 0.8), f"{where}.max_vel", *MAX_VEL_RANGE),
            path=tuple(_point(p, f"{where}.path[{j}]") for j, p in enumerate(path)),
            task=_robot_task(data.get("task", "cross"), f"{where}.task"),
            follows=tuple(_integer(i, f"{where}.follows[{j}]", 1, 10 * MAX_AGENTS)
                          for j, i in enumerate(data.get("follows") or [])),
            stops=tuple(_stop(s, f"{where}.stops[{j}]") for j, s in enumerate(data.get("stops") or [])),
        )
    except KeyError as exc:
        raise ScenarioError(f"{where}: missing key {exc.args[0]!r}") from None


ROBOT_TASKS = ("cross", "wait", "patrol", "follow")
ROBOT_STOP_SECONDS = (0.0, 3600.0)


def _stop(value: object, where: str) -> tuple[float, float, float]:
    if not isinstance(value, list) or len(value) != 3:
        raise ScenarioError(f"{where}: expected [x, y, seconds]")
    x, y = _point(value[:2], where)
    return (x, y, _number(value[2], f"{where}[2]", *ROBOT_STOP_SECONDS))


def _robot_task(value: object, where: str) -> str:
    if value not in ROBOT_TASKS:
        raise ScenarioError(f"{where}: {_short(value)} is not a robot task; use one of {', '.join(ROBOT_TASKS)}")
    return str(value)
