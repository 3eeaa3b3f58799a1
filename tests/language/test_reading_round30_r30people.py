"""People classes of round 30, each with sentences of its own over at least two worlds (none from the
understanding sets): role words the lexicon lacks, told by their ending or head ("the entrants leave",
"the watch chief"), a collective naming whose role a person has ("a crew leader", "a team coordinator"),
also as a second group placed with no verb of its own, and a name after a fronted feeling
("Intrigued, Dorothy shuffles ...")."""

from __future__ import annotations

import pytest


# ---- a. a role word the lexicon lacks, by its ending or head --------------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("tv_studio", "The contestants leave the green room.", None),
    ("tv_studio", "Both quiz contestants come back to the green room.", 2),
    ("mall", "The entrants leave the food court.", None),
    ("hospital", "The absentees return to the pharmacy.", None),
    ("station", "The auctioneers leave the cafe.", None),
    ("hospital", "The paramedic chief leaves the pharmacy.", 1),
    ("fire_station", "The watch chief leaves the pool table.", 1),
    ("fire_station", "The crew chief walks to the pool table.", 1),
])
def test_a_role_word_by_its_ending_is_people(read, world, prompt, count):
    r = read(world, prompt)
    assert len(r.groups) == 1
    g = r.groups[0]
    assert g.who.lower().startswith(("the", "both"))  # the phrase as written, not a stand-in crowd
    if count is not None:
        assert g.count.value == count and g.count.kind in ("exact", "implied")


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The printer in the pharmacy stops working."),
    ("mall", "The restaurant on the top floor closes at nine."),
    ("station", "The heater by the cafe comes on."),
])
def test_things_named_as_roles_are_no_people(read, world, prompt):
    r = read(world, prompt)
    assert not any(w in g.who.lower() for g in r.groups for w in ("printer", "restaurant", "heater"))


# ---- b. a collective saying whose role, and a second placed person with no verb ------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "Put four shoppers by the fountain and a crew supervisor at the food court.", "food_court"),
    ("mall", "Put four shoppers by the fountain and a crew leader at the food court.", "food_court"),
    ("hospital", "Have two porters at the lifts and a team coordinator by the pharmacy.", "pharmacy"),
    ("hospital", "Put two nurses at the pharmacy and a crew manager by the lifts.", "elevator_hall"),
    ("fire_station", "Have five firefighters round the pool table and a crew commander on the mobilising console.",
     "mobilising_console"),
    ("hospital", "Have two porters at the lifts and a greeter by the pharmacy.", "pharmacy"),
    ("job_centre", "Have three jobseekers on the waiting seats and a greeter by the leaflet stand.", "leaflet_stand"),
])
def test_a_second_placed_person_is_one_more_group(read, world, prompt, place):
    r = read(world, prompt)
    assert len(r.groups) == 2
    second = r.groups[1]
    assert second.count.value == 1
    assert second.location == place


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "A security team waits by the pharmacy.", None),
    ("mall", "The cleaning crew heads to the food court.", None),
])
def test_a_collective_of_people_is_still_a_group(read, world, prompt, count):
    g = read(world, prompt).groups[0]
    assert g.count.value > 1


# ---- c. a name after a fronted feeling ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,name", [
    ("care_home", "Intrigued, Dorothy shuffles to the lounge.", "Dorothy"),
    ("hospital", "Intrigued, Dorothy shuffles to the pharmacy.", "Dorothy"),
    ("museum", "Terrified, Oliver scurries to the cafe.", "Oliver"),
    ("hospital", "Terrified, Oliver scurries to the pharmacy.", "Oliver"),
    ("mall", "Terrified, Oliver scurries away from the robot.", "Oliver"),
])
def test_a_name_after_a_fronted_feeling_is_one_person(read, world, prompt, name):
    r = read(world, prompt)
    assert len(r.groups) == 1
    assert r.groups[0].who == name and r.groups[0].count.value == 1


@pytest.mark.parametrize("world,prompt,name", [
    ("mall", "Intrigued, Gertrude shuffles to the fountain.", "Gertrude"),
    ("museum", "Fascinated, Imogen shuffles towards the robot.", "Imogen"),
    ("care_home", "Bewildered, Arthur wanders to the lounge.", "Arthur"),
])
def test_names_after_fronted_feelings_read_before_keep_their_reading(read, world, prompt, name):
    assert read(world, prompt).groups[0].who == name


def test_a_fronted_feeling_toward_the_robot_keeps_its_reaction(read):
    g = read("care_home", "Intrigued, Dorothy shuffles across the lounge towards the robot.").groups[0]
    assert g.who == "Dorothy" and g.robot_reaction == "Curious" and g.robot_interaction == "approach"


@pytest.mark.parametrize("world,prompt,who,intent", [
    ("hospital", "two porters wait at the lifts and a cleaner wanders in the main corridor", "a cleaner", "wander"),
    ("mall", "four shoppers sit by the fountain and a guard wanders in the food court", "a guard", "wander"),
])
def test_a_persons_verb_after_them_is_no_role_word(read, world, prompt, who, intent):
    g = read(world, prompt).groups[-1]
    assert (g.who, g.intent) == (who, intent)
