"""Round 72: a door passed by a card ("swipe through the front doors and head up to ...") is where the
walk starts (coming_in.SWIPING_VERBS); one called out to a place after a stay by a thing ("After ten
minutes by the vending machines, a new starter is called out to ...") is summoned, no evacuation, and
starts at that thing (clause_cues)."""

from __future__ import annotations

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


def _group(world: str, sentence: str):
    return read_prompt(sentence, load_world(W + world + ".yaml")).groups[0]


def test_a_door_swiped_through_is_the_start():
    g = _group("call_centre", "Forty agents swipe through the front doors and head up to the call floor.")
    assert (g.start, g.destination) == ("front_doors", "call_floor")


def test_called_out_to_a_place_after_a_stay_by_a_thing_starts_at_the_thing():
    g = _group("call_centre", "After ten minutes by the vending machines, a new starter is called out to meeting room 1.")
    assert (g.intent, g.start, g.destination) == ("walk", "vending_machines", "meeting_room_1")


def test_everyone_called_out_after_an_alarm_still_evacuates():
    g = _group("gp_surgery", "The fire alarm sounds and everyone is called out to the car park.")
    assert g.intent == "evacuate"
