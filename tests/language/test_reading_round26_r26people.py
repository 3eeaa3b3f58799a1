"""Round 26 of the reader's people: a plural of a real word no list names ("loaders", "tasters") is
those people, not a misspelt place word one letter away; a fronted clock time or feeling is no
person and no count; a counted part of someone's people and someone's twins are one group of that
many; people only watched are no group; people typed as chat ("pt", "gf", "bf n gf", "5 browsing")
are people; one person placed by name or kind ("Put Mum on the settee") is one person there."""

import pytest


@pytest.mark.parametrize("world,prompt,who", [
    ("parcel_depot", "Four loaders drift over to the canteen.", "Four loaders"),
    ("residential", "Three tasters gather in the kitchen.", "Three tasters"),
    ("courthouse", "Two sawyers wait in the entrance hall.", "Two sawyers"),
    ("ferry_terminal", "Five tasters queue at the café.", "Five tasters"),
])
def test_a_real_plural_is_not_spelt_as_a_place_word(read, world, prompt, who):
    reading = read(world, prompt)
    assert [g.who for g in reading.groups] == [who]
    assert not reading.corrections


@pytest.mark.parametrize("world,prompt,who", [
    ("mall", "At nine Tom Hale walks to the food court.", "Tom Hale"),
    ("library", "By ten Jo Pike is waiting at the front desk.", "Jo Pike"),
    ("museum", "At 3 Sarah wanders round the main hall.", "Sarah"),
    ("office", "Around eleven Mrs Oakes walks to the boardroom.", "Mrs Oakes"),
    ("zoo", "At 10.30 Gran wanders over to the penguin pool.", "Gran"),
])
def test_a_fronted_clock_time_is_no_count_of_the_name_after_it(read, world, prompt, who):
    (group,) = read(world, prompt).groups
    assert group.who == who and group.count.value == 1


@pytest.mark.parametrize("world,prompt,value", [
    ("office", "About twelve Japanese tourists walk to the boardroom.", 12),
    ("stadium", "About fifty Rangers fans walk to the turnstiles.", 50),
    ("mall", "At nine two guards walk to the food court.", 2),
])
def test_a_count_after_a_fronted_word_stays_a_count(read, world, prompt, value):
    assert [g.count.value for g in read(world, prompt).groups] == [value]


@pytest.mark.parametrize("world,prompt,who", [
    ("museum", "Fascinated, a toddler near the main hall wanders over to the robot.", "a toddler"),
    ("hospital", "Worried, an old man near the pharmacy shuffles over to the robot.", "an old man"),
    ("mall", "Amazed, a little girl near the fountain toddles over to the robot.", "a little girl"),
    ("care_home", "Confused, an old lady near the lounge shuffles over to the robot.", "an old lady"),
    ("zoo", "Enthralled, a boy near the aquariums toddles over to the robot.", "a boy"),
])
def test_a_fronted_feeling_is_no_person(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == [who]


@pytest.mark.parametrize("world,prompt,who", [
    ("care_home", "Wilfred, a resident, shuffles over to the robot.", ["a resident"]),
    ("hospital", "Exhausted, two nurses slump in the staff room.", ["two nurses"]),
])
def test_fronted_words_keep_their_reading(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == who


@pytest.mark.parametrize("world,prompt,value", [
    ("courthouse", "A pair of the victim's sisters wait in the entrance hall.", 2),
    ("hospital", "A trio of the patient's cousins wait in the foyer.", 3),
    ("mall", "A couple of the bride's friends walk to the food court.", 2),
    ("museum", "Two of the guide's visitors walk to the main hall.", 2),
])
def test_a_counted_part_of_someones_people_is_one_group_of_that_many(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert group.count.kind in ("exact", "implied") and group.count.value == value


@pytest.mark.parametrize("world,prompt", [
    ("office", "The boss's twin daughters wait in the reception."),
    ("hospital", "The patient's twin sons wait in the foyer."),
    ("zoo", "The keeper's twin girls wander over to the penguin pool."),
    ("courthouse", "The usher's twin brothers wait in the entrance hall."),
])
def test_someones_twins_are_two(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 2 and group.count.low == 2 and group.count.high == 2


@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "The patient's two sons wait in the foyer.", 2),
    ("museum", "A group of students gather in the main hall.", 5),
    ("courthouse", "The twin brothers wait in the entrance hall.", 2),
])
def test_owned_and_counted_people_keep_their_reading(read, world, prompt, value):
    assert [g.count.value for g in read(world, prompt).groups] == [value]


@pytest.mark.parametrize("world,prompt,who", [
    ("museum", "Two guards stand by the door watching the children run about.", "Two guards"),
    ("mall", "A dad sits on a bench watching the kids play.", "A dad"),
    ("zoo", "Two keepers stand at the rail watching the visitors wander about.", "Two keepers"),
    ("ice_rink", "A steward stands by the boards watching the juniors skate about.", "A steward"),
    ("stadium", "Two stewards stand by the gate watching the fans mill about.", "Two stewards"),
])
def test_people_only_watched_are_no_group(read, world, prompt, who):
    assert [g.who for g in read(world, prompt).groups] == [who]


@pytest.mark.parametrize("world,prompt,count", [
    ("ice_rink", "Two coaches stand at the boards watching the skaters go round the rink.", 2),
    ("mall", "A guard watches as two shoppers walk to the exit.", 2),
    ("hospital", "A nurse watches the patients in the day room.", 1),
])
def test_watched_people_with_a_way_of_their_own_keep_their_reading(read, world, prompt, count):
    assert len(read(world, prompt).groups) == count


@pytest.mark.parametrize("world,prompt,whos", [
    ("mall", "bf n gf waiting by the fountain", ["boyfriend and girlfriend"]),
    ("zoo", "mum n dad queueing at the kiosk", ["mum and dad"]),
    ("hospital", "3 pts waiting @ pharmacy n a doctor in ward a", ["3 patients", "a doctor"]),
    ("care_home", "pt n her daughter waiting in the lounge", ["patient", "her daughter"]),
    ("airport", "pilot n steward walking to gate a1", ["pilot", "steward"]),
])
def test_people_typed_as_chat_are_people(read, world, prompt, whos):
    assert [g.who for g in read(world, prompt).groups] == whos


@pytest.mark.parametrize("world,prompt,counts", [
    ("mall", "4 queuing at the cafe, 2 by the fountain", [4, 2]),
    ("office", "2 chatting in the kitchen n 1 at reception", [2, 1]),
    ("garden_centre", "6 browsing the bulbs n 2 at the tills", [6, 2]),
    ("library", "3 reading in the quiet room, 2 at the front desk", [3, 2]),
])
def test_a_bare_count_before_what_its_people_do_is_people(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts


@pytest.mark.parametrize("world,prompt,whos", [
    ("airport", "a bloke and his girlfriend wait at the departures board", ["a bloke and his girlfriend"]),
    ("mall", "a lad and his boyfriend wait at the food court", ["a lad and his boyfriend"]),
    ("hotel", "a man and his missus wait in the lobby", ["a man and his missus"]),
    ("museum", "A girlfriend and her boyfriend walk to the main hall.", ["A girlfriend and her boyfriend"]),
])
def test_a_partner_is_a_person(read, world, prompt, whos):
    assert [g.who for g in read(world, prompt).groups] == whos


@pytest.mark.parametrize("world,prompt,whos", [
    ("hospital", "5 waiting rooms are full, 2 nurses walk to the pharmacy", ["2 nurses"]),
    ("hospital", "a woman and her fiance wait in the foyer", ["a woman and her fiance"]),
])
def test_chat_people_keep_their_reading(read, world, prompt, whos):
    assert [g.who for g in read(world, prompt).groups] == whos


@pytest.mark.parametrize("world,prompt,who,location", [
    ("residential", "Put Mum on the settee and leave the robot in the kitchen", "Mum", "sofa"),
    ("mall", "Put Grandad on a bench by the fountain", "Grandad", "atrium_benches"),
    ("care_home", "Put Nan in the lounge and leave the robot by the door", "Nan", "lounge"),
    ("hospital", "Put a pianist in the foyer", "a pianist", "entrance_lobby"),
    ("museum", "Put a florist by the main entrance", "a florist", "main_entrance"),
])
def test_one_person_placed_by_name_or_kind_is_one_person_there(read, world, prompt, who, location):
    (group,) = read(world, prompt).groups
    assert (group.who, group.count.value, group.location) == (who, 1, location)


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "Put a sign by the pharmacy"),
    ("mall", "Put Starbucks on the map"),
])
def test_a_thing_placed_is_no_person(read, world, prompt):
    assert all(g.count.kind == "vague" for g in read(world, prompt).groups)
