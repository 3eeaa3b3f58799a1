"""Who sees to the people brought somewhere, in a passive purpose (language/seen_to_by.py): "to be checked
over by the nurses in ward A" names no group of the scene, and the place after them is where the people are
taken; a thing that does it ("by the ambulance") is left as said."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A porter wheels a dizzy visitor out of the cafeteria to be checked over by the nurses in ward A.",
     "cafeteria", "ward_a"),
    ("hospital", "A volunteer walks a confused patient from reception to be seen by the doctors in radiology.",
     "reception_desk", "radiology"),
    ("museum", "A guide helps a fainting visitor out of the gallery to be checked over by a first-aider in the cafe.",
     "modern_art_gallery", "cafe"),
])
def test_the_doers_of_a_passive_purpose_are_no_group(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert reading.unknown_places == ()
    assert len(reading.groups) == 2
    taker, taken = reading.groups
    assert (taker.intent, taker.start, taker.destination) == ("walk", start, destination)
    assert taken.intent == "follow"
