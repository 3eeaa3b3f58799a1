"""A kind of place searched for with "the" in one word ("in search of the library", "looking for the
pharmacy") that the world has no place of is refused, as a place said; one the world has is not."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,refused", [
    ("residential", "Two teens drift out of the kitchen in search of the library.", "library"),
    ("residential", "Grandpa shuffles out of the bedroom looking for the pharmacy.", "pharmacy"),
    ("office", "A pair of interns wander out of the boardroom hunting for the chapel.", "chapel"),
])
def test_a_one_word_kind_searched_for_is_refused(worlds, world, prompt, refused):
    assert refused in read_prompt(prompt, worlds[world]).unknown_places


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Three pensioners drift out of the gift shop in search of the cafe."),
    ("museum", "A tourist wanders out of the great hall looking for the cloakroom."),
])
def test_a_kind_the_world_has_is_not_refused(worlds, world, prompt):
    assert read_prompt(prompt, worlds[world]).unknown_places == ()
