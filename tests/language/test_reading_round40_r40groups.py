"""Group classes of round 40, each with sentences of its own over at least two worlds (none from the
understanding sets): a person moved along by another, said in an aside set off by commas ("a porter,
pushing a woman in a wheelchair, hurries to ..."), is a group of their own that goes with the mover;
a verb the parser takes for a plural noun between one person and the plural thing they work on ("my
mum irons shirts in the kitchen") is that person's verb, and the person a group."""

from __future__ import annotations

import pytest


# ---- 1. a person moved along by another, said in a comma aside ----------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A nurse, wheeling an old man in a wheelchair, heads to the lifts.", None, "elevator_hall"),
    ("airport", "An attendant, pushing an elderly passenger in a wheelchair, makes her way from check-in to gate B.",
     "check_in_hall", "gate_b2"),
    ("care_home", "A carer, wheeling a resident, goes from the lounge to the dining room.", "lounge", "dining_room"),
    ("museum", "A volunteer, guiding two blind visitors, walks from the entrance to the gift shop.",
     "entrance_hall", "gift_shop"),
])
def test_a_person_moved_in_an_aside_is_a_group_going_with_the_mover(read, world, prompt, start, destination):
    mover, moved = read(world, prompt).groups
    assert mover.intent == "walk" and moved.intent == "follow"
    assert (moved.start, moved.destination) == (mover.start, mover.destination) == (start, destination)


# ---- 2. a verb taken for a plural noun before the plural thing one person works on ---------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("residential", "My mum irons shirts in the kitchen.", "kitchen"),
    ("hotel", "A chambermaid irons pillowcases in the laundry.", "laundry"),
    ("museum", "A volunteer dusts cabinets in the great hall.", "great_hall"),
    ("airport", "A cleaner empties bins in the departure lounge.", "airline_lounge"),
])
def test_one_person_working_on_plural_things_is_one_person_there(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", 1)
    assert group.location == location


@pytest.mark.parametrize("world,prompt,first,second", [
    ("hotel", "A maid irons sheets in the laundry while a guest checks in at the front desk.", "laundry", "reception_desk"),
    ("care_home", "A carer irons blouses in the lounge while two residents chat by the window.", "lounge", None),
])
def test_the_working_person_before_a_second_clause_is_kept(read, world, prompt, first, second):
    a, b = read(world, prompt).groups
    assert a.count.value == 1 and a.location == first
    assert b.location == second


# ---- guards: what the reader read already keeps its reading -------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The orderly, pushing a trolley, heads to the lifts."),
    ("mall", "A security guard, pushing his bike, walks to the exit."),
    ("maternity_unit", "A midwife, carrying a clipboard, hurries to the delivery suite."),
])
def test_a_thing_pushed_in_an_aside_is_no_group(read, world, prompt):
    assert len(read(world, prompt).groups) == 1


@pytest.mark.parametrize("world,prompt,intent,location", [
    ("office", "The intern files reports in the boardroom.", "wait", "boardroom"),
    ("station", "A guard checks tickets on platform 2.", "wait", "platform_2"),
    ("hospital", "A porter stacks trays in the cafeteria.", "wait", "cafeteria"),
    ("residential", "My brother peels potatoes in the kitchen.", "wait", "kitchen"),
])
def test_one_person_working_keeps_their_reading(read, world, prompt, intent, location):
    (group,) = read(world, prompt).groups
    assert (group.intent, group.location) == (intent, location)
