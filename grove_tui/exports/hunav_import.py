"""`grove import hunav AGENTS.yaml`: a HuNavSim 2.0 scenario (agents, global_goals, trees) as a GROVE bundle.

The agents YAML is checked as HuNavSim's loader reads it (exports/hunav_loader_check.py); each agent's
tree is the file HuNavSim's agent manager would load, `<yaml_base_name>__agent_<id>_bt.xml` (bt_node.cpp,
`initializeBehaviorTree`), looked up beside the YAML, in `--trees`, or in the wrapper layout's
`../behavior_trees/`. Its `<include>`s are inlined (bt/include.py) so the bundle is self-contained.
Trees keep HuNavSim's `goal_id`s; the bundle's scenario carries `global_goals`, which GROVE's runtime
resolves them with. Nodes an export kept as `Grove<Node>` get their GROVE names back.

The world: `--world`, else the YAML's `map` when it is a GROVE world (what `grove export hunav` writes),
else an open floor around every pose and goal (HuNavSim's worlds are Gazebo files GROVE cannot read),
written into the bundle as `world/<map>.yaml` (the bundle's own world file, read from the bundle
wherever it is used; never a name that could replace scenario.yaml).

The file is read as every user file is (a bounded regular file, UTF-8, YAML without alias bombs or
deep nesting) and checked against the limits generation keeps: finite poses and goals within the
coordinates scenarios use, speeds and radii as a bundle allows them, HuNavSim's behavior types, at most
MAX_GROUP_COUNT people per group and MAX_SCENARIO_AGENTS in all. What it writes, `simulate` reads.

Export, then import, then export again gives the same agents YAML and the same trees.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections import Counter
from pathlib import Path
from typing import Any

import yaml

from grove_tui.bt.include import resolve_includes
from grove_tui.bt.xml import BTError, check_tree_text, read_tree, write_tree
from grove_tui.errors import GroveError, HunavImportError
from grove_tui.exports.hunav import KEPT_NODE_PREFIX
from grove_tui.exports.hunav_loader_check import check_loader_parameters
from grove_tui.limits import (MAX_COORDINATE, MAX_GROUP_COUNT, MAX_SCENARIO_AGENTS, InputLimitError, load_yaml_bounded,
                              read_text_bounded)

OPEN_FLOOR_MARGIN = 4.0  # metres of floor around the farthest pose or goal of a synthesized world
# A HuNavSim scenario of MAX_SCENARIO_AGENTS agents is well under a megabyte of YAML.
MAX_AGENTS_YAML_BYTES = 8 * 1024 * 1024
# `map` and `yaml_base_name` become file names (world/<map>.yaml, <base>__agent_<id>_bt.xml).
PLAIN_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}$")
SHOWN_PROBLEMS = 3  # problems printed in the one-line error; the count of the rest follows


def _open_floor_world(name: str, points: list[tuple[float, float]]) -> str:
    xs = [p[0] for p in points] or [0.0]
    ys = [p[1] for p in points] or [0.0]
    x0, y0 = math.floor(min(xs) - OPEN_FLOOR_MARGIN), math.floor(min(ys) - OPEN_FLOOR_MARGIN)
    x1, y1 = math.ceil(max(xs) + OPEN_FLOOR_MARGIN), math.ceil(max(ys) + OPEN_FLOOR_MARGIN)
    world = {
        "name": "".join(c if c.isalnum() else "_" for c in name.lower()) or "hunav_world",
        "description": f"Open floor around the HuNavSim scenario {name!r} (its Gazebo world is not read).",
        "zones": [{"name": "floor", "type": "hall", "description": "Open floor.",
                   "boundary": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]}],
    }
    return yaml.safe_dump(world, sort_keys=False)


def _tree_file(folder_candidates: list[Path], base: str, agent_id: int) -> Path:
    name = f"{base}__agent_{agent_id}_bt.xml"
    for folder in folder_candidates:
        if (folder / name).is_file():
            return folder / name
    raise HunavImportError(f"{name}: not found in " + ", ".join(str(f) for f in folder_candidates),
                           hint="Pass --trees DIR, the folder holding the agents' tree files.")


def _grove_names(xml: bytes, source: str) -> str:
    """Trees an export wrote with --keep-grove-nodes name GROVE nodes Grove<Node>: give them back."""
    from grove_tui.bt.manifest import NODES

    document = read_tree(xml, source)
    for element in document.nodes():
        if element.tag.startswith(KEPT_NODE_PREFIX):
            name = element.tag[len(KEPT_NODE_PREFIX):]
            if name in NODES and NODES[name].origin == "grove":
                element.tag = name
    return write_tree(document)


def _one_line(problems: list[str], source: Path) -> str:
    """The file once, its first problems, then how many more: a million-agent file gave a 128 MB line."""
    prefix = f"{source}: "
    shown = "; ".join(problem.removeprefix(prefix) for problem in problems[:SHOWN_PROBLEMS])
    more = len(problems) - SHOWN_PROBLEMS
    return prefix + shown + (f" (and {more:,} more problems)" if more > 0 else "")


def _short(value: Any) -> str:
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _read_document(source: Path) -> dict[str, Any]:
    """The agents YAML's `ros__parameters`, read as every user file is and checked before any use."""
    try:
        text = read_text_bounded(source, MAX_AGENTS_YAML_BYTES, "agents YAML")
        document = load_yaml_bounded(text, str(source))
    except InputLimitError as exc:
        raise HunavImportError(str(exc)) from None
    params = document.get("hunav_loader", {}).get("ros__parameters") if isinstance(document, dict) and \
        isinstance(document.get("hunav_loader"), dict) else None
    agents = params.get("agents") if isinstance(params, dict) else None
    if isinstance(agents, list) and len(agents) > MAX_SCENARIO_AGENTS:
        # Before the per-agent checks: a million names would make a million problems.
        raise HunavImportError(f"{source}: `agents` lists {len(agents):,} agents; GROVE scenarios hold at most "
                               f"{MAX_SCENARIO_AGENTS:,} (the most generation writes)")
    problems = check_loader_parameters(document, str(source))
    if problems:
        raise HunavImportError(_one_line(problems, source), hint="HuNavSim's own loader would stop on this file too.")
    assert isinstance(params, dict)  # check_loader_parameters refuses a file without it
    return params


def _plain_name(params: dict[str, Any], key: str, default: str, source: Path) -> str:
    value = params.get(key, default)
    if not isinstance(value, str) or not PLAIN_NAME.match(value):
        raise HunavImportError(f"{source}: `{key}` is {_short(value)}; it names files, so it must be 1 to 100 "
                               "letters, digits, '_', '-' or '.' (not starting with '.')")
    return value


def _number(value: Any, where: str, low: float, high: float) -> float:
    """A finite number in [low, high], as a bundle's own checks take it (scenario/model.py)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise HunavImportError(f"{where} is {_short(value)}; expected a number")
    if isinstance(value, int) and not low <= value <= high:
        raise HunavImportError(f"{where} is {_short(value)}; it must be within {low:g}..{high:g}")
    number = float(value)
    if not (math.isfinite(number) and low <= number <= high):
        raise HunavImportError(f"{where} is {_short(value)}; it must be a finite number within {low:g}..{high:g}")
    return number


def _point(mapping: Any, where: str) -> tuple[float, float]:
    if not isinstance(mapping, dict):
        raise HunavImportError(f"{where} is {_short(mapping)}; expected a mapping with x and y (metres)")
    return (_number(mapping.get("x", 0.0), f"{where}.x", -MAX_COORDINATE, MAX_COORDINATE),
            _number(mapping.get("y", 0.0), f"{where}.y", -MAX_COORDINATE, MAX_COORDINATE))


def _agent_fields(name: str, entry: dict[str, Any], global_goals: dict[int, tuple[float, float]],
                  source: Path) -> dict[str, Any]:
    """One agent's values, each checked against what a bundle accepts (so `simulate` reads the result)."""
    from grove_tui.scenario.model import BEHAVIOR_TYPES, MAX_AGENTS, MAX_VEL_RANGE, RADIUS_RANGE

    where = f"{source}: {name}"
    behavior = entry.get("behavior", {})
    if behavior is None:
        behavior = {}
    if not isinstance(behavior, dict):
        raise HunavImportError(f"{where}.behavior is {_short(behavior)}; HuNavSim's loader reads a mapping "
                               f"(behavior: {{type: Scared, ...}})")
    kind = behavior.get("type", "Regular")
    if kind not in BEHAVIOR_TYPES:
        raise HunavImportError(f"{where}.behavior.type is {_short(kind)}; HuNavSim's behaviors are "
                               f"{', '.join(BEHAVIOR_TYPES)}")
    group = entry.get("group_id", -1)
    if isinstance(group, bool) or not isinstance(group, int) or not -1 <= group <= 10 * MAX_AGENTS:
        raise HunavImportError(f"{where}.group_id is {_short(group)}; expected -1 (no group) or a group id "
                               f"0..{10 * MAX_AGENTS}")
    return {
        "group": group,
        "start": _point(entry.get("init_pose", {}), f"{where}.init_pose"),
        "goals": tuple(global_goals[g] for g in entry.get("goals") or []),
        "radius": _number(entry.get("radius", 0.35), f"{where}.radius", *RADIUS_RANGE),
        "max_vel": _number(entry.get("max_vel", 1.0), f"{where}.max_vel", *MAX_VEL_RANGE),
        "behavior": kind,
    }


def _check_groups(groups: list[int], source: Path) -> None:
    """Generation's bounds: at most MAX_GROUP_COUNT people share a group."""
    sizes = Counter(group for group in groups if group >= 0)
    crowded = [(group, size) for group, size in sizes.items() if size > MAX_GROUP_COUNT]
    if crowded:
        group, size = crowded[0]
        raise HunavImportError(f"{source}: group_id {group} has {size:,} agents; a group holds at most "
                               f"{MAX_GROUP_COUNT} (as generation allows)")


def import_hunav(agents_yaml: str | Path, out_dir: str | Path, *, world: str | None = None,
                 trees_dir: str | Path | None = None, overwrite: bool = False) -> Path:
    """Write a GROVE bundle for a HuNavSim agents YAML and its trees; returns the bundle folder."""
    from grove_tui.generation.pipeline import GenerationResult, world_reference
    from grove_tui.navigation.grid import build_grid
    from grove_tui.scenario.bundle import WORLD_FOLDER, write_bundle
    from grove_tui.scenario.model import AgentSpec, Scenario, ScenarioError
    from grove_tui.world import list_worlds, load_world, parse_world

    source = Path(agents_yaml)
    params = _read_document(source)
    base = _plain_name(params, "yaml_base_name", "warehouse_agents", source)
    map_name = _plain_name(params, "map", "warehouse", source)
    global_goals = {int(k): _point(v, f"{source}: global_goals.{k}")
                    for k, v in (params.get("global_goals") or {}).items()}

    folders = [Path(trees_dir)] if trees_dir is not None else [source.parent, source.parent.parent / "behavior_trees"]
    # Every agent's values first (cheap), then the trees (parsed one by one): a bad value is refused
    # before any tree is read.
    checked: list[tuple[str, int, dict[str, Any]]] = []
    for name in params.get("agents") or []:
        entry = params[name]
        agent_id = entry.get("id", -1)
        if not 1 <= agent_id <= 10 * MAX_SCENARIO_AGENTS:
            raise HunavImportError(f"{source}: {name}.id is {_short(agent_id)}; GROVE numbers agents from 1 "
                                   f"(0 is the robot) up to {10 * MAX_SCENARIO_AGENTS}")
        checked.append((name, agent_id, _agent_fields(name, entry, global_goals, source)))
    _check_groups([fields["group"] for _name, _id, fields in checked], source)
    agents: list[AgentSpec] = []
    trees: dict[str, str] = {}
    points: list[tuple[float, float]] = list(global_goals.values())
    for name, agent_id, fields in checked:
        path = _tree_file(folders, base, agent_id)
        try:
            xml = _grove_names(resolve_includes(path, allowed_roots=[path.parent]), str(path))
        except BTError as exc:
            raise HunavImportError(str(exc), hint="Fix the tree, or pass --trees with the folder it includes from.") \
                from None
        tree_problems = check_tree_text(xml, str(path))
        if tree_problems:
            raise HunavImportError(f"{path}: " + "; ".join(str(p) for p in tree_problems))
        points.append(fields["start"])
        rel = f"trees/agent_{agent_id}.xml"
        trees[rel] = xml
        agents.append(AgentSpec(id=agent_id, zone="", tree=rel, label=name, **fields))

    world_text = None
    if world is not None:
        world_obj = load_world(world)
        world_ref = world_reference(world_obj)  # a shipped name or an absolute path, as generation records it
    elif map_name in list_worlds():
        world_ref = map_name
        world_obj = load_world(map_name)
    else:
        world_ref = f"{WORLD_FOLDER}/{map_name}.yaml"
        world_text = _open_floor_world(map_name, points)
        parsed, world_problems = parse_world(world_text, world_ref)
        if world_problems or parsed is None:
            problem = world_problems[0].message if world_problems else "no world"
            raise HunavImportError(f"{source}: cannot build an open floor for map {map_name!r} around the agents' "
                                   f"poses and goals: {problem}")
        world_obj = parsed
    agents = [dataclasses.replace(a, zone=getattr(world_obj.zone_at(*a.start), "name", "")) for a in agents]
    scenario = Scenario(world=world_ref, preset="normal", prompt=f"imported from HuNavSim {source.name}", seed=0,
                        models={}, agents=tuple(sorted(agents, key=lambda a: a.id)), robot=None,
                        global_goals=global_goals)
    try:  # the checks `simulate` makes when it reads the bundle back: what is written, loads
        Scenario.from_dict(scenario.to_dict(), f"{source} (as a bundle)")
        grid = build_grid(world_obj, scenario.resolution, scenario.grid_inflation)
    except (ScenarioError, GroveError) as exc:
        raise HunavImportError(str(exc)) from None
    report = {"stages": {}, "notes": [f"imported from {source} (HuNavSim map {map_name!r}, {len(agents)} agents)"]}
    files = dict(trees)
    if world_text is not None:
        files[world_ref] = world_text  # written in the same atomic step as the trees
    return write_bundle(GenerationResult(scenario, files, {}, grid, report), out_dir, overwrite=overwrite)
