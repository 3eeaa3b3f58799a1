"""A bare verb of crowding after a counted plural is the verb, not a collective (language/plural_gathering_verbs.py):
"fifteen student medics crowd round the cafe" is fifteen people, not fifteen crowds."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("museum", "Fifteen student medics crowd round the cafe.", [15]),
    ("airport", "Ten student paramedics crowd round the cafe.", [10]),
    ("hospital", "Eleven trainee medics crowd round the pharmacy, and four of them walk off to the exit.", [11, 4]),
]


@pytest.mark.parametrize("world, sentence, counts", CASES)
def test_the_crowding_verb_counts_no_crowds(world, sentence, counts):
    groups = read_prompt(sentence, load_world(world)).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exact", n) for n in counts]


def test_a_crowd_after_its_article_is_still_a_crowd():
    group, = read_prompt("A crowd of fans waits at the cafe.", load_world("museum")).groups
    assert group.count.kind != "exact"
