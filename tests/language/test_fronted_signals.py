"""Round 52 (r52a): the subject of a fronted time clause who only gives the signal ("When the
teacher claps", "Once the nurse calls out") is no group of its own (language/signal_fronts.py); one who
moves is kept; "N of the audience" is the one group, the audience no second group
(language/collective_parts.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "When the teacher claps, twenty pupils walk from reception to the cafeteria.", 20),
    ("hospital", "Once the nurse calls out, two patients walk from reception to the cafeteria.", 2),
    ("hospital", "When the porter blows the whistle, two patients walk from reception to the cafeteria.", 2),
])
def test_a_signal_giver_in_a_fronted_clause_is_no_group(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.value == value and group.destination == "cafeteria"


def test_a_mover_in_a_fronted_clause_is_kept(read):
    groups = read("hospital", "As soon as the manager arrives, three staff walk from reception to the cafeteria.").groups
    assert len(groups) == 2


@pytest.mark.parametrize("prompt", [
    "Once the band stops, around eighty of the audience surge out of the stalls into the stalls bar.",
    "Twenty of the audience walk out of the stalls into the stalls bar.",
])
def test_part_of_the_audience_is_the_one_group(read, prompt):
    (group,) = read("concert_venue", prompt).groups
    assert group.start == "stalls" and group.destination == "stalls_bar"
