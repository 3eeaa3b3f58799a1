"""A "for" event after a place whose name ends in a word for people ("the kids' club", "the health club",
"the year six class") is why they go there, not something done for a club of people."""

import pytest


@pytest.mark.parametrize("world,prompt,purpose", [
    ("hotel", "Two guests stroll down to the health club for the aqua aerobics session.", "aqua aerobics"),
    ("primary_school", "A teaching assistant walks to the year six class for the spelling test.", "spelling test"),
    ("cruise_ship", "A steward walks to the kids' club for the magic show.", "magic show"),
])
def test_a_for_event_after_a_named_place_is_a_purpose(read, world, prompt, purpose):
    (group,) = read(world, prompt).groups
    assert purpose in (group.purpose or "")


def test_waiting_for_a_person_is_unchanged(read):
    (group,) = read("hospital", "A nurse waits for the porter.").groups
    assert group.count.value == 1
