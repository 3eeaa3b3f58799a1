"""A fronted "while" clause in the passive with its doer said by "by" ("While the tills are restocked by a
cashier, a shopper waits ..."): the doer is not listed with the people after the comma; they stay at
the place worked on. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, doer, others", [
    ("supermarket", "While the tills are restocked by a cashier, a shopper waits at the bakery.",
     "checkouts", "bakery"),
    ("hospital", "As the pharmacy is being cleaned by a porter, two nurses wait in the lobby.",
     "pharmacy", "entrance_lobby"),
])
def test_the_doer_stays_at_the_place_worked_on(read, world, prompt, doer, others):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == [doer, others]
