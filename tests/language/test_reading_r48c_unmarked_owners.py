"""Another kind of person's place said without an apostrophe ("the family lounge", "the punters
lounge") where the world's one place of that kind is someone else's (the residents', the owners' and
trainers'): a place the world lacks, refused, not read as the other's. A place of that person under
another head ("the staff lounge" with a staff room) is not refused. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, unknown", [
    ("care_home", "Two visitors walk from the family lounge to the dining room.", "family lounge"),
    ("racecourse", "A bookie waits in the punters lounge.", "punters lounge"),
])
def test_another_kinds_place_is_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


def test_the_owners_place_under_another_head_is_not_refused(read):
    assert read("care_home", "A carer sits in the staff lounge.").unknown_places == ()


def test_the_place_of_the_owner_said_is_still_read(read):
    group = read("racecourse", "Two jockeys walk from the owners lounge to the parade ring.").groups[0]
    assert group.start == "owners_trainers_lounge"
