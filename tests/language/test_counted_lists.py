"""Round 55 (r55a): one count before a list of three or more kinds of people ("fifteen nurses, carers
and volunteers") is one group of that count, as "ten men and women" is; a kind with its own count
ends the list (language/counted_lists.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospice", "Fifteen nurses, carers and volunteers gather in the lounge.", 15),
    ("hotel", "About thirty guests, porters, and cleaners wait in the lobby.", 30),
    ("prison_visits_centre", "Forty-odd dads, sisters and grandparents queue at the booking-in desk.", 40),
])
def test_a_count_before_a_list_of_kinds_is_one_group(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value


def test_kinds_with_their_own_counts_stay_apart(read):
    groups = read("hotel", "Ten nurses, two porters and a cleaner wait in the lobby.").groups
    assert [g.count.value for g in groups] == [10, 2, 1]
