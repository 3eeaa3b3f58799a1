"""An event said with a day's possessive after "ahead of" ("tonight's whist drive", "Friday's sponsored
walk") is why people are there, whatever its head: no verb of going (ahead_of_events.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, sentence, location", [
    ("primary_school", "Two teachers stack cones in the playground ahead of Friday's sponsored walk.", "playground"),
    ("sports_centre", "A few coaches hang banners in the sports hall ahead of tomorrow's fun run.", "sports_hall"),
    ("community_centre", "Five or six helpers are putting out chairs in the main hall ahead of tonight's whist drive.",
     "main_hall"),
])
def test_day_event_is_a_purpose(read, world, sentence, location):
    g = read(world, sentence).groups[0]
    assert (g.start, g.location) == (None, location)
