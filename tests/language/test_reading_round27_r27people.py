"""Round 27 of the reader's people: a person word with an adverb before its verb is that verb's
subject ("Mum quickly walks"); a load of things ("a heavy sack of pellets") and a coach said as the
vehicle ("until the Glasgow coach comes") are no people; "away fans" keep their count; a role no
list keeps, placed by "Put"/"Stick"/"Plant" ("a fiddler", "a lab tech", "a PCSO"), is one person;
an elliptic ordinal after a count ("two guards ... and a third at X") is one more of them; a person
taken along past a particle or an aside ("helps Dorothy down to", "wheels Mrs Patel, still groggy,
from") is a second group that follows the taker."""

import pytest


@pytest.mark.parametrize("world,prompt,who", [
    ("residential", "Mum quickly walks to the kitchen.", "Mum"),
    ("residential", "Grandad slowly shuffles to the kitchen.", "Grandad"),
    ("mall", "Gran patiently waits by the fountain.", "Gran"),
    ("mall", "Old Tom stubbornly waits by the fountain.", "Old Tom"),
    ("care_home", "Grumpy Grandad deliberately stands his ground in the lounge.", "Grumpy Grandad"),
])
def test_an_adverb_before_the_verb_keeps_one_person_its_subject(read, world, prompt, who):
    (group,) = read(world, prompt).groups
    assert group.who == who and group.count.kind == "exact" and group.count.value == 1


@pytest.mark.parametrize("world,prompt", [
    ("zoo", "A zookeeper lugs a heavy crate of fish from the keepers' yard to the penguin pool."),
    ("mall", "A zookeeper lugs a heavy sack of potatoes from the food court to the fountain."),
    ("garden_centre", "A zookeeper lugs a heavy sack of compost from the cafe to the tills."),
    ("zoo", "A zookeeper lugs a heavy sack of carrots from the keepers' yard to the penguin pool."),
])
def test_a_load_of_things_is_no_person(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1 and group.intent == "walk" and group.start and group.destination


@pytest.mark.parametrize("world,prompt,who", [
    ("bus_station", "Two elderly sisters perch on the bay 4 bench until the Glasgow coach comes.", "Two elderly sisters"),
    ("bus_station", "Two students wait at the bay 4 bench until the London coach arrives.", "Two students"),
    ("bus_station", "A family sits in the cafe until the next coach pulls in.", "A family"),
    ("station", "Three hikers wait in the ticket hall until the airport coach arrives.", "Three hikers"),
])
def test_a_coach_said_as_the_vehicle_is_no_person(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == [who]


@pytest.mark.parametrize("world,prompt,value", [
    ("stadium", "Three away fans walk to gate C.", 3),
    ("stadium", "Five hundred away fans pour through gate C.", 500),
    ("stadium", "Twenty away supporters wait at gate C.", 20),
    ("ice_rink", "Forty away fans queue at the cafe.", 40),
])
def test_away_fans_keep_their_count(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == value


@pytest.mark.parametrize("world,prompt,whos", [
    ("stadium", "Put a fiddler on the concourse seats.", ["a fiddler"]),
    ("mall", "Put a juggler by the fountain.", ["a juggler"]),
    ("mall", "Plant a busker by the fountain.", ["a busker"]),
    ("research_lab_building", "Stick one lab tech at the centrifuge and a pair of postgrads by the incubators.",
     ["one lab tech", "a pair of postgrads"]),
    ("police_station", "Put a PCSO behind the front counter and two officers in IR1.", ["a PCSO", "two officers"]),
])
def test_a_placed_role_no_list_keeps_is_one_person(read, world, prompt, whos):
    groups = read(world, prompt).groups
    assert [g.who for g in groups] == whos and all(g.location for g in groups)


@pytest.mark.parametrize("world,prompt,first,place", [
    ("fire_station", "Have two firefighters stand by the cutting gear display and a third at the hydrant.", 2, None),
    ("mall", "Have two guards stand by the fountain and a third at the food court.", 2, "food_court"),
    ("mall", "Put three cleaners in the food court and a fourth by the fountain.", 3, "fountain"),
    ("museum", "Post one guard at the entrance and a second by the main hall.", 1, "great_hall"),
])
def test_an_elliptic_ordinal_is_one_more_of_them(read, world, prompt, first, place):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [first, 1]
    assert groups[1].location == (place or groups[1].location) and groups[1].location


@pytest.mark.parametrize("world,prompt,taken", [
    ("care_home", "A carer helps Dorothy down to the lounge.", "Dorothy"),
    ("care_home", "A carer helps Dorothy, on her walking frame, from the day room to the hairdresser's", "Dorothy"),
    ("residential", "Dad carries Ella, half asleep, from the living room up to the master bedroom.", "Ella"),
    ("care_home", "Dorothy is helped down to the lounge by a carer.", "Dorothy"),
])
def test_a_person_taken_along_is_a_second_group_that_follows(read, world, prompt, taken):
    groups = read(world, prompt).groups
    assert len(groups) == 2
    (follower,) = [g for g in groups if g.who == taken]
    assert follower.intent == "follow" and follower.count.value == 1


@pytest.mark.parametrize("world,prompt,whos", [
    ("mall", "A guard escorts Tom, a shoplifter, from the food court to the fountain.", ["A guard", "a shoplifter"]),
    ("sports_centre", "The coach waits in the changing rooms.", ["The coach"]),
    ("sports_centre", "The coach arrives at the sports hall.", ["The coach"]),
    ("mall", "A group of teenagers walk to the food court.", ["A group of teenagers"]),
    ("office", "The head of finance walks to the boardroom.", ["The head"]),
    ("mall", "A busload of tourists walk to the food court.", ["A busload of tourists"]),
    ("university", "Four overseas students wander over to the library.", ["Four overseas students"]),
    ("hospital", "A patient is wheeled into ward B by an orderly.", ["a patient", "An orderly"]),
    ("mall", "Put a heater by the fountain.", ["people"]),
])
def test_people_and_things_keep_their_reading(read, world, prompt, whos):
    assert [g.who for g in read(world, prompt).groups] == whos


@pytest.mark.parametrize("world,prompt,values", [
    ("hospital", "Two nurses wait in the pharmacy and a third of the patients head to the foyer.", [2, 1]),
    ("mall", "A guard deliberately waits by the fountain.", [1]),
    ("office", "Two interns queue at reception and a third waits in the boardroom.", [2, 1]),
])
def test_counts_keep_their_reading(read, world, prompt, values):
    assert [g.count.value for g in read(world, prompt).groups] == values
