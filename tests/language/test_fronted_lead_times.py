"""Round 60 (r60a): a lead time before a fronted "ahead of"/"before" ("Ten minutes ahead of the early
shift, ...") says when, so the shift it names is no group of ten (language/fronted_lead_times.py);
a unit's short form in capitals before a noun ("for an HR briefing") is an acronym, no hour's stay,
and the "for" phrase is the purpose (language/acronym_units.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("parcel_depot", "Ten minutes ahead of the early shift, forty-odd couriers troop from the clock-in machine to the "
                     "briefing room.", 40),
    ("hotel", "Five minutes ahead of the late shift, two porters walk from the lobby to the bar.", 2),
])
def test_lead_time_makes_no_group(read, world, prompt, count):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [count]


@pytest.mark.parametrize("world,prompt,word", [
    ("hotel", "Twenty minutes before the night shift, three porters walk from the lobby to the bar for an HR meeting.",
     "meeting"),
    ("supermarket", "Two cashiers walk to the cake counter for an HR chat.", "chat"),
])
def test_capital_unit_before_a_noun_is_no_stay(read, world, prompt, word):
    (group,) = read(world, prompt).groups
    assert group.wait_seconds is None
    assert group.purpose is not None and word in group.purpose


def test_call_centre_recruits_briefing(read):
    groups = read("call_centre", "Ten minutes ahead of the late shift, the six recruits in their second week of "
                                 "induction file out of the academy, over the floor and into Lomond for an HR "
                                 "briefing.").groups
    assert [g.count.value for g in groups] == [6]
    assert groups[0].destination == "meeting_room_1" and "briefing" in (groups[0].purpose or "")
