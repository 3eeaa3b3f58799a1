"""HuNavSim hand-off (issue 18): what HuNavSim 2.0's loader, factory and per-step ticking need.

Trees load in BehaviorTree.CPP 4 with exactly HuNavSim's node IDs (helpers/hunavsim_factory.py),
reach a final state the per-step ticking does not undo, and carry robot reactions; the agents YAML has
the types HuNavSim's loader declares; evacuees end apart, outside their exit.
"""

from __future__ import annotations

import math

import pytest
import yaml
from helpers.hunavsim_factory import HunavSimFactory
from lxml import etree

from grove_tui.bt.format.hunav_compat import HUNAV_NODES, hunav_loading_problems, restrict_to_hunav_ports
from grove_tui.bt.format.xml import read_tree, write_tree
from grove_tui.exports.hunav import ExportError, export_hunav
from grove_tui.scenario.model import DEFAULT_GOAL_RADIUS
from grove_tui.exports.hunav_loader_check import check_hunav_export, check_loader_parameters
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.pipeline import GenerationResult
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.bundle import write_bundle
from grove_tui.scenario.model import Scenario

pytest.importorskip("behaviortreepy")


def _bundle(world, preset_name, prompt, groups, out, seed=0):
    preset = load_preset(preset_name)
    grid = build_grid(world)
    reading = read_prompt(prompt, world, seed=seed)
    selection = select_rois(world, preset, reading)
    post = postprocess(world, grid, preset, Draft(tuple(groups)), selection, seed, reading,
                       ("Sequence", "GoTo", "Queue", "FollowVelocityField", "Wander", "Wait"))
    op = plan_operational(world, grid, preset, post, seed)
    scenario = Scenario(world=str(world.source), preset=preset.name, prompt=prompt, seed=seed, models={"bt": "hand"},
                        agents=tuple(op.agents), robot=op.robot,
                        fields={fid: f"fields/{fid}.npz" for fid in op.fields})
    return write_bundle(GenerationResult(scenario, op.trees, op.fields, grid, {"stages": {}, "notes": post.notes}),
                        out)


def _params(export):
    return yaml.safe_load(export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]


def test_every_tree_loads_with_hunavsims_ids_and_declared_ports(hospital_export):
    export = hospital_export
    factory = HunavSimFactory()
    for path in export.trees:
        xml = path.read_text()
        assert hunav_loading_problems(xml) == []
        factory.load(xml).tick_once()


def test_undeclared_ports_are_what_hunavsim_refuses():
    # RandomChanceCondition declares only `probability`; ApproachAgent has no closest_dist/max_vel (2.0 headers)
    xml = ('<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T"><Sequence>'
           '<RandomChanceCondition agent_id="{id}" probability="0.5"/>'
           '<ApproachAgent agent_id="{id}" target_agent_id="2" time_step="{dt}" closest_dist="1" max_vel="1" '
           'duration="5"/></Sequence></BehaviorTree></root>')
    problems = hunav_loading_problems(xml)
    assert len(problems) == 3 and "'agent_id'" in problems[0] and "'closest_dist'" in problems[1]
    fixed = write_tree(restrict_to_hunav_ports(read_tree(xml)))
    assert hunav_loading_problems(fixed) == []
    root = etree.fromstring(fixed.encode())
    assert dict(root.find(".//RandomChanceCondition").attrib) == {"probability": "0.5"}
    assert set(root.find(".//ApproachAgent").attrib) == {"agent_id", "target_agent_id", "time_step", "duration"}
    assert hunav_loading_problems(xml.replace("RandomChanceCondition", "Queue").replace('agent_id="{id}" p', 'p')) \
        [0].endswith("is not a node HuNavSim 2.0 registers")


def _tick_like_hunavsim(xml, steps=60):
    factory = HunavSimFactory()
    tree = factory.load(xml)
    statuses = []
    history = []
    for _ in range(steps):
        statuses.append(tree.tick_once().name)
        # actions the routine runs (conditions are re-checked by reactive nodes on every tick by design)
        history.append(sum(n for name, n in factory.ticks.items()
                           if name != "StopAndWaitTimerAction" and HUNAV_NODES[name].category == "action"))
    return statuses, history


def test_every_tree_reaches_a_final_state_that_ticking_on_does_not_undo(hospital_export):
    export = hospital_export
    for path in export.trees:
        statuses, moves = _tick_like_hunavsim(path.read_text())
        # The root never completes, so BT.CPP never resets it; after the routine, nothing but the hold runs.
        assert set(statuses[-20:]) == {"RUNNING"}, path.name
        assert moves[-1] == moves[-20] and moves[-1] > 0, path.name


def test_the_check_fails_for_a_tree_that_just_ends():
    plain = ('<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T"><Sequence>'
             '<GoTo agent_id="{id}" goal_id="1" time_step="{dt}" tolerance="0.2"/>'
             '<StopAndWaitTimerAction agent_id="{id}" wait_duration="3"/></Sequence></BehaviorTree></root>')
    statuses, moves = _tick_like_hunavsim(plain)
    assert "SUCCESS" in statuses and moves[-1] > moves[-20]  # re-walks: what row 6 of issue 18 describes


def test_surprised_agent_carries_its_reaction_and_goals_are_never_empty(hospital_export):
    export = hospital_export
    params = _params(export)
    lead = etree.fromstring((export.directory / "agents_hospital__agent_1_bt.xml").read_bytes())
    assert params["agent1"]["behavior"]["type"] == "Surprised"
    reaction = lead.find(".//ReactiveFallback")
    assert reaction is not None
    trigger = reaction[0]
    assert [el.tag for el in trigger] == ["IsRobotVisible", "ForceFailure"]
    assert trigger[1][0].tag == "SurprisedNav" and trigger[1][0].get("beh_duration") == "30"
    regular = etree.fromstring((export.directory / "agents_hospital__agent_2_bt.xml").read_bytes())
    assert regular.find(".//SurprisedNav") is None
    for name in params["agents"]:
        assert params[name]["goals"] and all(isinstance(g, int) for g in params[name]["goals"])


def test_every_goto_says_the_agents_goal_radius_which_is_the_radius_hunavsim_applies(hospital_export):
    export = hospital_export
    params = yaml.safe_load(export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    for name in params["agents"]:
        tree = export.directory / f"agents_hospital__agent_{params[name]['id']}_bt.xml"
        tolerances = {float(el.get("tolerance")) for el in etree.fromstring(tree.read_bytes()).iter("GoTo")}
        assert tolerances <= {params[name]["goal_radius"]} and params[name]["goal_radius"] == DEFAULT_GOAL_RADIUS == 0.1


def test_robot_start_and_goal_go_into_the_launch_arguments_and_readme(bundle, hospital_export):
    export = hospital_export
    scenario = Scenario.load(bundle / "scenario.yaml")
    readme = export.readme.read_text()
    x, y = scenario.robot.start
    assert f"gzpose_x:={x:.3f}" in readme and f"gzpose_y:={y:.3f}" in readme and "gzpose_Y:=" in readme
    gx, gy = scenario.robot.goal
    assert f"x: {gx:.3f}, y: {gy:.3f}" in readme and "/goal_pose" in readme
    assert "hunav_gazebo_wrapper/scenarios/" in readme and "hunav_gazebo_wrapper/behavior_trees/" in readme


def test_unknown_simulator_is_refused(bundle, tmp_path):
    with pytest.raises(ExportError, match="Gazebo Classic"):
        export_hunav(bundle, tmp_path / "x", simulator="gazebo")


def test_kept_grove_nodes_never_clash_with_hunavsims(bundle, tmp_path):
    kept = export_hunav(bundle, tmp_path / "keep", lower=False)
    model = etree.fromstring(kept.nodes_model.read_bytes())
    declared = {el.get("ID") for el in model.iter() if el.get("ID")}
    assert {"GroveQueue", "GroveGoTo", "GroveConverse"} <= declared and "Queue" not in declared
    for path in kept.trees:
        tags = {el.tag for el in etree.fromstring(path.read_bytes()).iter() if isinstance(el.tag, str)}
        assert not tags & {"Queue", "Converse", "Wait"}
        # HuNavSim's loader check names exactly the nodes a plugin must register
        for problem in hunav_loading_problems(path.read_text()):
            assert "<Grove" in problem and "is not a node HuNavSim 2.0 registers" in problem


def test_evacuees_end_apart_outside_their_exit(clinic, tmp_path):
    bundle = _bundle(clinic, "emergency", "Eight people in the cafeteria evacuate",
                     [DraftGroup("people", 8, "cafeteria", DraftNode("FollowVelocityField", {"exit": "back_exit"}))],
                     tmp_path / "b")
    export = export_hunav(bundle, tmp_path / "hunav")
    goals = _params(export)["global_goals"]
    door = clinic.find("back_exit")
    finals = []
    for path in export.trees:
        gotos = list(etree.fromstring(path.read_bytes()).iter("GoTo"))
        last = goals[int(gotos[-1].get("goal_id"))]
        finals.append((last["x"], last["y"]))
    assert len(finals) == 8
    for p in finals:
        assert clinic.zone_at(*p) is None  # no longer in the building
        outward = ((p[0] - door.position[0]) * -door.normal[0] + (p[1] - door.position[1]) * -door.normal[1])
        assert outward >= 1.5
    closest = min(math.dist(a, b) for i, a in enumerate(finals) for b in finals[i + 1:])
    assert closest >= 1.0 - 1e-6


def test_hunav_node_table_covers_the_manifests_hunavsim_nodes():
    from grove_tui.bt.format.manifest import NODES

    grove_side = {name for name, spec in NODES.items() if spec.origin == "hunavsim"}
    assert grove_side <= set(HUNAV_NODES)


def test_loader_emulation_passes_the_export_and_catches_what_aborts_hunavsim(hospital_export):
    export = hospital_export
    assert check_hunav_export(export.agents_yaml) == []
    document = yaml.safe_load(export.agents_yaml.read_text())
    params = document["hunav_loader"]["ros__parameters"]
    params["agent1"]["goals"] = []                      # no type: the loader aborts (issue 18 row 1)
    params["agent2"]["goals"] = [len(params["global_goals"]) + 5]   # an id global_goals lacks
    params["agent3"]["max_vel"] = 1                     # an integer where a double is declared
    params["global_goals"][1]["x"] = 3                  # likewise
    problems = check_loader_parameters(document)
    assert any("agent1.goals is []" in p for p in problems)
    assert any("agent2.goals names goal" in p for p in problems)
    assert any("agent3.max_vel is 1" in p for p in problems)
    assert any("global_goals.1.x is 3" in p for p in problems)
    del params["global_goals"][2]
    assert any("jump to 3 after 1" in p for p in check_loader_parameters(document))


def test_loader_emulation_names_a_missing_tree(hospital_export, tmp_path):
    import shutil

    export = hospital_export
    copy = tmp_path / "copy"
    shutil.copytree(export.directory, copy)
    (copy / "agents_hospital__agent_2_bt.xml").unlink()
    problems = check_hunav_export(copy / "agents_hospital.yaml")
    assert len(problems) == 1 and "agents_hospital__agent_2_bt.xml: missing" in problems[0]


def test_timed_nodes_say_which_clock_hunavsim_runs_them_on(hospital_export):
    export = hospital_export
    seen = set()
    for path in export.trees:
        for el in etree.fromstring(path.read_bytes()).iter("StopAndWaitTimerAction", "Timeout", "Delay"):
            assert el.get("name", "").endswith("(wall clock)"), etree.tostring(el)
            seen.add(el.tag)
        for el in etree.fromstring(path.read_bytes()).iter("SurprisedNav"):
            assert el.getparent().tag == "ForceFailure"
    assert {"StopAndWaitTimerAction", "Timeout"} <= seen
    assert "wall-clock seconds" in export.readme.read_text()
