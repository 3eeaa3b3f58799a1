"""People described by their shift ("on lates", "on shift", "on duty") go where the verb says, and a
place's head noun after a compound ("rather than the staff lounge") is no verb of what they do, even one
the lexicon knows as a verb ("lounge"), as object of a preposition or joined by "rather than" (issue 29).
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal", [
    ("hotel", "A pair of porters on shift go across to the restaurant for bacon sandwiches rather than the staff "
              "lounge.", "restaurant"),
    ("library", "Three librarians on lates go over to the café for cheese scones rather than the staff lounge.",
     "cafe"),
    ("primary_school", "Two teachers on duty go across to the hall for fish fingers rather than the staff lounge.",
     "school_hall"),
])
def test_a_place_noun_after_a_compound_is_no_verb(read, world, prompt, goal):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination) == ("walk", goal)
