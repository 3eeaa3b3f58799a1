"""A place chosen over another is where they go, the other no destination
(language/preferred_places.py); the floor a cleaner works on is of the place said next
(language/clauses.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("office", "Two engineers choose the kitchen over the boardroom.", "kitchen"),
    ("airport", "A pair of backpackers pick the cafe over the airline lounge.", "cafe"),
    ("pub", "The darts team prefer the games room to the snug.", "games_room"),
    ("library", "Three students opt for the computer lab.", "computer_lab"),
])
def test_a_place_chosen_over_another_is_the_destination(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.destination) == ("walk", place)
    assert group.location is None


@pytest.mark.parametrize("world, prompt, place", [
    ("hospital", "A cleaner mops the floor in the pharmacy.", "pharmacy"),
    ("museum", "A porter sweeps the floor outside the cafe.", None),  # beside the café, never a room named "floor"
    ("office", "A cleaner hoovers the floor by the kitchen.", None),
])
def test_the_floor_cleaned_is_of_the_place_said_next(read, world, prompt, place):
    location = read(world, prompt).groups[0].location
    assert location == place if place is not None else location not in (None, "open_plan_office")
