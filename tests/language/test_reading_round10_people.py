"""Round 10 of the reader on people, counts and clauses: sentences written for it over shipped and
extra worlds, each a class of phrasing (a second task after the first, ...)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, label, count, destination", [
    ("station", "the robot waits on platform 1, then leads passengers to the exit", "passenger", None, None),
    ("station", "The robot waits on platform 1 and then guides 5 passengers to the main entrance", "passenger", 5,
     "main_entrance"),
    ("station", "The robot patrols the concourse, then escorts an elderly man to platform 2", "man", 1, "platform_2"),
    ("hotel", "The robot waits in the lobby and later takes two guests to the lift lobby", "guest", 2, "lift_lobby"),
])
def test_people_the_robot_takes_along_in_its_second_task(read, world, prompt, label, count, destination):
    r = read(world, prompt)
    assert r.robot is not None
    assert [g.label for g in r.groups] == [label]
    g = r.groups[0]
    assert g.robot_interaction == "follow"
    assert count is None or g.count.value == count
    assert destination is None or g.destination == destination


def test_people_a_person_takes_along_in_a_second_task(read):
    r = read("university", "A porter waits in the entrance foyer, then leads 4 visitors to the canteen")
    assert [(g.label, g.count.value) for g in r.groups] == [("porter", 1), ("visitor", 4)]
    assert r.groups[1].destination == "canteen"


def test_a_leading_verb_after_then_names_nobody(read):
    r = read("library", "The robot waits in the foyer and then guides 3 students to the reading room")
    assert [g.label for g in r.groups] == ["student"]
    assert [g.label for g in read("library", "Two guides wait in the entrance foyer").groups] == ["guide"]
