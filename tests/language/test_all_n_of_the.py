"""Round 53 (r53a): "all N of the X" is one group of N, the X themselves, no part of a larger whole
(language/partitives.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,n", [
    ("hospital", "All twelve of the nurses walk to the cafeteria.", 12),
    ("hospital", "All 3 of the porters wait at reception.", 3),
    ("office", "All seven of the cleaners walk from the lobby to the kitchen.", 7),
])
def test_all_n_of_the_is_one_group(read, world, prompt, n):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", n)


def test_a_part_keeps_its_whole(read):
    assert len(read("office", "Two of the cleaners wait in the lobby.").groups) == 2


def test_quoted_case(read):
    (group,) = read("office", "At 9:30 sharp, all 7 of the sales reps troop from the office floor into the "
                              "boardroom for stand-up.").groups
    assert (group.count.value, group.start, group.destination) == (7, "open_plan_office", "boardroom")
