"""`grove import hunav AGENTS.yaml`: a HuNavSim scenario (agents, goals, trees) as a GROVE bundle.

Both agents-YAML layouts HuNavSim has shipped are read (exports/hunav_loader_check.hunav_layout):
- 2.0: `global_goals` {id: {x, y}}, each agent's `goals` a list of ids, `behavior.type` a name, and
  one tree per agent, `<yaml_base_name>__agent_<id>_bt.xml` (bt_node.cpp, `initializeBehaviorTree`),
  looked up beside the YAML, in `--trees`, or in the wrapper layout's `../behavior_trees/`; its
  `<include>`s are inlined (bt/format/include.py) for GROVE to run it;
- 1.0: each agent's `goals` a list of names, each name a block {x, y, h}, `behavior` a type number
  (or a block whose `type` is one). HuNavSim 1.0 runs a fixed tree per behavior; GROVE gives each agent
  HuNavSim's regular navigation tree, and its simulation wraps the behavior's robot reaction around it.

Nothing HuNavSim's loader reads is lost (the export writes it back, exports/hunav.py): every agent key
keeps its value and its place (AgentSpec's own fields, and `HunavAgent` for the rest: the key in the
file, skin, spawn height, the behavior block with configuration and force factors, goal names and
headings, goal ids); the file's top level (layout, yaml_base_name, simulator, map, publish_people, key
order) is `Scenario.hunav`; each 2.0 tree file is kept verbatim under `hunav/` and written back while
GROVE's tree made from it is unchanged. Numbers keep full precision (3.360 reads as the double 3.36).

The world: `--world` (a shipped name, or a world file copied into the bundle), else the YAML's `map`
when it is a shipped GROVE world, else an open floor around every pose and goal (HuNavSim's worlds are
Gazebo files GROVE cannot read) written into the bundle. Either way the bundle names a world it
carries or GROVE ships, never a path relative to the current folder: it runs from anywhere.

A file `grove export hunav` wrote carries GROVE's line (`# grove: {...}`: prompt, preset, seed, robot,
labels); importing it gives those back, so GROVE -> HuNavSim -> GROVE keeps the prompt and the robot.

The file is read as every user file is (a bounded regular file, UTF-8, YAML without alias bombs or
deep nesting) and checked against the limits generation keeps: finite poses and goals within the
coordinates scenarios use, speeds and radii as a bundle allows them, HuNavSim's behavior types, at most
MAX_GROUP_COUNT people per group and MAX_SCENARIO_AGENTS in all. What it writes, `simulate` reads.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import re
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from grove_tui.bt.format.include import included_files, resolve_includes
from grove_tui.bt.format.document import TreeDocument, TreeElement, TreeFiles, node
from grove_tui.errors import BTError
from grove_tui.bt.format.xml import check_document, read_tree, write_tree
from grove_tui.errors import GroveError, HunavImportError
from grove_tui.exports.hunav import GROVE_LINE_PREFIX, KEPT_NODE_PREFIX
from grove_tui.exports.hunav_loader_check import check_loader_parameters, hunav_layout, ignored_keys
from grove_tui.exports.scene import BEHAVIOR_NUMBERS
from grove_tui.limits import (MAX_COORDINATE, MAX_GROUP_COUNT, MAX_SCENARIO_AGENTS, InputLimitError, load_yaml_bounded,
                              read_text_bounded)
from grove_tui.scenario.bundle import HUNAV_FOLDER, WORLD_FOLDER
from grove_tui.scenario.model import (BEHAVIOR_TYPES, MAX_AGENTS, MAX_VEL_RANGE, RADIUS_RANGE, AgentSpec, HunavAgent,
                                      HunavBehavior, HunavSource, RobotSpec, Scenario)
from grove_tui.world.model import World

if TYPE_CHECKING:
    from grove_tui.generation.pipeline import GenerationResult

# A mapping of the agents YAML as parsed: its values are the file's own until each is checked.
YamlMapping = dict[str, Any]  # Any: YAML values, each checked where it is read

OPEN_FLOOR_MARGIN = 4.0  # metres of floor around the farthest pose or goal of a synthesized world
# A HuNavSim scenario of MAX_SCENARIO_AGENTS agents is well under a megabyte of YAML.
MAX_AGENTS_YAML_BYTES = 8 * 1024 * 1024
# `map` and `yaml_base_name` become file names (world/<map>.yaml, <base>__agent_<id>_bt.xml).
PLAIN_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}$")
SHOWN_PROBLEMS = 3  # problems printed in the one-line error; the count of the rest follows
GOAL_RADIUS_RANGE = (0.0, 100.0)  # metres, as a bundle takes it
BEHAVIOR_NAMES = {number: name for name, number in BEHAVIOR_NUMBERS.items()}


def regular_nav_tree() -> TreeDocument:
    """HuNavSim's regular navigation (hunav_agent_manager/behavior_trees/BTRegularNav.xml), what a 1.0
    agent runs: walk to the front goal, and on reaching it take the next (round and round if cyclic)."""
    walk = TreeElement("Sequence", {"name": "RegularNavigation"}, [
        node("Inverter", [node("IsGoalReached", agent_id="{id}")]),
        node("RegularNav", agent_id="{id}", time_step="{dt}")])
    root = TreeElement("Fallback", {"name": "RegularNavFallback"}, [walk, node("UpdateGoal", agent_id="{id}")])
    tree = TreeElement("BehaviorTree", {"ID": "RegularNavTree"}, [root])
    return TreeDocument("RegularNavTree", {"RegularNavTree": tree}, "BTRegularNav.xml")


def tree_digest(text: str) -> str:
    """What `HunavAgent.tree_digest` records of a GROVE tree: the SHA-256 of its text."""
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


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


def _grove_names(xml: bytes, source: str) -> TreeDocument:
    """The tree file read (once, here); trees an export wrote with --keep-grove-nodes name GROVE nodes
    Grove<Node>: give them back."""
    from grove_tui.bt.format.manifest import NODES

    document = read_tree(xml, source)
    for element in document.nodes():
        if element.tag.startswith(KEPT_NODE_PREFIX):
            name = element.tag[len(KEPT_NODE_PREFIX):]
            if name in NODES and NODES[name].origin == "grove":
                element.tag = name
    return document


def _grove_line(text: str) -> YamlMapping:
    """GROVE's own line in an agents YAML it exported (prompt, preset, seed, robot, labels), or {}."""
    for line in text.splitlines():
        if line.startswith(GROVE_LINE_PREFIX):
            try:
                data = json.loads(line[len(GROVE_LINE_PREFIX):])
            except json.JSONDecodeError:
                return {}
            return data if isinstance(data, dict) else {}
        if line.strip() and not line.startswith("#"):
            break
    return {}


def _one_line(problems: list[str], source: Path) -> str:
    """The file once, its first problems, then how many more: a million-agent file gave a 128 MB line."""
    prefix = f"{source}: "
    shown = "; ".join(problem.removeprefix(prefix) for problem in problems[:SHOWN_PROBLEMS])
    more = len(problems) - SHOWN_PROBLEMS
    return prefix + shown + (f" (and {more:,} more problems)" if more > 0 else "")


def _short(value: object) -> str:
    try:
        text = repr(value)
    except ValueError:  # an int too long to print
        return f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _read_document(source: Path) -> tuple[str, YamlMapping]:
    """The agents YAML's text and its `ros__parameters`, read as every user file is and checked before any use."""
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
    return text, params


def _plain_name(params: YamlMapping, key: str, default: str, source: Path) -> str:
    value = params.get(key, default)
    if not isinstance(value, str) or not PLAIN_NAME.match(value):
        raise HunavImportError(f"{source}: `{key}` is {_short(value)}; it names files, so it must be 1 to 100 "
                               "letters, digits, '_', '-' or '.' (not starting with '.')")
    return value


def _number(value: object, where: str, low: float, high: float) -> float:
    """A finite number in [low, high], as a bundle's own checks take it (scenario/model.py)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise HunavImportError(f"{where} is {_short(value)}; expected a number")
    if isinstance(value, int) and not low <= value <= high:
        raise HunavImportError(f"{where} is {_short(value)}; it must be within {low:g}..{high:g}")
    number = float(value)
    if not (math.isfinite(number) and low <= number <= high):
        raise HunavImportError(f"{where} is {_short(value)}; it must be a finite number within {low:g}..{high:g}")
    return number


def _point(mapping: object, where: str) -> tuple[float, float]:
    if not isinstance(mapping, dict):
        raise HunavImportError(f"{where} is {_short(mapping)}; expected a mapping with x and y (metres)")
    return (_number(mapping.get("x", 0.0), f"{where}.x", -MAX_COORDINATE, MAX_COORDINATE),
            _number(mapping.get("y", 0.0), f"{where}.y", -MAX_COORDINATE, MAX_COORDINATE))


def _optional_number(mapping: YamlMapping, key: str, where: str, low: float, high: float) -> float | None:
    return None if mapping.get(key) is None else _number(mapping[key], f"{where}.{key}", low, high)


def _check_groups(groups: list[int], source: Path) -> None:
    """Generation's bounds: at most MAX_GROUP_COUNT people share a group."""
    sizes = Counter(group for group in groups if group >= 0)
    crowded = [(group, size) for group, size in sizes.items() if size > MAX_GROUP_COUNT]
    if crowded:
        group, size = crowded[0]
        raise HunavImportError(f"{source}: group_id {group} has {size:,} agents; a group holds at most "
                               f"{MAX_GROUP_COUNT} (as generation allows)")


def _keys(mapping: YamlMapping, prefix: str = "") -> tuple[str, ...]:
    """The keys of an agent's block in file order, nested ones dotted ("init_pose.x", "g0.h")."""
    out: list[str] = []
    for key, value in mapping.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out += _keys(value, f"{name}.") or [name]
        else:
            out.append(name)
    return tuple(out)


def _behavior(entry: YamlMapping, layout: str, where: str) -> tuple[str, HunavBehavior | None]:
    """(GROVE behavior name, the block as given, or None for 1.0's flat `behavior: <number>`)."""
    given = entry.get("behavior")
    if given is not None and not isinstance(given, dict) and layout == "2.0":
        raise HunavImportError(f"{where}.behavior is {_short(given)}; HuNavSim's loader reads a mapping "
                               f"(behavior: {{type: Scared, ...}})")
    block = given if isinstance(given, dict) else None
    kind = block.get("type") if block is not None else given
    if kind is None:
        name = "Regular"  # the loader's default type
    elif isinstance(kind, int) and not isinstance(kind, bool) and kind in BEHAVIOR_NAMES:
        name = BEHAVIOR_NAMES[kind]  # 1.0 numbers its behaviors
    else:
        name = kind if isinstance(kind, str) else ""
    if name not in BEHAVIOR_TYPES:
        numbers = ", ".join(f"{number} {label}" for number, label in BEHAVIOR_NAMES.items())
        raise HunavImportError(f"{where}.behavior.type is {_short(kind)}; HuNavSim's behaviors are "
                               f"{', '.join(BEHAVIOR_TYPES)} (1.0 numbers them: {numbers})")
    if block is None:
        return name, None
    values: dict[str, Any] = {}  # Any: HunavBehavior's keyword arguments, the numbers checked below, the rest by the loader check
    for key in HunavBehavior.__dataclass_fields__:
        value = block.get(key)
        if value is not None and key not in ("configuration", "once"):
            value = _number(value, f"{where}.behavior.{key}", -1e6, 1e6)
        values[key] = value
    return name, HunavBehavior(**values)


def _type_is_number(entry: YamlMapping) -> bool:
    """Whether the agent's behavior type is written as a number (1.0) rather than a name (2.0)."""
    given = entry.get("behavior")
    kind = given.get("type") if isinstance(given, dict) else given
    return isinstance(kind, int) and not isinstance(kind, bool)


def _agent(name: str, entry: YamlMapping, layout: str, global_goals: dict[int, tuple[float, float]],
           source: Path) -> tuple[AgentSpec, HunavAgent]:
    """The agent as GROVE runs it and what else its file says (tree fields set by the caller), each value
    checked against what a bundle accepts (so `simulate` reads the result)."""
    where = f"{source}: {name}"
    agent_id = entry.get("id", -1)
    if isinstance(agent_id, bool) or not isinstance(agent_id, int) or not 1 <= agent_id <= 10 * MAX_SCENARIO_AGENTS:
        raise HunavImportError(f"{where}.id is {_short(agent_id)}; GROVE numbers agents from 1 "
                               f"(0 is the robot) up to {10 * MAX_SCENARIO_AGENTS}")
    group = entry.get("group_id", -1)
    if isinstance(group, bool) or not isinstance(group, int) or not -1 <= group <= 10 * MAX_AGENTS:
        raise HunavImportError(f"{where}.group_id is {_short(group)}; expected -1 (no group) or a group id "
                               f"0..{10 * MAX_AGENTS}")
    pose = entry.get("init_pose", {})
    start = _point(pose, f"{where}.init_pose")
    kind, behavior = _behavior(entry, layout, where)
    listed = list(entry.get("goals") or [])
    if layout == "2.0":
        goals = tuple(global_goals[g] for g in listed)
        names: tuple[str, ...] = ()
        headings: tuple[float | None, ...] = ()
        ids = tuple(int(g) for g in listed)
    else:
        goals = tuple(_point(entry.get(g), f"{where}.{g}") for g in listed)
        names = tuple(str(g) for g in listed)
        headings = tuple(_optional_number(entry[g], "h", f"{where}.{g}", -1e3, 1e3) for g in listed)
        ids = ()
    if goals == (start,):
        # What the export writes for an agent that stays where it is (HuNavSim's loader needs one goal):
        # GROVE says that with no goals, so the round trip gives the agent back as it was.
        goals, names, headings, ids = (), (), (), ()
    skin = entry.get("skin")
    if skin is not None and (isinstance(skin, bool) or not isinstance(skin, int) or not -1 <= skin <= 1000):
        raise HunavImportError(f"{where}.skin is {_short(skin)}; expected a mesh number")
    spec = AgentSpec(
        id=agent_id, group=group, start=start, goals=goals, zone="", tree=f"trees/agent_{agent_id}.xml",
        radius=_number(entry.get("radius", 0.35), f"{where}.radius", *RADIUS_RANGE),
        max_vel=_number(entry.get("max_vel", 1.0), f"{where}.max_vel", *MAX_VEL_RANGE), label=name, behavior=kind,
        # HuNavSim's loader defaults where the file is silent: the agent moves as HuNavSim moves it
        goal_radius=_number(entry.get("goal_radius", 0.0), f"{where}.goal_radius", *GOAL_RADIUS_RANGE),
        cyclic_goals=bool(entry.get("cyclic_goals", True)),
        heading=_number(pose.get("h", 0.0), f"{where}.init_pose.h", -1e3, 1e3))
    extra = HunavAgent(name=name, skin=skin, z=_optional_number(pose, "z", f"{where}.init_pose", -MAX_COORDINATE,
                                                                 MAX_COORDINATE),
                       behavior=behavior, goal_names=names, goal_headings=headings, goal_ids=ids, keys=_keys(entry))
    return spec, extra


def _world(world: str | None, map_name: str, grove: YamlMapping, points: list[tuple[float, float]],
           source: Path) -> tuple[str, str | None, World]:
    """(the scenario's world reference, the world file text to write into the bundle or None, World)."""
    from grove_tui.world import list_worlds, load_world, parse_world, read_world_file

    if world is not None:
        if world in list_worlds():
            return world, None, load_world(world)
        path, text = read_world_file(world)  # a user's world file: the bundle carries a copy
        return f"{WORLD_FOLDER}/{path.stem}.yaml", text, load_world(path)
    for candidate in (map_name, str(grove.get("world", ""))):
        if candidate in list_worlds():
            return candidate, None, load_world(candidate)
    reference = f"{WORLD_FOLDER}/{map_name}.yaml"
    text = _open_floor_world(map_name, points)
    parsed, problems = parse_world(text, reference)
    if problems or parsed is None:
        problem = problems[0].message if problems else "no world"
        raise HunavImportError(f"{source}: cannot build an open floor for map {map_name!r} around the agents' "
                               f"poses and goals: {problem}")
    return reference, text, parsed


def _robot(data: object, source: Path) -> RobotSpec | None:
    if data is None:
        return None
    try:
        probe = Scenario.from_dict({"world": "w", "preset": "p", "prompt": "", "seed": 0, "agents": [],
                                    "robot": data}, f"{source}: grove line")
    except GroveError as exc:
        raise HunavImportError(str(exc)) from None
    return probe.robot


def read_hunav(agents_yaml: str | Path, *, world: str | None = None,
               trees_dir: str | Path | None = None) -> GenerationResult:
    """A HuNavSim agents YAML and its trees as what a GROVE bundle is written from (the services layer
    writes it: `GroveSession.import_hunav`)."""
    from grove_tui.generation.pipeline import GenerationResult
    from grove_tui.navigation.grid import build_grid

    source = Path(agents_yaml)
    text, params = _read_document(source)
    layout = hunav_layout(params)
    grove = _grove_line(text)
    base = _plain_name(params, "yaml_base_name", source.stem, source)
    map_name = _plain_name(params, "map", source.stem, source)
    global_goals = {int(k): _point(v, f"{source}: global_goals.{k}")
                    for k, v in (params.get("global_goals") or {}).items()}
    # Every agent's values first (cheap), then the trees (parsed one by one): a bad value is refused
    # before any tree is read.
    checked = [(name, *_agent(name, params[name], layout, global_goals, source)) for name in params.get("agents") or []]
    _check_groups([spec.group for _name, spec, _extra in checked], source)

    folders = [Path(trees_dir)] if trees_dir is not None else [source.parent, source.parent.parent / "behavior_trees"]
    agents: list[AgentSpec] = []
    trees: TreeFiles = {}
    files: dict[str, str] = {}  # HuNavSim's own files and the world, kept verbatim
    points: list[tuple[float, float]] = list(global_goals.values())
    includes: list[str] = []
    numbered = False
    for name, spec, extra in checked:
        numbered = numbered or _type_is_number(params[name])
        if layout == "2.0":
            path = _tree_file(folders, base, spec.id)
            try:
                document = _grove_names(resolve_includes(path, allowed_roots=[path.parent]), str(path))
            except BTError as exc:
                raise HunavImportError(str(exc), hint="Fix the tree, or pass --trees with the folder it includes "
                                                      "from.") from None
            tree_problems = check_document(document)
            if tree_problems:
                raise HunavImportError(f"{path}: " + "; ".join(str(p) for p in tree_problems))
            kept = f"{HUNAV_FOLDER}/{path.name}"
            files[kept] = path.read_text(encoding="utf-8")  # verbatim, for a byte-exact export
            extra = replace(extra, tree_file=kept)
            for included in included_files(path, allowed_roots=[path.parent]):
                rel = Path(os.path.relpath(included, path.parent)).as_posix()
                if rel not in includes:
                    includes.append(rel)
                    files[f"{HUNAV_FOLDER}/{rel}"] = included.read_text(encoding="utf-8")
        else:
            document = regular_nav_tree()
        trees[spec.tree] = document
        xml = write_tree(document)  # the bytes the bundle will hold: what the digest is of
        labels = grove.get("agents", {}).get(str(spec.id), {}) if isinstance(grove.get("agents"), dict) else {}
        agents.append(replace(spec, hunav=replace(extra, tree_digest=tree_digest(xml)),
                              label=str(labels.get("label", spec.label)), zone=str(labels.get("zone", ""))))
        points += [spec.start, *spec.goals]

    world_ref, world_text, world_obj = _world(world, map_name, grove, points, source)
    agents = [a if a.zone else replace(a, zone=getattr(world_obj.zone_at(*a.start), "name", "")) for a in agents]
    hunav = HunavSource(layout=layout, file=source.name, agents=tuple(params.get("agents") or []),
                        behavior_type="number" if numbered else "name",
                        base_name=params.get("yaml_base_name"), simulator=params.get("simulator"),
                        map=params.get("map"), publish_people=params.get("publish_people"), keys=tuple(params),
                        grove_comment=bool(grove), includes=tuple(includes))
    scenario = Scenario(world=world_ref, preset=str(grove.get("preset", "normal")),
                        prompt=str(grove.get("prompt", f"imported from HuNavSim {source.name}")),
                        seed=int(grove.get("seed", 0)), models={}, agents=tuple(sorted(agents, key=lambda a: a.id)),
                        robot=_robot(grove.get("robot"), source), global_goals=global_goals, hunav=hunav,
                        resolution=float(grove.get("resolution", 0.1)))
    try:  # the checks `simulate` makes when it reads the bundle back: what is written, loads
        scenario = Scenario.from_dict(yaml.safe_load(scenario.dump_yaml()), f"{source} (as a bundle)")
        grid = build_grid(world_obj, scenario.resolution, scenario.grid_inflation)
    except GroveError as exc:
        raise HunavImportError(str(exc)) from None
    notes = [f"imported from {source} (HuNavSim {layout} layout, map {map_name!r}, {len(agents)} agents)"]
    ignored = ignored_keys({"hunav_loader": {"ros__parameters": params}})
    if ignored:
        notes.append("HuNavSim's loader never reads " + ", ".join(ignored[:SHOWN_PROBLEMS])
                     + (f" and {len(ignored) - SHOWN_PROBLEMS} more" if len(ignored) > SHOWN_PROBLEMS else "")
                     + ": not kept")
    report = {"stages": {}, "notes": notes}
    if world_text is not None:
        files[world_ref] = world_text  # written in the same atomic step as the trees
    return GenerationResult(scenario, trees, {}, grid, report, files=files)
