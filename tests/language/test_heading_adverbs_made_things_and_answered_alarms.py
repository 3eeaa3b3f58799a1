"""Five small readings (heading_adverbs.py, made_things.py, particle_purposes.py, place_compounds.py,
answered_alarms.py): a heading adverb after a place ends it ("from the gallery back to ..."), even where
the world has a name holding the word ("back corridor"); a thing worked on, said with "a", before the room
it is in; a verb with its particle after "to" is a purpose; a kind of building that is no part of this
world is refused; and one person sent by an alarm to an inner room walks there."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("museum", "A guide strolls from the great hall back to the entrance hall.", "great_hall", "entrance_hall"),
    ("office", "The intern carries a box from the boardroom back to reception.", "boardroom", "reception"),
    ("airport", "A cleaner pushes her cart from the baggage claim over to the arrivals hall.", "baggage_claim",
     "arrivals_hall"),
    ("station", "A guard wanders from the ticket hall out to platform 2.", "ticket_hall", "platform_2"),
])
def test_a_heading_adverb_after_a_place_ends_it(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.start, group.destination) == (start, destination)


def test_a_place_name_that_holds_the_word_is_still_read(read):
    group = read("museum", "Two technicians wait in the back corridor.").groups[0]
    assert group.location == "service_corridor"


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "An engineer fixes a wobbly chair in the kitchen.", "kitchen"),
    ("museum", "A conservator repairs a cracked vase in the education room.", "education_room"),
    ("hospital", "A porter oils a squeaky trolley in the pharmacy.", "pharmacy"),
])
def test_a_thing_said_with_a_before_the_room_is_no_place(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert group.location == location


@pytest.mark.parametrize("world,prompt,location,said", [
    ("hospital", "Five visitors queue at the reception desk to hand in their forms.", "reception_desk", "hand in"),
    ("mall", "Two couriers stop at the information desk to drop off a parcel.", "information_desk", "drop off"),
    ("station", "A commuter waits at the gateline to top up her card.", "gateline", "top up"),
])
def test_a_verb_with_its_particle_after_to_is_a_purpose(read, world, prompt, location, said):
    reading = read(world, prompt)
    group = reading.groups[0]
    assert group.location == location and said in (group.purpose or "")
    assert reading.unknown_places == ()


def test_a_person_after_to_is_no_purpose(read):
    group = read("hospital", "Three nurses chat to friends in the cafeteria.").groups[0]
    assert group.purpose is None and group.location == "cafeteria"


@pytest.mark.parametrize("world,prompt,refused", [
    ("town_square", "A couple stroll from the fountain to the shopping centre.", "shopping centre"),
    ("town_square", "Three teenagers head off to the leisure centre.", "leisure centre"),
])
def test_another_kind_of_building_is_refused(read, world, prompt, refused):
    assert refused in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,destination", [
    ("hospital", "Hearing the alarm, a nurse leaves the nurse station and hurries to the pharmacy.", "pharmacy"),
    ("office", "When the alarm sounds, the sysadmin runs to the server room.", "server_room"),
])
def test_one_person_sent_by_an_alarm_to_an_inner_room_walks(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination) == ("walk", destination)


@pytest.mark.parametrize("world,prompt", [
    ("office", "When the alarm sounds, the receptionist runs to the back door."),
    ("hospital", "When the fire alarm goes off, the twelve patients in the waiting room head for the main entrance."),
    ("office", "When the smoke alarm goes off, the manager escapes to the kitchen."),
])
def test_fleeing_on_an_alarm_is_still_an_evacuation(read, world, prompt):
    assert read(world, prompt).groups[0].intent == "evacuate"
