"""Keyboard slips (language/chat_slips.py): swapped small words ("teh", "adn") and the dropped "g" of a
verb the lexicon does not know after "are" ("are muckin out") are read as the English they stand for."""

from __future__ import annotations

import pytest

from grove_tui.language.chat_slips import written_out


@pytest.mark.parametrize("typed,read", [
    ("Teh nurses adn porters", "The nurses and porters"),
    ("cleaners were hosin down the yard", "cleaners were hosing down the yard"),
    ("They are certain the lift works", "They are certain the lift works"),
    ("We are Robin out back", "We are Robin out back"),
    ("the cabin out back", "the cabin out back"),
])
def test_written_out(typed, read):
    assert written_out(typed) == read


@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "Three nurses are waitin in teh cafeteria.", "cafeteria"),
    ("city_farm", "Two volunteers are muckin out hte goat barn.", "goat_barn"),
    ("office", "Two cleaners are hoovrin out teh boardroom.", "boardroom"),
])
def test_slipped_prompts_read_their_place(read, world, prompt, location):
    reading = read(world, prompt)
    assert len(reading.groups) == 1 and reading.unknown_places == ()
    g = reading.groups[0]
    if location is not None:
        assert location in (g.location, g.start, g.destination)
