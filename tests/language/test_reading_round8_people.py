"""Round 8 on people, counts, clauses and the robot, each class with sentences of its own over at least
two worlds (none from the understanding sets): a single person named by a role with "the", whatever
the world names after that role or the verb things do too; hostility to the robot (blows, shouting or
throwing at it, refusing it the way) is blocking it; an approximate count after a fronted phrase of time
or place ("At noon twenty or so ...", "During the lunch rush about fifteen staff ..."); what a vehicle
holds ("a coachload of pensioners"); a crew is a collective ("the cabin crew", "a crew of six"), but "three
cabin crew" are counted members; a count written "x10"; "a queue of 12 forms": no one "forms"; a
collective with its plural verb ("a retired couple dawdle"); whom the robot follows, named by two words
or a count ("the robot follows the security guard")."""

from __future__ import annotations

import pytest


def one(reading):
    assert reading.unknown_places == (), reading.unknown_places
    assert len(reading.groups) == 1, reading.groups
    return reading.groups[0]


# ---- 1. one person named by a role ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,place", [
    ("sports_centre", "The lifeguard sits in the high chair for twenty minutes", "lifeguard", "lifeguard_chair"),
    ("sports_centre", "the lifeguard walks over to reception", "lifeguard", "reception_desk"),
    ("sports_centre", "The coach waits by the pool until the lesson ends", "coach", "pool_hall"),
    ("sports_centre", "the referee stands in the sports hall all evening", "referee", "sports_hall"),
    ("library", "The bookseller reads to children in the reading room", "bookseller", "reading_room"),
    ("hospital", "The chaplain sits with a patient on the ward", "chaplain", "ward_a"),
    ("station", "the signalwoman waits on platform 2", "signalwoman", "platform_2"),
    ("mall", "The doorkeeper stands by the fountain for an hour", "doorkeeper", "fountain"),
])
def test_a_role_with_the_is_one_person(read, world, prompt, label, place):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind, g.count.value) == (label, "exact", 1)
    assert place in (g.location, g.destination)


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "the porter leans against the pharmacy counter for ten minutes", "porter"),
    ("library", "The librarian leans on the issue desk all afternoon", "librarian"),
    ("office", "three cleaners lean on their mops in the kitchen", "cleaner"),
])
def test_a_person_leaning_is_no_thing(read, world, prompt, label):
    g = one(read(world, prompt))
    assert g.label == label and g.intent == "wait"


@pytest.mark.parametrize("world,prompt", [
    ("office", "Two fans whir in the server room."),
    ("sports_centre", "A new mudguard sits by the entrance."),
])
def test_things_named_like_people_stay_things(read, world, prompt):
    assert all(g.label == "person" and g.count.kind != "exact" for g in read(world, prompt).groups)


# ---- 2. hostility to the robot is blocking it ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("library", "a student squares up to the robot by the entry gates"),
    ("hospital", "A drunk visitor squares up to the robot in the corridor"),
    ("mall", "a teenager won't let the robot through"),
    ("station", "a commuter won't budge for the robot"),
    ("office", "an intern refuses to get out of the robot's way"),
    ("hospital", "a porter doesn't make way for the robot"),
    ("mall", "two lads shout at the robot"),
    ("sports_centre", "a footballer yells at the robot"),
    ("airport", "a passenger throws a cup at the robot"),
    ("mall", "a kid pushes the robot"),
    ("museum", "a toddler slaps the robot"),
    ("station", "a man barges into the robot"),
    ("sports_centre", "some teenagers try to tip the robot over"),
    ("library", "a reader grabs the robot and won't let go"),
    ("mall", "a drunk man tries to fight the robot"),
    ("mall", "a teenager sits on the robot"),
    ("library", "a student rocks the robot back and forth"),
])
def test_hostility_to_the_robot_is_blocking_it(read, world, prompt):
    g = one(read(world, prompt))
    assert (g.robot_interaction, g.robot_reaction) == ("block", "Threatening")


@pytest.mark.parametrize("world,prompt,interaction", [
    ("museum", "kids shout with excitement when the robot rolls in", None),
    ("station", "a man pushes past the robot", None),
    ("mall", "a mother pushes a pram past the robot", None),
    ("office", "a cleaner steps aside to let the robot through", "avoid"),
    ("sports_centre", "a parent glares at the robot", "look"),
    ("hospital", "a patient sits on the bench next to the robot", None),
    ("mall", "a man rocks his baby while the robot passes", None),
])
def test_not_every_shout_or_push_is_hostile(read, world, prompt, interaction):
    assert one(read(world, prompt)).robot_interaction == interaction


# ---- 3. an approximate count after a fronted phrase ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,value", [
    ("hospital", "During the lunch rush about fifteen staff queue in the cafeteria", "staff", 15),
    ("sports_centre", "Once the class ends, about fifteen staff walk to the staff room", "staff", 15),
    ("office", "At lunchtime twenty or so developers head to the kitchen", "developer", 20),
    ("library", "When the bell goes, twenty or so students leave through the main entrance", "student", 20),
    ("museum", "In the afternoon twenty-odd pupils wander through the Egyptian gallery", "pupil", 20),
    ("station", "Every evening, thirty-odd commuters wait on platform 1", "commuter", 30),
    ("mall", "Outside the cinema around forty teenagers queue", "teenager", 40),
    ("library", "When the tour finishes, a dozen or so visitors go to the cafe", "visitor", 12),
])
def test_an_approximate_count_after_a_fronted_phrase(read, world, prompt, label, value):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind, g.count.value) == (label, "approximate", value)


@pytest.mark.parametrize("world,prompt", [
    ("sports_centre", "the class starts in the studio"),
    ("museum", "a school class ends its visit in the cafe"),
])
def test_a_class_with_a_place_is_still_people(read, world, prompt):
    assert one(read(world, prompt)).label == "class"


# ---- 4. collectives and counts in odd places ----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,kind,low,high", [
    # what a vehicle holds is a number nobody said (vague); a crew is a size the word implies
    ("library", "a coachload of pensioners arrives at the main entrance", "pensioner", "vague", 30, 50),
    ("mall", "a busload of tourists pours in through the main entrance", "tourist", "vague", 30, 50),
    ("airport", "the flight crew walk to gate B2", "flight crew", "implied", 3, 8),
    ("sports_centre", "the camera crew waits at reception", "crew", "implied", 3, 8),
])
def test_what_a_vehicle_or_a_crew_holds(read, world, prompt, label, kind, low, high):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind, g.count.low, g.count.high) == (label, kind, low, high)


@pytest.mark.parametrize("world,prompt,label,value", [
    ("airport", "a cabin crew of eight walks to gate B2", "cabin crew", 8),
    ("museum", "a film crew of four waits in the foyer", "crew", 4),
    ("airport", "three cabin crew walk to gate B1", "cabin crew", 3),
    ("sports_centre", "swimmers x10 queue at reception", "swimmer", 10),
    ("mall", "shoppers (x20) wander around the food court", "shopper", 20),
    ("station", "10x commuters wait on platform 2", "commuter", 10),
    ("hospital", "x3 porters wait at the lift", "porter", 3),
])
def test_a_count_said_after_or_inside_a_collective(read, world, prompt, label, value):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind, g.count.value) == (label, "exact", value)


@pytest.mark.parametrize("world,prompt,place", [
    ("library", "a queue of 12 forms at the issue desk", "issue_desk"),
    ("station", "a line of 30 stretches back from the ticket office", "ticket_office"),
])
def test_a_queue_of_a_number_and_its_verb(read, world, prompt, place):
    g = one(read(world, prompt))
    assert g.count.value in (12, 30) and g.label in ("queue", "line") and place in (g.location, g.start)


@pytest.mark.parametrize("world,prompt,label", [
    ("library", "a retired couple dawdle through the lending hall until closing", "couple"),
    ("mall", "a young family stroll past the fountain", "family"),
])
def test_a_collective_with_its_plural_verb(read, world, prompt, label):
    g = one(read(world, prompt))
    assert g.label == label and g.count.kind == "implied"


@pytest.mark.parametrize("world,prompt,label,value", [
    ("mall", "the robot delivers a parcel to the information desk while a dozen shoppers dawdle past the fountain",
     "shopper", 12),
    ("hospital", "the robot crosses the lobby while a dozen visitors dawdle past the pharmacy", "visitor", 12),
])
def test_counted_people_and_their_plural_verb_the_parser_calls_a_noun(read, world, prompt, label, value):
    g = one(read(world, prompt))
    assert (g.label, g.count.value, g.pace) == (label, value, "slow")


# ---- 5. the person the robot follows, named by two words or a count -----------------------------------

@pytest.mark.parametrize("world,prompt,label,follows", [
    ("mall", "the robot follows the security guard around the mall", "guard", "the security guard"),
    ("hospital", "the robot follows a security guard to the pharmacy", "guard", "a security guard"),
    ("station", "the robot follows the ticket inspector along platform 1", "inspector", "the ticket inspector"),
    ("library", "the robot follows two students to the cafe", "student", "two students"),
])
def test_whom_the_robot_follows(read, world, prompt, label, follows):
    r = read(world, prompt)
    assert one(r).label == label
    assert (r.robot.task, r.robot.follows) == ("follow", follows)


# ---- 6. a shift of workers, and the shift as a time ----------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,kind", [
    ("sports_centre", "the night shift cleans the changing rooms", "night shift", "implied"),
    ("station", "the night shift arrives at the main entrance", "night shift", "implied"),
    ("hospital", "the early shift of six nurses gathers at the nurse station", "nurse", "exact"),
])
def test_a_shift_of_workers_is_a_group(read, world, prompt, label, kind):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind) == (label, kind)


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "After the night shift, two nurses walk to the cafeteria", "nurse"),
    ("sports_centre", "After the class, ten kids go to the cafe", "kid"),
    ("library", "during the late shift a porter pushes a trolley to the lift", "porter"),
])
def test_a_shift_or_class_after_a_word_of_time_is_a_time(read, world, prompt, label):
    assert one(read(world, prompt)).label == label


# ---- 7. a bare number, then "the others": part of the group before, and the rest of it ---------------

@pytest.mark.parametrize("world,prompt,whole,part,rest", [
    ("library", "fifteen students arrive at the foyer; ten head to the reading room and the others go to the cafe",
     15, 10, 5),
    ("sports_centre", "twenty kids arrive at reception; five go to the pool hall and the rest go to the sports hall",
     20, 5, 15),
    ("station", "forty commuters pour off the train; thirty head to the exit and the rest wait on platform 1", 40, 30, 10),
    ("sports_centre", "thirty parents wait in the cafe; twelve go to the pool hall and everyone else stays put", 30, 12,
     18),
])
def test_a_bare_number_then_the_others_is_a_partition(read, world, prompt, whole, part, rest):
    g0, g1, g2 = read(world, prompt).groups
    assert (g0.count.value, g0.relation) == (whole, None)
    assert (g1.count.value, g1.relation) == (part, "subset_of:0")
    assert (g2.count.value, g2.relation) == (rest, "others_of:0")


def test_a_number_with_no_verb_of_its_own_is_a_group_of_its_own(read):
    g0, g1, g2 = read("hospital", "twenty people wait in the cafeteria and ten in the pharmacy while the others go home").groups
    assert g1.relation is None and g1.count.value == 10


@pytest.mark.parametrize("world,prompt", [
    ("museum", "a pair of tourists take selfies with the robot in the great hall"),
    ("library", "two students take selfies with the robot by the notice board"),
])
def test_selfies_with_the_robot_are_looking_at_it(read, world, prompt):
    assert one(read(world, prompt)).robot_interaction == "look"


# ---- 8. someone taken ill who is why a place is cleared is no group of the scene ----------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("sports_centre", "The sports hall is cleared after a player is injured; everyone in it, about 40 people, "
     "leaves through the main entrance.", 40),
    ("hospital", "The cafeteria is evacuated after a visitor faints; everyone, about 20 people, leaves through the "
     "main entrance.", 20),
    ("mall", "The food court is closed after a child is sick by the fountain; everyone there, about 30 shoppers, "
     "leaves through the west entrance.", 30),
])
def test_the_cause_of_a_clearing_is_no_group(read, world, prompt, value):
    g = one(read(world, prompt))
    assert g.who == "everyone" and g.count.value == value


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "a patient is sick in the waiting room while two nurses walk to the ward", "patient"),
    ("sports_centre", "the robot delivers towels to the changing rooms while swimmers queue at reception", "swimmer"),
])
def test_someone_taken_ill_with_no_clearing_is_a_group(read, world, prompt, label):
    assert read(world, prompt).groups[0].label == label


# ---- 9. paying the robot no heed is no reaction ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("sports_centre", "a group of mums chat by reception and pay no attention to the robot"),
    ("hospital", "visitors take no notice of the robot"),
    ("mall", "shoppers pay little attention to the robot as it passes"),
    ("office", "the developers never look at the robot"),
    ("library", "a librarian does not notice the robot"),
])
def test_paying_the_robot_no_heed_is_no_reaction(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert (g.robot_interaction, g.robot_reaction) == (None, None)


@pytest.mark.parametrize("world,prompt", [
    ("mall", "kids cannot stop staring at the robot"),
    ("station", "a commuter can't help staring at the robot"),
])
def test_not_stopping_to_look_is_still_looking(read, world, prompt):
    assert one(read(world, prompt)).robot_interaction == "look"


# ---- 10. more ways to say how many ----------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,kind,low,high", [
    ("library", "a few dozen students queue at the printer", "student", "vague", 24, 48),
    ("mall", "several dozen fans wait by the fountain", "fan", "vague", 36, 72),
    ("library", "loads of students fill the cafe", "student", "vague", 8, 15),
    ("library", "a student or two loiter by the bag lockers", "student", "vague", 1, 2),
    ("hospital", "a nurse or two walk to the ward", "nurse", "vague", 1, 2),
    ("library", "students (around 30) study in the reading room", "student", "approximate", 24, 36),
    ("hospital", "visitors - about 20 - wait in the cafeteria", "visitor", "approximate", 16, 24),
    ("sports_centre", "a swimming club of 20 queues at reception", "club", "exact", 20, 20),
    ("library", "a choir of thirty children sings in the foyer", "child", "exact", 30, 30),
    ("library", "the book club meets in the seminar room", "club", "implied", 6, 15),
    ("library", "a queue of about 8 forms at the self checkout", "queue", "approximate", 6, 10),
])
def test_more_ways_to_say_how_many(read, world, prompt, label, kind, low, high):
    g = one(read(world, prompt))
    assert (g.label, g.count.kind, g.count.low, g.count.high) == (label, kind, low, high)


@pytest.mark.parametrize("world,prompt,who,label", [
    ("sports_centre", "ten kids run to the pool hall while the rest of the class dawdle behind", "the rest of the class",
     "kid"),
    ("hospital", "two nurses go to the pharmacy and the rest of the nurses stay on the ward", "the rest of the nurses",
     "nurse"),
])
def test_the_rest_of_a_named_group(read, world, prompt, who, label):
    g = read(world, prompt).groups[1]
    assert (g.who, g.label, g.relation) == (who, label, "others_of:0")


# ---- 11. a verb of pace with its "-s" ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,pace", [
    ("sports_centre", "a family with a pushchair dawdles from reception to the cafe", "slow"),
    ("mall", "an old man trudges to the food court", "slow"),
    ("hospital", "a porter moseys along the corridor", "slow"),
    ("library", "a student scurries to the printer", "fast"),
])
def test_a_verb_of_pace_with_its_s(read, world, prompt, pace):
    assert one(read(world, prompt)).pace == pace


# ---- 12. what people carry or hold is no place -----------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("office", "an intern carrying coffees hurries to the boardroom", "boardroom"),
    ("library", "a man carrying a stack of books hurries to the issue desk", "issue_desk"),
    ("library", "a student holding a coffee walks to the printer", "printer"),
])
def test_what_people_carry_is_no_place(read, world, prompt, destination):
    g = one(read(world, prompt))
    assert (g.start, g.location, g.destination) == (None, None, destination)


@pytest.mark.parametrize("world,prompt,label,place", [
    ("station", "The station announcer sits in the ticket office all afternoon", "announcer", "ticket_office"),
    ("sports_centre", "the pool attendant stands by the high chair for an hour", "attendant", "lifeguard_chair"),
])
def test_a_role_named_with_a_noun_before_it_is_one_person(read, world, prompt, label, place):
    g = one(read(world, prompt))
    assert (g.label, g.count.value, g.location) == (label, 1, place)


# ---- 13. more ways of reacting to the robot, and a duty that is nobody ---------------------------------

@pytest.mark.parametrize("world,prompt,interaction", [
    ("sports_centre", "two boys sneak up behind the robot", "approach"),
    ("library", "a toddler creeps up on the robot in the foyer", "approach"),
    ("sports_centre", "a little girl waves to the robot and then hides behind her mum", "look"),
    ("hospital", "an old man waves to the robot from his wheelchair", "look"),
])
def test_more_reactions_to_the_robot(read, world, prompt, interaction):
    assert one(read(world, prompt)).robot_interaction == interaction


@pytest.mark.parametrize("world,prompt,place", [
    ("library", "the robot stands guard at the staff entrance all night", "staff_entrance"),
    ("museum", "the robot stands guard in the Egyptian gallery", "egyptian_gallery"),
])
def test_standing_guard_is_the_robots_duty_and_nobody(read, world, prompt, place):
    r = read(world, prompt)
    assert all(g.label == "person" and g.who == "people" for g in r.groups)
    assert (r.robot.task, r.robot.location) == ("wait", place)


@pytest.mark.parametrize("world,prompt,whole,who", [
    ("station", "twenty commuters wait on platform 1; a few leave through the main entrance", 20, "a few"),
    ("hospital", "ten patients wait in the waiting room and several walk to the pharmacy", 10, "several"),
    ("library", "thirty students revise in the reading room; some go to the cafe", 30, "some"),
])
def test_a_vague_few_after_a_group_is_part_of_it(read, world, prompt, whole, who):
    g0, g1 = read(world, prompt).groups
    assert g0.count.value == whole and (g1.who, g1.relation) == (who, "subset_of:0")
    assert g1.destination is not None and g0.destination is None
