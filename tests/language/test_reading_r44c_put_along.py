"""People put along a place ("Position a panel of 5 interviewers along one side of the table", "Put three
guards along the side of the great hall") are put there: where they stay, not a way they go along.
"Position" places people as "Put" does. Someone who walks along a corridor still goes through it. Real
spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, location", [
    ("office", "Position a panel of 5 interviewers along one side of the table in huddle room two.", "meeting_table_2"),
    ("courthouse", "Position two ushers along the corridor outside court 1.", "main_corridor"),
    ("museum", "Put three guards along the side of the great hall.", "great_hall"),
])
def test_people_put_along_a_place_stay_there(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.location, group.via) == ("wait", location, ())


def test_walking_along_a_corridor_is_still_a_way_through(read):
    group = read("hospital", "A nurse walks along the corridor to the ward.").groups[0]
    assert group.via == ("main_corridor",)
