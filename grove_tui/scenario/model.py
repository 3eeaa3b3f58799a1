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


@dataclass(frozen=True)
class RobotSpec:
    start: Point
    goal: Point
    radius: float = 0.3
    max_vel: float = 0.8
    path: tuple[Point, ...] = ()  # planned path start..goal (empty when not planned)


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

    @property
    def grid_inflation(self) -> float:
        """How far the planner's grid keeps centres off walls: the largest body radius of its people."""
        return max((a.radius for a in self.agents), default=DEFAULT_AGENT_RADIUS)

    def to_dict(self) -> dict[str, Any]:
        data = asdict(self)
        data["agents"] = [_agent_to_dict(a) for a in self.agents]
        data["robot"] = None if self.robot is None else _robot_to_dict(self.robot)
        if self.global_goals:
            data["global_goals"] = {int(k): [float(v[0]), float(v[1])] for k, v in self.global_goals.items()}
        else:
            del data["global_goals"]  # generated bundles stay as they were
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
    def from_dict(cls, data: Any, source: str = "<scenario>") -> Scenario:
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
            )
        except KeyError as exc:
            raise ScenarioError(f"{source}: missing key {exc.args[0]!r}") from None
        except (TypeError, ValueError) as exc:
            if isinstance(exc, ScenarioError):
                raise
            raise ScenarioError(f"{source}: {exc}") from None


def _short(value: Any) -> str:
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _number(value: Any, where: str, low: float, high: float) -> float:
    """A finite float in [low, high]; bools and strings are refused (YAML 'yes' is not a number)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ScenarioError(f"{where}: expected a number, got {_short(value)}")
    if isinstance(value, int) and not (low <= value <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low:g}..{high:g}")
    number = float(value)
    if not math.isfinite(number) or not (low <= number <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low:g}..{high:g}")
    return number


def _integer(value: Any, where: str, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ScenarioError(f"{where}: expected a whole number, got {_short(value)}")
    if not (low <= value <= high):
        raise ScenarioError(f"{where}: {_short(value)} is out of range {low}..{high}")
    return value


def _text(value: Any, where: str) -> str:
    if not isinstance(value, str) or not value.strip():
        raise ScenarioError(f"{where}: expected a non-empty string, got {_short(value)}")
    return value


def bundle_relative(value: Any, where: str) -> str:
    """A path inside the bundle: relative, no '..' parts, no backslashes or drive letters.

    Symbolic links are checked where the file is opened (scenario.bundle.open_member): the text alone
    cannot tell where a link points."""
    text = _text(value, where)
    candidate = PurePosixPath(text)
    if candidate.is_absolute() or "\\" in text or ":" in text or ".." in candidate.parts or "\0" in text:
        raise ScenarioError(f"{where}: {_short(text)} must be a relative path inside the bundle "
                            f"(no leading /, no '..')")
    return text


def _point(value: Any, where: str) -> Point:
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


def _agent_to_dict(agent: AgentSpec) -> dict[str, Any]:
    data = asdict(agent)
    data["start"] = list(agent.start)
    data["goals"] = [list(g) for g in agent.goals]
    return data


def _agent_from_dict(data: Any, where: str) -> AgentSpec:
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
        )
    except KeyError as exc:
        raise ScenarioError(f"{where}: missing key {exc.args[0]!r}") from None


def _robot_to_dict(robot: RobotSpec) -> dict[str, Any]:
    data = asdict(robot)
    data["start"] = list(robot.start)
    data["goal"] = list(robot.goal)
    data["path"] = [list(p) for p in robot.path]
    return data


def _robot_from_dict(data: Any, where: str) -> RobotSpec:
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
        )
    except KeyError as exc:
        raise ScenarioError(f"{where}: missing key {exc.args[0]!r}") from None
