"""Round 50 (r50c): a verb and its particle joined by a hyphen after "to" ("walks to check-in", "head to
drop-off") is where people go, not a purpose "to check" (hyphened_nouns.py); written apart ("to check
in") it stays a purpose."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination", [
    ("ferry_terminal", "Two drivers stroll to check-in.", "check_in_hall"),
    ("airport", "A couple wheel their trolley to check-in.", "check_in_hall"),
])
def test_to_a_hyphened_place_is_a_walk_there(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.destination, group.purpose) == (destination, None)


def test_to_check_in_written_apart_stays_a_purpose(read):
    group = read("airport", "A family walks to the desk to check in.").groups[0]
    assert group.purpose == "to check in"
