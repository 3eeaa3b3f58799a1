"""A part of a counted group that leaves with a verb of parting the parser takes for a noun ("four peel
off", "three break away", "six slope off"): the part is a group of its own, a subset of the whole, going
where it goes. Real spaCy, real worlds."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt

DATA_CENTRE = "eval/understanding/worlds/data_centre.yaml"


@pytest.mark.parametrize("world, prompt, whole, part, destination", [
    ("hospital", "Of the ten visitors in the cafeteria, three break away to the pharmacy.", 10, 3, "pharmacy"),
    ("museum", "Of the fifteen pupils in the main hall, six slope off to the cafe.", 15, 6, "cafe"),
    ("office", "Of the eight engineers in the open office, two peel off to the kitchen.", 8, 2, "kitchen"),
])
def test_a_part_that_parts_from_a_counted_group_is_its_own_group(worlds, world, prompt, whole, part, destination):
    reading = read_prompt(prompt, worlds[world], seed=0)
    assert [g.count.value for g in reading.groups] == [whole, part], [g.who for g in reading.groups]
    moved = reading.groups[1]
    assert moved.relation == "subset_of:0" and moved.destination == destination
