"""A person's wheelchair, bed or buggy moved by someone is that person moved along, whatever the verb
("trundles", "eases", "jiggles") and however long the name ("Mr Singh's", "Edith Baxter's")
(language/objects.py: carried_owner)."""

from __future__ import annotations

import pytest

CASES = [
    ("museum", "A volunteer eases Mr Singh's wheelchair from the entrance hall to the auditorium.",
     "entrance_hall", "auditorium"),
    ("care_home", "A carer jiggles Edith Baxter's wheelchair out of the lounge to the dining room.", "lounge",
     "dining_room"),
    ("hospital", "A porter trundles Mrs Lee's bed from ward B to radiology.", "ward_b", "radiology"),
]


@pytest.mark.parametrize("world,prompt,start,destination", CASES)
def test_the_owner_of_the_ride_goes_along(read, world, prompt, start, destination):
    mover, moved = read(world, prompt).groups
    assert moved.intent == "follow" and moved.follows == mover.who
    assert (moved.start, moved.destination) == (start, destination)
    assert mover.count.value == 1 and moved.count.value == 1


def test_a_trolley_of_ones_own_moves_nobody(read):
    (nurse,) = read("hospital", "A nurse trundles her trolley from ward A to the pharmacy.").groups
    assert nurse.destination == "pharmacy"


@pytest.mark.parametrize("sentence", [
    "A guide hurries from the entrance hall to the Egyptian gallery and ten tourists follow her",
    "Two nurses walk to the pharmacy and a porter follows them",
])
def test_a_sentence_ending_on_its_object_is_read(read, sentence):
    assert len(read("museum", sentence).groups) == 2
