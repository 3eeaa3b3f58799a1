"""Round 46 (r46a): a passive with "by" opened by "while", "as" ("While the cafeteria gets mopped by two
cleaners, the robot ...") names the doer and the place it is done in: the doer is in the passive's subject
place, as when the passive opens the sentence (clauses.py, _OPENING_LINKS)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,location", [
    ("hospital", "While the cafeteria gets mopped by two cleaners, the robot takes a parcel to the pharmacy.", 2,
     "cafeteria"),
    ("hospital", "As the pharmacy is restocked by a porter, the robot waits in the lobby.", 1, "pharmacy"),
    ("museum", "While the cafe is swept by a volunteer, the robot heads to the foyer.", 1, "cafe"),
])
def test_the_doer_of_a_passive_opened_by_while_is_in_its_place(read, world, prompt, count, location):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.location) == (count, location)
