"""People placed by a participle of staying, then moved in the passive by an alarm ("the travellers
waiting there are ushered up the emergency stairs"): an evacuation from where they wait, not a wait at
the stairs (waiting_then_sent.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start", [
    ("underground_station", "A smoke alarm goes off on the northbound platform and the travellers waiting there "
                            "are ushered up the northbound emergency stairs.", "northbound_platform"),
    ("office", "The smoke alarm goes off in the kitchen and the five staff standing there are sent out to the car park.",
     "kitchen"),
    ("hospital", "A fire alarm sounds in the canteen and the twelve visitors waiting there are hurried out of the "
                 "building.", "cafeteria"),
])
def test_people_staying_somewhere_then_sent_out_by_an_alarm_are_evacuated_from_there(read, world, prompt, start):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start) == ("evacuate", start)


def test_people_sitting_on_a_platform_sent_out_are_evacuated_from_it(read):
    group = read("underground_station", "A fire alarm sounds on the southbound platform and the twenty commuters "
                 "sitting there are sent out.").groups[0]
    assert (group.intent, group.start, group.count.value) == ("evacuate", "southbound_platform", 20)
