"""One person said by an age, then a verb no lexicon lists ("our ten-year-old trudges"), is that one
person (language/age_nouns.py)."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

CASES = [
    ("residential", "Our ten-year-old trudges to the kitchen."),
    ("residential", "The 7-year-old staggers to the kitchen."),
    ("mall", "Sleepy, my six-year-old stumbles towards the fountain."),
]


@pytest.mark.parametrize("world, sentence", CASES)
def test_an_age_then_an_unlisted_verb_is_one_person(world, sentence):
    group, = read_prompt(sentence, load_world(world)).groups
    assert (group.count.kind, group.count.value) == ("exact", 1)


def test_an_age_then_a_person_word_is_still_that_person():
    group, = read_prompt("Our 8-year-old twins clamber to the kitchen.", load_world("residential")).groups
    assert group.count.value == 2
