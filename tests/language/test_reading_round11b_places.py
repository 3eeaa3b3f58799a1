"""Round 11b of place reading: a generic word for the way in is the public main entrance, not a staff or
security door whose name holds "entrance" or "entry"; someone there to pay or be served stands at the
room's counter or till. Sentences written for these tests, over shipped and understanding-set worlds."""

import pytest


@pytest.mark.parametrize("world, prompt, role, expected", [
    ("ferry_terminal", "A man walks from the entry to the cafe.", "start", "check_in_hall"),
    ("airport", "Two travellers walk to the entry.", "destination", "west_entrance"),
    ("office", "A courier waits by the entry.", "location", "reception"),
    ("courthouse", "Two visitors walk from the way in to the witness service.", "start", "entrance_hall"),
    ("hotel", "A family walks to the way in.", "destination", "lobby"),
    ("library", "Two students walk from the entrance doors to the cafe.", "start", "main_entrance"),
    ("sports_centre", "Three swimmers walk from the entrance doors to the cafe.", "start", "main_entrance"),
    ("hospital", "A porter walks from the entrance doors to the pharmacy.", "start", "main_entrance"),
])
def test_generic_entrance_is_the_public_main_entrance(read, world, prompt, role, expected):
    group = read(world, prompt).groups[0]
    assert getattr(group, role) == expected


@pytest.mark.parametrize("world, prompt, expected", [
    ("courthouse", "The judges walk from the judges' entrance to their chambers.", "judges_entrance"),
    ("station", "A taxi driver walks from the side entrance to the cafe.", "south_entrance"),
    ("airport", "Two pilots walk from the security entrance to the lounge.", "security_entry"),
])
def test_an_entrance_said_which_keeps_its_words(read, world, prompt, expected):
    assert read(world, prompt).groups[0].start == expected


@pytest.mark.parametrize("world, prompt, expected", [
    ("mall", "A woman queues to pay for her shopping in the supermarket.", "checkout_tills"),
    ("mall", "Two teenagers wait to be served in the toy store.", "toy_till"),
    ("station", "A man queues in the newsagent to pay for a paper.", "newsagent_till"),
    ("hotel", "A couple waits in the bar to order drinks.", "bar_counter"),
    ("sports_centre", "A mum queues in the cafe to pay for two smoothies.", "cafe_counter"),
])
def test_paying_or_being_served_in_a_room_is_at_its_counter(read, world, prompt, expected):
    assert read(world, prompt).groups[0].location == expected


@pytest.mark.parametrize("world, prompt, expected", [
    ("mall", "Three people wait in the supermarket.", "supermarket"),
    ("hotel", "Two guests wait in the bar to meet a friend.", "bar"),
])
def test_a_room_without_a_purpose_of_paying_stays_the_room(read, world, prompt, expected):
    assert read(world, prompt).groups[0].location == expected
