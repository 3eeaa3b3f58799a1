"""Nouns for a group of a set size count their people: "a foursome of teens" is four, "a twosome" two, "a
sextet" six (lexicon.IMPLIED_RANGES), as "a trio" and "a quartet" were."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


@pytest.mark.parametrize("world, sentence, count", [
    ("mall", "A foursome of teens hangs about by the fountain.", 4),
    ("eval/understanding/worlds/cinema.yaml", "A foursome of lads at the bar ignore the robot.", 4),
    ("museum", "A twosome of pensioners strolls to the cafe.", 2),
    ("office", "A sextet of interns crowds into the kitchen.", 6),
])
def test_a_group_noun_of_a_set_size_counts_its_people(world, sentence, count):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert group.count.value == count and group.together
