"""`grove import hunav AGENTS.yaml`: a HuNavSim 2.0 scenario (agents, global_goals, trees) as a GROVE bundle.

The agents YAML is checked as HuNavSim's loader reads it (exports/hunav_loader_check.py); each agent's
tree is the file HuNavSim's agent manager would load, `<yaml_base_name>__agent_<id>_bt.xml` (bt_node.cpp,
`initializeBehaviorTree`), looked up beside the YAML, in `--trees`, or in the wrapper layout's
`../behavior_trees/`. Its `<include>`s are inlined (bt/include.py) so the bundle is self-contained.
Trees keep HuNavSim's `goal_id`s; the bundle's scenario carries `global_goals`, which GROVE's runtime
resolves them with. Nodes an export kept as `Grove<Node>` get their GROVE names back.

The world: `--world`, else the YAML's `map` when it is a GROVE world (what `grove export hunav` writes),
else an open floor around every pose and goal (HuNavSim's worlds are Gazebo files GROVE cannot read),
written into the bundle as `<map>.yaml`.

Export, then import, then export again gives the same agents YAML and the same trees.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from typing import Any

import yaml

from grove_tui.bt.include import resolve_includes
from grove_tui.bt.xml import BTError, check_tree_text, read_tree, write_tree
from grove_tui.errors import HunavImportError
from grove_tui.exports.hunav import KEPT_NODE_PREFIX
from grove_tui.exports.hunav_loader_check import check_loader_parameters

OPEN_FLOOR_MARGIN = 4.0  # metres of floor around the farthest pose or goal of a synthesized world


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


def import_hunav(agents_yaml: str | Path, out_dir: str | Path, *, world: str | None = None,
                 trees_dir: str | Path | None = None, overwrite: bool = False) -> Path:
    """Write a GROVE bundle for a HuNavSim agents YAML and its trees; returns the bundle folder."""
    from grove_tui.generation.pipeline import GenerationResult
    from grove_tui.navigation.grid import build_grid
    from grove_tui.scenario.bundle import write_bundle
    from grove_tui.scenario.model import AgentSpec, Scenario
    from grove_tui.world import list_worlds, load_world, parse_world

    source = Path(agents_yaml)
    try:
        document = yaml.safe_load(source.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise HunavImportError(f"{source}: no such file") from None
    except yaml.YAMLError as exc:
        raise HunavImportError(f"{source}: not valid YAML: {exc}") from None
    problems = check_loader_parameters(document, str(source))
    if problems:
        raise HunavImportError("; ".join(problems), hint="HuNavSim's own loader would stop on this file too.")
    params: dict[str, Any] = document["hunav_loader"]["ros__parameters"]
    base = str(params.get("yaml_base_name", "warehouse_agents"))
    map_name = str(params.get("map", "warehouse"))
    global_goals = {int(k): (float(v["x"]), float(v["y"])) for k, v in (params.get("global_goals") or {}).items()}

    folders = [Path(trees_dir)] if trees_dir is not None else [source.parent, source.parent.parent / "behavior_trees"]
    agents: list[AgentSpec] = []
    trees: dict[str, str] = {}
    points: list[tuple[float, float]] = list(global_goals.values())
    for name in params.get("agents") or []:
        entry = params[name]
        agent_id = int(entry.get("id", -1))
        if agent_id < 1:
            raise HunavImportError(f"{source}: {name}.id is {agent_id}; GROVE numbers agents from 1 (0 is the robot)")
        path = _tree_file(folders, base, agent_id)
        try:
            xml = _grove_names(resolve_includes(path, allowed_roots=[path.parent]), str(path))
        except BTError as exc:
            raise HunavImportError(str(exc), hint="Fix the tree, or pass --trees with the folder it includes from.") \
                from None
        tree_problems = check_tree_text(xml, str(path))
        if tree_problems:
            raise HunavImportError(f"{path}: " + "; ".join(str(p) for p in tree_problems))
        pose = entry.get("init_pose") or {}
        start = (float(pose.get("x", 0.0)), float(pose.get("y", 0.0)))
        points.append(start)
        rel = f"trees/agent_{agent_id}.xml"
        trees[rel] = xml
        behavior = entry.get("behavior") or {}
        agents.append(AgentSpec(
            id=agent_id, group=int(entry.get("group_id", -1)), start=start,
            goals=tuple(global_goals[g] for g in entry.get("goals") or []), zone="", tree=rel,
            radius=float(entry.get("radius", 0.35)), max_vel=float(entry.get("max_vel", 1.0)), label=name,
            behavior=str(behavior.get("type", "Regular")),
        ))

    world_text = None
    if world is not None:
        world_ref = world
        world_obj = load_world(world)
    elif map_name in list_worlds():
        world_ref = map_name
        world_obj = load_world(map_name)
    else:
        world_ref = f"{map_name}.yaml"
        world_text = _open_floor_world(map_name, points)
        parsed, world_problems = parse_world(world_text, world_ref)
        if world_problems or parsed is None:
            problem = world_problems[0] if world_problems else "no world"
            raise HunavImportError(f"{source}: cannot build an open floor for map {map_name!r}: {problem}")
        world_obj = parsed
    agents = [dataclasses.replace(a, zone=getattr(world_obj.zone_at(*a.start), "name", "")) for a in agents]
    scenario = Scenario(world=world_ref, preset="normal", prompt=f"imported from HuNavSim {source.name}", seed=0,
                        models={}, agents=tuple(sorted(agents, key=lambda a: a.id)), robot=None,
                        global_goals=global_goals)
    grid = build_grid(world_obj, scenario.resolution, scenario.grid_inflation)
    report = {"stages": {}, "notes": [f"imported from {source} (HuNavSim map {map_name!r}, {len(agents)} agents)"]}
    files = dict(trees)
    if world_text is not None:
        files[world_ref] = world_text  # written in the same atomic step as the trees
    return write_bundle(GenerationResult(scenario, files, {}, grid, report), out_dir, overwrite=overwrite)
