"""A place whose own name holds a word for the robot ("the robot lab", "the robot arena") is a place
of the world, read as any other: the robot word inside a whole name or alias is no mention of the
robot. Only the university world names places so; other words and sentences than the held-out case.
Real spaCy, understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


CASES = [
    ("The robot escorts two visiting professors from the main corridor to the robot arena.",
     "main_corridor", "test_arena"),
    ("Our robot takes a prospective student from the lobby to the robot lab.", "entrance_foyer", "robotics_lab"),
]


@pytest.mark.parametrize(("sentence", "start", "destination"), CASES)
def test_a_place_named_with_a_robot_word_is_read(sentence: str, start: str, destination: str) -> None:
    reading = read_prompt(sentence, _world("university"))
    assert reading.robot is not None
    assert (reading.robot.start, reading.robot.destination) == (start, destination)
    assert reading.unknown_places == ()
