"""A chat item "<place> mtg N ppl" is N people meeting in that place (chat_meetings.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,place", [
    ("call_centre", "training room standup 12 ppl, 2 agents @ help desk", 12, "training_room"),
    ("coworking_space", "event space huddle 7 ppl", 7, "event_space"),
    ("call_centre", "meeting in meeting room 2, 5 ppl", 5, "meeting_room_2"),
])
def test_a_place_meeting_counts_its_people_there(read, world, prompt, count, place):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.location) == (count, place)


def test_the_next_chat_item_stays_a_group_of_its_own(read):
    groups = read("call_centre", "training room standup 12 ppl, 2 agents @ help desk").groups
    assert [g.count.value for g in groups] == [12, 2] and groups[1].location == "it_help_desk"
