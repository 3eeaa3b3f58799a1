"""A person named by the place they work at is at that place when nothing else says where (issue 29).
Real spaCy, real worlds (cruise_ship from eval/understanding/worlds)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("hospital", "The cafeteria staff chat among themselves.", "cafeteria"),
    ("mall", "A bored cinema attendant hangs about.", "cinema_lobby"),
    ("hospital", "A pharmacy assistant restocks the shelves.", "pharmacy"),
    ("cruise_ship", "Two casino staff stand around chatting.", "casino"),
])
def test_a_worker_named_by_a_place_is_there(read, world, prompt, place):
    assert read(world, prompt).groups[0].location == place


def test_a_place_said_outright_wins(read):
    group = read("hospital", "The cafeteria staff walk to the main entrance.").groups[0]
    assert (group.destination, group.location) == ("main_entrance", None)
