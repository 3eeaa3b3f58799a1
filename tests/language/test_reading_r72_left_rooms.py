"""Round 72: leaving one's room said by shutting its door behind one ("shuts his office door behind him
and walks over to ...") starts in that room, an owner's office by its owner (closed_behind); "leaves X for
<place> and the <event>" goes to the place, the event its purpose (left_for_events)."""

from __future__ import annotations

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

W = "eval/understanding/worlds/"


def _group(world: str, sentence: str):
    return read_prompt(sentence, load_world(W + world + ".yaml")).groups[0]


def test_shutting_ones_office_door_then_going_starts_in_the_office():
    g = _group("driving_test_centre", "Marcus Lindley shuts his office door behind him and walks over to the front desk.")
    assert (g.start, g.destination) == ("manager_office", "reception_desk")


def test_locking_a_rooms_door_then_going_starts_in_that_room():
    g = _group("pub", "The landlord locks the pub office door behind him and heads down to the cellar.")
    assert (g.start, g.destination) == ("pub_office", "cellar")


def test_a_car_door_is_no_room_left():
    g = _group("pub", "A driver slams the car door and runs to the beer garden.")
    assert g.start != "pub_office" and g.destination == "beer_garden"


def test_leaving_for_a_place_and_an_event_goes_to_the_place_for_the_event():
    g = _group("boxing_gym", "Frank Doyle leaves his office for the ring and the evening sparring session.")
    assert (g.start, g.destination) == ("coaches_office", "boxing_ring")
    assert g.purpose is not None and "sparring" in g.purpose
