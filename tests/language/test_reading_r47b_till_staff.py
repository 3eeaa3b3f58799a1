""""A pair of" before a collective people noun ("staff", "crew") counts two, and "till" before a noun
is the shop's till ("till staff", "till operators"), not "until": the people after it are counted
and their talk ("gossip", "chat") is a conversation where they are."""

import pytest


@pytest.mark.parametrize("world,prompt,label,location", [
    ("supermarket", "Shoppers stroll to the exit while a pair of till staff gossip by the checkouts.", "staff",
     "checkouts"),
    ("airport", "Travellers walk to the café while a pair of ground crew gossip by the check-in desks.",
     "ground crew", "check_in_hall"),
    ("airport", "A pair of kitchen staff gossip in the café.", "staff", "cafe"),
])
def test_a_pair_of_collective_people_talking_is_two(read, world, prompt, label, location):
    talkers = read(world, prompt).groups[-1]
    assert (talkers.label, talkers.count.value, talkers.intent, talkers.location) == (label, 2, "converse", location)


def test_a_till_before_a_noun_is_the_shops_till(read):
    (group,) = read("supermarket", "Two till operators chat at the checkouts.").groups
    assert (group.label, group.count.value, group.intent) == ("operator", 2, "converse")


def test_till_as_a_word_of_time_stays_until(read):
    (group,) = read("hospital", "A nurse waits in the lobby till the doctor comes.").groups
    assert (group.label, group.count.value, group.intent) == ("nurse", 1, "wait")
