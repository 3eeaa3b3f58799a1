"""A fronted stay said with a past participle of being kept somewhere (issue 29): "After twenty minutes
stuck at X, ..." is as long a wait at X as "After twenty minutes waiting at X": they start there. Real
spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, goal, seconds", [
    ("hospital", "After an hour stranded in the waiting room, a patient limps over to the pharmacy.",
     "main_waiting_room", "pharmacy", 3600),
    ("mall", "After half an hour sat at the food court, two teens wander over to the cinema.", "food_court",
     "cinema_lobby", 1800),
    ("airport", "After twenty minutes stuck at lost and found, a frazzled tourist gives up and trudges over to the "
     "rental desk.", "lost_luggage_desk", "car_rental_desk", 1200),
])
def test_a_fronted_stay_stuck_somewhere_is_a_wait_there(read, world, prompt, start, goal, seconds):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, goal)
    assert group.wait_seconds == seconds
