"""Class of round 42 (places said by what is done there), with sentences of its own over several worlds
(none from the understanding sets):

1. a place said only by a clause of what is done there ("to where the forklifts get repaired", "the place
   where guests get made up") is the one room whose description says every word of it, whatever the
   inflection, not a place only named like the thing done to (language/done_there.py)."""

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
