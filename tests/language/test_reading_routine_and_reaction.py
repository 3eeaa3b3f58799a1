"""A group asked to do something and to react to the robot keeps the something: "six patients queue at the
pharmacy and look at the robot as it passes" reads intent "robot", interaction "look" (the convention of the
understanding sets) and, beside it, routine "queue" at the pharmacy. Before, the queue was lost: the reading
had only the reaction, reconcile removed the model's Queue and the report claimed no queue. A reaction alone
keeps routine None. Real spaCy, shipped worlds and understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.model import GroupReading
from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world

LIBRARY = "eval/understanding/worlds/library.yaml"
RINK = "eval/understanding/worlds/ice_rink.yaml"


@cache
def _world(name: str):
    return load_world(name)


def _group(world: str, sentence: str) -> GroupReading:
    reading = read_prompt(sentence, _world(world))
    assert len(reading.groups) == 1, reading.groups
    return reading.groups[0]


# (world, sentence, interaction, routine, the routine's place field, the place, wait seconds)
CASES = [
    ("hospital", "Six patients queue at the pharmacy and look at the robot as it passes.", "look", "queue",
     "location", "pharmacy", None),
    ("hospital", "Four visitors wait in the cafeteria for ten seconds and avoid the robot.", "avoid", "wait",
     "location", "cafeteria", 10.0),
    ("hospital", "Three nurses walk to ward A and keep away from the robot.", "avoid", "walk", "destination",
     "ward_a", None),
    ("hospital", "Queuing at the pharmacy, five patients glance at the robot.", "look", "queue", "location",
     "pharmacy", None),
    ("museum", "Eight tourists queue at the ticket desk while watching the robot.", "look", "queue", "location",
     "ticket_desk", None),
    ("museum", "Two guards chat in the lobby and keep clear of the robot.", "avoid", "converse", "location",
     "entrance_hall", None),
    ("museum", "Five visitors walk to the gift shop, staring at the robot as it passes.", "look", "walk",
     "destination", "gift_shop", None),
    (LIBRARY, "Four students walk to the reading room and avoid the robot.", "avoid", "walk", "destination",
     "reading_room", None),
    (LIBRARY, "Three readers wait at the issue desk for a minute and watch the robot go by.", "look", "wait",
     "location", "issue_desk", 60.0),
    (RINK, "Ten skaters queue at the skate hire counter and stare at the robot.", "look", "queue", "location",
     "hire_counter", None),
    (RINK, "Two parents wait at the rinkside for thirty seconds while keeping away from the robot.", "avoid",
     "wait", "location", "rinkside", 30.0),
    ("station", "Seven commuters queue at the ticket office and glance at the robot as it goes past.", "look",
     "queue", "location", "ticket_office", None),
    ("station", "Two travellers walk to platform 2, avoiding the robot.", "avoid", "walk", "destination",
     "platform_2", None),
]


@pytest.mark.parametrize("world, sentence, interaction, routine, field, place, seconds", CASES)
def test_the_routine_beside_the_reaction(world, sentence, interaction, routine, field, place, seconds):
    g = _group(world, sentence)
    assert (g.intent, g.robot_interaction, g.routine) == ("robot", interaction, routine), g
    assert getattr(g, field) == place, g
    assert g.wait_seconds == seconds, g


def test_a_routine_read_from_the_words_before_the_group_is_less_sure():
    g = _group("hospital", "Queuing at the pharmacy, five patients glance at the robot.")
    confidence = g.confidence_of("routine")
    assert confidence is not None and 0.6 <= confidence.score < 1.0, g.confidence
    assert _group("hospital", "Six patients queue at the pharmacy and look at the robot.").confidence_of(
        "routine") is None


def test_the_routine_round_trips():
    g = _group("hospital", "Six patients queue at the pharmacy and look at the robot as it passes.")
    back = GroupReading.from_dict(g.to_dict())
    assert back == g and back.routine == "queue"
    # a reading written before the field had it reads as no routine
    old = {k: v for k, v in g.to_dict().items() if k != "routine"}
    assert GroupReading.from_dict(old).routine is None


GUARDS = [
    ("hospital", "A man walks up to the robot."),
    ("hospital", "Two porters stare at the robot in the main corridor."),
    ("hospital", "A child follows the robot to the cafeteria."),
    ("hospital", "Two nurses stop and stare at the robot."),
    ("hospital", "A boy runs over to look at the robot."),
    ("museum", "A child runs away from the robot."),
    ("museum", "A visitor chats to the robot in the lobby."),
    ("museum", "Children crowd around the robot in the lobby."),
    ("museum", "Two guards stand at the ticket desk and block the robot."),
    (LIBRARY, "A librarian steers clear of the robot."),
    (LIBRARY, "A student walks away from the robot."),
    (RINK, "A steward blocks the robot at the rinkside."),
]


def test_a_reaction_alone_has_no_routine():
    for world, sentence in GUARDS:
        g = _group(world, sentence)
        assert g.intent == "robot" and g.robot_interaction, (sentence, g)
        assert g.routine is None, (sentence, g)


def test_people_who_do_not_react_have_no_routine():
    reading = read_prompt("Six patients queue at the pharmacy while two children stare at the robot.",
                          _world("hospital"))
    patients, children = reading.groups
    assert (patients.intent, patients.routine) == ("queue", None)
    assert (children.intent, children.routine) == ("robot", None)
