"""What a sentence asks of the robot itself (PromptReading.robot) and how sure the reader is of each
field (GroupReading.confidence): the robot's clause is read for the robot and never for a group, and
a field the reader inferred carries a score below 1 and the reason."""

from __future__ import annotations

import pytest

from grove_tui.language.model import UNSURE_BELOW, PromptReading
from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,task,places", [
    ("hospital", "A robot drives from the pharmacy to ward B.", "cross", {"start": "pharmacy", "destination": "ward_b"}),
    ("hospital", "The delivery robot rolls along the main corridor to the cafeteria.", "cross",
     {"destination": "cafeteria", "via": ("main_corridor",)}),
    ("office", "Send the robot to the server room.", "cross", {"destination": "server_room"}),
    ("office", "Have the robot wait by the front desk.", "wait", {"location": "reception_desk"}),
    ("office", "The robot is in the kitchen.", "wait", {"location": "kitchen"}),
    ("station", "The robot patrols the concourse.", "patrol", {"location": "concourse"}),
    ("airport", "A cleaning robot sweeps the check-in hall.", "patrol", {"location": "check_in_hall"}),
    ("museum", "The robot crosses the great hall to the dinosaur gallery.", "cross",
     {"via": ("great_hall",), "destination": "dinosaur_gallery"}),
    ("residential", "The robot stays in the hallway.", "wait", {"location": "hallway"}),
])
def test_the_robot_s_own_clause_gives_its_task_and_places(worlds, world, prompt, task, places):
    robot = read_prompt(prompt, worlds[world]).robot
    assert robot is not None and robot.task == task, robot
    for role, want in places.items():
        assert getattr(robot, role) == want, (role, robot)


@pytest.mark.parametrize("world,prompt,group_places,robot_places", [
    # the group's clause, then the robot's after "while": the robot's places are never the group's
    ("station", "Eight commuters wait on platform 2 while a robot crosses the concourse to the ticket hall.",
     {"location": "platform_2", "destination": None}, {"destination": "ticket_hall", "via": ("concourse",)}),
    ("hospital", "The robot waits by the pharmacy counter while four visitors walk to the cafeteria.",
     {"destination": "cafeteria", "location": None}, {"location": "pharmacy_counter"}),
    ("office", "Three engineers chat in the kitchen as the robot drives from the reception to the boardroom.",
     {"location": "kitchen", "start": None}, {"start": "reception", "destination": "boardroom"}),
    ("museum", "A guide stands by the mummy case, and the robot rolls from the foyer to the café.",
     {"location": "mummy_case", "destination": None}, {"start": "entrance_hall", "destination": "cafe"}),
])
def test_a_group_never_takes_the_robot_s_places(worlds, world, prompt, group_places, robot_places):
    reading = read_prompt(prompt, worlds[world])
    assert len(reading.groups) == 1, reading.groups
    group = reading.groups[0]
    for role, want in group_places.items():
        assert getattr(group, role) == want, (role, group)
    assert reading.robot is not None
    for role, want in robot_places.items():
        assert getattr(reading.robot, role) == want, (role, reading.robot)


@pytest.mark.parametrize("world,prompt,interaction,via", [
    ("hospital", "The robot drives to ward A; two nurses step aside as it passes the nurse station.", "avoid",
     ("nurse_station",)),
    ("station", "The robot rolls to the café and a boy runs after it as it crosses the ticket hall.", "follow",
     ("ticket_hall",)),
    ("airport", "A robot heads to gate B2, and three travellers stare at it as it passes the cafe.", "look",
     ("cafe",)),
])
def test_where_the_robot_passes_is_its_way_and_the_group_reacts(worlds, world, prompt, interaction, via):
    reading = read_prompt(prompt, worlds[world])
    assert [g.robot_interaction for g in reading.groups] == [interaction]
    assert reading.groups[0].location is None and reading.groups[0].via == ()
    assert reading.robot is not None and reading.robot.task == "cross" and reading.robot.via == via


@pytest.mark.parametrize("prompt", ["Two children follow the robot.", "The robot is followed by two children.",
                                    "A nurse blocks its way when the robot comes near.",
                                    "Ten patients queue at the pharmacy counter."])
def test_reactions_to_the_robot_ask_nothing_of_the_robot_itself(worlds, prompt):
    reading = read_prompt(prompt, worlds["hospital"])
    assert reading.robot is None and reading.groups


def test_the_robot_follows_someone(worlds):
    reading = read_prompt("A porter walks to the waiting room and the robot follows him.", worlds["station"])
    assert reading.robot is not None and reading.robot.task == "follow" and reading.robot.follows == "A porter"
    assert [g.destination for g in reading.groups] == ["waiting_room"]


@pytest.mark.parametrize("world, prompt, followed", [
    # a pronoun points back to the group said last before the robot's clause ("them", "her")
    ("hospital", "Three visitors walk from the lobby to ward C and the robot follows them.", "Three visitors"),
    ("museum", "A class of pupils walks to the auditorium and then the robot follows them.", "A class of pupils"),
    ("office", "Two developers wait in the kitchen while a manager walks to the reception, and the robot follows "
               "her.", "a manager"),
    # "her" is one person, though a group was said after her
    ("station", "A guard walks to the ticket hall, four commuters wait on platform 1, and the robot follows her.",
     "A guard"),
])
def test_the_robot_follows_the_group_a_pronoun_points_back_to(worlds, world, prompt, followed):
    reading = read_prompt(prompt, worlds[world])
    assert reading.robot is not None and reading.robot.task == "follow"
    assert reading.robot.follows == followed


def test_the_robot_round_trips_through_plain_data(worlds):
    reading = read_prompt("Nine commuters queue at the ticket office while a robot crosses the booking hall to the "
                          "platforms.", worlds["station"])
    assert PromptReading.from_dict(reading.to_dict()) == reading


@pytest.mark.parametrize("prompt, seconds", [
    ("The robot waits at the cloakroom for two minutes.", 120.0),
    ("The robot waits at the cloakroom for a while.", 600.0),
    ("The robot waits at the cloakroom until closing.", None),  # the whole run: no length
    ("The robot waits at the cloakroom.", None),
])
def test_the_robot_s_wait_carries_its_asked_seconds(worlds, prompt, seconds):
    # the clause reader's stay, as a group's wait_seconds; without it a 10 s run earned the wait a ✓
    reading = read_prompt(prompt, worlds["museum"])
    assert reading.robot is not None and reading.robot.task == "wait" and reading.robot.location == "cloakroom"
    assert reading.robot.wait_seconds == seconds
    assert PromptReading.from_dict(reading.to_dict()).robot == reading.robot


# ---- confidence ------------------------------------------------------------------------------------


def test_a_sentence_that_says_everything_is_sure(worlds):
    reading = read_prompt("Ten patients walk from the pharmacy to the cafeteria.", worlds["hospital"])
    assert reading.groups[0].confidence == () and reading.unsure() == []


@pytest.mark.parametrize("world,prompt,field", [
    ("station", "A man waits on the platform.", "location"),  # two platforms alike
    ("hospital", "Two visitors walk to the corridor.", "destination"),  # three corridors
    ("airport", "A pilot sits at the gate desk.", "location"),  # four gate desks
])
def test_two_places_scoring_alike_are_unsure_with_the_alternatives(worlds, world, prompt, field):
    reading = read_prompt(prompt, worlds[world])
    conf = reading.groups[0].confidence_of(field)
    assert conf is not None and conf.unsure and conf.alternatives, reading.groups[0]
    assert getattr(reading.groups[0], field) not in conf.alternatives
    assert (0, conf) in reading.unsure()


def test_a_zone_named_before_decides_between_places_alike(worlds):
    g = read_prompt("On platform 2 a man sits on the bench.", worlds["station"]).groups[0]
    conf = g.confidence_of("location")
    assert g.location == "platform_2_bench"
    assert conf is None or not conf.unsure


@pytest.mark.parametrize("prompt,score_below", [
    ("Visitors walk to the cafeteria.", UNSURE_BELOW),  # no number at all: a guess
    ("A family walks to the cafeteria.", 0.7),  # a collective's usual size
    ("A few visitors walk to the cafeteria.", 0.8),  # a vague word's range
    ("About twenty visitors walk to the cafeteria.", 0.95),
])
def test_counts_that_are_not_said_outright_carry_how_sure_they_are(worlds, prompt, score_below):
    conf = read_prompt(prompt, worlds["hospital"]).groups[0].confidence_of("count")
    assert conf is not None and conf.score < score_below and conf.reason


def test_a_group_nobody_names_is_marked_as_assumed(worlds):
    reading = read_prompt("Evacuate the pharmacy.", worlds["hospital"])
    conf = reading.groups[0].confidence_of("group")
    assert conf is not None and conf.unsure and "assumed" in conf.reason


def test_an_unsure_robot_destination_is_reported(worlds):
    reading = read_prompt("A robot crosses the booking hall to the platforms.", worlds["station"])
    assert reading.robot is not None and reading.robot.destination in ("platform_1", "platform_2")
    assert any(index is None and c.field == "destination" for index, c in reading.unsure())
