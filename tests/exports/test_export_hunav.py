"""HuNavSim export: agents.yaml and per-agent BT XML that BehaviorTree.CPP v4 itself loads."""

from __future__ import annotations

import math

import pytest
import yaml
from helpers.btcpp import load_in_btcpp as _load_in_btcpp
from helpers.handmade import build_hospital_bundle
from lxml import etree

from grove_tui.exports.hunav import GROVE_ONLY, export_hunav
from grove_tui.files import OutputError
from grove_tui.scenario.model import Scenario

pytest.importorskip("behaviortreepy")


@pytest.fixture(scope="module")
def hospital_bundle(tmp_path_factory):
    return build_hospital_bundle(tmp_path_factory.mktemp("bundle"))


def test_lowered_export_round_trips_goals_poses_and_groups(hospital_bundle, tmp_path):
    out = export_hunav(hospital_bundle, tmp_path / "hunav")
    doc = yaml.safe_load(out.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    scenario = Scenario.load(hospital_bundle / "scenario.yaml")
    goals = doc["global_goals"]
    assert sorted(goals) == list(range(1, len(goals) + 1))
    assert doc["yaml_base_name"] == "agents_hospital" and doc["map"] == "hospital"
    assert doc["agents"] == [f"agent{a.id}" for a in scenario.agents]
    for agent in scenario.agents:
        entry = doc[f"agent{agent.id}"]
        assert entry["id"] == agent.id
        assert entry["group_id"] == agent.group
        assert (entry["init_pose"]["x"], entry["init_pose"]["y"]) == pytest.approx(agent.start, abs=1e-3)
        resolved = [(goals[g]["x"], goals[g]["y"]) for g in entry["goals"]]
        assert resolved == pytest.approx([tuple(round(c, 2) for c in g) for g in agent.goals], abs=1e-6)
        assert entry["behavior"]["type"] == agent.behavior
    assert len(out.trees) == len(scenario.agents)
    for path in out.trees:
        xml = path.read_text()
        assert path.name.startswith("agents_hospital__agent_") and path.name.endswith("_bt.xml")
        root = etree.fromstring(xml.encode())
        assert root.get("BTCPP_format") == "4" and root.get("main_tree_to_execute") == "DefaultTree"
        for el in root.iter():
            if isinstance(el.tag, str) and el.tag in GROVE_ONLY:
                # The only GROVE name left is GoTo, in HuNavSim's own form with a global goal id
                assert el.tag == "GoTo" and el.get("goal_id") is not None, etree.tostring(el)
                assert int(el.get("goal_id")) in goals
        _load_in_btcpp(xml)


def test_lowered_queue_walks_slot_by_slot_toward_the_counter(hospital_bundle, tmp_path):
    out = export_hunav(hospital_bundle, tmp_path / "hunav")
    doc = yaml.safe_load(out.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    goals = doc["global_goals"]
    counter = (48.4, 8.0)
    # agent 3 is second in the pharmacy queue (ids allocate sequentially): two slots, then one, then aside
    root = etree.fromstring((tmp_path / "hunav" / "agents_hospital__agent_3_bt.xml").read_bytes())
    queue = next(el for el in root.iter("SequenceWithMemory") if el.get("name", "").startswith("Queue_"))
    steps = [el for el in queue if isinstance(el.tag, str)]
    assert [el.tag if el.tag != "Inverter" else el.get("name") for el in steps] == [
        "GoTo", "ForceSuccess", "ahead_moved_on", "GoTo", "StopAndWaitTimerAction", "GoTo"]
    gotos = [el for el in steps if el.tag == "GoTo"]
    d = [math.dist(counter, (goals[int(g.get("goal_id"))]["x"], goals[int(g.get("goal_id"))]["y"])) for g in gotos]
    assert d[0] == pytest.approx(1.2, abs=0.02) and d[1] == pytest.approx(0.6, abs=0.02)
    assert d[2] >= 1.2 - 1e-6  # served, it steps out of the line
    # it moves up when agent 2, the one ahead of it, has moved on: not on a timer of its own
    waits = [el for el in steps[1].iter("IsAgentClose")] + [el for el in steps[2].iter("IsAgentClose")]
    assert {el.get("target_agent_id") for el in waits} == {"2"}
    assert [el.get("wait_duration") for el in steps if el.tag == "StopAndWaitTimerAction"] == ["8"]
    head = etree.fromstring((tmp_path / "hunav" / "agents_hospital__agent_2_bt.xml").read_bytes())
    assert not list(head.iter("IsAgentClose"))  # nobody ahead of the head of the line


def test_conversation_members_meet_on_their_own_spots(hospital_bundle, tmp_path):
    out = export_hunav(hospital_bundle, tmp_path / "hunav")
    goals = yaml.safe_load(out.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]["global_goals"]
    spots = {}
    for agent_id, other in ((4, "5"), (5, "4")):
        root = etree.fromstring((tmp_path / "hunav" / f"agents_hospital__agent_{agent_id}_bt.xml").read_bytes())
        assert not list(root.iter("ConversationFormation"))
        converse = next(el for el in root.iter("SequenceWithMemory") if el.get("name", "").startswith("Converse_"))
        steps = [el for el in converse if isinstance(el.tag, str)]
        last_goto = [el for el in steps if el.tag == "GoTo"][-1]
        spots[agent_id] = (goals[int(last_goto.get("goal_id"))]["x"], goals[int(last_goto.get("goal_id"))]["y"])
        assert [el.get("target_agent_id") for el in converse.iter("IsAgentClose")] == [other]
        assert [el.tag for el in steps[-2:]] == ["LookAtPoint", "StopAndWaitTimerAction"]
        assert steps[-1].get("wait_duration") == "30"
    assert spots[4] != spots[5]
    from grove_tui.world import load_world

    centre = load_world("hospital").find("cafeteria_table_1").interaction_point
    assert math.dist(spots[4], centre) == pytest.approx(0.7, abs=0.15)  # radius 0.5 + 0.2 for two
    assert math.dist(spots[5], centre) == pytest.approx(0.7, abs=0.15)


def test_kept_grove_nodes_come_with_their_treenodes_model(hospital_bundle, tmp_path):
    out = export_hunav(hospital_bundle, tmp_path / "keep", lower=False)
    assert out.nodes_model is not None
    model = etree.fromstring(out.nodes_model.read_bytes())
    declared = {el.get("ID") for el in model.iter() if el.get("ID")}
    # kept under their own names, so they never clash with HuNavSim's registered GoTo
    assert {"GroveQueue", "GroveGoTo", "GroveConverse", "GroveJoinGroup"} <= declared
    xml = (tmp_path / "keep" / "agents_hospital__agent_2_bt.xml").read_text()
    assert "<GroveQueue" in xml
    # kept GoTo nodes name their goal by this export's global_goals ids
    goals = yaml.safe_load(out.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]["global_goals"]
    numbered = [el for path in out.trees for el in etree.fromstring(path.read_bytes()).iter("GroveGoTo")
                if el.get("goal_id") is not None]
    assert numbered  # agent 1's GoTo carried the pipeline's goal id 7
    for el in numbered:
        entry = goals[int(el.get("goal_id"))]
        assert (entry["x"], entry["y"]) == pytest.approx((float(el.get("x")), float(el.get("y"))), abs=0.01)


def test_export_refuses_a_directory_it_did_not_write(hospital_bundle, tmp_path):
    foreign = tmp_path / "notes"
    foreign.mkdir()
    (foreign / "thesis.tex").write_text("precious")
    with pytest.raises(OutputError, match="is not a GROVE HuNavSim export.*--overwrite"):
        export_hunav(hospital_bundle, foreign)
    assert (foreign / "thesis.tex").read_text() == "precious"


def test_missing_tree_is_named(hospital_bundle, tmp_path):
    import shutil

    broken = tmp_path / "broken"
    shutil.copytree(hospital_bundle, broken)
    (broken / "trees" / "agent_3.xml").unlink()
    from grove_tui.scenario.bundle import BundleError

    with pytest.raises(BundleError, match="tree file of agent 3 trees/agent_3.xml is missing"):
        export_hunav(broken, tmp_path / "out")
    assert not (tmp_path / "out").exists()
