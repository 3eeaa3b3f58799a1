"""Round 44: a purpose whose verb is also a one-word name of a place ("to check tomorrow's rota" where the
reception is also "check-in") is a purpose when an object follows the verb; the scorer looks for the
purpose's words in the reading's purpose."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination,said", [
    ("day_spa", "Helen walks to the nail bar to check the rota.", "nail_bar", "rota"),
    ("hotel", "The night porter nips down to the front desk to check tomorrow's bookings.", "reception_desk",
     "bookings"),
    ("office", "Two interns go to reception to print their boarding passes.", "reception", "boarding passes"),
])
def test_a_verb_with_its_object_is_a_purpose(read, world, prompt, destination, said):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)
    assert said in (g.purpose or "")


def test_a_place_named_after_to_is_still_where_they_go(read):
    (g,) = read("day_spa", "A guest goes to check-in.").groups
    assert g.destination in ("reception", "reception_desk")
