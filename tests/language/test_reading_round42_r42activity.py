"""Class of round 42 (places said by what is done there), with sentences of its own over several worlds
(none from the understanding sets):

1. a place said only by a clause of what is done there ("to where the forklifts get repaired", "the place
   where guests get made up") is the one room whose description says every word of it, whatever the
   inflection, not a place only named like the thing done to (language/done_there.py);
2. a place said by the work done there, a gerund ("head for scanning", "to fingerprinting"): the room whose
   own names say it, not a fixture in it read by meaning (language/done_there.py, gerund_room)."""

from __future__ import annotations

import pytest


# ---- 1. the one room whose description says the activity ------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("warehouse", "A driver walks to where the forklifts get repaired.", "maintenance_workshop"),
    ("playhouse", "Two actors hurry to where their costumes get fitted.", "wardrobe"),
    ("tv_studio", "Two guests head to the place where presenters get made up.", "make_up"),
    ("tv_studio", "A contestant wanders to where the guests get made up.", "make_up"),
])
def test_a_room_whose_description_says_what_is_done_there(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.destination == place


# ---- guards: places already read by what is done there keep their reading --------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("diy_store", "A builder walks to where boards get cut to size.", "panel_saw"),
    ("warehouse", "A picker walks to where the conveyors get repaired.", "maintenance_workshop"),
    ("blood_donor_centre", "Two nurses carry boxes to where samples get chilled.", "processing_room"),
    ("gp_surgery", "A toddler's dad walks to where children have their jabs.", "treatment_room"),
    ("hotel", "A porter heads to where the linen gets washed.", "laundry"),
    ("physio_clinic", "A runner limps to the place where patients do their exercise programmes.", "rehab_gym"),
])
def test_places_read_by_what_is_done_there_keep_their_reading(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.destination == place


# ---- 2. a gerund of the work done in a room is the room, not its fixture --------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("maternity_unit", "Two midwives walk to scanning.", "scan_room"),
    ("maternity_unit", "A couple head for scanning.", "scan_room"),
    ("consulate", "Two applicants make their way to fingerprinting.", "biometrics_room"),
])
def test_a_gerund_of_the_work_done_is_the_room(read, world, prompt, place):
    (group,) = read(world, prompt).groups
    assert group.destination == place


def test_waiting_for_a_gerund_is_in_the_room(read):
    (group,) = read("consulate", "A student queues for fingerprinting.").groups
    assert group.location == "biometrics_room"


# ---- guards: gerunds already read as their rooms, and fixtures named by a gerund, keep their reading -----------

@pytest.mark.parametrize("world,prompt,place", [
    ("brewery", "Three visitors head for sampling.", "tasting_room"),
    ("brewery", "Four visitors head for fermenting.", "fermentation_hall"),
    ("blood_donor_centre", "A donor walks to processing.", "processing_room"),
    ("airport", "A couple head for ticketing.", "check_in_hall"),
    ("station", "A couple head for booking.", "ticket_hall"),
    ("hospital", "An orderly wheels a patient to imaging.", "radiology"),
])
def test_gerunds_already_read_as_rooms_keep_their_reading(read, world, prompt, place):
    assert read(world, prompt).groups[0].destination == place
