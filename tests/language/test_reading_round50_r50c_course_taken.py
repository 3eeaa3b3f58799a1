"""Round 50 (r50c): a course a person is on is no place ("a lad on the knife-skills course"), so a world
without one refuses nothing (courses_taken.py), and a verb in "-s" after it, tagged a noun ("sidles
away"), is no part of the place's name (verb_after_place.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("tennis_club", "Nervous, a girl on the junior coaching course edges away from the robot."),
    ("museum", "A student on the art-history course sidles away from the robot."),
    ("hospital", "A nurse on the first-aid course walks to the pharmacy."),
    ("office", "Three trainees on an induction programme wait in the lobby."),
])
def test_a_course_people_are_on_is_no_place(read, world, prompt):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert reading.groups


@pytest.mark.parametrize("world,prompt", [
    ("museum", "A guard on the night-shift rota sidles away from the robot."),
    ("station", "A commuter by the ticket machines slinks off when the robot comes near."),
])
def test_a_verb_after_a_place_phrase_is_no_part_of_its_name(read, world, prompt):
    reading = read(world, prompt)
    assert not any("sidles" in u or "slinks" in u for u in reading.unknown_places)
    assert reading.groups[0].robot_interaction == "avoid"
