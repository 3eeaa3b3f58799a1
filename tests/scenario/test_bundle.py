"""Bundles: written atomically, loaded back exactly, simulated identically."""

from __future__ import annotations

import filecmp

import numpy as np
import pytest

from grove_tui.scenario.bundle import BundleError, load_bundle, load_report, write_bundle
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.simulation.simulation import Simulation
from helpers.clinic import QUEUE, make_result


def test_bundle_round_trips(clinic, tmp_path):
    result = make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                         [DraftGroup("patients", 6, "lobby", QUEUE)])
    out = write_bundle(result, tmp_path / "b")
    assert sorted(p.name for p in out.iterdir()) == ["generation.json", "grid.npz", "scenario.yaml", "trees"]
    scenario, trees, fields, grid = load_bundle(out)
    assert scenario == result.scenario
    assert trees == result.trees
    assert fields == {}
    assert np.array_equal(grid.occupied, result.grid.occupied) and grid.origin == result.grid.origin
    assert load_report(out)["notes"] == result.report["notes"]


def test_emergency_bundle_keeps_its_fields(clinic, tmp_path):
    result = make_result(clinic, "emergency", "Eight people in the cafeteria evacuate",
                         [DraftGroup("people", 8, "cafeteria", DraftNode("FollowVelocityField", {"exit": "back_exit"}))])
    out = write_bundle(result, tmp_path / "e")
    scenario, _, fields, _ = load_bundle(out)
    assert scenario.fields == {"group_1": "fields/group_1.npz"}
    assert np.array_equal(fields["group_1"].vectors, result.fields["group_1"].vectors)


def test_a_bundle_simulates_identically_twice(clinic, tmp_path):
    result = make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                         [DraftGroup("patients", 6, "lobby", QUEUE)])
    out = write_bundle(result, tmp_path / "s")
    runs = []
    for _ in range(2):
        scenario, *_ = load_bundle(out)
        sim = Simulation.from_scenario(scenario, out, world=clinic)
        sim.run(10.0)
        runs.append(sim.recorder.to_array())
    assert np.array_equal(runs[0], runs[1]) and len(runs[0]) > 0


def test_failed_write_leaves_no_partial_bundle_and_keeps_the_old_one(clinic, tmp_path):
    good = make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                       [DraftGroup("patients", 6, "lobby", QUEUE)])
    out = write_bundle(good, tmp_path / "b")
    before = (out / "scenario.yaml").read_text()
    broken = make_result(clinic, "emergency", "Eight people in the cafeteria evacuate",
                         [DraftGroup("people", 8, "cafeteria", DraftNode("FollowVelocityField", {"exit": "back_exit"}))])
    broken.fields.clear()  # the scenario names a field the result does not carry: writing it fails midway
    with pytest.raises(KeyError):
        write_bundle(broken, out)
    assert (out / "scenario.yaml").read_text() == before
    assert [p.name for p in tmp_path.iterdir()] == ["b"]  # no staging directory left behind
    with pytest.raises(KeyError):
        write_bundle(broken, tmp_path / "new")
    assert not (tmp_path / "new").exists()


def test_same_inputs_same_bundle_bytes(clinic, tmp_path):
    args = ("queuing", "Six patients in the lobby queue at the pharmacy counter", [DraftGroup("patients", 6, "lobby", QUEUE)])
    a = write_bundle(make_result(clinic, *args, seed=5), tmp_path / "a")
    b = write_bundle(make_result(clinic, *args, seed=5), tmp_path / "b")
    assert (a / "scenario.yaml").read_bytes() == (b / "scenario.yaml").read_bytes()
    cmp = filecmp.dircmp(a / "trees", b / "trees")
    assert not cmp.diff_files and not cmp.left_only and not cmp.right_only


def test_loading_a_broken_bundle_names_the_problem(clinic, tmp_path):
    with pytest.raises(BundleError, match="no such bundle directory"):
        load_bundle(tmp_path / "nothing")
    result = make_result(clinic, "queuing", "Six patients in the lobby queue at the pharmacy counter",
                         [DraftGroup("patients", 6, "lobby", QUEUE)])
    out = write_bundle(result, tmp_path / "b")
    (out / "trees" / "agent_3.xml").unlink()
    with pytest.raises(BundleError, match="agent 3's tree trees/agent_3.xml is missing"):
        load_bundle(out)
    (out / "scenario.yaml").write_text("agents: [")
    with pytest.raises(BundleError, match="not valid YAML"):
        load_bundle(out)
