"""The Scenario: what generation produces and simulation, exports and evaluation consume.

A scenario lives on disk as a bundle directory (see grove_tui.scenario.bundle):
    scenario.yaml      this model
    trees/*.xml        one BehaviorTree.CPP v4 file per agent (Agent.tree is its relative path)
    fields/*.npz       velocity fields referenced by FollowVelocityField nodes (emergency preset)
    grid.npz           the occupancy grid used for planning
    generation.json    per-stage timings, tokens, selected RoIs, retrieved nodes
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import yaml

from grove_tui.errors import ScenarioError
from grove_tui.files import write_text_atomic

Point = tuple[float, float]


@dataclass(frozen=True)
class AgentSpec:
    id: int  # 1-based; 0 is the robot
    group: int  # -1 for none
    start: Point
    goals: tuple[Point, ...]  # every navigation target in order, injected waypoints included
    zone: str  # name of the zone the agent is headed for
    tree: str  # path of its BT XML file, relative to the bundle
    radius: float = 0.35
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
        try:
            data = yaml.safe_load(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise ScenarioError(f"{path}: no such scenario file") from None
        except yaml.YAMLError as exc:
            raise ScenarioError(f"{path}: not valid YAML: {exc}") from None
        return cls.from_dict(data, source=str(path))

    @classmethod
    def from_dict(cls, data: Any, source: str = "<scenario>") -> Scenario:
        if not isinstance(data, dict):
            raise ScenarioError(f"{source}: expected a mapping at the top level")
        try:
            agents = tuple(_agent_from_dict(a, f"{source}: agents[{i}]") for i, a in enumerate(data["agents"]))
            robot = None if data.get("robot") is None else _robot_from_dict(data["robot"], f"{source}: robot")
            return cls(
                world=str(data["world"]),
                preset=str(data["preset"]),
                prompt=str(data["prompt"]),
                seed=int(data["seed"]),
                models={str(k): str(v) for k, v in (data.get("models") or {}).items()},
                agents=agents,
                robot=robot,
                fields={str(k): str(v) for k, v in (data.get("fields") or {}).items()},
                resolution=float(data.get("resolution", 0.1)),
                global_goals={int(k): _point(v, f"{source}: global_goals[{k}]")
                              for k, v in (data.get("global_goals") or {}).items()},
            )
        except KeyError as exc:
            raise ScenarioError(f"{source}: missing key {exc.args[0]!r}") from None
        except (TypeError, ValueError) as exc:
            if isinstance(exc, ScenarioError):
                raise
            raise ScenarioError(f"{source}: {exc}") from None


def _point(value: Any, where: str) -> Point:
    if not (isinstance(value, (list, tuple)) and len(value) == 2):
        raise ScenarioError(f"{where}: expected [x, y], got {value!r}")
    return (float(value[0]), float(value[1]))


def _agent_to_dict(agent: AgentSpec) -> dict[str, Any]:
    data = asdict(agent)
    data["start"] = list(agent.start)
    data["goals"] = [list(g) for g in agent.goals]
    return data


def _agent_from_dict(data: Any, where: str) -> AgentSpec:
    if not isinstance(data, dict):
        raise ScenarioError(f"{where}: expected a mapping")
    try:
        return AgentSpec(
            id=int(data["id"]),
            group=int(data.get("group", -1)),
            start=_point(data["start"], f"{where}.start"),
            goals=tuple(_point(g, f"{where}.goals[{j}]") for j, g in enumerate(data.get("goals") or [])),
            zone=str(data.get("zone", "")),
            tree=str(data["tree"]),
            radius=float(data.get("radius", 0.35)),
            max_vel=float(data.get("max_vel", 1.0)),
            label=str(data.get("label", "")),
            behavior=str(data.get("behavior", "Regular")),
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
        return RobotSpec(
            start=_point(data["start"], f"{where}.start"),
            goal=_point(data["goal"], f"{where}.goal"),
            radius=float(data.get("radius", 0.3)),
            max_vel=float(data.get("max_vel", 0.8)),
            path=tuple(_point(p, f"{where}.path[{j}]") for j, p in enumerate(data.get("path") or [])),
        )
    except KeyError as exc:
        raise ScenarioError(f"{where}: missing key {exc.args[0]!r}") from None
