"""Scenario bundles: one directory per generated scenario, written atomically, loaded back exactly.

    scenario.yaml      the Scenario (world, preset, prompt, seed, models, agents, robot, fields)
    trees/*.xml        one BehaviorTree.CPP v4 file per agent
    fields/*.npz       velocity fields (emergency preset)
    grid.npz           the occupancy grid planning used
    generation.json    per-stage seconds and tokens, selected RoIs, retrieved nodes, the draft
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from grove_tui.engine.atomic import atomic_directory
from grove_tui.engine.errors import GroveError
from grove_tui.engine.grid import OccupancyGrid
from grove_tui.engine.scenario import Scenario, ScenarioError
from grove_tui.engine.velocity_field import VelocityField

SCENARIO_FILE = "scenario.yaml"
GRID_FILE = "grid.npz"
REPORT_FILE = "generation.json"


class BundleError(GroveError):
    """A bundle directory is missing a file or holds a broken one; the message names it."""


def write_bundle(result: Any, out_dir: str | Path, overwrite: bool = True) -> Path:
    """Write a GenerationResult as a bundle; a reader sees the old bundle or the complete new one."""
    out = Path(out_dir)
    scenario: Scenario = result.scenario
    try:
        with atomic_directory(out, overwrite=overwrite) as stage:
            (stage / SCENARIO_FILE).write_text(scenario.dump_yaml(), encoding="utf-8")
            for rel, xml in sorted(result.trees.items()):
                path = stage / rel
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(xml, encoding="utf-8")
            for field_id, rel in sorted(scenario.fields.items()):
                result.fields[field_id].save(stage / rel)
            result.grid.save(stage / GRID_FILE)
            (stage / REPORT_FILE).write_text(json.dumps(result.report, indent=2, sort_keys=False) + "\n", encoding="utf-8")
    except FileExistsError:
        raise BundleError(f"{out} already exists; choose another --out or allow overwriting") from None
    return out


def load_bundle(bundle_dir: str | Path) -> tuple[Scenario, dict[str, str], dict[str, VelocityField], OccupancyGrid]:
    """(Scenario, trees by relative path, fields by id, grid) of a bundle directory."""
    root = Path(bundle_dir)
    if not root.is_dir():
        raise BundleError(f"{root}: no such bundle directory")
    try:
        scenario = Scenario.load(root / SCENARIO_FILE)
    except ScenarioError as exc:
        raise BundleError(str(exc)) from None
    trees: dict[str, str] = {}
    for agent in scenario.agents:
        path = root / agent.tree
        if not path.is_file():
            raise BundleError(f"{root}: agent {agent.id}'s tree {agent.tree} is missing")
        trees[agent.tree] = path.read_text(encoding="utf-8")
    fields: dict[str, VelocityField] = {}
    for field_id, rel in scenario.fields.items():
        path = root / rel
        if not path.is_file():
            raise BundleError(f"{root}: velocity field {field_id} ({rel}) is missing")
        fields[field_id] = VelocityField.load(path)
    if not (root / GRID_FILE).is_file():
        raise BundleError(f"{root}: {GRID_FILE} is missing")
    grid = OccupancyGrid.load(root / GRID_FILE)
    return scenario, trees, fields, grid


def load_report(bundle_dir: str | Path) -> dict[str, Any]:
    path = Path(bundle_dir) / REPORT_FILE
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise BundleError(f"{path}: missing") from None
    except json.JSONDecodeError as exc:
        raise BundleError(f"{path}: not valid JSON: {exc}") from None
