"""Round 17 of the reader's people: a titled surname ending in "s" after a fronted clause ("Once
clinic is over, Dr Hughes walks ...") is one person and owns the room the world names after them;
a trade's word the world also gives a room ("the hairdresser goes ...") is one person."""

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("gp_surgery", "Once morning clinic is over, Dr Hughes walks from room 3 to the pharmacy", "consulting_room_3", "pharmacy"),
    ("gp_surgery", "When the clinic closes, Dr Hughes walks to the pharmacy", None, "pharmacy"),
    ("gp_surgery", "Dr Hughes walks from room 3 to the pharmacy", "consulting_room_3", "pharmacy"),
])
def test_a_titled_surname_in_s_is_one_person(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", 1) and g.label == "doctor"
    assert (g.start, g.destination) == (start, destination)


def test_his_room_of_a_surname_in_s_is_the_world_s_room(read):
    (g,) = read("gp_surgery", "After lunch, Dr Hughes goes to his room").groups
    assert g.count.value == 1 and g.destination == "consulting_room_3"


@pytest.mark.parametrize("world,prompt,label", [
    ("care_home", "The hairdresser goes from the salon to Mrs Okafor's room", "hairdresser"),
    ("care_home", "The hairdresser goes from the salon to the lounge", "hairdresser"),
    ("care_home", "The hairdresser is in the salon", "hairdresser"),
    ("mall", "A barber heads to the food court", "barber"),
])
def test_a_trade_with_a_room_of_its_own_is_one_person(read, world, prompt, label):
    (g,) = read(world, prompt).groups
    assert (g.label, g.count.kind, g.count.value) == (label, "exact", 1)
