"""How-many-groups classes of round 38, each with sentences of its own over at least two worlds (none
from the understanding sets): people who plant themselves before the robot, or bar it, block it; a
person moved in their own chair by someone of theirs ("Grace's son steers her chair from ...") is a
second group taken along; a person by bare name a carer steadies or helps "as he shuffles from ... to
..." is a second group on that route."""

from __future__ import annotations

import pytest


# ---- 1. standing before the robot, barring it ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("airport", "Two drunk lads plant themselves before the robot near gate B2."),
    ("airport", "A couple of teenagers stand before the robot at the check-in desks, barring it."),
    ("mall", "Three lads outside the food court bar the robot."),
    ("mall", "A man at the fountain stations himself before the robot and refuses to move."),
    ("museum", "Two schoolboys park themselves squarely before the robot in the entrance hall."),
    ("library", "A grumpy reader plants herself right before the robot by the issue desk."),
])
def test_standing_before_the_robot_blocks_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.robot_reaction) == ("robot", "block", "Threatening")


@pytest.mark.parametrize("world,prompt", [
    ("museum", "Two schoolboys sit down in the entrance hall before the robot arrives."),
    ("mall", "Three lads wait at the fountain before the robot comes past."),
])
def test_before_the_robot_as_a_time_is_no_reaction(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction is None


# ---- 2. a person moved in their own chair by someone of theirs --------------------------------------------

@pytest.mark.parametrize("world,prompt,moved,start,destination", [
    ("care_home", "Grace's son pushes her wheelchair from the lounge to the dining room.", "Grace", "lounge",
     "dining_room"),
    ("hospital", "Mr Patel's daughter pushes his wheelchair from the cafeteria back to ward B.", "Mr Patel",
     "cafeteria", "ward_b"),
    ("hospital", "His carer wheels his bed from the cafeteria down to radiology.", "him", "cafeteria", "radiology"),
    ("residential", "Her son pushes her wheelchair from the kitchen into the living room.", "her", "kitchen",
     "living_room"),
    ("care_home", "Edna's grandson steers her chair from the garden over to the lounge.", "Edna", "garden", "lounge"),
])
def test_a_person_moved_in_their_own_chair_goes_along(read, world, prompt, moved, start, destination):
    mover, taken = read(world, prompt).groups
    assert (mover.start, mover.destination) == (start, destination)
    assert taken.who == moved and taken.count.value == 1 and taken.intent == "follow"
    assert taken.follows == mover.who and (taken.start, taken.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "Her husband pushes her pram from the fountain to the food court."),
    ("hospital", "A porter pushes his trolley from the cafeteria to the pharmacy."),
    ("care_home", "Stan's carer pushes his trolley from the kitchen to the dining room."),
])
def test_a_thing_of_ones_own_stays_one_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 1


# ---- 3. a person by bare name helped along "as he shuffles from ... to ..." -------------------------------

@pytest.mark.parametrize("world,prompt,moved,start,destination", [
    ("care_home", "A carer steadies Doris as she totters from the lounge to the garden.", "Doris", "lounge",
     "garden"),
    ("hospital", "A nurse helps Doris, with her stick, while she hobbles from the pharmacy to ward B.", "Doris",
     "pharmacy", "ward_b"),
    ("museum", "An attendant supports Frank on his crutches as he limps from the cafe to the entrance hall.",
     "Frank", "cafe", "entrance_hall"),
    ("care_home", "A nurse steadies Albert on his zimmer as he creeps from the dining room to the lounge.",
     "Albert", "dining_room", "lounge"),
])
def test_a_named_person_helped_as_they_walk_goes_along(read, world, prompt, moved, start, destination):
    helper, helped = read(world, prompt).groups
    assert (helper.start, helper.destination) == (start, destination)
    assert helped.who == moved and helped.intent == "follow" and helped.follows == helper.who
    assert (helped.start, helped.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("care_home", "A carer steadies the tea trolley in the lounge."),
    ("hospital", "A nurse helps out at the pharmacy while the porters go from ward B to radiology."),
])
def test_helping_with_no_named_person_adds_no_group(read, world, prompt):
    assert len([g for g in read(world, prompt).groups if g.intent == "follow"]) == 0
