"""Clause classes of round 33, each with sentences of its own over at least two worlds (none from the
understanding sets): leaving after a thing starts smoking, sparking or blows is an evacuation
(giving_off.py); a verb of crowding the parser takes for a plural noun after a count ("a class of twenty
crowds about the robot": gathering_verbs.py); pacing between two places is going from one to the other
(pacing_between.py); a place whose name ends in a particle, then "and" another ("between goods in and
the dispatch bay": particle_ends.py)."""

from __future__ import annotations

import pytest


# ---- 1. leaving after a thing gives off smoke or sparks, or blows ----------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "When an oven in the food court starts to smoke, the shoppers leave by the main entrance."),
    ("hospital", "As soon as a heater in the pharmacy starts sparking, the visitors leave through the main entrance."),
    ("museum", "When the boiler blows up, twenty visitors leave by the main entrance."),
    ("station", "When the coffee machine starts smoking, the passengers head out through the main entrance."),
    ("warehouse", "After a transformer blows, the pickers leave through the main entrance."),
    ("diy_store", "When the demo bench starts smoking, a dozen shoppers in the tool department leave by the "
                  "sliding doors."),
    ("hospital", "When a gas main ruptures, the visitors leave through the main entrance."),
])
def test_leaving_after_a_thing_smokes_or_blows_is_an_evacuation(read, world, prompt):
    g = read(world, prompt).groups[-1]
    assert g.intent == "evacuate"


def test_a_person_smoking_or_a_whistle_is_no_hazard(read):
    g = read("mall", "When the whistle blows, the shoppers leave by the main entrance.").groups[-1]
    assert g.intent == "walk"
    g = read("mall", "A porter starts smoking by the fountain while the shoppers leave by the main entrance.").groups[-1]
    assert g.intent == "walk"
    g = read("mall", "Two staff walk to the outdoor smoking shelter while the shoppers leave by the main "
                     "entrance.").groups[-1]
    assert g.intent == "walk"
    g = read("hospital", "When the shop closes, the visitors leave through the main entrance.").groups[-1]
    assert g.intent == "walk"


# ---- 2. a verb of crowding after a count, taken for a plural noun ----------------------------------------

@pytest.mark.parametrize("world,prompt,count", [
    ("museum", "A class of twenty crowds about the robot in the dinosaur gallery, spellbound.", 20),
    ("station", "A class of thirty throngs around the robot at the newsagent.", 30),
    ("mall", "A party of ten clusters round the robot.", 10),
    ("zoo", "A school group of thirty throngs about the robot by the penguins.", 30),
    ("hospital", "A family of four crowds round the robot in the main waiting room.", 4),
])
def test_a_counted_group_crowding_round_the_robot_approaches_it(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.robot_interaction, g.count.value) == ("robot", "approach", count)
    assert g.robot_reaction == "Curious"


def test_crowds_as_people_keep_their_reading(read):
    (g,) = read("mall", "Crowds gather round the robot at the fountain.").groups
    assert g.robot_interaction == "approach"
    (g,) = read("station", "Four children gather round the robot at the newsagent.").groups
    assert (g.count.value, g.robot_interaction) == (4, "approach")


# ---- 3. pacing between two places -------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "A guard paces between the fountain and the food court.", "fountain", "food_court"),
    ("hospital", "Two nurses shuttle between the pharmacy and the cafeteria.", "pharmacy", "cafeteria"),
    ("station", "A cleaner patrols between the newsagent and the ticket office.", "newsagent", "ticket_office"),
    ("warehouse", "A supervisor paces up and down between the canteen and the dispatch bay.", "canteen",
     "dispatch_bay"),
    ("warehouse", "A guard paces between goods in and the dispatch bay.", "goods_in", "dispatch_bay"),
])
def test_pacing_between_two_places_goes_from_one_to_the_other(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


def test_staying_between_two_places_keeps_its_reading(read):
    (g,) = read("mall", "A man waits between the fountain and the food court.").groups
    assert g.intent == "wait"
    (g,) = read("hospital", "A nurse goes back and forth between the pharmacy and the cafeteria.").groups
    assert (g.intent, g.start, g.destination) == ("walk", "pharmacy", "cafeteria")


# ---- 4. a place named with a particle, then "and" another -------------------------------------------------

@pytest.mark.parametrize("world,prompt,first,second", [
    ("warehouse", "The robot patrols between goods in and the dispatch bay.", "goods_in", "dispatch_bay"),
    ("research_lab_building", "The robot patrols between goods in and the seminar room.", "goods_in", "seminar_room"),
    ("diy_store", "The robot patrols between goods in and the paint department.", "goods_in", "paint_department"),
    ("warehouse", "The robot shuttles between goods in and the canteen.", "goods_in", "canteen"),
])
def test_the_robot_between_a_particle_name_and_another_keeps_both(read, world, prompt, first, second):
    robot = read(world, prompt).robot
    assert robot is not None
    assert first in (robot.location, robot.start, *robot.via)
    assert second in (robot.location, robot.destination, *robot.via)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("warehouse", "A picker walks between goods in and the packing area.", "goods_in", "packing_area"),
    ("research_lab_building", "A technician walks between goods in and the cold room.", "goods_in", "cold_room"),
])
def test_a_walk_between_a_particle_name_and_another_keeps_both(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)


def test_a_particle_name_alone_keeps_its_reading(read):
    (g,) = read("warehouse", "A picker walks from goods in to the dispatch bay.").groups
    assert (g.start, g.destination) == ("goods_in", "dispatch_bay")
    robot = read("warehouse", "The robot patrols between the dispatch bay and goods in.").robot
    assert robot is not None and (robot.location, robot.via) == ("dispatch_bay", ("goods_in",))
