"""Clause classes of round 34, each with sentences of its own over at least two worlds (none from the
understanding sets): going said by "make for" after a participle's object, or by "set off for"
(going_idioms.py); working a post said by a verb whose object the post is ("looks after the front
desk", "minds the sign-in desk": post_verbs.py); a queue said as a line people are stuck or sit in
(queue_lines.py); a verb of perceiving with nothing perceived is watching at a post ("have two
instructors spotting by the cave": watching_posts.py); escorting said by the arm (lent_arms.py); a
drill said as over is no evacuation (past_drills.py); the robot's laps said in chat ("bot doin laps":
chat_spelling.py); a fronted time said by a bare "-ing" noun ("After pudding a carer ...":
fronted_ing_times.py)."""

from __future__ import annotations

import pytest


# ---- 1. going said by an idiom ----------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("mall", "Three students doing coursework make for the food court.", "food_court"),
    ("mall", "A family sets off for the food court.", "food_court"),
    ("station", "Two backpackers set out for the ticket office.", "ticket_office"),
    ("airport", "Four pilots strike out for the duty free.", "duty_free"),
])
def test_going_said_by_an_idiom_walks_there(read, world, prompt, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.destination) == ("walk", destination)


def test_setting_things_off_or_out_is_no_going(read):
    (g,) = read("mall", "A guard sets off the alarm at the fountain.").groups
    assert g.intent != "walk"
    (g,) = read("mall", "Two cleaners set out the chairs in the food court.").groups
    assert g.intent != "walk"
    (g,) = read("mall", "The shoppers set off from the fountain.").groups
    assert (g.intent, g.start) == ("walk", "fountain")
    (g,) = read("mall", "Two teenagers head for the food court.").groups
    assert (g.intent, g.destination) == ("walk", "food_court")
    (g,) = read("library", "A student sets off towards the cafe.").groups
    assert (g.intent, g.destination) == ("walk", "cafe")
    (g,) = read("hospital", "Two porters doing paperwork make for the cafeteria, not the pharmacy.").groups
    assert (g.intent, g.destination) == ("walk", "cafeteria")


# ---- 2. working a post said by a verb whose object the post is ---------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("office", "Janet minds the sign-in desk.", "reception_desk"),
    ("office", "Janet looks after the reception desk.", "reception_desk"),
    ("mall", "A clerk looks after the information desk.", "information_desk"),
    ("hospital", "A porter looks after the main entrance.", "main_entrance"),
])
def test_working_a_post_stands_there(read, world, prompt, location):
    g = read(world, prompt).groups[0]
    assert g.location == location


def test_looking_after_people_keeps_its_reading(read):
    groups = read("mall", "A dad looks after the kids by the fountain.").groups
    assert all(g.location in (None, "fountain") for g in groups)
    (g,) = read("hospital", "A nurse minds the front desk.").groups
    assert g.location == "reception_desk"
    g = read("office", "Two temps keep an eye on the sign-in desk while a courier waits in the lobby.").groups[0]
    assert g.location == "reception_desk"


# ---- 3. a queue said as a line people are stuck or sit in ------------------------------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("station", "Ten passengers are stuck in a long line at the ticket office.", "ticket_office"),
    ("airport", "Twenty travellers are stuck in a long line at the check-in kiosks.", "check_in_kiosks"),
    ("mall", "Twelve shoppers are in a long line at the food court.", "food_court"),
    ("library", "Five students remain in a slow line at the issue desk.", "issue_desk"),
])
def test_a_line_people_are_stuck_in_is_a_queue(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.location) == ("queue", location)


def test_stuck_without_a_line_keeps_its_reading(read):
    (g,) = read("mall", "A man is stuck at the fountain.").groups
    assert g.intent == "wait"
    (g,) = read("station", "Ten passengers line up at the ticket office.").groups
    assert g.intent == "queue"
    (g,) = read("hospital", "Six patients sit in a long queue at the pharmacy.").groups
    assert (g.intent, g.location) == ("queue", "pharmacy")


# ---- 4. a verb of perceiving with nothing perceived: watching at a post -----------------------------------

@pytest.mark.parametrize("world,prompt,first,second", [
    ("mall", "Have two guards spotting by the fountain and a cleaner at the food court.", "fountain", "food_court"),
    ("sports_centre", "Have two coaches spotting by the weights rack and one parent in the cafe.", "weights_rack",
     "cafe"),
    ("hospital", "Two nurses noticing by the pharmacy, a porter at the main entrance.", "pharmacy", "main_entrance"),
    ("museum", "Two guards are spotting by the whale skeleton, a cleaner at the gift shop.", "whale_skeleton",
     "gift_shop"),
])
def test_spotting_at_a_post_is_a_group_there(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == [first, second]


def test_who_only_perceives_a_hazard_is_still_no_group(read):
    (g,) = read("mall", "A guard notices smoke in the food court and the shoppers leave.").groups
    assert g.intent == "evacuate"


# ---- 5. escorting said by the arm ---------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("care_home", "A carer gives Mr Reid her arm from the lounge back to the dining room.", "lounge", "dining_room"),
    ("hospital", "A nurse lends her arm to an old man from the pharmacy to the main entrance.", "pharmacy",
     "main_entrance"),
    ("mall", "A guard offers Mrs Patel a steadying arm from the fountain to the food court.", "fountain",
     "food_court"),
    ("station", "A porter takes the old lady's arm and walks her from the newsagent to the ticket office.",
     "newsagent", "ticket_office"),
])
def test_an_arm_given_walks_the_person_along(read, world, prompt, start, destination):
    leader, led = read(world, prompt).groups
    assert (leader.intent, leader.start, leader.destination) == ("walk", start, destination)
    assert led.intent == "follow"


def test_a_hand_or_an_arm_of_ones_own_keeps_its_reading(read):
    groups = read("mall", "A guard gives Tom a hand with the bags at the fountain.").groups
    assert not any(g.intent == "follow" for g in groups)


# ---- 6. a drill said as over is no evacuation ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("mall", "Shoppers hurry to the food court after last week's fire drill."),
    ("hospital", "After the fire drill, twenty visitors rush back to the cafeteria."),
    ("museum", "Two guards chat by the fountain while ten pupils race to the cafe after a drill."),
    ("library", "Following the evacuation drill the students hurry back to the reading room."),
])
def test_a_drill_that_is_over_is_no_evacuation(read, world, prompt):
    g = read(world, prompt).groups[-1]
    assert g.intent == "walk"


def test_a_drill_now_is_still_an_evacuation(read):
    g = read("mall", "During a fire drill the shoppers leave by the main entrance.").groups[-1]
    assert g.intent == "evacuate"


# ---- 7. the robot's laps in chat --------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("office", "bot doin laps of the corridor"),
    ("mall", "2 guards at fountain, robot doin laps of the food court"),
    ("hospital", "robot doin circuits of the main corridor"),
    ("airport", "bot doin laps of the concourse"),
    ("museum", "robot doin a lap of the great hall"),
])
def test_the_robots_laps_in_chat_are_a_patrol(read, world, prompt):
    assert read(world, prompt).robot.task == "patrol"


def test_dropped_gs_of_people_keep_their_reading(read):
    (g,) = read("mall", "2 kids sittin by the fountain").groups
    assert g.location == "fountain"
    assert read("station", "bot goin round the concourse").robot.task == "patrol"


# ---- 8. a fronted time said by a bare "-ing" noun ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("care_home", "After pudding a carer walks Mr Reid from the dining room to the lounge."),
    ("sports_centre", "After training a coach walks a swimmer from the gym to the cafe."),
    ("museum", "After swimming a teacher walks a pupil from the cafe to the gift shop."),
    ("mall", "After dancing a mum walks her son from the fountain to the food court."),
    ("station", "After skating a dad takes a child from the newsagent to the ticket office."),
])
def test_a_fronted_ing_time_keeps_the_person_who_leads(read, world, prompt):
    leader, led = read(world, prompt).groups
    assert leader.intent == "walk" and led.intent == "follow"


def test_a_fronted_verb_with_its_object_keeps_its_reading(read):
    (g,) = read("mall", "After feeding the ducks, two kids walk to the food court.").groups
    assert (g.count.value, g.destination) == (2, "food_court")
    for world, prompt in (("hospital", "After bingo a porter wheels a patient from the cafeteria to the main entrance."),
                          ("museum", "Before briefing a guide takes two pupils from the cafe to the gift shop.")):
        leader, led = read(world, prompt).groups
        assert leader.intent == "walk" and led.intent == "follow"


# ---- 9. an order's first item said by a bare count and an "-ing" verb -------------------------------------

@pytest.mark.parametrize("world,prompt,first,second", [
    ("mall", "Have two waiting by the fountain and three shoppers at the food court.", "fountain", "food_court"),
    ("station", "Have two waiting in the ticket office and a guard at the newsagent.", "ticket_office", "newsagent"),
    ("airport", "Get three queuing at the information desk and a pilot at the cafe.", "information_desk", "cafe"),
    ("museum", "Put four chatting by the whale skeleton and two guards at the gift shop.", "whale_skeleton",
     "gift_shop"),
])
def test_an_orders_bare_count_doing_something_is_a_group(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == [first, second]


def test_an_orders_count_of_things_is_no_group_of_people(read):
    groups = read("mall", "I have two shopping bags at the fountain.").groups
    assert not any(g.count.value == 2 for g in groups)
    groups = read("mall", "Two waiting by the fountain and three shoppers at the food court.").groups
    assert [g.count.value for g in groups] == [2, 3]
