"""What HuNavSim 2.0's `hunav_loader` and agent manager would do with an exported scenario, without ROS.

Emulates robotics-upo/hunav_sim 2.0 `hunav_agent_manager/src/hunav_loader.cpp` (`namespace hunav`,
as stored in the public code index): every parameter it declares, with the type it declares it with.
rclcpp throws InvalidParameterTypeException when a parameters-file value has another type (an integer
where a double is declared, `x: 3` instead of `x: 3.0`), and an empty YAML list has no type at all,
so `<agent>.goals` (declared PARAMETER_INTEGER_ARRAY) must be a non-empty list of integers. The loader
reads `global_goals.<n>.x/y` for n = 1, 2, ... and stops at the first gap, and declares a goal id it
did not find with the default (0.0, 0.0): ids must be consecutive from 1 and every referenced id must
exist. bt_node.cpp then loads `<yaml_base_name>__agent_<id>_bt.xml` per agent; those trees are
checked against HuNavSim's registered nodes (bt/hunav_compat.hunav_loading_problems).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from grove_tui.bt.hunav_compat import hunav_loading_problems

# hunav_loader.cpp: name -> declared type ("double" accepts only floats: rclcpp does not convert)
TOP_LEVEL = {"yaml_base_name": "string", "simulator": "string", "map": "string", "publish_people": "bool",
             "agents": "string_array"}
AGENT = {
    "id": "int", "skin": "int", "group_id": "int", "max_vel": "double", "radius": "double",
    "behavior.type": "string", "behavior.configuration": "int", "behavior.duration": "double",
    "behavior.once": "bool", "behavior.vel": "double", "behavior.dist": "double",
    "behavior.goal_force_factor": "double", "behavior.obstacle_force_factor": "double",
    "behavior.social_force_factor": "double", "behavior.other_force_factor": "double",
    "init_pose.x": "double", "init_pose.y": "double", "init_pose.z": "double", "init_pose.h": "double",
    "goal_radius": "double", "cyclic_goals": "bool", "goals": "int_array",
}
# Declared without a default (declare_parameter(name, ParameterType)): absent means the node aborts.
REQUIRED_AGENT = frozenset({"goals"})
SIMULATORS = ("Gazebo Classic", "Gazebo Fortress", "Isaac Sim", "Webots")


def _type_ok(value: Any, kind: str) -> bool:
    if kind == "string":
        return isinstance(value, str)
    if kind == "bool":
        return isinstance(value, bool)
    if kind == "int":
        return isinstance(value, int) and not isinstance(value, bool)
    if kind == "double":
        return isinstance(value, float)
    if kind == "string_array":
        return isinstance(value, list) and bool(value) and all(isinstance(v, str) for v in value)
    if kind == "int_array":
        return (isinstance(value, list) and bool(value)
                and all(isinstance(v, int) and not isinstance(v, bool) for v in value))
    raise ValueError(kind)


def _lookup(mapping: dict, dotted: str) -> tuple[bool, Any]:
    node: Any = mapping
    for part in dotted.split("."):
        if not isinstance(node, dict) or part not in node:
            return False, None
        node = node[part]
    return True, node


def _describe(kind: str) -> str:
    return {"double": "a floating-point number (write 3.0, not 3)", "int": "an integer", "bool": "true or false",
            "string": "a string", "string_array": "a non-empty list of strings",
            "int_array": "a non-empty list of integers (an empty list has no type)"}[kind]


def check_loader_parameters(document: Any, source: str = "agents yaml") -> list[str]:
    """Every problem HuNavSim 2.0's loader would hit with this parameters file (empty: it loads)."""
    problems: list[str] = []
    if not isinstance(document, dict) or not isinstance(document.get("hunav_loader"), dict):
        return [f"{source}: the file must start with `hunav_loader:` (the loader node's name)"]
    params = document["hunav_loader"].get("ros__parameters")
    if not isinstance(params, dict):
        return [f"{source}: `hunav_loader` needs a `ros__parameters` mapping"]
    for key, kind in TOP_LEVEL.items():
        found, value = _lookup(params, key)
        if found and not _type_ok(value, kind):
            problems.append(f"{source}: `{key}` is {value!r}; the loader declares it as {_describe(kind)}")
    simulator = params.get("simulator")
    if isinstance(simulator, str) and simulator not in SIMULATORS:
        problems.append(f"{source}: simulator {simulator!r} is not one HuNavSim names ({', '.join(SIMULATORS)}); "
                        "the agent manager would look for the Webots wrapper")
    goals = params.get("global_goals") or {}
    goal_ids: set[int] = set()
    if not isinstance(goals, dict):
        problems.append(f"{source}: `global_goals` must map ids 1, 2, ... to {{x, y}}")
        goals = {}
    def order(k: Any) -> tuple[bool, int, str]:
        numeric = isinstance(k, int) and not isinstance(k, bool)
        return (not numeric, k if numeric else 0, str(k))

    for expected, key in enumerate(sorted(goals, key=order), start=1):
        if not isinstance(key, int) or isinstance(key, bool):
            problems.append(f"{source}: global_goals key {key!r} is not an integer id")
            continue
        if key != expected:
            problems.append(f"{source}: global_goals jump to {key} after {expected - 1}; the loader stops at the "
                            f"first gap, so goal {key} and later never load")
            break
        goal_ids.add(key)
        for axis in ("x", "y"):
            found, value = _lookup(goals[key], axis) if isinstance(goals[key], dict) else (False, None)
            if not found or not _type_ok(value, "double"):
                problems.append(f"{source}: global_goals.{key}.{axis} is {value!r}; the loader declares "
                                f"{_describe('double')}")
    agents = params.get("agents") or []
    seen_ids: dict[int, str] = {}
    for name in agents if isinstance(agents, list) else []:
        entry = params.get(name)
        if not isinstance(entry, dict):
            problems.append(f"{source}: agent {name!r} is listed in `agents` but has no `{name}:` block")
            continue
        for key, kind in AGENT.items():
            found, value = _lookup(entry, key)
            if not found:
                if key in REQUIRED_AGENT:
                    problems.append(f"{source}: {name}.{key} is missing; the loader declares it without a default")
                continue
            if not _type_ok(value, kind):
                problems.append(f"{source}: {name}.{key} is {value!r}; the loader declares it as {_describe(kind)}")
        for goal in entry.get("goals") or []:
            if isinstance(goal, int) and goal not in goal_ids:
                problems.append(f"{source}: {name}.goals names goal {goal}, which global_goals does not define "
                                "(the loader would put it at 0, 0)")
        agent_id = entry.get("id")
        if isinstance(agent_id, int):
            if agent_id in seen_ids:
                problems.append(f"{source}: {name} and {seen_ids[agent_id]} share id {agent_id}")
            seen_ids[agent_id] = name
    return problems


def check_hunav_export(agents_yaml: str | Path, trees_dir: str | Path | None = None) -> list[str]:
    """Loader check of an agents yaml plus, per agent, the tree file the agent manager would load."""
    path = Path(agents_yaml)
    document = yaml.safe_load(path.read_text(encoding="utf-8"))
    problems = check_loader_parameters(document, str(path))
    if problems:
        return problems
    params = document["hunav_loader"]["ros__parameters"]
    base = params.get("yaml_base_name", "warehouse_agents")
    folder = Path(trees_dir) if trees_dir is not None else path.parent
    for name in params.get("agents") or []:
        agent_id = params[name].get("id", -1)
        tree = folder / f"{base}__agent_{agent_id}_bt.xml"
        if not tree.is_file():
            problems.append(f"{tree}: missing; bt_node.cpp loads <yaml_base_name>__agent_<id>_bt.xml for {name}")
            continue
        problems += [f"{tree}: {p}" for p in hunav_loading_problems(tree.read_text(encoding="utf-8"))]
    return problems
