"""Round 19 of the reader's clauses and events: an event said as the cause of people leaving (a place
that shuts, a thing left behind so a zone is cleared) is no group of its own, and the zone is where
the leavers start; a bell that is no alarm makes no evacuation; a wait for a time before going on
starts from where it is spent."""

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("mall", "Smoke is seen in the toy store, so the toy store shuts and the 12 shoppers browsing in it hurry "
             "out through the east entrance.", "toy_store", "east_entrance"),
    ("museum", "Flames are seen in the gift shop, so the gift shop shuts and the 10 tourists browsing there "
               "hurry out through the main entrance.", "gift_shop", "main_entrance"),
    ("mall", "Somebody has left a suitcase by the fountain, so the main atrium is cleared: about 60 shoppers "
             "are sent out via the main entrance.", "main_atrium", "main_entrance"),
    ("hospital", "Someone has abandoned a holdall under the reception desk, so the entrance lobby is cleared: "
                 "roughly 50 visitors are sent out via the main entrance.", "entrance_lobby", "main_entrance"),
    ("station", "A man has dumped a box beside the ticket machines, so the ticket hall is evacuated and about "
                "90 travellers hurry out through the main entrance.", "ticket_hall", "main_entrance"),
])
def test_an_event_that_clears_a_zone_is_one_evacuating_group_from_it(read, world, prompt, start, destination):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.intent == "evacuate" and g.start == start and g.destination == destination
    assert not r.unknown_places


@pytest.mark.parametrize("world,prompt,start", [
    ("hospital", "When the bell rings at 8 pm, about 20 visitors drift out of ward a towards the main entrance.",
     "ward_a"),
    ("mall", "When the bell goes at closing time, some 30 shoppers wander out of the bookshop towards the west "
             "entrance.", "bookshop"),
    ("museum", "When the bell rings at five, around 40 visitors stroll out of the great hall towards the main "
               "entrance.", "great_hall"),
    ("library", "As soon as the bell goes, a dozen students file out of the reading room towards the main entrance.", "reading_room"),
])
def test_a_bell_that_is_no_alarm_is_no_evacuation(read, world, prompt, start):
    (g,) = read(world, prompt).groups
    assert g.intent == "walk" and g.start == start


# A guard, not a new reading: a bell said as an alarm still evacuates.
@pytest.mark.parametrize("world,prompt", [
    ("mall", "When the fire bell rings, about 30 shoppers leave the bookshop through the west entrance."),
    ("hospital", "The alarm bells ring and twenty visitors hurry out of ward b."),
])
def test_a_fire_bell_is_still_an_alarm(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "evacuate"


@pytest.mark.parametrize("world,prompt,start,destination,seconds", [
    ("mall", "A girl hangs around at the phone kiosk for 5 minutes before strolling off alone to the bookshop.",
     "phone_kiosk", "bookshop", 300),
    ("museum", "Two tourists linger in the great hall for 10 mins before wandering off to the cafe.",
     "great_hall", "cafe", 600),
    ("office", "A developer waits by the kitchen for five minutes, then heads off to the reception.",
     "kitchen", "reception", 300),
    ("hospital", "An old man sits in the cafeteria for half an hour, then shuffles off to the pharmacy.",
     "cafeteria", "pharmacy", 1800),
])
def test_a_wait_for_a_time_before_going_on_starts_where_it_is_spent(read, world, prompt, start, destination,
                                                                    seconds):
    (g,) = read(world, prompt).groups
    assert g.start == start and g.destination == destination and g.wait_seconds == seconds


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A nervous shopper sidles warily past the robot, keeping the fountain between herself and it."),
    ("office", "An anxious intern creeps past the robot, keeping the printer between him and it."),
    ("hospital", "A cleaner tiptoes cautiously past the robot towards the pharmacy."),
    ("station", "A small boy edges gingerly around the robot on the concourse."),
    ("library", "Two readers step carefully round the robot, keeping a shelf between themselves and it."),
])
def test_going_past_the_robot_warily_or_keeping_something_between_is_avoiding_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "robot" and g.robot_interaction == "avoid" and g.robot_reaction == "Scared"


@pytest.mark.parametrize("world,prompt", [
    ("station", "Two lads deliberately stand where the robot wants to go."),
    ("hospital", "A porter deliberately parks himself where the robot is trying to drive."),
    ("office", "Two developers stubbornly position themselves where the robot needs to pass."),
    ("museum", "Three schoolboys deliberately stand where the robot is trying to go."),
])
def test_standing_where_the_robot_wants_to_go_is_blocking_it(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.intent == "robot" and g.robot_interaction == "block"


# A guard: walking past the robot, in no wary manner, is no reaction to it.
def test_walking_past_the_robot_is_no_reaction(read):
    (g,) = read("museum", "A guard walks past the robot to the great hall.").groups
    assert g.intent == "walk" and g.robot_interaction is None


@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Bent over the reception desk, two receptionists type on.", "reception_desk"),
    ("office", "Hunched over the kitchen table, three developers eat their lunch, ignoring the robot.", "kitchen_table"),
    ("hospital", "Leaning over the reception desk, a man chats to the receptionist.", "reception_desk"),
    ("hospital", "Stooped over the food counter, two cooks chat.", "food_counter"),
    ("mall", "Bent over the checkout counter, a cashier counts the takings.", "checkout_counter"),
])
def test_a_fronted_phrase_over_a_fixture_is_where_the_group_is(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


# A guard: "over" before a number is a count, and over a thing the world lacks no place.
@pytest.mark.parametrize("world,prompt,location", [
    ("station", "Over 30 commuters wait on the concourse.", "concourse"),
    ("mall", "Two boys argue over the bill in the food court.", "food_court"),
])
def test_over_a_number_or_a_thing_is_no_place(read, world, prompt, location):
    r = read(world, prompt)
    (g,) = r.groups
    assert g.location == location and not r.unknown_places


@pytest.mark.parametrize("world,prompt,location", [
    ("museum", "Three kids play inside the gift shop.", "gift_shop"),
    ("hospital", "A toddler romps inside the main waiting room.", "main_waiting_room"),
    ("mall", "Two girls are messing about inside the bookshop.", "bookshop"),
    ("office", "Some children frolic inside the kitchen.", "kitchen"),
    ("station", "Two boys play inside the ticket hall.", "ticket_hall"),
])
def test_inside_a_place_with_no_verb_of_motion_is_being_there(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.intent in ("wait", "wander") and g.location == location


@pytest.mark.parametrize("world,prompt,location,seconds", [
    ("mall", "A woman makes one coffee last half an hour in the food court.", "food_court", 1800),
    ("office", "A developer makes a single tea last 20 minutes in the kitchen.", "kitchen", 1200),
    ("hospital", "An old man makes a cup of tea last forty minutes in the cafeteria.", "cafeteria", 2400),
    ("museum", "A pensioner is making a pot of tea last 25 minutes in the cafe.", "cafe", 1500),
])
def test_making_a_drink_last_a_time_is_a_wait_that_long(read, world, prompt, location, seconds):
    (g,) = read(world, prompt).groups
    assert g.intent == "wait" and g.location == location and g.wait_seconds == seconds
