"""What HuNavSim's `hunav_loader` and agent manager would do with an agents YAML, without ROS.

Two layouts (`hunav_layout`): 2.0 (`global_goals`, integer goal ids, `behavior.type` a name) and 1.0
(goals named per agent with x, y, h; `behavior` a type number, or a block whose `type` is one, as
hunav_loader.cpp@03330520 and the wrapper's scenarios@3e5219e have it). What follows is 2.0's loader;
1.0's declares `<agent>.goals` a PARAMETER_STRING_ARRAY and `<agent>.<goal>.x/y/h` doubles instead.

Emulates robotics-upo/hunav_sim 2.0 `hunav_agent_manager/src/hunav_loader.cpp` (`namespace hunav`,
as stored in the public code index): every parameter it declares, with the type it declares it with.
rclcpp throws InvalidParameterTypeException when a parameters-file value has another type (an integer
where a double is declared, `x: 3` instead of `x: 3.0`), and an empty YAML list has no type at all,
so `<agent>.goals` (declared PARAMETER_INTEGER_ARRAY) must be a non-empty list of integers. The loader
reads `global_goals.<n>.x/y` for n = 1, 2, ... and stops at the first gap, and declares a goal id it
did not find with the default (0.0, 0.0): ids must be consecutive from 1 and every referenced id must
exist. bt_node.cpp then loads `<yaml_base_name>__agent_<id>_bt.xml` per agent; those trees are
checked against HuNavSim's registered nodes (bt/format/hunav_compat.hunav_loading_problems).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from grove_tui.bt.format.hunav_compat import hunav_loading_problems
from grove_tui.bt.format.include import resolve_includes
from grove_tui.errors import BTError

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
# HuNavSim 1.0's loader (hunav_loader.cpp, humble@afa9743 and 03330520): goals are names, each a block.
AGENT_1 = {key: kind for key, kind in AGENT.items() if not key.startswith("behavior.")} | {"goals": "string_array"}
BEHAVIOR_BLOCK_1 = {key: kind for key, kind in AGENT.items() if key.startswith("behavior.")} | {"behavior.type": "int"}
GOAL_1 = {"x": "double", "y": "double", "h": "double"}
# Declared without a default (declare_parameter(name, ParameterType)): absent means the node aborts.
REQUIRED_AGENT = frozenset({"goals"})


def hunav_layout(params: object) -> str:
    """"2.0" for a file with global_goals or integer goal ids, else "1.0" (goals named per agent)."""
    if not isinstance(params, dict):
        return "2.0"
    if "global_goals" in params or "yaml_base_name" in params:
        return "2.0"
    for name in params.get("agents") or []:
        entry = params.get(name) if isinstance(name, str) else None
        goals = entry.get("goals") if isinstance(entry, dict) else None
        if isinstance(goals, list) and goals:
            return "1.0" if all(isinstance(g, str) for g in goals) else "2.0"
    return "2.0"


# An agents YAML as parsed, after check_loader_parameters has passed it: its values are still the file's own.
LoaderDocument = dict[str, Any]  # Any: YAML values, of the types the loader check has confirmed
SIMULATORS = ("Gazebo Classic", "Gazebo Fortress", "Isaac Sim", "Webots")


def _type_ok(value: object, kind: str) -> bool:
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


def _lookup(mapping: dict, dotted: str) -> tuple[bool, object]:
    node: object = mapping
    for part in dotted.split("."):
        if not isinstance(node, dict) or part not in node:
            return False, None
        node = node[part]
    return True, node


def _describe(kind: str) -> str:
    return {"double": "a floating-point number (write 3.0, not 3)", "int": "an integer", "bool": "true or false",
            "string": "a string", "string_array": "a non-empty list of strings",
            "int_array": "a non-empty list of integers (an empty list has no type)"}[kind]


def _listed(value: object) -> list[object]:
    """A list as it is, anything else as no entries (its type is reported by the declared-type check)."""
    return value if isinstance(value, list) else []


def _short(value: object) -> str:
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def check_loader_parameters(document: object, source: str = "agents yaml") -> list[str]:
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
    def order(k: object) -> tuple[bool, int, str]:
        if isinstance(k, int) and not isinstance(k, bool):
            return (False, k, str(k))
        return (True, 0, str(k))

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
    layout = hunav_layout(params)
    agents = params.get("agents") or []
    seen_ids: dict[int, str] = {}
    for name in agents if isinstance(agents, list) else []:
        if not isinstance(name, str):  # `agents` names blocks; a number or a mapping names none
            problems.append(f"{source}: `agents` lists {_short(name)}, which is not an agent's name")
            continue
        entry = params.get(name)
        if not isinstance(entry, dict):
            problems.append(f"{source}: agent {name!r} is listed in `agents` but has no `{name}:` block")
            continue
        declared = AGENT
        if layout == "1.0":
            behavior = entry.get("behavior")
            declared = AGENT_1 | (BEHAVIOR_BLOCK_1 if isinstance(behavior, dict) else {"behavior": "int"})
            for goal in _listed(entry.get("goals")):
                block = entry.get(goal) if isinstance(goal, str) else None
                if not isinstance(block, dict):
                    problems.append(f"{source}: {name}.goals names goal {goal!r}, which has no `{goal}:` block "
                                    "(the loader would put it at 0, 0)")
                    continue
                for axis, kind in GOAL_1.items():
                    found, value = _lookup(block, axis)
                    if found and not _type_ok(value, kind):
                        problems.append(f"{source}: {name}.{goal}.{axis} is {value!r}; the loader declares "
                                        f"{_describe(kind)}")
        for key, kind in declared.items():
            found, value = _lookup(entry, key)
            if not found:
                if key in REQUIRED_AGENT:
                    problems.append(f"{source}: {name}.{key} is missing; the loader declares it without a default")
                continue
            if not _type_ok(value, kind):
                problems.append(f"{source}: {name}.{key} is {value!r}; the loader declares it as {_describe(kind)}")
        for goal in _listed(entry.get("goals")):
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
    if hunav_layout(params) == "1.0":
        return problems  # HuNavSim 1.0 runs its own tree per behavior: there is no tree file to load
    base = params.get("yaml_base_name", path.stem)
    folder = Path(trees_dir) if trees_dir is not None else path.parent
    for name in params.get("agents") or []:
        agent_id = params[name].get("id", -1)
        tree = folder / f"{base}__agent_{agent_id}_bt.xml"
        if not tree.is_file():
            problems.append(f"{tree}: missing; bt_node.cpp loads <yaml_base_name>__agent_<id>_bt.xml for {name}")
            continue
        text = tree.read_text(encoding="utf-8")
        if "<include" in text:  # BT.CPP reads included files relative to the tree's folder; so does this
            try:
                text = resolve_includes(tree, allowed_roots=[folder]).decode("utf-8")
            except BTError as exc:
                problems.append(f"{tree}: {exc}")
                continue
        problems += [f"{tree}: {p}" for p in hunav_loading_problems(text)]
    return problems


# What HuNavSim's loader takes when a key is left out (hunav_loader.cpp, both versions).
TOP_DEFAULTS: dict[str, object] = {"yaml_base_name": None, "simulator": None, "map": "map.yaml",
                                   "publish_people": True}
AGENT_DEFAULTS: dict[str, object] = {"id": -1, "skin": -1, "group_id": -1, "max_vel": 1.0, "radius": 0.35,
                                     "init_pose.x": 0.0, "init_pose.y": 0.0, "init_pose.z": 0.0, "init_pose.h": 0.0,
                                     "goal_radius": 0.0, "cyclic_goals": True}
BEHAVIOR_DEFAULTS: dict[str, object] = {"behavior.type": None, "behavior.configuration": 0, "behavior.duration": 40.0,
                                        "behavior.once": True, "behavior.vel": 1.0, "behavior.dist": 0.0,
                                        "behavior.goal_force_factor": 2.0, "behavior.obstacle_force_factor": 10.0,
                                        "behavior.social_force_factor": 5.0, "behavior.other_force_factor": 20.0}


def loader_parameters(document: LoaderDocument) -> dict[str, object]:
    """Every parameter HuNavSim's loader declares for this file, by its dotted name, with the value it
    reads: the file's, else the loader's default. Two files the loader reads alike give equal dicts;
    keys it never declares (a typo such as `H:` for `h:`) are not in it (see `ignored_keys`)."""
    params = document["hunav_loader"]["ros__parameters"]
    layout = hunav_layout(params)
    out: dict[str, object] = {}
    for key, default in TOP_DEFAULTS.items():
        found, value = _lookup(params, key)
        out[key] = value if found else default
    names = list(params.get("agents") or [])
    out["agents"] = names
    if layout == "2.0":
        goals = params.get("global_goals") or {}
        n = 1
        while n in goals:  # the loader reads ids 1, 2, ... and stops at the first gap
            for axis in ("x", "y"):
                out[f"global_goals.{n}.{axis}"] = goals[n].get(axis, 0.0)
            n += 1
    for name in names:
        entry = params[name]
        for key, default in AGENT_DEFAULTS.items():
            found, value = _lookup(entry, key)
            out[f"{name}.{key}"] = value if found else default
        behavior = entry.get("behavior")
        if layout == "1.0" and not isinstance(behavior, dict):
            out[f"{name}.behavior"] = -1 if behavior is None else behavior
        else:
            for key, default in BEHAVIOR_DEFAULTS.items():
                found, value = _lookup(entry, key)
                out[f"{name}.{key}"] = value if found else default
        out[f"{name}.goals"] = list(entry.get("goals") or [])
        if layout == "1.0":
            for goal in entry.get("goals") or []:
                block = entry.get(goal) if isinstance(entry.get(goal), dict) else {}
                for axis in ("x", "y", "h"):
                    out[f"{name}.{goal}.{axis}"] = block.get(axis, 0.0)
    return out


def ignored_keys(document: LoaderDocument) -> list[str]:
    """Keys of the file HuNavSim's loader never declares, so never reads (dotted names)."""
    read = loader_parameters(document)

    def leaves(mapping: dict, prefix: str) -> list[str]:
        out = []
        for key, value in mapping.items():
            dotted = f"{prefix}{key}"
            out += leaves(value, dotted + ".") if isinstance(value, dict) else [dotted]
        return out

    return [key for key in leaves(document["hunav_loader"]["ros__parameters"], "") if key not in read]
