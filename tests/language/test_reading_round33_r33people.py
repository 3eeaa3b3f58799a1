"""People classes of round 33, each with sentences of its own over at least two worlds (none from the
understanding sets): a range of small counts said with "or" before a describing word ("four or five weary
shoppers", "a couple or three visitors") is approximate; a couple's word said bare ("Honeymooners") is
two; a name after "from" ends a phrase about people and a vehicle said for its load is a load; a count
before a hyphenated phrase ("a pair of art-school doodlers"), or one person whose verb comes before a
later clause's ("a sixth-former nips over ... because her ... needs ..."); a person the lexicon lacks
with a participle of where they are ("a nervous flyer sitting at gate 5 shrinks back")."""

from __future__ import annotations

import pytest


def _one(reading):
    (g,) = reading.groups
    return g


# ---- 1. a range of small counts before a describing word: approximate ---------------------------------------

@pytest.mark.parametrize("world,prompt,low,high", [
    ("supermarket", "Four or five weary shoppers queue at the tills.", 4, 5),
    ("mall", "Two or three nervous children sit in the food court.", 2, 3),
    ("station", "Three or four sleepy commuters wait on platform 2.", 3, 4),
    ("hospital", "Five or six off-duty porters walk to the pharmacy.", 5, 6),
    ("mall", "Two or three long-haired teenagers wander around the food court.", 2, 3),
    ("museum", "A couple or three teenagers hang about in the cafe.", 2, 3),
    ("hospital", "A couple or three visitors walk to the pharmacy.", 2, 3),
])
def test_a_range_before_a_describing_word_is_approximate(read, world, prompt, low, high):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.low, g.count.high) == ("approximate", low, high)
    assert low <= g.count.value <= high


def test_a_range_before_the_person_noun_keeps_its_reading(read):
    for world, prompt, kind, low, high in [
            ("hospital", "Two or three people queue at the pharmacy.", "vague", 2, 3),
            ("hospital", "Three or four porters chat in the cafeteria.", "vague", 3, 4),
            ("office", "Six to eight tired developers wander around the open office.", "vague", 6, 8),
            ("hospital", "A couple of visitors walk to the pharmacy.", "exact", 2, 2)]:
        g = _one(read(world, prompt))
        assert (g.count.kind, g.count.low, g.count.high) == (kind, low, high)


# ---- 2. a couple's word said bare: two ----------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Newlyweds walk to the pharmacy."),
    ("mall", "Honeymooners wander around the food court."),
    ("hotel", "Newlyweds choosing a room walk from the lobby to the bar."),
    ("mall", "Happy honeymooners walk from the food court to the exit."),
])
def test_a_couples_word_said_bare_is_two(read, world, prompt):
    g = _one(read(world, prompt))
    assert g.count.value == 2
    assert g.count.kind in ("implied", "exact")


def test_counted_couple_words_keep_their_reading(read):
    g = _one(read("mall", "Three newlyweds walk to the exit."))
    assert (g.count.kind, g.count.value) == ("exact", 3)
    g = _one(read("mall", "Some newlyweds walk to the exit."))
    assert g.count.kind == "vague"
    g = _one(read("hospital", "The newlyweds walk to the pharmacy."))
    assert g.count.value == 2


# ---- 3. a collective from a named place; a vehicle said for its load ------------------------------------------

@pytest.mark.parametrize("world,prompt,low,high,place", [
    ("mall", "A coachload of day-trippers from Cardiff mills around the food court.", 30, 50, "food_court"),
    ("station", "A busload of day-trippers from York mills around platform 2.", 30, 50, "platform_2"),
    ("hotel", "A coachload of day-trippers from Bath mills around the lobby.", 30, 50, "lobby"),
])
def test_a_collective_from_a_named_place_is_one_group(read, world, prompt, low, high, place):
    g = _one(read(world, prompt))
    assert (g.count.low, g.count.high) == (low, high)
    assert (g.intent, g.location) == ("wander", place)


@pytest.mark.parametrize("world,prompt,low,high", [
    ("mall", "A minibus of pensioners from Leeds walks to the exit.", 10, 16),
    ("supermarket", "A minibus of pensioners from Hull potters around the bakery.", 10, 16),
    ("hospital", "A busful of pensioners from Hull queues at the pharmacy.", 30, 50),
    ("station", "A van full of roadies walks to platform 2.", 5, 10),
    ("museum", "A coachful of day-trippers from Leeds potters around the cafe.", 30, 50),
])
def test_a_vehicle_said_for_its_load_is_a_load(read, world, prompt, low, high):
    g = _one(read(world, prompt))
    assert (g.count.low, g.count.high) == (low, high)


def test_people_from_a_place_and_a_coach_keep_their_reading(read):
    g = _one(read("museum", "A coach of the under-12s walks to the cafe."))
    assert g.count.value == 1
    g = _one(read("museum", "A family from Leeds walks to the cafe."))
    assert g.count.kind == "implied"
    g = _one(read("museum", "Tom from Leeds walks to the cafe."))
    assert (g.count.value, g.destination) == (1, "cafe")
    g = _one(read("station", "A busload of fans from Glasgow mills around platform 2."))
    assert (g.count.low, g.count.high) == (30, 50)


# ---- 4. a count before a hyphenated phrase; one person before a later clause's verb ----------------------------

@pytest.mark.parametrize("world,prompt", [
    ("museum", "A pair of art-school doodlers put down their pads to watch the robot."),
    ("mall", "A pair of sixth-form doodlers lay down their pads to stare at the robot."),
    ("art_gallery", "A pair of art-college sketchers lay aside their pencils to watch the robot."),
    ("station", "A pair of art-school doodlers lay down their pads to watch the robot."),
])
def test_a_pair_before_a_hyphenated_phrase_is_two(read, world, prompt):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", 2)
    assert g.intent == "robot"


@pytest.mark.parametrize("world,prompt", [
    ("museum", "A sixth-former nips over to the cafe because his expired passport needs a photo."),
    ("station", "A sixth-former nips over to platform 2 because her cheap ticket needs a stamp."),
    ("airport", "A sixth-former nips over to gate 5 because his boarding pass needs a check."),
    ("post_office", "A sixth-former nips over to the photo booth because his expired passport needs a photo."),
    ("mall", "A sixth-former nips over to the exit because her late bus needs catching."),
])
def test_one_person_before_a_later_clause_is_one(read, world, prompt):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    assert g.intent == "walk"


def test_counted_hyphenated_phrases_keep_their_reading(read):
    g = _one(read("museum", "Two art-college sketchers put away their pencils and wander around the cafe."))
    assert (g.count.kind, g.count.value) == ("exact", 2)
    g = _one(read("office", "A sixth-former nips over to the kitchen because her cold lunch needs a microwave."))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    g = _one(read("hospital", "A pair of off-duty nurses walk to the pharmacy."))
    assert (g.count.kind, g.count.value) == ("exact", 2)


# ---- 5. a person the lexicon lacks, with a participle of where they are ----------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("airport", "A nervous flyer sitting at gate 5 shrinks back whenever the robot rolls close."),
    ("airport", "A nervous flyer sitting by the windows shrinks back whenever the robot rolls close."),
    ("hospital", "A nervous flyer waiting by the lifts shrinks back whenever the robot comes near."),
    ("museum", "A timid sketcher sitting by the whale skeleton cowers when the robot approaches."),
    ("station", "A weary stopper sitting on the benches shrinks back whenever the robot rolls close."),
])
def test_a_person_sitting_somewhere_is_one(read, world, prompt):
    g = _one(read(world, prompt))
    assert (g.count.kind, g.count.value) == ("exact", 1)
    assert g.intent == "robot"


def test_listed_people_sitting_somewhere_keep_their_reading(read):
    g = _one(read("hospital", "An old man sitting on the benches backs away when the robot approaches."))
    assert (g.count.value, g.intent) == (1, "robot")
    g = _one(read("mall", "A shy shopper perched on the benches cowers when the robot approaches."))
    assert (g.count.value, g.location) == (1, "atrium_benches")
