"""Round 60 (r60a): a chore verb in "-s" the parser took for a noun ("a commis preps vegetables in the
kitchen, ...") is the clause's verb, and its doer is one person (language/chore_verbs_tagged.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts,first_at", [
    ("hotel", "A commis preps vegetables in the kitchen, two guests wait at the bar, and a couple of porters "
              "carry bags to the lobby.", [1, 2, 2], "kitchen"),
    ("supermarket", "A trainee portions cheese at the deli counter, three shoppers browse the cake counter, and two "
                    "kids queue at the tills.", [1, 3, 2], "deli_counter"),
])
def test_first_clause_chore_doer_is_read(read, world, prompt, counts, first_at):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert groups[0].location == first_at


def test_zoo_keeper_preps_fish(read):
    groups = read("zoo", "A keeper preps fish in the keepers' yard, around fifteen children watch the penguins, and a "
                         "couple of teens line up for cones at the ice cream hut.").groups
    assert [g.count.value for g in groups] == [1, 15, 2]
