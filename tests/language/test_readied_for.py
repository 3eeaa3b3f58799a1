"""What a purpose of getting ready is for ("to set up for dinner") is part of the purpose (issue 29).
Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, goal, occasion", [
    ("hospital", "Two porters go to the cafeteria to get ready for the lunch rush.", "cafeteria", "lunch rush"),
    ("mall", "A busker heads to the food court to prepare for his show.", "food_court", "show"),
    ("cruise_ship", "Four waiters hurry to the casino to set up for the evening quiz.", "casino", "quiz"),
])
def test_what_they_get_ready_for_is_the_purpose(read, world, prompt, goal, occasion):
    group = read(world, prompt).groups[0]
    assert group.destination == goal
    assert occasion in (group.purpose or "")


def test_a_time_after_for_is_no_occasion(read):
    group = read("hospital", "A nurse walks to the pharmacy to set up for a while.").groups[0]
    assert "while" not in (group.purpose or "")
