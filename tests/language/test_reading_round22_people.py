"""Round 22 of the reader's people, counts and groups: one person said by a name the parser tags an
adjective, by a noun no list has after a word for people, by an abbreviation after a modifier ("a
locum GP"), or by a noun kept for a machine that goes from one room into another, is one person; a
person's verb after a place phrase and before "when" or "and" is a verb ("a little girl wails when
..."), not a crowd of "wails"."""

import pytest


@pytest.mark.parametrize("world,prompt,start,destination,location", [
    ("care_home", "Doreen pops out of the lounge and along to the dining room.", "lounge", "dining_room", None),
    ("office", "Doreen pops out of the kitchen and along to the boardroom.", "kitchen", "boardroom", None),
    ("supermarket", "An elderly gent dawdles by the tills.", None, None, "checkouts"),
    ("hospital", "An elderly gent lingers in the cafeteria.", None, None, "cafeteria"),
    ("hospital", "A nursing auxiliary bustles from the pharmacy into the cafeteria.", "pharmacy", "cafeteria", None),
    ("care_home", "A nursing auxiliary bustles from the kitchen into the lounge.", "kitchen", "lounge", None),
    ("hospital", "The dispenser hurries out of the pharmacy into the cafeteria.", "pharmacy", "cafeteria", None),
    ("office", "The dispenser scurries out of the kitchen into the boardroom.", "kitchen", "boardroom", None),
])
def test_one_person_no_list_names_is_one(read, world, prompt, start, destination, location):
    r = read(world, prompt)
    (one,) = r.groups
    assert one.count.kind == "exact" and one.count.value == 1
    assert (one.start, one.destination, one.location) == (start, destination, location)


@pytest.mark.parametrize("world,prompt,place", [
    ("hospital", "By the pharmacy a little girl wails when she sees the robot.", "pharmacy"),
    ("office", "In the kitchen a young lad whimpers and hides from the robot.", "kitchen"),
    ("care_home", "In the lounge an old dear shrieks when she spots the robot.", "lounge"),
    ("market_hall", "Beside the noodle stall a wee girl wails when she sees the robot.", "noodle_stall"),
])
def test_a_place_first_then_one_person_who_reacts(read, world, prompt, place):
    (one,) = read(world, prompt).groups
    assert one.count.value == 1 and one.location == place


@pytest.mark.parametrize("world,prompt,where", [
    ("hospital", "The porter nips out of the pharmacy into the cafeteria, while a locum GP loiters by reception.",
     "reception_desk"),
    ("office", "A courier dashes from reception to the kitchen, while a locum GP waits in the boardroom.",
     "boardroom"),
])
def test_an_abbreviated_role_after_a_modifier_is_one_person(read, world, prompt, where):
    first, second = read(world, prompt).groups
    assert first.count.value == 1 and second.count.value == 1 and second.location == where


@pytest.mark.parametrize("world,prompt,value,start", [
    ("office", "Some 30 well-wishers drift out of the boardroom towards reception.", 30, "boardroom"),
    ("care_home", "Some 20 well-wishers drift out of the lounge towards reception.", 20, "lounge"),
    ("market_hall", "Some 40 holiday-makers drift from the bakery stall towards the noodle stall.", 40, "bakery_stall"),
    ("office", "About a dozen job-seekers mill about in reception.", 12, None),
])
def test_some_number_of_hyphenated_people_whose_verb_the_parser_took_for_a_noun(read, world, prompt, value, start):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "approximate" and group.count.value == value and group.count.low < value < group.count.high
    assert group.start == start


@pytest.mark.parametrize("world,prompt,first,second", [
    ("market_hall", "Sue the florist scoots over from the noodle stall to the bakery stall, while two traders haul "
     "crates from the loading bay into the cold store.", ("noodle_stall", "bakery_stall"), ("loading_bay", "cold_store")),
    ("market_hall", "Kev the florist scoots over from the bakery stall to the noodle stall, as two porters wheel boxes "
     "from the loading bay into the cold store.", ("bakery_stall", "noodle_stall"), ("loading_bay", "cold_store")),
    ("gp_surgery", "Mo the dispenser scoots over from the pharmacy to the kitchen, while two receptionists carry files "
     "from reception into the kitchen.", ("pharmacy", "staff_kitchen"), ("reception", "staff_kitchen")),
    ("care_home", "Val the hairdresser scoots over from the lounge to the dining room, as two carers wheel a trolley "
     "from the kitchen into the lounge.", ("lounge", "dining_room"), ("kitchen", "lounge")),
])
def test_a_named_trade_the_world_has_a_place_of_goes_then_a_second_clause(read, world, prompt, first, second):
    named, others = read(world, prompt).groups
    assert named.count.value == 1 and (named.start, named.destination) == first
    assert others.count.value == 2 and (others.start, others.destination) == second
