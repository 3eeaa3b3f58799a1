"""Round 44: a plural thing one letter from a word for people ("scones" and "sons", "brooms" and "grooms")
is no misspelt person when its singular is an English word: in a list whose item's verb the parser takes
for a noun ("four volunteers butter scones in the kitchen, and a driver hangs about ...") it is no group,
nor anywhere else ("brooms stand in the corridor"). A true misspelling ("childern", "passangers") is read
as the people it means."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,people", [
    ("hotel", "Two maids chat in the laundry while brooms lean against the wall.", 1),
    ("hotel", "A porter waits by the lifts; brooms stand in the corridor.", 1),
    ("community_centre", "The caretaker sweeps the main hall, four volunteers butter scones in the kitchen, and a "
                         "delivery driver hangs about by the noticeboard.", 3),
])
def test_a_thing_one_letter_from_people_is_no_group(read, world, prompt, people):
    groups = read(world, prompt).groups
    assert len(groups) == people
    assert all(g.label not in ("scone", "broom", "son", "groom") for g in groups)


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "Five childern walk to the cafeteria.", 5),
    ("hospital", "Three passangers wait in the lobby.", 3),
])
def test_a_misspelt_word_for_people_is_still_people(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert g.count.value == count
