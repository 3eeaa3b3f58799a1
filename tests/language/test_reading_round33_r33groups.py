"""Group classes of round 33, each with sentences of its own over at least two worlds (none from the
understanding sets): a person a relative or carer moves, said with a pronoun ("his carer wheels him
back to ..."); a couple under one name escorted ("escorts Mr and Mrs Obi from ..."); whoever shuts a
place whose people are then moved off; walking or cycling on a machine of exercise; a thing filled,
stocked or locked up as where people are."""

from __future__ import annotations

import pytest


# ---- 1. a person moved by a relative or carer, said with a pronoun ---------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("physio_clinic", "Mrs Patel's son wheels her from reception over to the mats.", "reception", "mat_area"),
    ("hospital", "His carer wheels him from radiology to the pharmacy.", "radiology", "pharmacy"),
    ("care_home", "Mrs Kaur's grandson walks her from the lounge to the dining room.", "lounge", "dining_room"),
    ("mall", "His mum drags him out of the toy shop.", "toy_store", None),
    ("hospital", "Her husband wheels her from radiology to the pharmacy while two nurses wait in the lobby.",
     "radiology", "pharmacy"),
])
def test_a_person_moved_by_someone_of_theirs_goes_along(read, world, prompt, start, destination):
    groups = read(world, prompt).groups
    assert len(groups) >= 2
    mover, moved = groups[0], groups[1]
    assert moved.count.value == 1 and moved.intent == "follow"
    assert (mover.start, mover.destination) == (start, destination)
    assert (moved.start, moved.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "Her son pushes her pram to the cafeteria.", 1),
    ("hospital", "A nurse helps her son to the cafeteria.", 2),
    ("hospital", "A porter wheels him to radiology.", 1),
    ("hospital", "His carer gives him a coffee in the cafeteria.", 1),
    ("hospital", "A girl waits in the lobby until her dad wheels her to the cafeteria.", 2),
])
def test_a_pronoun_that_is_no_one_moved_adds_no_group(read, world, prompt, count):
    assert len(read(world, prompt).groups) == count


# ---- 2. a couple under one name, escorted ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,couple,start,destination", [
    ("car_showroom", "A salesman escorts Mr and Mrs Obi to the handover bay.", "Mr and Mrs Obi", None,
     "handover_bay"),
    ("hospital", "A nurse shows Dr and Mrs Lee from the lobby to radiology.", "Dr and Mrs Lee", "entrance_lobby",
     "radiology"),
    ("hospital", "A porter takes Mr and Mrs Khan up to the pharmacy while two nurses wait in the lobby.",
     "Mr and Mrs Khan", None, "pharmacy"),
    ("museum", "A guide leads Mr and Mrs Okafor from the entrance to the cafe.", "Mr and Mrs Okafor",
     "entrance_hall", "cafe"),
])
def test_a_couple_escorted_is_one_group_of_two_that_goes_along(read, world, prompt, couple, start, destination):
    groups = read(world, prompt).groups
    leader, led = groups[0], groups[1]
    assert (led.who, led.count.value, led.intent) == (couple, 2, "follow")
    assert (leader.start, leader.destination) == (start, destination)
    assert (led.start, led.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,groups", [
    ("car_showroom", "Mr and Mrs Obi walk to the handover bay.", [("Mr and Mrs Obi", 2)]),
    ("hospital", "A nurse meets Mr and Mrs Lee in the lobby.", [("A nurse", 1), ("Mr and Mrs Lee", 2)]),
    ("hospital", "A nurse waits in the lobby and Mr and Mrs Lee walk to radiology.",
     [("A nurse", 1), ("Mr and Mrs Lee", 2)]),
])
def test_a_couple_said_as_a_subject_or_met_is_one_group_of_two(read, world, prompt, groups):
    assert [(g.who, g.count.value) for g in read(world, prompt).groups] == groups


def test_two_people_each_with_their_title_stay_two_groups(read):
    groups = read("hospital", "Dr Jones and Mrs Lee walk to radiology.").groups
    assert [(g.who, g.count.value) for g in groups] == [("Dr Jones", 1), ("Mrs Lee", 1)]


# ---- 3. whoever shuts a place whose people are moved off -----------------------------------------------

@pytest.mark.parametrize("world,prompt,count,start", [
    ("hospital", "Staff close the cafeteria and the twenty people in it are cleared out.", 20, "cafeteria"),
    ("mall", "Security seal off the food court and the fifty-odd shoppers there are ushered out.", 50, "food_court"),
    ("museum", "Guards close the gift shop over a suspicious bag and the thirty visitors in it are moved out.", 30,
     "gift_shop"),
    ("station", "Police shut platform 1 over a suspect package and the sixty-odd passengers on it are moved off.",
     60, "platform_1"),
])
def test_whoever_shuts_the_place_people_are_moved_off_is_no_group(read, world, prompt, count, start):
    groups = read(world, prompt).groups
    assert [(g.count.value, g.intent, g.start) for g in groups] == [(count, "evacuate", start)]


@pytest.mark.parametrize("world,prompt,who", [
    ("hospital", "A guard locks the pharmacy while two nurses are sent to the cafeteria.", ["A guard", "two nurses"]),
    ("hospital", "Two nurses close the pharmacy and walk to the cafeteria.", ["Two nurses"]),
])
def test_one_who_shuts_a_place_beside_others_is_still_a_group(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == who


# ---- 4. walking or cycling on a machine of exercise --------------------------------------------------

@pytest.mark.parametrize("world,prompt,index,location", [
    ("physio_clinic", "Have two patients stretching on the mats and one jogging on a treadmill.", 1, "treadmills"),
    ("sports_centre", "Have two members lifting weights and one running on a treadmill.", 1, "treadmills"),
    ("sports_centre", "A member cycles on the exercise bikes while two swimmers wait by the pool.", 0, "spin_bikes"),
    ("physio_clinic", "Two patients walk on the treadmills.", 0, "treadmills"),
])
def test_people_on_a_machine_of_exercise_stay_at_it(read, world, prompt, index, location):
    g = read(world, prompt).groups[index]
    assert (g.location, g.start) == (location, None)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("physio_clinic", "A runner jogs on a treadmill for ten minutes, then goes to the changing rooms.", "treadmills",
     "changing_rooms"),
    ("sports_centre", "Two members walk from the treadmills to the cafe.", "treadmills", "cafe"),
])
def test_people_who_leave_a_machine_start_there(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.start, g.destination) == (start, destination)


# ---- 5. a thing filled, stocked or locked up ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("aquarium", "A keeper tops up the touch tank, thirty pupils sketch in the jellyfish gallery.", "touch_tank"),
    ("hospital", "A porter fills up the vending machine while two nurses chat in the lobby.", "vending_machine"),
    ("museum", "A guard locks up the gift shop and two visitors walk to the cafe.", "gift_shop"),
    ("office", "A cleaner tops up the printer.", "printer"),
])
def test_a_thing_filled_or_locked_up_is_where_they_are(read, world, prompt, location):
    g = read(world, prompt).groups[0]
    assert (g.location, g.via) == (location, ())


@pytest.mark.parametrize("world,prompt,field,value", [
    ("hospital", "Two nurses walk up the corridor.", "via", ("main_corridor",)),
    ("hospital", "A cleaner wipes down the tables in the cafeteria.", "location", "cafeteria"),
])
def test_a_way_up_and_a_thing_wiped_keep_their_reading(read, world, prompt, field, value):
    assert getattr(read(world, prompt).groups[0], field) == value


# ---- 6. a bare count as an imperative's first item ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,items", [
    ("sports_centre", "Put three on the bikes and two by the pool.", [(3, "spin_bikes"), (2, "pool_hall")]),
    ("hospital", "Put two in the lobby and three in the cafeteria.", [(2, "entrance_lobby"), (3, "cafeteria")]),
    ("hospital", "Please have four at the pharmacy and one in the lobby.", [(4, "pharmacy"), (1, "entrance_lobby")]),
    ("mall", "Put six in the food court.", [(6, "food_court")]),
])
def test_a_bare_count_first_in_an_imperative_is_people_at_its_place(read, world, prompt, items):
    assert [(g.count.value, g.location) for g in read(world, prompt).groups] == items


def test_a_counted_noun_first_in_an_imperative_keeps_its_reading(read):
    groups = read("hospital", "Put two nurses in the lobby and three in the cafeteria.").groups
    assert [(g.who, g.count.value, g.location) for g in groups] == [("two nurses", 2, "entrance_lobby"),
                                                                    ("three", 3, "cafeteria")]
