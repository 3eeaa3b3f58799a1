"""Broken and hostile bundles: every command that reads one says what is wrong in one line, exits 2
and leaves the files as they were."""

from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.scenario.bundle import load_bundle
from grove_tui.scenario.model import Scenario, ScenarioError

# The `simulated` fixture's run (tests/conftest.py): metrics and exports need trajectories to read.
SIMULATED_SECONDS = 2.0
COMMANDS = {
    "metrics": lambda b, tmp: ["metrics", str(b)],
    "export hunav": lambda b, tmp: ["export", "hunav", str(b), "--out", str(tmp / "hunav_out")],
    "export trajectories": lambda b, tmp: ["export", "trajectories", str(b), "--out", str(tmp / "traj_out")],
    "picture": lambda b, tmp: ["picture", str(b), "--out", str(tmp / "picture.png")],
    "simulate": lambda b, tmp: ["simulate", str(b), "--seconds", "1"],
}


def snapshot(root: Path) -> dict[str, str]:
    """Every entry under root: file digests, link targets; so 'unchanged' is checked exactly."""
    state = {}
    for path in sorted(root.rglob("*")):
        rel = str(path.relative_to(root))
        if path.is_symlink():
            state[rel] = "-> " + os.readlink(path)
        elif path.is_file():
            state[rel] = hashlib.sha256(path.read_bytes()).hexdigest()
        else:
            state[rel] = "dir"
    return state


def edit_scenario(simulated_copy: Path, change) -> None:
    path = simulated_copy / "scenario.yaml"
    data = yaml.safe_load(path.read_text())
    change(data)
    path.write_text(yaml.safe_dump(data, sort_keys=False))


def run_all(simulated_copy: Path, tmp_path: Path, expected: str, commands=tuple(COMMANDS)) -> None:
    before = snapshot(tmp_path)
    for name in commands:
        result = CliRunner().invoke(main, COMMANDS[name](simulated_copy, tmp_path))
        assert result.exit_code == 2, f"{name}: exit {result.exit_code}\n{result.output}\n{result.exception!r}"
        assert not isinstance(result.exception, Exception) or isinstance(result.exception, SystemExit), name
        message = result.output.strip()
        assert expected in message, f"{name}: {message}"
        assert len(message.splitlines()) == 1, f"{name}: not one line: {message}"
        assert "Traceback" not in message
        assert snapshot(tmp_path) == before, f"{name} changed the file system"


def test_missing_scenario_yaml(simulated_copy, tmp_path):
    (simulated_copy / "scenario.yaml").unlink()
    run_all(simulated_copy, tmp_path, "no such scenario file")


def test_broken_scenario_yaml(simulated_copy, tmp_path):
    (simulated_copy / "scenario.yaml").write_text("world: [unclosed\n")
    run_all(simulated_copy, tmp_path, "not valid YAML")


def test_scenario_yaml_alias_bomb(simulated_copy, tmp_path):
    levels = "a: &a [x,x,x,x,x,x,x,x,x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [" + ",".join(["*" + chr(97 + i)] * 9) + "]\n" for i in range(8))
    (simulated_copy / "scenario.yaml").write_text(levels + "agents: *i\n")
    run_all(simulated_copy, tmp_path, "expands to more than")


@pytest.mark.parametrize("key, value, expected", [
    ("seed", -1, "seed: -1 is out of range 0..4294967295"),
    ("seed", "abc", "seed: expected a whole number"),
    ("resolution", 0, "resolution: 0 is out of range"),
])
def test_bad_scenario_values(simulated_copy, tmp_path, key, value, expected):
    edit_scenario(simulated_copy, lambda data: data.__setitem__(key, value))
    run_all(simulated_copy, tmp_path, expected)


@pytest.mark.parametrize("field, value, expected", [
    ("id", 1, "id 1 is used by another agent"),
    ("radius", 1e6, "radius: 1000000.0 is out of range 0.05..2"),
    ("max_vel", 1e308, "max_vel: 1e+308 is out of range 0..10"),
    ("behavior", "Berserk", "'Berserk' is not a HuNavSim behavior"),
    ("tree", "../../outside.xml", "must be a relative path inside the bundle"),
    ("tree", "/etc/passwd", "must be a relative path inside the bundle"),
    ("start", [float("nan"), 1.0], "start: nan is out of range"),
])
def test_silently_accepted_agents_are_refused(simulated_copy, tmp_path, field, value, expected):
    def change(data):
        for agent in data["agents"]:
            agent[field] = value
    edit_scenario(simulated_copy, change)
    run_all(simulated_copy, tmp_path, expected)


def test_tree_linked_to_a_device_is_refused(simulated_copy, tmp_path):
    tree = simulated_copy / "trees" / "agent_1.xml"
    tree.unlink()
    tree.symlink_to("/dev/zero")
    run_all(simulated_copy, tmp_path, "points outside the bundle folder", commands=("export hunav", "simulate"))


def test_tree_that_is_a_pipe_inside_the_bundle_is_refused_without_blocking(simulated_copy, tmp_path):
    tree = simulated_copy / "trees" / "agent_1.xml"
    tree.unlink()
    os.mkfifo(tree)
    run_all(simulated_copy, tmp_path, "is a pipe, not a file", commands=("export hunav", "simulate"))


def test_tree_linked_outside_the_bundle_is_refused(simulated_copy, tmp_path):
    outside = tmp_path / "elsewhere.xml"
    shutil.copy(simulated_copy / "trees" / "agent_1.xml", outside)
    tree = simulated_copy / "trees" / "agent_1.xml"
    tree.unlink()
    tree.symlink_to(outside)
    run_all(simulated_copy, tmp_path, "points outside the bundle folder", commands=("export hunav", "simulate"))


def test_truncated_grid(simulated_copy, tmp_path):
    grid = simulated_copy / "grid.npz"
    grid.write_bytes(grid.read_bytes()[:100])
    run_all(simulated_copy, tmp_path, "not a readable .npz file", commands=("export hunav", "simulate"))


def test_grid_with_zero_resolution(simulated_copy, tmp_path):
    with np.load(simulated_copy / "grid.npz") as data:
        arrays = dict(data)
    arrays["resolution"] = np.float64(0.0)
    np.savez_compressed(simulated_copy / "grid.npz", **arrays)
    run_all(simulated_copy, tmp_path, "resolution must be", commands=("export hunav", "simulate"))


def test_a_good_bundle_still_loads(simulated_copy):
    scenario, trees, fields, grid = load_bundle(simulated_copy)
    assert len(scenario.agents) == 5 and len(trees) == 5 and grid.resolution == 0.1
    # And what the model writes is what it reads back.
    assert Scenario.from_dict(scenario.to_dict()) == scenario


def test_scenario_error_is_a_grove_error():
    from grove_tui.errors import GroveError

    with pytest.raises(GroveError):
        Scenario.from_dict({"world": "hospital"})
    assert ScenarioError("x").exit_code == 2
