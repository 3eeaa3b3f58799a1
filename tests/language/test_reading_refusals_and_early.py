"""Three readings of the nineteenth session, in worlds other than the sentences that showed them:
a refusal of the robot's way after an earlier mention of it ("crowd round the robot and won't let it
through") is a block, and "refuse to ..." opens no purpose; an event people are early for ("ahead of
the 3 pm show", "in advance of the lecture") is their purpose, while "ahead of the class" (people) is
none; "new starter", "new hire" name a person. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Four fans crowd around the robot by the fountain and refuse to let it pass."),
    ("museum", "Three teenagers surround the robot in the main hall and will not let it by."),
    ("station", "Two kids follow the robot along the concourse and won't let it leave."),
    ("airport", "A group of five tourists gathers round the robot at check-in and won't let it through."),
])
def test_a_later_refusal_of_the_robots_way_is_a_block(read, world, prompt):
    g, = read(world, prompt).groups
    assert (g.robot_interaction, g.robot_reaction) == ("block", "Threatening")
    assert not (g.purpose or "").startswith("to let")


def test_letting_the_robot_pass_stays_what_it_was(read):
    g, = read("mall", "Two kids wave at the robot by the fountain and let it pass.").groups
    assert g.robot_interaction == "look"


@pytest.mark.parametrize("world,prompt,event", [
    ("hospital", "About twenty students wait outside the lecture theatre ahead of the 2 pm lecture.", "lecture"),
    ("museum", "Ten pupils gather in the main hall in advance of the guided talk.", "talk"),
    ("mall", "Forty fans queue outside the cinema ahead of the midnight screening.", "screening"),
])
def test_an_event_people_are_early_for_is_their_purpose(read, world, prompt, event):
    g, = read(world, prompt).groups
    assert event in (g.purpose or "")


def test_ahead_of_people_is_no_purpose(read):
    groups = read("museum", "Two guides walk ahead of the class to the main hall.").groups
    assert not any("class" in (g.purpose or "") for g in groups)


@pytest.mark.parametrize("world,prompt,label", [
    ("office", "The new hire waits at reception while two managers walk to the kitchen.", "new hire"),
    ("hospital", "A new starter follows the ward manager to the nurses' station.", "new starter"),
])
def test_new_starters_are_people(read, world, prompt, label):
    assert label in [g.label for g in read(world, prompt).groups]
