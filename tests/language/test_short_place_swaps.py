"""A three-letter place word with two neighbouring letters swapped is read as the world's word when it
completes a name with the word beside it ("the oty shop": toy shop); a real word, or one that
completes no name, is left as written."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,role,place,fixed", [
    ("mall", "Two shoppers push a pram over to the oty shop.", "destination", "toy_store", "oty"),
    ("mall", "Four teenagers dawdle over to the burger abr.", "destination", "burger_counter", "abr"),
    ("museum", "A student sketches quietly in the modern atr gallery.", "location", "modern_art_gallery", "atr"),
])
def test_a_swapped_short_place_word_is_read_as_the_name(worlds, world, prompt, role, place, fixed):
    reading = read_prompt(prompt, worlds[world])
    group = reading.groups[0]
    assert getattr(group, role) == place, group
    assert any(f"'{fixed}'" in c for c in reading.corrections), reading.corrections


@pytest.mark.parametrize("world,prompt,word", [
    ("mall", "Two kids chase a rat towards the toy shop.", "rat"),  # a real word
    ("mall", "A courier waits by the oty for ten minutes.", "oty"),  # completes no name
])
def test_a_real_or_lone_short_word_is_left_as_written(worlds, world, prompt, word):
    reading = read_prompt(prompt, worlds[world])
    assert not any(f"'{word}'" in c for c in reading.corrections), reading.corrections
