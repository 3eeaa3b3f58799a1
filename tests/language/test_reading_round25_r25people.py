"""Round 25 of the reader's people and counts: a count and a plural noun no list names, with the
words of its kind between ("thirty-odd Rainbows troop into ...", "roughly three hundred
bargain-seekers are lined up at ...", "a pair of hospital cops saunter ..."), is that many people,
and "troop" after them is their verb, not a collective. One person said by a short title or a name
that a "his" or "her" of its own clause points back to ("The Earl leaves his car ...", "come six
o'clock Jo Pike makes her way ..."), or by an adjective only people are for their life, age or looks
("a retired miner finally goes up to the counter", "a balding rancher ..."), is one person, not a
vague crowd."""

import pytest


@pytest.mark.parametrize("world,prompt,value,low,high", [
    ("zoo", "Forty-odd Rainbows troop into the reptile house.", 40, 32, 48),
    ("airport", "Sixty-odd hipsters troop into the departures lounge.", 60, 48, 72),
    ("stadium", "Roughly three hundred bargain-seekers are lined up at the turnstiles.", 300, 240, 360),
    ("hospital", "A pair of hospital cops saunter through the main entrance.", 2, 2, 2),
    ("museum", "Twelve sixth-form goths troop into the main hall.", 12, 12, 12),
])
def test_a_counted_kind_no_list_names_is_that_many(read, world, prompt, value, low, high):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.count.low, group.count.high) == (value, low, high)


@pytest.mark.parametrize("world,prompt,value", [
    ("museum", "Two posters hang in the main hall.", None),
    ("primary_school", "Twenty top-year infants troop into the hall.", 20),
    ("mall", "About fifty freshers are lined up at the food court.", 50),
    ("office", "Eight junior devs troop into the boardroom.", 8),
])
def test_counted_kinds_keep_their_reading(read, world, prompt, value):
    groups = read(world, prompt).groups
    if value is None:
        assert all(g.count.kind == "vague" for g in groups)
    else:
        assert [g.count.value for g in groups] == [value]


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("town_hall", "The Earl leaves his car and walks into the main hall.", None, "foyer"),
    ("cathedral", "The Dean of Ely leaves his stall and walks to the nave.", "choir_stalls", "nave"),
    ("courthouse", "The Beak leaves his chambers and walks to court one.", "judges_chambers", "courtroom_1"),
    ("library", "Come six o'clock Jo Pike makes her way from the reading room to the exit.", "reading_room",
     "entry_gates"),
])
def test_one_told_by_his_or_her_is_one_person(read, world, prompt, start, destination):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == 1
    assert (group.start, group.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt", [
    ("zoo", "The gate stays open for his van."),
])
def test_a_thing_before_his_or_her_is_no_one(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt,destination", [
    ("high_street_bank", "A retired miner finally goes up to the counter.", "cashiers_counter"),
    ("supermarket", "A retired crofter finally goes up to till 2.", "checkout_2"),
    ("library", "A bearded shepherd finally goes over to the issue desk.", "issue_desk"),
    ("airport", "A balding rancher finally goes over to the check-in desks.", "check_in_hall"),
    ("museum", "A widowed fisher finally goes up to the gift shop.", "gift_shop"),
    ("care_home", "A widowed baker sits in the lounge.", None),
])
def test_one_told_by_a_life_adjective_is_one_person(read, world, prompt, destination):
    (group,) = read(world, prompt).groups
    assert group.count.kind == "exact" and group.count.value == 1 and group.destination == destination


@pytest.mark.parametrize("world,prompt,location", [
    ("bus_station", "A retired docker finally goes up to the ticket office.", None),
    ("bus_station", "A bearded trucker waits by the kiosk.", "ticket_machines"),
    ("hospital", "A retired lorry driver heads over to the pharmacy.", None),
])
def test_life_adjectives_keep_one_person(read, world, prompt, location):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1
    if location:
        assert group.location == location


@pytest.mark.parametrize("world,prompt,counts,locations", [
    ("hospital", "4 nurses in ward A, porter @ pharmacy", [4, 1], ["ward_a", "pharmacy"]),
    ("library", "12 students in the reading room, librarian @ issue desk", [12, 1], ["reading_room", "issue_desk"]),
    ("office", "3 devs in kitchen, receptionist at reception desk", [3, 1], ["kitchen", "reception_desk"]),
    ("airport", "loads of ppl @ check-in, pilot in the lounge", [12, 1], ["check_in_hall", "airline_lounge"]),
    ("zoo", "10 kids @ penguin beach + cleaner @ the cafe", [10, 1], ["penguin_beach", "cafe"]),
])
def test_a_bare_person_of_a_chat_list_is_a_group_of_its_own(read, world, prompt, counts, locations):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert [g.location for g in groups] == locations


@pytest.mark.parametrize("world,prompt,counts", [
    ("supermarket", "6 ppl in q @ till 3, cleaner mopping aisle 2", [6, 1]),
    ("hospital", "nurses in ward A, security at the main entrance", [3]),
])
def test_chat_lists_keep_their_groups(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts


@pytest.mark.parametrize("world,prompt,counts,locations", [
    ("hospital", "Stick a porter in ward A and get a pair of nurses waiting at the pharmacy.", [1, 2],
     ["ward_a", "pharmacy"]),
    ("hospital", "Put two nurses in ward A and leave a porter waiting at the pharmacy.", [2, 1],
     ["ward_a", "pharmacy"]),
    ("library", "Put a librarian at the issue desk and get two students waiting in the reading room.", [1, 2],
     ["issue_desk", "reading_room"]),
    ("office", "Post a receptionist at the reception desk and get two developers sitting in the kitchen.", [1, 2],
     ["reception_desk", "kitchen"]),
    ("supermarket", "Stick two cashiers at till 1 and get a supervisor waiting by the entrance.", [2, 1],
     ["checkout_1", "entrance_lobby"]),
])
def test_a_placing_repeated_after_and_places_a_second_group(read, world, prompt, counts, locations):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert [g.location for g in groups] == locations


@pytest.mark.parametrize("world,prompt,counts", [
    ("airport", "Station two guards at security and have a cleaner waiting by the departure board.", [2, 1]),
    ("museum", "Put a guard in the main hall and have a volunteer waiting at the gift shop.", [1, 1]),
    ("hospital", "Put a porter in ward A. Two nurses chat and get a coffee at the cafeteria.", [1, 2]),
])
def test_placings_keep_their_groups(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
