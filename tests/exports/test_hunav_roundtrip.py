"""Issue 30, lossless round trips.

HuNavSim -> GROVE -> HuNavSim over HuNavSim's own shipped scenarios (house and warehouse, in the 1.0
and the 2.0 layout, tests/data/hunavsim/): every parameter HuNavSim's loader reads comes back with the
same value (field by field, exact doubles), in the same place, in the same layout; 2.0's tree files
come back byte for byte. GROVE -> HuNavSim -> GROVE over hand-built bundles keeps the prompt, the robot
and every agent field, and a second export equals the first. (Generated bundles: test_pipeline_e2e.py.)
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
import yaml
from helpers.handmade import build_evacuation_bundle, build_hospital_bundle
from helpers.paths import REPO

from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.hunav_import import import_hunav
from grove_tui.exports.hunav_loader_check import check_hunav_export, ignored_keys, loader_parameters
from grove_tui.scenario.model import Scenario
from grove_tui.simulation.simulation import Simulation

pytest.importorskip("behaviortreepy")

DATA = REPO / "tests" / "data" / "hunavsim"
SHIPPED = {
    "1.0-house": DATA / "1.0" / "agents_house.yaml",
    "1.0-warehouse": DATA / "1.0" / "agents_warehouse.yaml",
    "2.0-house": DATA / "2.0" / "scenarios" / "agents_house.yaml",
    "2.0-warehouse": DATA / "2.0" / "scenarios" / "agents_warehouse.yaml",
}


def _document(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def _leaves(mapping: dict, prefix: str = "") -> list[str]:
    out = []
    for key, value in mapping.items():
        out += _leaves(value, f"{prefix}{key}.") if isinstance(value, dict) else [f"{prefix}{key}"]
    return out


def _without(document: dict, dotted_keys: list[str]) -> dict:
    import copy

    document = copy.deepcopy(document)
    for dotted in dotted_keys:
        *parents, last = dotted.split(".")
        node = document["hunav_loader"]["ros__parameters"]
        for part in parents:
            node = node[part]
        del node[last]
    return document


def field_differences(original: dict, exported: dict) -> list[str]:
    """Every loader parameter whose value differs, as `name: before -> after` (empty: none)."""
    before, after = loader_parameters(original), loader_parameters(exported)
    return [f"{key}: {before.get(key)!r} -> {after.get(key)!r}" for key in sorted(set(before) | set(after))
            if before.get(key) != after.get(key) or type(before.get(key)) is not type(after.get(key))]


@pytest.fixture(scope="module", params=list(SHIPPED))
def shipped_round_trip(request, tmp_path_factory):
    source = SHIPPED[request.param]
    folder = tmp_path_factory.mktemp(request.param)
    bundle = import_hunav(source, folder / "bundle")
    export = export_hunav(bundle, folder / "hunav")
    return request.param, source, bundle, export


def test_every_parameter_the_loader_reads_comes_back_field_by_field(shipped_round_trip):
    name, source, bundle, export = shipped_round_trip
    original, exported = _document(source), _document(export.agents_yaml)
    assert field_differences(original, exported) == [], name
    # Not only what the loader reads: the whole file, less keys the loader never reads (the
    # warehouse 1.0 file's `worker4.g3.H`, a typo for `h`), parses to the same document...
    ignored = ignored_keys(original)
    assert ignored == (["worker4.g3.H"] if name == "1.0-warehouse" else [])
    notes = json.loads((bundle / "generation.json").read_text())["notes"]
    assert any("never reads worker4.g3.H" in note for note in notes) == bool(ignored)
    assert _without(original, ignored) == exported
    # ...with every key in its place: the same order, top level and agent by agent
    stripped = _without(original, ignored)["hunav_loader"]["ros__parameters"]
    again = exported["hunav_loader"]["ros__parameters"]
    assert list(stripped) == list(again)
    for agent in stripped["agents"]:
        assert _leaves(stripped[agent]) == _leaves(again[agent]), agent


def test_the_layout_and_the_trees_come_back_as_they_were(shipped_round_trip):
    name, source, _bundle, export = shipped_round_trip
    layout = name.split("-")[0]
    assert export.layout == layout
    assert check_hunav_export(export.agents_yaml) == []
    if layout == "1.0":
        assert export.trees == ()  # HuNavSim 1.0 runs its own tree per behavior
        return
    trees = sorted((source.parent.parent / "behavior_trees").glob(f"{source.stem}__agent_*_bt.xml"))
    assert [p.name for p in export.trees] == [p.name for p in trees] and trees
    for theirs, ours in zip(trees, export.trees):
        assert ours.read_bytes() == theirs.read_bytes(), theirs.name
    # what they <include> comes along, verbatim, beside them (BT.CPP reads it relative to the tree)
    included = theirs.parent / "BTRegularNav.xml"
    assert (export.directory / included.name).read_bytes() == included.read_bytes()


def test_the_fields_the_issue_names_survive_the_house(tmp_path):
    """configuration 2 and 1, force factors 8.6/5.6 and 1.0/6.0/0.0, cyclic goals, goal radius 0.3,
    skins, init_pose.h and goal precision (3.360, not rounded) of HuNavSim 2.0's house."""
    bundle = import_hunav(SHIPPED["2.0-house"], tmp_path / "bundle")
    params = _document(export_hunav(bundle, tmp_path / "hunav").agents_yaml)["hunav_loader"]["ros__parameters"]
    one, three = params["agent1"], params["agent3"]
    assert one["behavior"]["configuration"] == 2 and three["behavior"]["configuration"] == 1
    assert (one["behavior"]["obstacle_force_factor"], one["behavior"]["social_force_factor"]) == (8.6, 5.6)
    assert [three["behavior"][k] for k in ("obstacle_force_factor", "social_force_factor", "other_force_factor")] \
        == [1.0, 6.0, 0.0]
    assert all(params[a]["cyclic_goals"] is True and params[a]["goal_radius"] == 0.3 for a in params["agents"])
    assert [params[a]["skin"] for a in params["agents"]] == [3, 0, 2]
    assert one["init_pose"]["h"] == 2.415 and one["init_pose"]["z"] == 1.25
    assert params["global_goals"][1] == {"x": 3.36, "y": 0.964} and params["global_goals"][4]["x"] == -7.761


@pytest.mark.parametrize("name", list(SHIPPED))
def test_an_imported_shipped_scenario_plays_in_grove_as_hunavsim_would(name, tmp_path):
    bundle = import_hunav(SHIPPED[name], tmp_path / "bundle")
    scenario = Scenario.load(bundle / "scenario.yaml")
    params = _document(SHIPPED[name])["hunav_loader"]["ros__parameters"]
    first = params[params["agents"][0]]
    agent = scenario.agents[0]
    # GROVE's own fields carry what HuNavSim's loader reads
    assert (agent.goal_radius, agent.cyclic_goals, agent.heading) == (first["goal_radius"], first["cyclic_goals"],
                                                                      first["init_pose"]["h"])
    sim = Simulation.from_scenario(scenario, bundle)
    assert sim.crowd.goal_radius[0] == first["goal_radius"] and sim.crowd.yaw[0] == first["init_pose"]["h"]
    sim.run(15.0)
    assert sim.tree_errors == {}
    moved = [abs(sim.crowd.pos[i][0] - a.start[0]) + abs(sim.crowd.pos[i][1] - a.start[1])
             for i, a in enumerate(scenario.agents)]
    assert max(moved) > 2.0


BUNDLES = {"hospital": build_hospital_bundle, "evacuation": build_evacuation_bundle}


@pytest.fixture(scope="module", params=list(BUNDLES))
def grove_round_trip(request, tmp_path_factory):
    folder = tmp_path_factory.mktemp(request.param)
    bundle = BUNDLES[request.param](folder / "bundle")
    first = export_hunav(bundle, folder / "first")
    back = import_hunav(first.agents_yaml, folder / "back")
    second = export_hunav(back, folder / "second")
    return bundle, first, back, second


def test_grove_to_hunavsim_to_grove_keeps_the_prompt_the_robot_and_every_agent(grove_round_trip):
    bundle, _first, back, _second = grove_round_trip
    original, imported = Scenario.load(bundle / "scenario.yaml"), Scenario.load(back / "scenario.yaml")
    assert (imported.prompt, imported.preset, imported.seed, imported.world, imported.resolution) == \
        (original.prompt, original.preset, original.seed, original.world, original.resolution)
    assert imported.robot == original.robot and original.robot is not None
    assert len(imported.agents) == len(original.agents)
    for theirs, mine in zip(original.agents, imported.agents):
        keep = ("id", "group", "start", "goals", "radius", "max_vel", "behavior", "label", "zone", "goal_radius",
                "cyclic_goals")
        assert {k: getattr(mine, k) for k in keep} == {k: getattr(theirs, k) for k in keep}, theirs.id
        assert mine.initial_heading() == theirs.initial_heading()


def test_a_second_export_is_the_first_field_by_field_and_tree_by_tree(grove_round_trip):
    _bundle, first, _back, second = grove_round_trip
    assert field_differences(_document(first.agents_yaml), _document(second.agents_yaml)) == []
    assert _document(first.agents_yaml) == _document(second.agents_yaml)
    assert first.agents_yaml.read_text() == second.agents_yaml.read_text()  # GROVE's line included
    assert [p.name for p in second.trees] == [p.name for p in first.trees]
    for a, b in zip(first.trees, second.trees):
        assert a.read_bytes() == b.read_bytes(), a.name


def test_an_edited_imported_tree_is_exported_from_grove_not_copied(tmp_path):
    bundle = import_hunav(SHIPPED["2.0-house"], tmp_path / "bundle")
    tree = bundle / "trees" / "agent_2.xml"
    tree.write_text(tree.read_text().replace('name="MainFallback"', 'name="edited"'))
    export = export_hunav(bundle, tmp_path / "hunav")
    source = DATA / "2.0" / "behavior_trees" / "agents_house__agent_2_bt.xml"
    assert (export.directory / source.name).read_bytes() != source.read_bytes()
    assert 'name="edited"' in (export.directory / source.name).read_text()
    assert (export.directory / "agents_house__agent_1_bt.xml").read_bytes() == \
        (source.parent / "agents_house__agent_1_bt.xml").read_bytes()
    # a 1.0 scenario whose tree was edited needs tree files: the export switches to the 2.0 layout
    old = import_hunav(SHIPPED["1.0-house"], tmp_path / "old")
    edited = old / "trees" / "agent_1.xml"
    edited.write_text(edited.read_text().replace('name="RegularNavFallback"', 'name="edited"'))
    export = export_hunav(old, tmp_path / "old_hunav")
    assert export.layout == "2.0" and len(export.trees) == 5
    assert check_hunav_export(export.agents_yaml) == []
    params = _document(export.agents_yaml)["hunav_loader"]["ros__parameters"]
    original = _document(SHIPPED["1.0-house"])["hunav_loader"]["ros__parameters"]
    assert params["agents"] == original["agents"]  # agent7 keeps its name (id 3)
    assert params["agent7"]["behavior"]["configuration"] == 1 and params["agent7"]["skin"] == 3
    goals = params["global_goals"]
    assert [(goals[g]["x"], goals[g]["y"]) for g in params["agent2"]["goals"]] == [
        (original["agent2"][g]["x"], original["agent2"][g]["y"]) for g in original["agent2"]["goals"]]


def test_a_generated_scenario_edited_in_grove_exports_the_edit(tmp_path):
    """The imported file is a record, not a mask: a value changed in GROVE is what the export says."""
    bundle = import_hunav(SHIPPED["2.0-warehouse"], tmp_path / "bundle")
    scenario = Scenario.load(bundle / "scenario.yaml")
    first = dataclasses.replace(scenario.agents[0], max_vel=1.2, goal_radius=0.5)
    dataclasses.replace(scenario, agents=(first, *scenario.agents[1:])).save(bundle / "scenario.yaml")
    params = _document(export_hunav(bundle, tmp_path / "hunav").agents_yaml)["hunav_loader"]["ros__parameters"]
    assert (params["agent1"]["max_vel"], params["agent1"]["goal_radius"]) == (1.2, 0.5)
    assert params["agent2"]["max_vel"] == 2.0
