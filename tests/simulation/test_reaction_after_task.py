"""People asked to react to the robot keep doing so once their task is over, in GROVE's simulation and in the
HuNavSim export alike. HuNavSim ticks every root on every step and its own trees put the reaction first in a
fallback around the navigation; GROVE's trees ran once and then no longer reacted (students who had reached
the reading room stood in the robot's way), while the export's run-once-then-hold sat outside the tree's
reaction (so it stopped too) or, for a behavior-level reaction, inside it (so it went on): the report checked a
scenario the export did not replay. Planned from a hand-written draft (no model), one real simulation."""

from __future__ import annotations

import json

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.bt.format.after_task import HOLD_NAME, RUN_ONCE_NAME
from grove_tui.bt.format.xml import read_tree
from grove_tui.exports.hunav import export_hunav
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.simulation.after_task import with_hold_after_task
from grove_tui.simulation.simulation import with_robot_reaction
from grove_tui.world import load_world

SENTENCE = ("Four students walk to the reading room and avoid the robot, while the robot drives from the entrance "
            "foyer to the reading room.")


@pytest.fixture(scope="module")
def students(tmp_path_factory):
    world = load_world("eval/understanding/worlds/library.yaml")
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "reading_room"}),))
    return plan_by_hand(world, "normal", SENTENCE, (DraftGroup("students", 4, "main_corridor", tree),),
                        tmp_path_factory.mktemp("students") / "b")


def test_people_who_arrived_before_the_robot_still_react_to_it(students):
    report = students.run(60.0)
    claim = next(c for g in report.groups for c in g.claims if c.kind == "robot_avoid")
    assert claim.status == "holds", claim.evidence
    events = [json.loads(line) for line in (students.bundle / "events.jsonl").read_text().splitlines()]
    arrived = {e["agent_id"]: e["t"] for e in events if e["kind"] == "goal_reached"}
    reacted_after = {e["agent_id"] for e in events if e["kind"] == "robot_reaction"
                     and e["agent_id"] in arrived and e["t"] >= arrived[e["agent_id"]]}
    # two of them reach the reading room before the robot comes; they still get out of its way
    assert reacted_after, events


def _ids(element):
    return [e.id for e in element.walk()]


def test_the_simulation_and_the_export_hold_inside_the_reaction(students, tmp_path):
    agent = students.op.agents[0]
    grove = read_tree((students.bundle / agent.tree).read_text(encoding="utf-8"), "grove")
    held = with_hold_after_task(with_robot_reaction(grove, agent.behavior))
    for document in (held, read_tree(export_hunav(students.bundle, tmp_path / "hunav").trees[0].read_text(), "x")):
        root = document.main
        assert root.id == "ReactiveFallback", _ids(root)
        cue, routine = root.children
        assert cue.children[0].id == "IsRobotClose"
        # the routine runs once and holds *inside* the reaction: the cue is checked on every tick for ever
        assert routine.get("name") == RUN_ONCE_NAME
        assert routine.children[-1].get("name") == HOLD_NAME


def test_the_exported_tree_reacts_after_its_routine_in_btcpp(students, tmp_path):
    pytest.importorskip("behaviortreepy")
    import behaviortreepy as bt
    from helpers.hunavsim_factory import HunavSimFactory

    class RobotComes(HunavSimFactory):
        robot_near = False

        def _simple(self, name):
            plain = super()._simple(name)

            def tick(node):
                if name == "IsRobotClose" and self.robot_near:
                    self.ticks[name] += 1
                    return bt.NodeStatus.SUCCESS
                return plain(node)
            return tick

    xml = export_hunav(students.bundle, tmp_path / "hunav").trees[0].read_text()
    factory = RobotComes()
    tree = factory.load(xml)
    for _ in range(20):  # the walk ends (the stub GoTo succeeds), then the hold
        tree.tick_once()
    assert factory.ticks["GoTo"] >= 1 and factory.ticks["StopAndWaitTimerAction"] >= 1
    factory.robot_near = True
    for _ in range(3):
        tree.tick_once()
    assert factory.ticks["AvoidRobot"] >= 1, factory.ticks


def test_a_tree_that_deals_with_the_robot_gets_no_second_reaction_in_either():
    from grove_tui.bt.format.document import TreeDocument, node
    from grove_tui.bt.format.hunav_compat import wrap_for_hunav

    def avoiding():
        return TreeDocument.single("DefaultTree", node("AvoidRobot", agent_id="{id}", time_step="{dt}",
                                                       safe_distance="3", runaway_vel="1.2", duration="0"))

    grove = with_robot_reaction(avoiding(), "Scared")
    exported = wrap_for_hunav(avoiding(), reaction=("ScaredNav", 3.0, 40.0, False), hold_seconds=60.0,
                              looping=frozenset({"RegularNav"}))
    assert "ScaredNav" not in {e.id for e in grove.nodes()}
    assert "ScaredNav" not in {e.id for e in exported.nodes()}


def test_avoiding_keeps_as_far_away_as_the_check_counts(students):
    """ScaredNav flees only inside HuNavSim's 3 m and otherwise stands facing the robot; the cue fires and
    the check counts from 6 m, so people the robot came within 4 m of stood there and failed the check."""
    claim = next(c for g in students.report.groups for c in g.claims if c.kind == "robot_avoid")
    xml = (students.bundle / students.op.agents[0].tree).read_text(encoding="utf-8")
    document = read_tree(xml, "t")
    avoid = next(e for e in document.nodes() if e.id == "AvoidRobot")
    assert float(avoid.get("safe_distance")) >= (claim.distance or 0.0)
