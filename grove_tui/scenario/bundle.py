"""Scenario bundles: one directory per generated scenario, written atomically, loaded back exactly.

    scenario.yaml      the Scenario (world, preset, prompt, seed, models, agents, robot, fields)
    trees/*.xml        one BehaviorTree.CPP v4 file per agent
    fields/*.npz       velocity fields (emergency preset)
    grid.npz           the occupancy grid planning used
    generation.json    per-stage seconds and tokens, selected RoIs, retrieved nodes, the draft, the
                       planned grounding report
    after a run: trajectories.csv, events.jsonl, metrics.json, grounding.json (the report checked on the run)
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Mapping
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any, Protocol

from grove_tui.bt.format.document import TreeDocument, TreeFiles
from grove_tui.bt.format.xml import read_tree, write_tree
from grove_tui.jsontypes import JSONMapping
from grove_tui.files import (absolute_path, atomic_directory, link_or_copy, protect_folders, relative_file,
                             write_files_atomic)
from grove_tui.errors import BundleError, GroveError
from grove_tui.limits import InputLimitError, check_regular_file, read_text_bounded
from grove_tui.navigation.grid import MAX_GRID_FILE_BYTES, OccupancyGrid
from grove_tui.scenario.model import Scenario, ScenarioError
from grove_tui.navigation.velocity_field import MAX_FIELD_UNPACKED_BYTES, VelocityField

if TYPE_CHECKING:
    from grove_tui.world.model import World

SCENARIO_FILE = "scenario.yaml"
GRID_FILE = "grid.npz"
REPORT_FILE = "generation.json"
# What a simulation adds to a bundle; replaced together, never one without the others.
RUN_FILES = ("trajectories.csv", "events.jsonl", "metrics.json", "grounding.json")
# trajectories.csv is read a block at a time, so its size costs time, not memory: a 500-person hour is
# about 2 GB. The bound refuses what no run writes, such as a link to a huge unrelated file.
MAX_TRAJECTORY_BYTES = 64 * 1024**3
# What a recorded Gym episode adds (gym.recording): the policy's commands, enough to replay them.
EPISODE_FILE = "episode.json"
# Where a bundle keeps a world file of its own (an imported HuNavSim scenario's open floor).
WORLD_FOLDER = "world"
# Where an imported bundle keeps HuNavSim's tree files (and what they include), verbatim.
HUNAV_FOLDER = "hunav"
# Every name a bundle's own writers use: no other output may take one (`--out BUNDLE/trees`, an
# imported world called scenario.yaml). episode.json is a recorded Gym episode's.
OWN_NAMES = (SCENARIO_FILE, "trees", "fields", GRID_FILE, REPORT_FILE, *RUN_FILES, EPISODE_FILE, WORLD_FOLDER,
             HUNAV_FOLDER)
# Files at fixed places: a tree, field or world file named like one of them would overwrite it.
FIXED_FILES = frozenset({SCENARIO_FILE, GRID_FILE, REPORT_FILE, *RUN_FILES, EPISODE_FILE})
WHAT = "scenario bundle"


def is_bundle(path: Path) -> bool:
    """A folder GROVE wrote as a bundle (the only kind of folder `--out` replaces without asking)."""
    return (path / SCENARIO_FILE).is_file() and not (path / SCENARIO_FILE).is_symlink()


protect_folders(is_bundle, OWN_NAMES, WHAT)


class BundleContents(Protocol):
    """What a bundle is written from: generation's GenerationResult (scenario is below generation, so it
    names the result by what it holds)."""

    @property
    def scenario(self) -> Scenario: ...

    @property
    def trees(self) -> Mapping[str, TreeDocument]: ...  # bundle-relative path ("trees/agent_1.xml") -> tree

    @property
    def files(self) -> Mapping[str, str]: ...  # other text files, written verbatim: relative path -> text

    @property
    def fields(self) -> Mapping[str, VelocityField]: ...

    @property
    def grid(self) -> OccupancyGrid: ...

    @property
    def report(self) -> JSONMapping: ...  # generation.json: JSON, written as it is


def tree_texts(trees: Mapping[str, TreeDocument]) -> dict[str, str]:
    """The trees as the files a bundle holds: relative path -> BT.CPP v4 XML (the codec's one writer)."""
    return {rel: write_tree(document) for rel, document in trees.items()}


def _member_files(result: BundleContents) -> list[tuple[PurePosixPath, str]]:
    """The trees (written as XML here, where their bytes are) and any other text files of a
    GenerationResult, each checked to be a plain relative path that names none of the bundle's fixed files."""
    texts = {**result.files, **tree_texts(result.trees)}
    checked = []
    for rel, text in sorted(texts.items()):
        try:
            path = relative_file(rel)
        except GroveError as exc:
            raise BundleError(f"a bundle file {exc}") from None
        if str(path) in FIXED_FILES or path.parts[0] in FIXED_FILES:
            raise BundleError(f"a bundle file named {rel!r} would replace the bundle's own {path.parts[0]}")
        checked.append((path, text))
    return checked


def write_bundle(result: BundleContents, out_dir: str | Path, overwrite: bool = False) -> Path:
    """Write a GenerationResult as a bundle; a reader sees the old bundle or the complete new one.

    An existing bundle at `out_dir` is replaced; any other non-empty folder only with `overwrite`.
    """
    scenario = result.scenario
    members = _member_files(result)
    # Absolute first: after `--out .` the process's own folder is replaced, so "." names the old one.
    target = absolute_path(out_dir)
    with atomic_directory(target, owned=is_bundle, what=WHAT, overwrite=overwrite) as stage:
        (stage / SCENARIO_FILE).write_text(scenario.dump_yaml(), encoding="utf-8")
        for member_path, xml in members:
            member = stage.joinpath(*member_path.parts)
            member.parent.mkdir(parents=True, exist_ok=True)
            member.write_text(xml, encoding="utf-8")
        for field_id, rel in sorted(scenario.fields.items()):
            result.fields[field_id].save(stage / rel)
        result.grid.save(stage / GRID_FILE)
        (stage / REPORT_FILE).write_text(json.dumps(result.report, indent=2, sort_keys=False) + "\n", encoding="utf-8")
    return target


def write_bundle_files(files: Mapping[str, bytes], out_dir: str | Path, overwrite: bool = False) -> Path:
    """Write a bundle given as its files' bytes (relative path -> bytes), with `write_bundle`'s guarantees.

    How a Ray batch's driver writes the bundle a worker without its file system generated and sent back.
    """
    if SCENARIO_FILE not in files:
        raise BundleError(f"{out_dir}: the files sent as a bundle have no {SCENARIO_FILE}")
    return write_files_atomic(absolute_path(out_dir), files, owned=is_bundle, what=WHAT, overwrite=overwrite)


def derive_bundle(source: str | Path, out_dir: str | os.PathLike[str], scenario: Scenario, *,
                  keep: Callable[[PurePosixPath], bool], trees: Mapping[str, TreeDocument] | None = None,
                  write: Callable[[Path], None] | None = None, overwrite: bool = False) -> Path:
    """Write a bundle made from another one, with `write_bundle`'s guarantees (atomic, guarded).

    The source's regular files (never a link) whose relative path `keep` accepts are hard-linked (or
    copied); then `scenario` becomes scenario.yaml, `trees` (relative path -> document) are written over
    them, and `write(stage)` writes the rest (a run's files). How an evaluation baseline rewrites
    GROVE's trees, and how a Gym episode becomes a bundle.
    """
    root = Path(source)
    members = [(relative_file(rel), text) for rel, text in sorted(tree_texts(trees or {}).items())]
    # Never link what is written next: writing into a hard link would change the source bundle too.
    written = {SCENARIO_FILE, *RUN_FILES, *(str(rel) for rel, _text in members)}
    target = absolute_path(out_dir)
    with atomic_directory(target, owned=is_bundle, what=WHAT, overwrite=overwrite) as stage:
        for path in sorted(root.rglob("*")):
            rel = PurePosixPath(path.relative_to(root).as_posix())
            if str(rel) in written or path.is_symlink() or not path.is_file() or not keep(rel):
                continue
            link_or_copy(path, stage / rel)
        for member_path, text in members:
            member = stage.joinpath(*member_path.parts)
            member.parent.mkdir(parents=True, exist_ok=True)
            member.write_text(text, encoding="utf-8")
        (stage / SCENARIO_FILE).write_text(scenario.dump_yaml(), encoding="utf-8")
        if write is not None:
            write(stage)
    return target


def replace_run_outputs(bundle_dir: str | Path, write: Callable[[Path], None]) -> Path:
    """Give a bundle new simulation outputs in one atomic step.

    The bundle is staged as hard links (cheap), its old run files left out; `write(stage)` writes the
    new ones; then the staged bundle takes the old one's place in a rename. Interrupted anywhere, the
    bundle keeps all its old outputs or gets all the new ones, never a mix.
    """
    root = Path(bundle_dir)
    if not is_bundle(root):
        raise BundleError(f"{root}: not a bundle ({SCENARIO_FILE} is missing)")
    with atomic_directory(root, owned=is_bundle, what=WHAT) as stage:
        for path in sorted(root.rglob("*")):
            rel = path.relative_to(root)
            if str(rel) in RUN_FILES or path.is_symlink() or not path.is_file():
                continue
            link_or_copy(path, stage / rel)
        write(stage)
    return root


# A behavior tree of one agent is a few kB; anything this large is not one.
MAX_TREE_BYTES = 4 * 1024 * 1024


def bundle_member(bundle_dir: str | Path, rel: str, what: str, max_bytes: int = MAX_TREE_BYTES) -> Path:
    """The file `rel` of a bundle, checked before anything reads it: it must stay inside the bundle
    (after following links), be a regular file (not /dev/zero, not a pipe) and be at most `max_bytes`.
    """
    root = Path(bundle_dir)
    real_root = os.path.realpath(root)
    real_path = os.path.realpath(root / rel)
    if os.path.commonpath([real_root, real_path]) != real_root or real_path == real_root:
        raise BundleError(f"{root}: {what} {rel} points outside the bundle folder")
    try:
        check_regular_file(real_path, max_bytes, what)
    except InputLimitError as exc:
        missing = not os.path.lexists(root / rel)
        raise BundleError(f"{root}: {what} {rel} is missing" if missing else f"{root}: {exc}") from None
    return root / rel


def read_bundle_text(bundle_dir: str | Path, rel: str, what: str, max_bytes: int = MAX_TREE_BYTES) -> str:
    path = bundle_member(bundle_dir, rel, what, max_bytes)
    try:
        return read_text_bounded(path, max_bytes, what)
    except InputLimitError as exc:
        raise BundleError(f"{bundle_dir}: {exc}") from None


def load_scenario(bundle_dir: str | Path) -> Scenario:
    """The bundle's Scenario; a missing or broken scenario.yaml is a BundleError naming it."""
    root = Path(bundle_dir)
    if not root.is_dir():
        raise BundleError(f"{root}: no such bundle directory")
    try:
        return Scenario.load(root / SCENARIO_FILE)
    except ScenarioError as exc:
        raise BundleError(str(exc)) from None


def load_field(bundle_dir: str | Path, field_id: str, rel: str) -> VelocityField:
    path = bundle_member(bundle_dir, rel, f"velocity field {field_id}", MAX_FIELD_UNPACKED_BYTES)
    try:
        return VelocityField.load(path)
    except GroveError as exc:
        raise BundleError(str(exc)) from None


def load_grid(bundle_dir: str | Path) -> OccupancyGrid:
    path = bundle_member(bundle_dir, GRID_FILE, "occupancy grid", MAX_GRID_FILE_BYTES)
    try:
        return OccupancyGrid.load(path)
    except GroveError as exc:
        raise BundleError(str(exc)) from None


def load_trees(bundle_dir: str | Path, scenario: Scenario) -> TreeFiles:
    """The agents' trees of a bundle by relative path, each file read (bounded, inside the bundle) and parsed
    once, here: BundleError for a file that is missing or too large, BTError (file and line) for one that
    is not a behavior tree."""
    root = Path(bundle_dir)
    trees: TreeFiles = {}
    for agent in scenario.agents:
        if agent.tree not in trees:
            text = read_bundle_text(root, agent.tree, f"agent {agent.id}'s tree")
            trees[agent.tree] = read_tree(text, str(root / agent.tree))
    return trees


def load_bundle(bundle_dir: str | Path) -> tuple[Scenario, TreeFiles, dict[str, VelocityField], OccupancyGrid]:
    """(Scenario, trees by relative path, fields by id, grid) of a bundle directory."""
    root = Path(bundle_dir)
    scenario = load_scenario(root)
    trees = load_trees(root, scenario)
    fields = {field_id: load_field(root, field_id, rel) for field_id, rel in scenario.fields.items()}
    return scenario, trees, fields, load_grid(root)


def world_source(bundle_dir: str | Path, scenario: Scenario) -> str | Path:
    """What `load_world` takes for a bundle's world: a shipped name, the absolute path of the user's
    world file (what generation records), or a world file inside the bundle (an imported HuNavSim
    scenario's open floor). A relative path is always the bundle's own file, never one in the
    current folder, and it must stay inside the bundle and be a bounded regular file."""
    from grove_tui.world.loader import MAX_WORLD_FILE_BYTES

    reference = scenario.world
    relative = not os.path.isabs(reference) and ("/" in reference or reference.endswith((".yaml", ".yml")))
    if relative:
        return bundle_member(bundle_dir, reference, "world file", MAX_WORLD_FILE_BYTES)
    return reference


def load_bundle_world(bundle_dir: str | Path, scenario: Scenario) -> World:
    """The World a bundle plays in (see `world_source`)."""
    from grove_tui.world import load_world

    return load_world(world_source(bundle_dir, scenario))


def load_report(bundle_dir: str | Path) -> dict[str, Any]:  # Any: generation.json as parsed, read key by key by its users
    path = Path(bundle_dir) / REPORT_FILE
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise BundleError(f"{path}: missing") from None
    except json.JSONDecodeError as exc:
        raise BundleError(f"{path}: not valid JSON: {exc}") from None
