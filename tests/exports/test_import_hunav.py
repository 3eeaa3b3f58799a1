"""`grove import hunav`: a HuNavSim scenario becomes a bundle that plays in GROVE; export, import and
export again give the same agents, goals and trees."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import HunavImportError
from grove_tui.exports.hunav import export_hunav
from grove_tui.services.session import GroveSession
from grove_tui.scenario.bundle import load_bundle
from grove_tui.scenario.model import Scenario
from grove_tui.simulation.simulation import Simulation

import_hunav = GroveSession().import_hunav  # the services layer writes every bundle

pytest.importorskip("behaviortreepy")


def _params(path):
    return yaml.safe_load(path.read_text())["hunav_loader"]["ros__parameters"]


def test_export_import_export_gives_the_same_agents_goals_and_trees(hospital_export, tmp_path):
    first = hospital_export
    bundle = import_hunav(first.agents_yaml, tmp_path / "imported")
    second = export_hunav(bundle, tmp_path / "again")
    assert _params(second.agents_yaml) == _params(first.agents_yaml)
    assert [p.name for p in second.trees] == [p.name for p in first.trees]
    for a, b in zip(first.trees, second.trees):
        assert a.read_text() == b.read_text(), a.name


def test_imported_bundle_has_the_exported_agents_and_global_goals(bundle, hospital_export, tmp_path):
    original = bundle
    first = hospital_export
    params = _params(first.agents_yaml)
    bundle = import_hunav(first.agents_yaml, tmp_path / "imported")
    scenario, trees, _, _ = load_bundle(bundle)
    source = Scenario.load(original / "scenario.yaml")
    assert [a.id for a in scenario.agents] == [a.id for a in source.agents]
    for mine, theirs in zip(scenario.agents, source.agents):
        assert mine.start == pytest.approx(theirs.start, abs=1e-3)
        assert (mine.group, mine.behavior) == (theirs.group, theirs.behavior)
    goals = {int(k): (v["x"], v["y"]) for k, v in params["global_goals"].items()}
    assert scenario.global_goals == goals
    # the trees are HuNavSim's, verbatim: goal ids resolved by the scenario's global goals
    assert (bundle / "trees/agent_1.xml").read_text() == (first.directory / "agents_hospital__agent_1_bt.xml").read_text()


def test_imported_bundle_plays_in_grove(hospital_export, tmp_path):
    first = hospital_export
    bundle = import_hunav(first.agents_yaml, tmp_path / "imported")
    scenario = Scenario.load(bundle / "scenario.yaml")
    sim = Simulation.from_scenario(scenario, bundle)
    sim.run(20.0)
    assert sim.tree_errors == {}
    moved = [math.dist(sim.crowd.pos[i], a.start) for i, a in enumerate(scenario.agents)]
    assert max(moved) > 2.0
    # the queue leader walks toward its slot by HuNavSim goal ids alone
    assert all(status != "failed" for status in sim.tree_result)


def test_foreign_map_gets_an_open_floor_and_plays(hospital_export, tmp_path):
    first = hospital_export
    params = yaml.safe_load(first.agents_yaml.read_text())
    params["hunav_loader"]["ros__parameters"]["map"] = "cafe"
    folder = tmp_path / "cafe"
    folder.mkdir()
    (folder / "agents_hospital.yaml").write_text(yaml.safe_dump(params))
    for tree in first.trees:
        (folder / tree.name).write_text(tree.read_text())
    result = CliRunner().invoke(main, ["import", "hunav", str(folder / "agents_hospital.yaml"),
                                       "--out", str(tmp_path / "b")])
    assert result.exit_code == 0, result.output
    scenario = Scenario.load(tmp_path / "b" / "scenario.yaml")
    assert scenario.world == "world/cafe.yaml" and (tmp_path / "b" / "world" / "cafe.yaml").is_file()
    sim = Simulation.from_scenario(scenario, tmp_path / "b")
    sim.run(5.0)
    assert sim.tree_errors == {}


def test_broken_scenarios_are_refused_with_the_reason(hospital_export, tmp_path):
    first = hospital_export
    params = yaml.safe_load(first.agents_yaml.read_text())
    params["hunav_loader"]["ros__parameters"]["agent1"]["goals"] = []
    (tmp_path / "bad.yaml").write_text(yaml.safe_dump(params))
    with pytest.raises(HunavImportError, match="agent1.goals is"):
        import_hunav(tmp_path / "bad.yaml", tmp_path / "out")
    lonely = tmp_path / "lonely"
    lonely.mkdir()
    (lonely / "agents_hospital.yaml").write_text(first.agents_yaml.read_text())
    result = CliRunner().invoke(main, ["import", "hunav", str(lonely / "agents_hospital.yaml"),
                                       "--out", str(tmp_path / "out2")])
    assert result.exit_code == 2 and "agents_hospital__agent_1_bt.xml: not found" in result.output
    assert not (tmp_path / "out").exists() and not (tmp_path / "out2").exists()


@pytest.mark.parametrize("absolute_out", [False, True], ids=["relative-out", "absolute-out"])
def test_an_imported_bundle_stands_alone_from_any_folder(absolute_out, tmp_path, monkeypatch):
    """Issue 30: import in one folder (HuNavSim's house, whose map GROVE does not know, and a GROVE world
    given by a relative path), then simulate, picture, measure and export from another one."""
    from helpers.paths import REPO

    data = REPO / "tests" / "data" / "hunavsim" / "2.0" / "scenarios" / "agents_house.yaml"
    here, elsewhere = tmp_path / "here", tmp_path / "elsewhere"
    here.mkdir()
    elsewhere.mkdir()
    (here / "my_world.yaml").write_text((REPO / "worlds" / "office.yaml").read_text())
    monkeypatch.chdir(here)
    runner = CliRunner()
    bundles = {}
    for name, extra in (("house", []), ("mine", ["--world", "my_world.yaml"])):
        out = (here / name) if absolute_out else Path(name)
        result = runner.invoke(main, ["import", "hunav", str(data), "--out", str(out), *extra])
        assert result.exit_code == 0, result.output
        bundles[name] = here / name
    assert Scenario.load(bundles["mine"] / "scenario.yaml").world == "world/my_world.yaml"
    (here / "my_world.yaml").unlink()  # the bundle carries its own copy
    monkeypatch.chdir(elsewhere)
    for name, bundle in bundles.items():
        for args in (["simulate", str(bundle), "--seconds", "5"], ["picture", str(bundle), "--width", "60"],
                     ["picture", str(bundle), "--out", str(elsewhere / f"{name}.svg")],
                     ["metrics", str(bundle), "--json"],
                     ["export", "hunav", str(bundle), "--out", str(elsewhere / f"{name}_hunav")],
                     ["export", "trajectories", str(bundle), "--out", str(elsewhere / f"{name}_traj")]):
            result = runner.invoke(main, args)
            assert result.exit_code == 0, (name, args, result.output)


def test_cli_export_then_import_prints_the_files(bundle, tmp_path):
    result = CliRunner().invoke(main, ["export", "hunav", str(bundle), "--out", str(tmp_path / "e")])
    assert result.exit_code == 0, result.output
    printed = result.output.split()
    for name in ("agents_hospital.yaml", "hospital.world", "hospital.yaml", "README.md"):
        assert any(line.endswith(name) for line in printed), name
    result = CliRunner().invoke(main, ["import", "hunav", str(tmp_path / "e" / "agents_hospital.yaml"),
                                       "--out", str(tmp_path / "b")])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "b" / "scenario.yaml").is_file()


HUNAV_STYLE_YAML = """hunav_loader:
  ros__parameters:
    yaml_base_name: agents_lab
    simulator: Gazebo Classic
    map: lab
    publish_people: true
    global_goals:
      1: {x: 1.0, y: 1.0}
      2: {x: 6.0, y: 1.5}
      3: {x: 6.5, y: 5.0}
    agents: [agent1, agent2]
    agent1:
      id: 1
      group_id: -1
      skin: 0
      max_vel: 1.2
      radius: 0.4
      goal_radius: 0.3
      cyclic_goals: true
      init_pose: {x: 0.5, y: 4.0, z: 1.25, h: 0.0}
      behavior: {type: Regular, configuration: 0}
      goals: [1, 2]
    agent2:
      id: 2
      group_id: -1
      skin: 1
      max_vel: 1.0
      radius: 0.4
      goal_radius: 0.3
      cyclic_goals: true
      init_pose: {x: 3.0, y: 6.0, z: 1.25, h: 0.0}
      behavior: {type: Surprised, dist: 2.0, duration: 20.0, once: true, configuration: 0}
      goals: [3]
"""
REGULAR_TREE = """<root BTCPP_format="4" main_tree_to_execute="RegularNavTree">
  <BehaviorTree ID="RegularNavTree">
    <Fallback>
      <Sequence><Inverter><IsGoalReached agent_id="{id}"/></Inverter><RegularNav agent_id="{id}" time_step="{dt}"/></Sequence>
      <UpdateGoal agent_id="{id}"/>
    </Fallback>
  </BehaviorTree>
</root>
"""


def _agent_tree(goal_ids):
    sets = "".join(f'<RunOnce><SetGoal agent_id="{{id}}" goal_id="{g}"/></RunOnce>' for g in goal_ids)
    return f"""<root BTCPP_format="4" main_tree_to_execute="DefaultTree">
  <include path="BTRegularNav.xml"/>
  <BehaviorTree ID="DefaultTree">
    <Fallback>
      <Inverter><Sequence>{sets}</Sequence></Inverter>
      <Sequence>
        <SetBlackboard output_key="agentid" value="{{id}}"/>
        <SetBlackboard output_key="timestep" value="{{dt}}"/>
        <SubTree ID="RegularNavTree" id="{{agentid}}" dt="{{timestep}}"/>
      </Sequence>
    </Fallback>
  </BehaviorTree>
</root>
"""


def test_a_hunavsim_scenario_with_includes_imports_and_plays(tmp_path):
    """HuNavSim's wrapper layout: scenarios/agents_<x>.yaml, behavior_trees/<base>__agent_<id>_bt.xml that
    include BTRegularNav.xml and set their goals by global goal id; an unknown map gets an open floor."""
    (tmp_path / "scenarios").mkdir()
    (tmp_path / "behavior_trees").mkdir()
    (tmp_path / "scenarios" / "agents_lab.yaml").write_text(HUNAV_STYLE_YAML)
    (tmp_path / "behavior_trees" / "BTRegularNav.xml").write_text(REGULAR_TREE)
    (tmp_path / "behavior_trees" / "agents_lab__agent_1_bt.xml").write_text(_agent_tree([1, 2]))
    (tmp_path / "behavior_trees" / "agents_lab__agent_2_bt.xml").write_text(_agent_tree([3]))
    bundle = import_hunav(tmp_path / "scenarios" / "agents_lab.yaml", tmp_path / "bundle")
    scenario = Scenario.load(bundle / "scenario.yaml")
    assert scenario.world == "world/lab.yaml" and scenario.global_goals == {1: (1.0, 1.0), 2: (6.0, 1.5), 3: (6.5, 5.0)}
    assert [a.goals for a in scenario.agents] == [((1.0, 1.0), (6.0, 1.5)), ((6.5, 5.0),)]
    assert [a.behavior for a in scenario.agents] == ["Regular", "Surprised"]
    trees = load_bundle(bundle)[1]
    assert "<include" not in (bundle / "trees/agent_1.xml").read_text() and "RegularNavTree" in trees["trees/agent_1.xml"].trees
    sim = Simulation.from_scenario(scenario, bundle)
    sim.run(12.0)
    assert sim.tree_errors == {}
    # agent 2 walks to its one goal (6.5, 5.0) from (3.0, 6.0)
    assert math.dist(sim.crowd.pos[1], (6.5, 5.0)) < math.dist((3.0, 6.0), (6.5, 5.0)) - 2.0
