"""HuNavSim export: agents.yaml and per-agent BT XML that BehaviorTree.CPP v4 itself loads."""

from __future__ import annotations

import math

import pytest
import yaml
from lxml import etree

from grove_tui.engine.bt.manifest import NODES
from grove_tui.engine.export_hunav import GROVE_ONLY, ExportError, export_hunav
from grove_tui.engine.grid import build_grid
from grove_tui.engine.planner import ThetaStarPlanner
from grove_tui.engine.scenario import AgentSpec, RobotSpec, Scenario
from grove_tui.engine.waypoints import inject_waypoints
from grove_tui.engine.world import load_world

bt = pytest.importorskip("behaviortreepy")


def _tree(agent_id: int, body: str) -> str:
    return (f'<root BTCPP_format="4" main_tree_to_execute="agent_{agent_id}">'
            f'<BehaviorTree ID="agent_{agent_id}">{body}</BehaviorTree></root>')


@pytest.fixture(scope="module")
def hospital_bundle(tmp_path_factory):
    world = load_world("hospital")
    grid = build_grid(world, 0.1)
    planner = ThetaStarPlanner(grid)
    counter = world.find("pharmacy_counter").interaction_point
    lobby = (30.0, 5.0)
    table = world.find("cafeteria_table_1").interaction_point
    bundle = tmp_path_factory.mktemp("bundle")
    (bundle / "trees").mkdir()
    specs = []
    bodies = {
        1: f'<Sequence><GoTo target="pharmacy_counter" x="{counter[0]}" y="{counter[1]}"/>'
           f'<Wait duration="4"/></Sequence>',
        2: f'<Sequence><GoTo target="pharmacy" x="{counter[0] - 1.0}" y="{counter[1] + 2.0}"/>'
           f'<Queue service_point="pharmacy_counter" x="{counter[0]}" y="{counter[1]}" spacing="0.6" service_time="8"/>'
           f'</Sequence>',
        3: f'<Queue service_point="pharmacy_counter" x="{counter[0]}" y="{counter[1]}" spacing="0.6" service_time="8"/>',
        4: f'<Sequence><JoinGroup group_id="1" members="4,5"/><Converse target="cafeteria_table_1" x="{table[0]}" '
           f'y="{table[1]}" members="4,5" duration="30"/></Sequence>',
        5: f'<Sequence><JoinGroup group_id="1" members="4,5"/><Converse target="cafeteria_table_1" x="{table[0]}" '
           f'y="{table[1]}" members="4,5" duration="30"/></Sequence>',
    }
    starts = {1: lobby, 2: (31.0, 6.0), 3: (32.0, 5.0), 4: (33.0, 6.0), 5: (33.5, 5.0)}
    for agent_id, body in bodies.items():
        xml = inject_waypoints(_tree(agent_id, body), starts[agent_id], planner)
        (bundle / "trees" / f"agent_{agent_id}.xml").write_text(xml)
        root = etree.fromstring(xml.encode())
        goals = []
        for el in root.iter():
            if el.tag in ("GoTo", "Converse"):
                wps = [tuple(map(float, p.split(","))) for p in (el.get("waypoints") or "").split(";") if p]
                goals += wps + [(float(el.get("x")), float(el.get("y")))]
            if el.tag == "Queue":
                goals.append((float(el.get("x")), float(el.get("y"))))
        specs.append(AgentSpec(id=agent_id, group=1 if agent_id in (4, 5) else -1, start=starts[agent_id],
                               goals=tuple(goals), zone="pharmacy" if agent_id < 4 else "cafeteria",
                               tree=f"trees/agent_{agent_id}.xml", behavior="Surprised" if agent_id == 1 else "Regular"))
    Scenario(world="hospital", preset="normal", prompt="hand-built", seed=3, models={}, agents=tuple(specs),
             robot=RobotSpec(start=(28.0, 4.0), goal=(45.0, 5.0))).save(bundle / "scenario.yaml")
    grid.save(bundle / "grid.npz")
    return bundle


def _load_in_btcpp(xml: str) -> list[str]:
    """Load a tree in BehaviorTree.CPP v4 and tick it; return the leaf types it saw.

    behaviortreepy 0.1.4 registers Python leaves without a port list, and BT.CPP rejects ports a
    node type did not declare, so leaf attributes are dropped for this load (the ports themselves
    are checked against our manifest by check_tree_text). Built-in control nodes and decorators keep
    theirs and are checked by BT.CPP.
    """
    root = etree.fromstring(xml.encode())
    leaves = set()
    for el in root.iter():
        if isinstance(el.tag, str) and el.tag in NODES and NODES[el.tag].origin != "btcpp":
            leaves.add(el.tag)
            for attr in list(el.attrib):
                if attr != "name":
                    del el.attrib[attr]
    factory = bt.BehaviorTreeFactory()
    for name in sorted(leaves):
        if NODES[name].category == "condition":
            factory.register_simple_condition(name, lambda node: bt.NodeStatus.SUCCESS)
        else:
            factory.register_simple_action(name, lambda node: bt.NodeStatus.SUCCESS)
    tree = factory.create_tree_from_text(etree.tostring(root, encoding="unicode"))
    status = tree.tick_exactly_once()
    assert status.name in ("SUCCESS", "FAILURE", "RUNNING")
    return sorted(leaves)


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
    # agent 3 is second in the pharmacy queue (ids allocate sequentially): two slots, then one
    root = etree.fromstring((tmp_path / "hunav" / "agents_hospital__agent_3_bt.xml").read_bytes())
    queue = next(el for el in root.iter("Sequence") if el.get("name", "").startswith("Queue_"))
    steps = [el for el in queue if isinstance(el.tag, str)]
    gotos = [el for el in steps if el.tag == "GoTo"]
    waits = [el for el in steps if el.tag == "StopAndWaitTimerAction"]
    assert len(gotos) == 2 and len(waits) == 2
    d = [math.dist(counter, (goals[int(g.get("goal_id"))]["x"], goals[int(g.get("goal_id"))]["y"])) for g in gotos]
    assert d[0] == pytest.approx(1.2, abs=0.02) and d[1] == pytest.approx(0.6, abs=0.02)
    assert all(w.get("wait_duration") == "8" for w in waits)


def test_conversation_is_led_by_its_first_member(hospital_bundle, tmp_path):
    export_hunav(hospital_bundle, tmp_path / "hunav")
    lead = etree.fromstring((tmp_path / "hunav" / "agents_hospital__agent_4_bt.xml").read_bytes())
    other = etree.fromstring((tmp_path / "hunav" / "agents_hospital__agent_5_bt.xml").read_bytes())
    formation = list(lead.iter("ConversationFormation"))
    assert len(formation) == 1 and formation[0].get("non_main_agent_ids") == "5"
    assert not list(other.iter("ConversationFormation"))
    assert [el.get("group_id") for el in lead.iter("SetGroupId")] == ["1"]


def test_kept_grove_nodes_come_with_their_treenodes_model(hospital_bundle, tmp_path):
    out = export_hunav(hospital_bundle, tmp_path / "keep", lower=False)
    assert out.nodes_model is not None
    model = etree.fromstring(out.nodes_model.read_bytes())
    declared = {el.get("ID") for el in model.iter() if el.get("ID")}
    assert {"Queue", "GoTo", "Converse", "JoinGroup"} <= declared
    xml = (tmp_path / "keep" / "agents_hospital__agent_2_bt.xml").read_text()
    assert "<Queue" in xml
    _load_in_btcpp(xml)


def test_export_refuses_a_directory_it_did_not_write(hospital_bundle, tmp_path):
    foreign = tmp_path / "notes"
    foreign.mkdir()
    (foreign / "thesis.tex").write_text("precious")
    with pytest.raises(ExportError, match="not a GROVE export"):
        export_hunav(hospital_bundle, foreign)
    assert (foreign / "thesis.tex").read_text() == "precious"


def test_missing_tree_is_named(hospital_bundle, tmp_path):
    import shutil

    broken = tmp_path / "broken"
    shutil.copytree(hospital_bundle, broken)
    (broken / "trees" / "agent_3.xml").unlink()
    with pytest.raises(ExportError, match="agent_3.xml: tree file of agent 3 is missing"):
        export_hunav(broken, tmp_path / "out")
    assert not (tmp_path / "out").exists()
