"""A participle set off before or around the person ("Intrigued by the flashing LEDs, a toddler ...",
"a girl, dazzled by the chandeliers, ...") names after "by" what drew or stirred them: no place to read
or refuse. A participle of position ("Seated by the window") still says where. Real spaCy,
understanding worlds, no model."""

from __future__ import annotations

from functools import cache

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world.loader import load_world
from grove_tui.world.model import World


@cache
def _world(name: str) -> World:
    return load_world(f"eval/understanding/worlds/{name}.yaml")


CAUGHT = [
    ("hotel", "A little girl, dazzled by the chandeliers, skips from the lobby towards the robot.", "lobby"),
    ("food_bank", "Puzzled by the humming motors, a small boy creeps out of the play corner towards the robot.",
     "childrens_corner"),
    ("tennis_club", "Slightly startled by the beeping sensors, a junior backs away from the foyer.", "foyer"),
]


@pytest.mark.parametrize(("world", "sentence", "start"), CAUGHT)
def test_what_stirred_them_is_no_place(world: str, sentence: str, start: str) -> None:
    reading = read_prompt(sentence, _world(world))
    assert reading.unknown_places == (), reading.unknown_places
    assert reading.groups[0].start == start


def test_a_participle_of_position_still_says_where() -> None:
    reading = read_prompt("Seated by the window, a guest reads in the lobby.", _world("hotel"))
    assert reading.groups[0].location == "lobby"
