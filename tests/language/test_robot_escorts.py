"""The robot keeping someone company to a place takes them there: it crosses, they follow it."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


@pytest.mark.parametrize("world, sentence, destination", [
    (W + "care_home.yaml", "Mrs Patel is lost in the garden, so the robot accompanies her back to the lounge.", "lounge"),
    (W + "hotel.yaml", "An elderly guest has wandered into the spa, so the robot sees her back to the lifts.",
     "lift_lobby"),
    (W + "aquarium.yaml", "The robot sees a lost boy back to the gift shop.", "gift_shop"),
    (W + "hotel.yaml", "The robot accompanies an elderly guest to the lifts.", "lift_lobby"),
])
def test_the_person_kept_company_to_a_place_follows_the_robot(world, sentence, destination):
    reading = read_prompt(sentence, load_world(world))
    assert reading.robot is not None and (reading.robot.task, reading.robot.destination) == ("cross", destination)
    assert [g.robot_interaction for g in reading.groups] == ["follow"]


def test_keeping_company_with_no_place_is_still_following():
    reading = read_prompt("The robot accompanies the librarian on her rounds.", load_world(W + "library.yaml"))
    assert reading.robot is not None and reading.robot.task == "follow"
