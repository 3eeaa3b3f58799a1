"""Robot classes of round 23, each with sentences of its own over at least two worlds (none from the
understanding sets): the robot through, past or around a crowd, a queue or a group (the people stay
where they are, a group there, and their place is one the robot passes); the robot staying or going
round said in other words; people who let the robot lead them; a reaction said as a state."""

from __future__ import annotations

import pytest


# ---- 1. the robot through, past or around people ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,kind,intent,location,destination", [
    ("station", "The robot picks its way through the crowd of commuters on the concourse to reach platform 2.",
     "vague", "wait", "concourse", "platform_2"),
    ("airport", "The robot edges its way past the queue of passengers at the security checkpoint towards gate B1.",
     "implied", "queue", "security_checkpoint", "gate_b1"),
    ("mall", "The robot noses its way through a throng of shoppers in the food court to get to the cinema lobby.",
     "vague", "wait", "food_court", "cinema_lobby"),
    ("museum", "The robot squeezes past a group of pupils in the great hall on its way to the cafe.",
     "implied", "wait", "great_hall", "cafe"),
])
def test_people_the_robot_makes_its_way_through_are_a_group_where_they_are(read, world, prompt, kind, intent,
                                                                            location, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert (g.count.kind, g.intent, g.location, g.destination, g.robot_interaction) == (kind, intent, location, None,
                                                                                        None)
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))


@pytest.mark.parametrize("world,prompt,location,destination", [
    ("station", "Thirty commuters queue at the ticket office while the robot rolls past the queue to the cafe.",
     "ticket_office", "cafe"),
    ("airport", "A dozen passengers wait at gate A2 as the robot weaves around them towards the duty free.",
     "gate_a2", "duty_free"),
    ("mall", "Forty shoppers crowd the food court as the robot picks its way through them to the cinema lobby.",
     "food_court", "cinema_lobby"),
    ("museum", "Twenty pupils crowd around the whale skeleton while the robot edges past them to the cafe.",
     "whale_skeleton", "cafe"),
    ("museum", "A crowd of tourists fills the entrance hall and the robot threads a path through them to the gift shop.",
     "entrance_hall", "gift_shop"),
])
def test_the_place_of_people_said_before_is_where_the_robot_passes(read, world, prompt, location, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.location == location and g.robot_interaction is None
    assert r.robot is not None and (r.robot.task, r.robot.destination, r.robot.via) == ("cross", destination,
                                                                                      (location,))


def test_gathering_round_the_robot_itself_is_still_coming_to_it(read):
    (g,) = read("mall", "Twenty kids crowd round the robot at the fountain.").groups
    assert g.robot_interaction == "approach"
    (g,) = read("station", "Two porters chat to the robot on platform 1.").groups
    assert g.robot_interaction == "approach"
