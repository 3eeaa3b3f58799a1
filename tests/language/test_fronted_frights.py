"""A person's cry after a clause fronted by the robot ("When the robot comes round the corner, a porter
yelps and bolts"): the cry is the person's verb, though the parser takes it for a plural noun, and a
phrase of time ("the instant the robot ...") is no one (singular_verbs.py, people.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "When the robot comes round the corner, an old porter yelps and bolts for the lifts.", "porter"),
    ("office", "As the robot glides past reception, a courier screams and drops his parcels.", "courier"),
    ("mall", "The instant the robot turns into the food court, a toddler shrieks and hides behind her dad.", "toddler"),
    ("airport", "The moment the robot trundles up to gate B2, a nervous flyer gasps and backs away.", "flyer"),
])
def test_a_cry_after_a_fronted_robot_clause_is_one_persons_reaction(read, world, prompt, label):
    group = read(world, prompt).groups[0]
    assert group.label == label and group.count.value == 1 and group.intent == "robot"


def test_a_patient_going_back_to_his_room_goes_to_a_patients_room(read):
    (group,) = read("hospital", "After lunch an elderly patient shuffles back to his room.").groups
    assert group.destination in ("ward_a", "ward_b", "ward_c")
