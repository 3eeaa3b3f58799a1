"""Post-processing: counts follow the prompt, ids are automatic, spawns and goals are sampled in free space."""

from __future__ import annotations

import math

import pytest
from lxml import etree

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.postprocess import GOAL_SPACING, SPAWN_SPACING, postprocess
from grove_tui.errors import PromptError
from grove_tui.generation.presets import load_preset
from grove_tui.language.reading import read_prompt
from grove_tui.generation.rois import select_rois


def queue_tree(place="pharmacy_counter"):
    return DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": place}), DraftNode("Queue", {"service_point": place})))


def run(clinic, grid, preset, prompt, groups, seed=0, nodes=("Sequence", "GoTo", "Queue", "Converse", "JoinGroup")):
    preset = load_preset(preset)
    reading = read_prompt(prompt, clinic, seed=seed)
    selection = select_rois(clinic, preset, reading)
    return postprocess(clinic, grid, preset, Draft(tuple(groups)), selection, seed, reading, nodes)


PROMPT = "Ten patients queue at the pharmacy counter while two nurses chat in the lobby"


def goto_targets(tree):
    """Where a tree walks to, in order: GoTo targets, and the exit a walk out of the building goes through."""
    return [n.ports["target"] if n.node == "GoTo" else n.ports["exit"] for n in tree.walk()
            if n.node == "GoTo" or (n.node == "FollowVelocityField" and n.ports.get("exit"))]


def test_counts_follow_the_reading_and_missing_groups_are_added_where_their_words_say(clinic, grid):
    out = run(clinic, grid, "queuing", PROMPT, [DraftGroup("patients", 3, "pharmacy", queue_tree())])
    assert [(g.label, g.count, g.spawn) for g in out.groups] == [("patient", 10, "pharmacy"), ("nurse", 2, "lobby")]
    assert [a.id for a in out.agents] == list(range(1, 13))
    nurses = [a for a in out.agents if a.label == "nurse"]
    assert all(a.spawn_zone == "lobby" and a.zone == "lobby" for a in nurses)
    assert any("count 3 -> 10" in n for n in out.notes) and any("group 'nurse': added" in n for n in out.notes)


def test_groups_are_matched_to_the_reading_by_label_and_extra_groups_dropped(clinic, grid):
    groups = [DraftGroup("staff", 5, "lobby", DraftNode("GoTo", {"target": "lobby"})),
              DraftGroup("nurses", 5, "lobby", DraftNode("GoTo", {"target": "lobby"})),
              DraftGroup("patients", 1, "pharmacy", queue_tree())]
    out = run(clinic, grid, "queuing", PROMPT, groups)
    assert [(g.label, g.count) for g in out.groups] == [("patient", 10), ("nurse", 2)]
    assert any("dropped group 'staff'" in n for n in out.notes)


def test_without_stated_counts_the_model_counts_stand(clinic, grid):
    out = run(clinic, grid, "normal", "patients wander in the cafeteria",
              [DraftGroup("patients", 3, "cafeteria", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert len(out.agents) == 3


def test_spawns_are_free_inside_their_zone_and_two_radii_apart(clinic, grid):
    out = run(clinic, grid, "queuing", PROMPT, [DraftGroup("patients", 10, "pharmacy", queue_tree())])
    for a in out.agents:
        assert grid.is_free(*a.start)
        assert clinic.zone(a.spawn_zone).polygon.contains(__import__("shapely").Point(a.start))
    for i, a in enumerate(out.agents):
        for b in out.agents[i + 1:]:
            assert math.dist(a.start, b.start) >= SPAWN_SPACING - 1e-9


def test_sequential_goal_allocation_gives_each_queuer_its_own_place_in_line(clinic, grid):
    out = run(clinic, grid, "queuing", "Ten patients queue at the pharmacy counter",
              [DraftGroup("patients", 10, "pharmacy", queue_tree())])
    firsts = [a.targets[0][1] for a in out.agents]
    assert firsts[0] == (17.0, 11.8)  # the head walks to the service point itself
    assert len(set(firsts)) == 10
    assert all(clinic.zone("pharmacy").polygon.contains(__import__("shapely").Point(p)) for p in firsts)
    assert all(grid.is_free(*p) for p in firsts)
    # the queue node is always told the service point
    assert all(a.targets[1] == ("pharmacy_counter", (17.0, 11.8)) for a in out.agents)


def test_zone_goals_are_spread_inside_the_zone(clinic, grid):
    out = run(clinic, grid, "normal", "Six visitors walk to the cafeteria",
              [DraftGroup("visitors", 6, "lobby", DraftNode("GoTo", {"target": "cafeteria"}))])
    goals = [a.targets[0][1] for a in out.agents]
    assert len(set(goals)) == 6
    poly = clinic.zone("cafeteria").polygon
    assert all(poly.contains(__import__("shapely").Point(p)) and grid.is_free(*p) for p in goals)
    assert min(math.dist(p, q) for i, p in enumerate(goals) for q in goals[i + 1:]) >= 0.8 - 1e-9
    assert all(a.zone == "cafeteria" for a in out.agents)


def test_xml_is_btcpp_v4_with_ids_members_and_resolved_points(clinic, grid):
    tree = DraftNode("Sequence", {}, (DraftNode("JoinGroup", {}), DraftNode("Converse", {"target": "lobby"})))
    out = run(clinic, grid, "normal", "a family of four chats in the lobby", [DraftGroup("family", 4, "lobby", tree)])
    roots = [etree.fromstring(a.xml.encode()) for a in out.agents]
    for agent, root in zip(out.agents, roots):
        assert root.get("BTCPP_format") == "4"
        assert root.get("main_tree_to_execute") == f"agent_{agent.id}"
        converse = root.find(".//Converse")
        assert converse.get("members") == "1,2,3,4"
    centres = {(r.find(".//Converse").get("x"), r.find(".//Converse").get("y")) for r in roots}
    assert len(centres) == 1  # one conversation circle for the whole group
    assert {a.sfm_group for a in out.agents} == {0}
    # a group that talks starts together
    starts = [a.start for a in out.agents]
    assert max(math.dist(p, q) for p in starts for q in starts) < 4.0


def test_join_group_names_the_members_and_the_group(clinic, grid):
    tree = DraftNode("Sequence", {}, (DraftNode("JoinGroup", {}), DraftNode("GoTo", {"target": "cafeteria"})))
    out = run(clinic, grid, "normal", "a family of four walks together to the cafeteria",
              [DraftGroup("family", 4, "lobby", tree)])
    for agent in out.agents:
        join = etree.fromstring(agent.xml.encode()).find(".//JoinGroup")
        assert join.get("members") == "1,2,3,4" and join.get("agent_id") == "{id}" and join.get("group_id") == "0"


def test_same_seed_same_result_other_seed_other_spawns(clinic, grid):
    groups = [DraftGroup("patients", 10, "pharmacy", queue_tree())]
    a = run(clinic, grid, "queuing", PROMPT, groups, seed=3)
    b = run(clinic, grid, "queuing", PROMPT, groups, seed=3)
    c = run(clinic, grid, "queuing", PROMPT, groups, seed=4)
    assert [x.xml for x in a.agents] == [x.xml for x in b.agents]
    assert [x.start for x in a.agents] == [x.start for x in b.agents]
    assert [x.start for x in a.agents] != [x.start for x in c.agents]


def test_impossible_count_names_the_zone_and_its_capacity(clinic, grid):
    prompt = "10,000 people crowd into the bathroom"
    with pytest.raises(PromptError, match=r"10000 people do not fit in zone 'restroom'.*holds at most \d+"):
        run(clinic, grid, "normal", prompt, [DraftGroup("people", 5, "restroom", DraftNode("GoTo", {"target": "restroom"}))])


def test_count_above_the_preset_limit_is_refused(clinic, grid):
    prompt = "50 people wait in the cafeteria"
    with pytest.raises(PromptError, match="allows at most 40 per group"):
        run(clinic, grid, "normal", prompt, [DraftGroup("people", 5, "cafeteria", DraftNode("GoTo", {"target": "cafeteria"}))])


def evac(exit_name="main_entrance"):
    return DraftNode("FollowVelocityField", {"exit": exit_name})


def test_emergency_uses_one_shared_exit_named_in_the_prompt(clinic, grid):
    out = run(clinic, grid, "emergency", "Eight people in the cafeteria leave through the back exit",
              [DraftGroup("people", 8, "cafeteria", evac("main_entrance"))], nodes=("Sequence", "FollowVelocityField"))
    assert out.exit == "back_exit"
    for a in out.agents:
        root = etree.fromstring(a.xml.encode())
        node = root.find(".//FollowVelocityField")
        assert node.get("exit") == "back_exit" and node.get("field") == "group_1"
        assert (float(node.get("x")), float(node.get("y"))) == (24.0, 4.0)


def test_emergency_without_a_named_exit_sends_each_person_to_their_nearest(clinic, grid):
    # The model's tree names the main entrance; the prompt allows every exit, and from the
    # cafeteria the back exit is the nearer walk (issue 19: no single shared exit).
    out = run(clinic, grid, "emergency", "Eight people evacuate the cafeteria",
              [DraftGroup("people", 8, "cafeteria", evac("main_entrance"))], nodes=("Sequence", "FollowVelocityField"))
    assert sorted(out.exits) == ["back_exit", "main_entrance"]
    assert {a.exit for a in out.agents} == {"back_exit"}
    for a in out.agents:
        assert etree.fromstring(a.xml.encode()).find(".//FollowVelocityField").get("exit") == "back_exit"


@pytest.mark.parametrize("preset", ["emergency", "normal"])
def test_an_exit_the_sentence_rules_out_is_used_by_nobody(clinic, grid, preset):
    # from the cafeteria the back exit is the nearer walk; the sentence rules it out
    out = run(clinic, grid, preset, "Eight people evacuate the cafeteria, but not through the back exit",
              [DraftGroup("people", 8, "cafeteria", evac("back_exit"))], nodes=("Sequence", "FollowVelocityField"))
    assert goto_targets(out.groups[0].tree) == ["main_entrance"]
    assert {a.exit for a in out.agents} <= {"main_entrance", None}
    assert out.groups[0].exits_shunned == ("back_exit",)


def test_a_place_the_sentence_rules_out_is_kept_apart_from_where_they_go(clinic, grid):
    out = run(clinic, grid, "normal", "Four visitors walk from the lobby to the cafeteria, avoiding the pharmacy",
              [DraftGroup("visitors", 4, "lobby", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert out.groups[0].places_shunned == ("pharmacy",)
    assert goto_targets(out.groups[0].tree) == ["cafeteria"]


def test_spawn_follows_the_prompts_place_words_not_the_destination(clinic, grid):
    prompt = "Four visitors in the lobby walk to the cafeteria"
    out = run(clinic, grid, "normal", prompt,
              [DraftGroup("visitors", 4, "restroom", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert out.groups[0].spawn == "lobby"
    out = run(clinic, grid, "normal", "Four visitors walk to the cafeteria",
              [DraftGroup("visitors", 4, "lobby", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert out.groups[0].spawn == "lobby"  # the prompt is silent: the model's choice stands
    out = run(clinic, grid, "normal", "Four visitors walk to the cafeteria",
              [DraftGroup("visitors", 4, "cafeteria", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert out.groups[0].spawn == "corridor"  # not where they are going: the room next to it


def test_queuing_overlay_adds_the_queue_subtree_the_model_left_out(clinic, grid):
    wait_tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "pharmacy"}), DraftNode("Wait", {"duration": 10.0})))
    out = run(clinic, grid, "queuing", "Ten patients wait in line at the pharmacy counter",
              [DraftGroup("patients", 10, "pharmacy", wait_tree)], nodes=("Sequence", "GoTo", "Queue", "Wait"))
    kinds = [n.node for n in out.groups[0].tree.walk()]
    assert kinds == ["Sequence", "GoTo", "Queue"]
    assert etree.fromstring(out.agents[3].xml.encode()).find(".//Queue").get("service_point") == "pharmacy_counter"


def test_emergency_overlay_makes_every_group_leave(clinic, grid):
    out = run(clinic, grid, "emergency", "Six people in the cafeteria hear the alarm",
              [DraftGroup("people", 6, "cafeteria", DraftNode("Wait", {"duration": 5.0}))],
              nodes=("Sequence", "Wait", "FollowVelocityField"))
    kinds = [n.node for n in out.groups[0].tree.walk()]
    assert kinds[-1] == "FollowVelocityField"
    assert out.exit in ("main_entrance", "back_exit")


def test_destinations_the_reading_names_are_reached_when_the_model_leaves_them_out(clinic, grid):
    out = run(clinic, grid, "normal", "Two visitors walk from the lobby to the cafeteria",
              [DraftGroup("visitors", 2, "lobby", DraftNode("JoinGroup", {}))])
    assert [n.node for n in out.groups[0].tree.walk()][-1] == "GoTo"
    assert all(a.zone == "cafeteria" and a.targets[-1][0] == "cafeteria" for a in out.agents)
    assert out.groups[0].spawn == "lobby"
    kept = run(clinic, grid, "normal", "Two visitors walk from the lobby to the cafeteria",
               [DraftGroup("visitors", 2, "lobby", DraftNode("GoTo", {"target": "vending_machine"}))])
    assert [n.node for n in kept.groups[0].tree.walk()] == ["GoTo"]  # already reaches the cafeteria


def test_a_group_does_what_its_own_words_say_where_they_say_it(clinic, grid):
    """The small model queued everyone at the exit; the words say the patients queue at the counter
    and the family walks to the exit."""
    wrong = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "main_entrance"}),
                                       DraftNode("Queue", {"service_point": "main_entrance"})))
    out = run(clinic, grid, "queuing", "ten patients queue at the pharmacy counter while a family walks to the main entrance",
              [DraftGroup("patients", 10, "lobby", wrong), DraftGroup("patients", 10, "lobby", wrong)])
    patients, family = out.groups
    assert patients.count == 10 and 3 <= family.count <= 4
    assert {n.ports.get("service_point") for n in patients.tree.walk() if n.node == "Queue"} == {"pharmacy_counter"}
    assert goto_targets(family.tree)[-1] == "main_entrance"


def test_a_group_sent_to_the_exit_walks_to_one_exit(clinic, grid):
    """"the exit" names no door; the group still walks to one (the exit nearest the scene)."""
    queued = queue_tree("pharmacy_counter")
    out = run(clinic, grid, "queuing", "ten patients queue at the pharmacy while a family walks to the exit",
              [DraftGroup("patients", 10, "pharmacy", queued), DraftGroup("patients", 4, "pharmacy", queued)])
    patients, family = out.groups
    assert {n.ports.get("service_point") for n in patients.tree.walk() if n.node == "Queue"} == {"pharmacy_counter"}
    assert clinic.find(goto_targets(family.tree)[-1]).exit  # the exit nearest the pharmacy the sentence names


def test_walking_to_the_zone_of_a_named_door_is_not_walking_to_the_door(clinic, grid):
    """The embedded model sent "a family walks to the exit" to the lobby the exit opens from: a
    door or thing the words name must be the goal itself; anywhere in a named zone is fine."""
    to_lobby = DraftNode("GoTo", {"target": "lobby"})
    out = run(clinic, grid, "normal", "a family walks to the main entrance",
              [DraftGroup("family", 4, "pharmacy", to_lobby)])
    assert goto_targets(out.groups[0].tree)[-1] == "main_entrance"
    out = run(clinic, grid, "normal", "ten patients queue at the pharmacy while a family walks to the exit",
              [DraftGroup("patients", 10, "pharmacy", queue_tree("pharmacy_counter")),
               DraftGroup("family", 4, "pharmacy", to_lobby)])
    assert clinic.find(goto_targets(out.groups[1].tree)[-1]).exit
    # A thing inside a named zone still counts as going to the zone: nothing is added.
    kept = run(clinic, grid, "normal", "two visitors walk to the cafeteria",
               [DraftGroup("visitors", 2, "lobby", DraftNode("GoTo", {"target": "vending_machine"}))])
    assert [n.node for n in kept.groups[0].tree.walk()] == ["GoTo"]


def test_people_who_come_in_through_a_door_start_there_and_leavers_go_there(clinic, grid):
    """"through" is where arrivals come from and where leavers go."""
    to_lobby = DraftNode("GoTo", {"target": "lobby"})
    out = run(clinic, grid, "normal", "four visitors come in through the main entrance and go to the cafeteria",
              [DraftGroup("visitors", 4, "cafeteria", to_lobby)])
    visitors = out.groups[0]
    assert visitors.spawn == clinic.find("main_entrance").zone
    assert "main_entrance" not in goto_targets(visitors.tree) and goto_targets(visitors.tree)[-1] == "cafeteria"
    out = run(clinic, grid, "normal", "four visitors in the cafeteria leave through the main entrance",
              [DraftGroup("visitors", 4, "cafeteria", to_lobby)])
    assert goto_targets(out.groups[0].tree)[-1] == "main_entrance"
    assert out.groups[0].spawn == "cafeteria"


def test_people_sent_to_one_door_or_thing_get_goal_points_of_their_own(clinic, grid):
    """Four people on one goal point jostle for it for the rest of the run; they stand side by side instead."""
    # (an exit is not among them: people sent to it leave through it, out of the scene)
    for target in ("lobby_corridor_door", "vending_machine"):
        out = run(clinic, grid, "normal", f"four visitors walk to the {target.replace('_', ' ')}",
                  [DraftGroup("visitors", 4, "pharmacy", DraftNode("GoTo", {"target": target}))])
        goals = [a.targets[-1][1] for a in out.agents]
        assert len(goals) == 4
        assert min(math.dist(a, b) for i, a in enumerate(goals) for b in goals[i + 1:]) >= GOAL_SPACING - 1e-9
        obj = clinic.find(target)
        anchor = obj.interaction_point if hasattr(obj, "interaction_point") else obj.position
        assert max(math.dist(g, anchor) for g in goals) < 3.0  # still at the door / the machine
        assert all(grid.is_free(*g) for g in goals)


def test_a_big_walking_group_walks_as_small_social_groups(clinic, grid):
    together = DraftNode("Sequence", {}, (DraftNode("JoinGroup", {}), DraftNode("GoTo", {"target": "cafeteria"})))
    out = run(clinic, grid, "normal", "twelve visitors walk together from the lobby to the cafeteria",
              [DraftGroup("visitors", 12, "lobby", together)])
    parties = {}
    for a in out.agents:
        parties.setdefault(a.sfm_group, []).append(a)
    assert sorted(len(p) for p in parties.values()) == [4, 4, 4] and -1 not in parties
    for members in parties.values():  # each party starts together
        assert max(math.dist(a.start, b.start) for a in members for b in members) < 3.0
    assert any("12 people walk together as 3 groups of 4" in n for n in out.notes)
    for members in parties.values():  # ... and arrives together: goal points next to each other, not
        goals = [a.targets[-1][1] for a in members]  # spread over the zone, pulling the group apart
        assert max(math.dist(g, h) for g in goals for h in goals) < 3.0
    spread = {a.targets[-1][1] for a in out.agents}
    assert len(spread) == 12 and min(math.dist(g, h) for g in spread for h in spread if g != h) >= GOAL_SPACING - 1e-9
    family = run(clinic, grid, "normal", "a family walks from the lobby to the cafeteria",
                 [DraftGroup("family", 4, "lobby", together)])
    assert len({a.sfm_group for a in family.agents}) == 1  # a family stays one group


def test_people_said_to_be_somewhere_stay_there(clinic, grid):
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "cafeteria"}), DraftNode("Converse", {"target": "cafeteria"})))
    out = run(clinic, grid, "normal", "three visitors in the cafeteria", [DraftGroup("visitors", 3, "cafeteria", tree)],
              nodes=("Sequence", "GoTo", "Wait", "Converse"))
    assert out.groups[0].spawn == "cafeteria"
    assert all(a.zone == "cafeteria" for a in out.agents)


def test_chatting_happens_where_the_words_put_it(clinic, grid):
    elsewhere = DraftNode("Converse", {"target": "pharmacy"})
    out = run(clinic, grid, "normal", "four nurses chat in the cafeteria", [DraftGroup("nurses", 4, "lobby", elsewhere)])
    assert [(n.node, n.ports.get("target")) for n in out.groups[0].tree.walk()] == [("Converse", "cafeteria")]
