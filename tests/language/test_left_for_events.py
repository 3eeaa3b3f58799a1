"""People who leave a place for an event said with its own place (language/left_for_events.py): they walk
from the place they leave to the event's place; the event is no place to refuse and they do not wait."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("office", "Five developers abandon their desks for the morning briefing at the whiteboard.", "open_plan_office",
     "whiteboard"),
    ("office", "Two analysts leave their desks for the weekly meeting in the boardroom.", "open_plan_office",
     "boardroom"),
    ("hospital", "Three nurses desert the nurses station for the handover in the staff room.", "nurse_station",
     "staff_room"),
    ("hospital", "A surgeon leaves ward B for the ward round in ward A.", "ward_b", "ward_a"),
    ("hospital", "Two porters quit the corridor for the shift briefing at reception.", "main_corridor",
     "reception_desk"),
])
def test_leaving_for_an_event_at_a_place_is_going_there(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    group = reading.groups[0]
    assert len(reading.groups) == 1 and group.intent == "walk"
    assert (group.start, group.destination) == (start, destination)


def test_leaving_for_an_event_at_a_time_keeps_no_place(read):
    group = read("office", "An intern leaves the kitchen for the meeting at nine.").groups[0]
    assert group.start == "kitchen" and group.intent == "walk"
