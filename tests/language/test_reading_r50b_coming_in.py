"""Round 50 (r50b): coming in by a door and then settling somewhere is going there (coming_in.py): "let
themselves in" is coming in, and "sit down" after "come in" does not make the clause a wait at the door."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("tennis_club", "Early on Saturday, four members let themselves in by the car park gate and settle in the lounge.",
     "car_park_gate", "bar_lounge"),
    ("tennis_club", "Two coaches come in through the clubhouse door and sit down in the bar.", "clubhouse_door", "bar_lounge"),
    ("vaccination_centre", "Two nurses come in through the staff door and sit down at the observation desk.",
     "vaccination_staff_door", "observation_desk"),
])
def test_coming_in_then_settling_is_going_there(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)


def test_sitting_down_without_coming_in_is_still_a_wait(read):
    (group,) = read("tennis_club", "Two coaches sit down in the bar.").groups
    assert group.intent == "wait"
