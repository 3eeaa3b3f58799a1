"""The draft checked against the reading (generation/reconcile.py) and the grounding report.

Drafts are written by hand here, as a weak or a capable model would write them, so each repair
(and each thing that must NOT be repaired) is tested on its own; the e2e tests run the real model.
"""

from __future__ import annotations

import pytest

from grove_tui.crowd.leaves.hunav import ROBOT_ACTIVITIES, ROBOT_REACTIONS
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import grounding_report, is_idle, reconcile
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.model import RobotSpec
from grove_tui.scenario.report import GroundingReport


@pytest.fixture(scope="module")
def coarse_grid(hospital):
    """The hospital at 20 cm cells: the repairs checked here do not depend on finer ones."""
    return build_grid(hospital, resolution=0.2, inflation=0.35)


def goto(target):
    return DraftNode("GoTo", {"target": target})


def seq(*children):
    return DraftNode("Sequence", {}, tuple(children))


def run(hospital, prompt, groups, notes=None):
    notes = [] if notes is None else notes
    return reconcile(Draft(tuple(groups)), read_prompt(prompt, hospital), hospital, "entrance_lobby", notes), notes


def test_a_tree_that_only_checks_conditions_is_idle_and_replaced(hospital):
    idle = DraftNode("Sequence", {}, (DraftNode("IsRobotVisible", {"distance": 5.0}),))
    assert is_idle(idle)
    groups, notes = run(hospital, "Six visitors walk to the cafeteria.", [DraftGroup("visitors", 6, "entrance_lobby", idle)])
    assert not is_idle(groups[0].tree)
    assert any(n.node == "GoTo" and n.ports["target"] == "cafeteria" for n in groups[0].tree.walk())
    assert any("no action" in n for n in notes)


@pytest.mark.parametrize("model_tree", [goto("pharmacy_counter"), seq(goto("cafeteria"), DraftNode("Wait", {}))])
def test_a_queue_the_model_turned_into_something_else_is_repaired(hospital, model_tree):
    groups, notes = run(hospital, "Five patients line up at the reception desk to register.",
                        [DraftGroup("patients", 5, "entrance_lobby", model_tree)])
    queue = [n for n in groups[0].tree.walk() if n.node == "Queue"]
    assert [q.ports["service_point"] for q in queue] == ["reception_desk"]
    assert notes


def test_a_pause_after_arriving_stays_and_is_listed_as_added(hospital):
    # The model walks them to the cafeteria and adds a wait there: kept, but said, never a claim.
    tree = seq(goto("main_corridor"), goto("cafeteria"), DraftNode("Wait", {"duration": 30.0}))
    groups, notes = run(hospital, "Six visitors walk to the cafeteria.", [DraftGroup("visitors", 6, "entrance_lobby", tree)])
    assert groups[0].tree == seq(goto("cafeteria"), DraftNode("Wait", {"duration": 30.0}))
    assert groups[0].added == ["waits for 30 s afterwards"]


@pytest.mark.parametrize("prompt,model_tree,unasked", [
    # a Queue for a walker (the queuing preset's habit)
    ("A nurse walks to the cafeteria.", seq(goto("pharmacy_counter"), DraftNode("Queue", {"service_point":
                                                                                           "pharmacy_counter"}),
                                            goto("cafeteria")), "Queue"),
    # a minute of talk before a walk
    ("A family of five walks to the cafeteria.", seq(DraftNode("Converse", {"target": "entrance_lobby",
                                                                            "duration": 60.0}), goto("cafeteria")),
     "Converse"),
    # people following each other in a loop
    ("Four visitors walk to ward a.", seq(DraftNode("FollowAgent", {"duration": 60.0}), goto("ward_a")),
     "FollowAgent"),
    # a detour to a place the sentence does not name
    ("Six visitors walk to the cafeteria.", seq(goto("pharmacy"), goto("cafeteria")), "GoTo(pharmacy)"),
])
def test_what_the_sentence_does_not_ask_for_is_removed(hospital, prompt, model_tree, unasked):
    groups, notes = run(hospital, prompt, [DraftGroup("people", 4, "entrance_lobby", model_tree)])
    nodes = [n.node for n in groups[0].tree.walk()]
    assert unasked.split("(")[0] not in nodes or unasked.startswith("GoTo")
    assert all(n.ports.get("target") != "pharmacy" for n in groups[0].tree.walk())
    assert any(unasked in n for n in notes if "does not ask" in n), notes
    assert groups[0].added == []


def test_a_destination_the_tree_never_reaches_is_where_they_go(hospital):
    tree = seq(goto("main_corridor"), DraftNode("Wait", {"duration": 10.0}))
    groups, notes = run(hospital, "Six visitors walk to the cafeteria.", [DraftGroup("visitors", 6, "entrance_lobby", tree)])
    assert groups[0].tree == goto("cafeteria")


def test_a_missing_second_group_is_added_and_counts_follow_the_reading(hospital):
    prompt = "Ten patients walk to the pharmacy, while a few others stroll around the lobby."
    groups, notes = run(hospital, prompt, [DraftGroup("patients", 3, "entrance_lobby", goto("pharmacy"))])
    reading = read_prompt(prompt, hospital)
    assert [(g.label, g.count) for g in groups] == [("patient", 10), ("patient", reading.groups[1].count.value)]
    assert [n.node for n in groups[1].tree.walk()] == ["Wander"]
    assert any("count 3 -> 10" in n for n in notes) and any("added" in n for n in notes)


def test_extra_model_groups_are_dropped_with_a_note(hospital):
    groups, notes = run(hospital, "Six visitors walk to the cafeteria.",
                        [DraftGroup("visitors", 6, "entrance_lobby", goto("cafeteria")),
                         DraftGroup("FollowAgent", 2, "entrance_lobby", goto("pharmacy"))])
    assert len(groups) == 1 and any("dropped group 'FollowAgent'" in n for n in notes)


@pytest.mark.parametrize("phrase,behavior", [("stares at the robot", "Surprised"), ("follows the robot", "Curious"),
                                             ("avoids the robot", "Scared"), ("blocks the robot", "Threatening"),
                                             ("approaches the robot", "Curious")])
def test_robot_reactions_set_the_behavior_and_the_tree(hospital, phrase, behavior):
    prompt = f"Eight visitors walk to the cafeteria and one of them {phrase}."
    groups, _ = run(hospital, prompt, [DraftGroup("visitors", 8, "entrance_lobby", goto("cafeteria"))])
    assert [(g.count, g.behavior) for g in groups] == [(7, "Regular"), (1, behavior)]
    reactor = groups[1].tree
    assert not is_idle(reactor)
    assert any(n.node in ROBOT_REACTIONS or n.node in ROBOT_ACTIVITIES for n in reactor.walk())


@pytest.mark.parametrize("phrase,node", [("follow the robot", "ApproachRobot"), ("block the robot", "BlockRobot"),
                                         ("avoid the robot", "AvoidRobot"), ("stare at the robot", "LookAtRobot"),
                                         ("walk up to the robot", "ApproachRobot")])
def test_a_group_whose_activity_is_the_robot_does_it_ungated(hospital, phrase, node):
    # "two children follow the robot": not IsRobotVisible(10) and wait for a robot that never comes
    groups, _ = run(hospital, f"Two children {phrase}.",
                    [DraftGroup("children", 2, "ward_a", seq(DraftNode("IsRobotVisible", {"distance": 10.0}),
                                                             DraftNode("FollowAgent", {})))])
    (group,) = groups
    nodes = [n.node for n in group.tree.walk()]
    assert node in nodes and "IsRobotVisible" not in nodes and "FollowAgent" not in nodes
    assert group.reacts_only


def test_structured_counts_become_parties(hospital):
    groups, _ = run(hospital, "Two families of three walk to the cafeteria.",
                    [DraftGroup("families", 2, "entrance_lobby", goto("cafeteria"))])
    assert (groups[0].count, groups[0].party_size, groups[0].label) == (6, 3, "family")
    assert groups[0].tree.children[0].node == "JoinGroup"


@pytest.mark.parametrize("prompt", [
    "Ten patients queue at the pharmacy counter while two nurses chat in the staff room.",
    "Two families of three walk together to the cafeteria, while a few others stroll around the lobby.",
    "Evacuate the pharmacy: twenty people leave by the main entrance and one of them follows the robot.",
    "Nobody is here except one guard who waits on the bench for five minutes.",
])
def test_postprocessed_scenario_grounds_every_group(hospital, coarse_grid, prompt):
    preset = load_preset("normal")
    reading = read_prompt(prompt, hospital)
    selection = select_rois(hospital, preset, reading)
    # The weakest draft: one idle group with a node name for a label.
    draft = Draft((DraftGroup("FollowAgent", 1, "entrance_lobby", DraftNode("IsRobotVisible", {})),))
    post = postprocess(hospital, coarse_grid, preset, draft, selection, 0, reading, ("GoTo", "Queue"))
    assert all(not is_idle(g.tree) for g in post.groups)
    assert all(g.label not in ("FollowAgent",) for g in post.groups)
    report = grounding_report(reading, post.groups, post.agents, hospital, post.notes)
    # planned, never ✓ before a run, and nothing the plan already contradicts
    assert report.status == "planned" and not report.ok, report.lines()
    assert all(c.status == "planned" for g in report.groups for c in g.claims), report.lines()
    assert len(report.groups) == len([g for g in post.groups])
    assert GroundingReport.from_dict(report.to_dict()) == report
    for g in post.groups:
        reading_group = reading.groups[g.reading_index]
        if reading_group.robot_reaction:
            assert all(a.behavior == reading_group.robot_reaction for a in post.agents if a.group_index == g.index)


def test_the_report_says_what_was_not_honoured(hospital, coarse_grid):
    prompt = "Six visitors walk to the cafeteria."
    preset = load_preset("normal")
    reading = read_prompt(prompt, hospital)
    selection = select_rois(hospital, preset, reading)
    post = postprocess(hospital, coarse_grid, preset, Draft((DraftGroup("visitors", 6, "entrance_lobby", goto("cafeteria")),)),
                       selection, 0, reading, ("GoTo",))
    post.groups[0].tree = goto("pharmacy")  # as if something downstream had sent them elsewhere
    post.groups[0].count = 4
    report = grounding_report(reading, post.groups, post.agents, hospital)
    claims = {c.kind: c for c in report.groups[0].claims}
    assert claims["reach"].status == "fails" and claims["count"].status == "fails" and report.status == "fails"
    assert any(line.startswith("✗") for line in report.lines())


def test_wandering_at_the_destination_is_kept_after_walking_there(hospital):
    tree = DraftNode("Wander", {"zone": "ward_a", "duration": 120.0})
    groups, notes = run(hospital, "Three visitors walk from the entrance lobby to ward a.",
                        [DraftGroup("visitors", 3, "ward_a", tree)])
    assert groups[0].tree == seq(goto("ward_a"), DraftNode("Wander", {"zone": "ward_a", "duration": 120.0}))
    assert groups[0].spawn == "entrance_lobby"
    assert groups[0].added == ["wanders in ward_a for 120 s afterwards"]


def test_a_sentence_that_names_nobody_is_one_group_the_model_fills(hospital, coarse_grid):
    prompt = "The cafeteria gets busy around noon."
    preset = load_preset("normal")
    reading = read_prompt(prompt, hospital)
    assert len(reading.groups) == 1 and reading.groups[0].confidence_of("group").unsure
    selection = select_rois(hospital, preset, reading)
    draft = Draft((DraftGroup("diners", 5, "cafeteria", goto("cafeteria")),))
    post = postprocess(hospital, coarse_grid, preset, draft, selection, 0, reading, ("GoTo",))
    assert [g.tree for g in post.groups] == [goto("cafeteria")]  # the model's tree: nothing contradicts it
    assert post.groups[0].count == reading.groups[0].count.value
    report = grounding_report(reading, post.groups, post.agents, hospital, post.notes)
    assert len(report.groups) == 1


def test_the_report_carries_the_place_spelling_corrections(hospital, coarse_grid):
    prompt = "Six visitors walk to the cafetaria."
    preset = load_preset("normal")
    reading = read_prompt(prompt, hospital)
    assert reading.groups[0].destination == "cafeteria" and reading.corrections
    selection = select_rois(hospital, preset, reading)
    post = postprocess(hospital, coarse_grid, preset, Draft((DraftGroup("visitors", 6, "entrance_lobby", goto("cafeteria")),)),
                       selection, 0, reading, ("GoTo",))
    report = grounding_report(reading, post.groups, post.agents, hospital)
    assert report.corrections == reading.corrections and report.status == "planned", report.lines()
    assert any(line.startswith("~ correction: read 'cafetaria'") for line in report.lines())
    assert GroundingReport.from_dict(report.to_dict()) == report


def test_walking_out_with_no_destination_is_honoured_by_the_evacuation_field(hospital, coarse_grid):
    # In an emergency every mover follows the field to the nearest exit; a sentence that says they
    # walk ("get out", "leave") and names no destination is then played as it asks.
    prompt = "Four visitors in the cafeteria get out of the building."
    preset = load_preset("emergency")
    reading = read_prompt(prompt, hospital)
    assert reading.groups[0].intent == "walk" and not reading.groups[0].destination
    selection = select_rois(hospital, preset, reading)
    draft = Draft((DraftGroup("visitors", 4, "cafeteria", DraftNode("FollowVelocityField", {})),))
    post = postprocess(hospital, coarse_grid, preset, draft, selection, 0, reading, ("FollowVelocityField",))
    assert any(n.node == "FollowVelocityField" for n in post.groups[0].tree.walk())
    report = grounding_report(reading, post.groups, post.agents, hospital, post.notes)
    (evacuate,) = [c for c in report.groups[0].claims if c.kind == "evacuate"]
    assert evacuate.status == "planned", report.lines()


def test_the_emergency_field_is_for_those_the_sentence_evacuates(hospital, coarse_grid):
    # A guard who waits by the reception desk during the drill waits: the preset does not evacuate him.
    prompt = "Twenty people in the cafeteria evacuate while a guard waits by the reception desk."
    preset = load_preset("emergency")
    reading = read_prompt(prompt, hospital)
    assert [g.intent for g in reading.groups] == ["evacuate", "wait"]
    selection = select_rois(hospital, preset, reading)
    draft = Draft((DraftGroup("people", 20, "cafeteria", DraftNode("FollowVelocityField", {})),
                   DraftGroup("guard", 1, "cafeteria", DraftNode("FollowVelocityField", {}))))
    post = postprocess(hospital, coarse_grid, preset, draft, selection, 0, reading, ("FollowVelocityField", "Wait"))
    guard = post.groups[1]
    assert "FollowVelocityField" not in {n.node for n in guard.tree.walk()} and guard.field_id is None
    assert all(a.field_id is None for a in post.agents if a.group_index == guard.index)
    assert any("exits in use" in n and "(20 people)" in n for n in post.notes)


def test_the_robot_s_asked_wait_is_its_stay_claim(hospital, coarse_grid):
    # "waits at reception for two minutes": the stay claim carries the 120 s and a run shorter than
    # them cannot tell it (a 10 s run earned the wait a ✓ when the seconds were dropped)
    preset = load_preset("normal")
    reading = read_prompt("Two visitors walk to the pharmacy and the robot waits at the reception for two minutes.",
                          hospital)
    selection = select_rois(hospital, preset, reading)
    draft = Draft((DraftGroup("visitors", 2, "entrance_lobby", goto("pharmacy")),))
    post = postprocess(hospital, coarse_grid, preset, draft, selection, 0, reading, ("GoTo", "Queue"))
    robot = RobotSpec(start=(20.0, 10.0), goal=(20.0, 10.0), path=((20.0, 10.0),), task="wait")
    report = grounding_report(reading, post.groups, post.agents, hospital, post.notes, robot=robot)
    assert report.robot is not None
    (stay,) = [c for c in report.robot.claims if c.kind == "robot_stay"]
    assert stay.seconds == 120.0 and stay.needs_seconds is not None and stay.needs_seconds >= 120.0
    assert "120 s" in stay.asked
