"""Round 22 of the reader's clauses, events, places and reactions: verbs of going with a load or at a
stroll that say where they go walk there; a purpose is not the "for" of who someone is; going off
whenever the robot comes is avoiding it."""

import pytest


@pytest.mark.parametrize("world,prompt,start,destination,via", [
    ("residential", "My wife carries the weekly shop from the front door to the kitchen.", "front_door", "kitchen", ()),
    ("mall", "A dad lugs the big shop from the supermarket to the food court.", "supermarket", "food_court", ()),
    ("hospital", "A nurse leaves the pharmacy and ambles down the corridor to the cafeteria.",
     "pharmacy", "cafeteria", ("main_corridor",)),
    ("airport", "A pilot steps out of the lounge and saunters along the concourse to gate A2.",
     "airline_lounge", "gate_a2", ("concourse",)),
])
def test_going_with_a_load_or_at_a_stroll_to_a_place_walks(read, world, prompt, start, destination, via):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.start == start and g.destination == destination and g.via == via


@pytest.mark.parametrize("world,prompt,purpose", [
    ("courthouse", "A solicitor for the family heads from the robing room to the interview room to see his client.",
     "client"),
    ("office", "A consultant for the bank goes from reception to the boardroom to brief her team.", "team"),
    ("hospital", "A lawyer for the family walks from the entrance lobby to the cafeteria to meet his client.", "client"),
    ("courthouse", "Counsel for the prosecution walks to the interview room to brief a witness.", "witness"),
])
def test_the_for_of_who_someone_is_is_no_purpose(read, world, prompt, purpose):
    g = read(world, prompt).groups[0]
    assert g.purpose is not None and purpose in g.purpose and "for the" not in g.purpose


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "A nervous child scurries away whenever the robot comes close."),
    ("museum", "A little boy scuttles off every time the robot rolls up."),
    ("primary_school", "A shy Year 2 boy scampers away each time the robot comes past."),
    ("airport", "A wary toddler scampers away whenever the robot rolls towards her."),
])
def test_going_off_whenever_the_robot_comes_avoids_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.robot_interaction == "avoid" and g.robot_reaction == "Scared"


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "With its window blown in by the gale, the cafeteria's 20 diners evacuate via the main entrance."),
    ("mall", "With its ceiling brought down by the flood, the food court's 40 diners evacuate via the main entrance."),
    ("hospital", "Three patients flick through leaflets near the water dispenser."),
    ("airport", "Two travellers leaf through newspapers at gate A1."),
    ("mall", "A woman thumbs through brochures by the fountain."),
    ("hospital", "Two nurses head off for a walk."),
])
def test_nouns_that_name_no_place_are_not_refused(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


@pytest.mark.parametrize("world,prompt,start,unknown", [
    ("airport", "Four pilots leave the lounge and set off for the casino.", "airline_lounge", "casino"),
    ("hospital", "Two porters leave the pharmacy and set off for the aquarium.", "pharmacy", "aquarium"),
    ("mall", "Three kids leave the food court and set off for the bowling alley.", "food_court", "bowling alley"),
    ("zoo", "Five pupils leave the giraffe house and set off for the planetarium.", "giraffe_house", "planetarium"),
])
def test_a_place_set_off_for_that_the_world_lacks_is_refused_after_a_known_one(read, world, prompt, start, unknown):
    r = read(world, prompt)
    assert r.unknown_places == (unknown,) and r.groups[0].start == start


@pytest.mark.parametrize("world,prompt,field,place", [
    ("supermarket", "A shopper walks from the checkouts to the in-store pharmacy.", "destination", "pharmacy"),
    ("supermarket", "Two women sit in the in-store coffee shop for 20 minutes.", "location", "cafe"),
    ("hospital", "Two nurses walk from the pharmacy to the on-site cafe.", "destination", "cafeteria"),
    ("airport", "A pilot walks from gate A1 to the in-station cafe.", "destination", "cafe"),
])
def test_a_place_said_as_of_this_place_is_the_place(read, world, prompt, field, place):
    (g,) = read(world, prompt).groups
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Two designers are hunched over desk 4.", "desk_4"),
    ("office", "Bent over desk 4, two designers sketch quietly.", "desk_4"),
    ("hospital", "Leaning over bed 3, two nurses chat.", "ward_a_bed_3"),
    ("office", "Hunched over desk 2, a pair of testers type away.", "desk_2"),
])
def test_hunched_over_a_numbered_thing_is_at_it(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,start", [
    ("hospital", "The cafeteria's smoke detector trips and about twenty visitors stream out through the main entrance.",
     "cafeteria"),
    ("mall", "The food court's fire alarm goes off and around sixty diners pile out through the main entrance.",
     "food_court"),
    ("museum", "The gift shop's sprinklers go off and a dozen visitors hurry out through the main entrance.", "gift_shop"),
    ("hospital", "The cafeteria's alarm goes off and twenty visitors stream out through the main entrance.", "cafeteria"),
])
def test_people_leave_the_zone_whose_own_alarm_goes_off(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert g.intent == "evacuate" and g.start == start and g.destination == "main_entrance"


@pytest.mark.parametrize("world,prompt,start", [
    ("mall", "A suitcase is spotted by the fountain, so all 12 in the food court have to get out via the main entrance.",
     "food_court"),
    ("museum", "An abandoned bag is found near the gift shop, so all 20 in the main hall have to leave via the main "
     "entrance.", "great_hall"),
    ("hospital", "A suspicious package is found under a bench, so the 15 people in the cafeteria have to leave via the "
     "main entrance.", "cafeteria"),
    ("airport", "An unattended rucksack is spotted by the benches, so all 30 at gate A1 have to get out via the "
     "concourse.", "gate_a1"),
])
def test_a_bag_left_alone_that_is_found_makes_leaving_an_evacuation(read, world, prompt, start):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.intent == "evacuate" and g.start == start and r.unknown_places == ()


@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "Lightning is spotted nearby, so the cinema shuts and the 40 people in it hurry out via the main entrance.",
     "main_entrance"),
    ("zoo", "A thunderstorm breaks overhead, so the children's farm shuts and the 25 visitors in it hurry out via the "
     "west emergency gate.", "west_emergency_gate"),
    ("stadium", "Lightning strikes nearby, so the north stand is closed and its 300 fans hurry out via gate C.", "gate_c"),
    ("theme_park", "Lightning flashes overhead, so the log flume shuts and 20 riders hurry out via the east emergency "
     "gate.", "east_emergency_gate"),
])
def test_people_hurrying_out_of_a_place_shut_for_a_storm_evacuate(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert g.intent == "evacuate" and g.destination == destination
