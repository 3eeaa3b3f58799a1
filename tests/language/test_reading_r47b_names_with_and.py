"""A place named by two owners joined by "and" ("the relatives' and visitors' lounge") is one place: the
rest of its name after "and" is taken with it, so a word of the name ("lounge") is never the clause's
verb and the walk stays a walk to where the sentence sends them. A purpose whose object is a person
("to meet her client") does not change the walk either."""

import pytest


@pytest.mark.parametrize("world,prompt,label,start,destination", [
    ("hospice", "A chaplain walks from the family and visitors' lounge to the chapel.", "chaplain",
     "family_lounge", "chapel"),
    ("hospice", "A nurse hurries over from the relatives' and visitors' lounge to the nurses' station.", "nurse",
     "family_lounge", "nurses_station"),
    ("care_home", "A carer strolls from the residents' and visitors' lounge to the dining room.", "carer",
     "lounge", "dining_room"),
])
def test_a_name_joined_by_and_is_one_place(read, world, prompt, label, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.label, group.intent, group.start, group.destination) == (label, "walk", start, destination)


@pytest.mark.parametrize("world,prompt,destination", [
    ("care_home", "A carer walks over from the lounge to the dining room to meet her client.", "dining_room"),
    ("hospital", "A porter walks from the lobby to the pharmacy to brief the pharmacist.", "pharmacy"),
])
def test_a_purpose_about_a_person_keeps_the_walk(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.count.value, group.intent, group.destination) == (1, "walk", destination)
