"""A relative clause of what people did before the scene (language/relative_pasts.py): "kids who've sat
through the film pile out of X" is a walk out of X, not a wait at a place "through" names."""

from __future__ import annotations

import pytest

from grove_tui.language.relative_pasts import without_relative_pasts


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Six visitors who have sat through the talk file out of the cafeteria to the pharmacy.",
     "cafeteria", "pharmacy"),
    ("office", "Four interns who've watched the induction video stream out of the boardroom into the kitchen.",
     "boardroom", "kitchen"),
])
def test_the_relative_clause_is_not_their_verb(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert len(reading.groups) == 1 and reading.unknown_places == ()
    g = reading.groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


@pytest.mark.parametrize("text", [
    "The nurses who have waited in the lounge walk to the cafeteria.",  # where they were: kept
    "Two men who work here walk out.",  # no past verb
    "Ten fans who bought a ticket queue at the gate.",  # no verb of going
])
def test_other_relative_clauses_are_kept(text):
    assert without_relative_pasts(text) == text
