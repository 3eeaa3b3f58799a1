"""Chat and rough-count classes of round 43, each with sentences of its own over at least two worlds
(none from the understanding sets):
1. verbless chat items: a count alone before "from" or an "-ing" word counts people ("2 from IT chatting
   at the printer, 1 making coffee in the kitchen": two groups, 2 and 1), and a counted plural joined to
   one person before an "-ing" word keeps both ("2 nurses + the porter bickering by the lifts").
2. a counted stay in chat said after a comma, or of two groups at once ("4 kiddies + 1 instructor waitin
   @ ski school desk, 5 mins then out thru chairlift door"): each group starts there, waits, walks on.
3. a spread of people ("a scattering of", "a smattering of", "a sprinkling of") is a vague handful."""

from __future__ import annotations

import pytest


# ---- 1. verbless chat items ------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,counts", [
    ("office", "2 from IT chatting at the printer, 1 making coffee in the kitchen", [2, 1]),
    ("hospital", "2 from pharmacy chatting by the lifts, 1 mopping the floor by the reception", [2, 1]),
    ("mall", "4 from the youth club loitering by the fountain, 2 queuing at the food court", [4, 2]),
    ("museum", "5 from the school group sketching in the foyer, 2 queuing at the cafe", [5, 2]),
    ("library", "3 from the book club whispering by the issue desk, 1 dozing in the reading room", [3, 1]),
    ("office", "3 engineers + the intern squabbling by the printer", [3, 1]),
    ("hospital", "3 nurses + the matron bickering at the nurse station", [3, 1]),
    ("mall", "3 teens + the janitor bickering by the fountain", [3, 1]),
    ("station", "2 guards + the cleaner bickering on the concourse", [2, 1]),
])
def test_verbless_chat_items_count_their_people(read, world, prompt, counts):
    groups = read(world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exact", n) for n in counts]


@pytest.mark.parametrize("world,prompt,counts", [
    ("office", "4 developers + the manager arguing in the kitchen", [4, 1]),
    ("mall", "4 teens + a security guard loitering by the fountain", [4, 1]),
    ("sports_centre", "3 swimmers + their coach chatting at reception", [3, 1]),
    ("hospital", "2 nurses + 1 porter chatting by the lifts", [2, 1]),
    ("office", "3 people from sales are gossiping at the printer", [3]),
])
def test_chat_items_already_read_stay(read, world, prompt, counts):
    groups = read(world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exact", n) for n in counts]


@pytest.mark.parametrize("world,prompt", [
    ("office", "The 2 meeting rooms are empty and a cleaner mops the kitchen."),
    ("hospital", "At 3 building work starts; a porter waits by the lifts."),
])
def test_ing_nouns_after_a_count_are_no_people(read, world, prompt):
    assert [(g.count.kind, g.count.value) for g in read(world, prompt).groups] == [("exact", 1)]


# ---- 2. counted stays in chat after a comma or of two groups ---------------------------------------------

@pytest.mark.parametrize("world,prompt,start,wait,dest,n", [
    ("ski_lodge", "4 kiddies + 1 instructor waitin @ ski school desk, 5 mins then out thru chairlift door",
     "ski_school_desk", 300.0, "chairlift_door", 2),
    ("mall", "3 lads @ the food court, 15 mins then off to the fountain", "food_court", 900.0, "fountain", 1),
    ("office", "2 temps + the intern @ the printer, 10 mins then off to the kitchen", "printer", 600.0, "kitchen", 2),
    ("hospital", "3 visitors waiting at the pharmacy, 5 mins then out through the main entrance", "pharmacy",
     300.0, "main_entrance", 1),
    ("library", "2 students + a tutor at the issue desk, 10 mins then off to the reading room", "issue_desk",
     600.0, "reading_room", 2),
    ("station", "4 lads at the ticket office, 20 mins then off to the concourse", "ticket_office", 1200.0,
     "concourse", 1),
])
def test_counted_chat_stays_after_a_comma(read, world, prompt, start, wait, dest, n):
    groups = read(world, prompt).groups
    assert len(groups) == n
    for g in groups:
        assert (g.start, g.wait_seconds, g.destination) == (start, wait, dest)


@pytest.mark.parametrize("world,prompt,start,wait,dest", [
    ("mall", "3 ppl lookin at the fountain 2 mins then off to the food court", "fountain", 120.0, "food_court"),
    ("mall", "cleaner stuck @ fountain 5 mins then off to food court", "fountain", 300.0, "food_court"),
    ("hospital", "porter parked @ pharmacy 10 mins then off to main entrance", "pharmacy", 600.0, "main_entrance"),
    ("ski_lodge", "6 kids wait at ski school desk for 10 minutes, then go out through the chairlift door",
     "ski_school_desk", 600.0, "chairlift_door"),
])
def test_counted_chat_stays_already_read_stay(read, world, prompt, start, wait, dest):
    (g,) = read(world, prompt).groups
    assert (g.start, g.wait_seconds, g.destination) == (start, wait, dest)


# ---- 3. a spread of people is a vague handful ------------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("museum", "A smattering of tourists sit on the gallery bench."),
    ("library", "A smattering of students read in the reading room."),
    ("hospital", "A smattering of visitors sit in the cafeteria."),
    ("station", "A scattering of commuters wait on the concourse."),
    ("office", "A scattering of interns eat lunch in the kitchen."),
])
def test_a_spread_of_people_is_a_handful(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.count.kind == "vague" and 2 <= g.count.value <= 8


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A sprinkling of shoppers linger by the fountain."),
    ("airport", "A scattering of backpackers doze at the gate."),
    ("office", "A sprinkling of temps wait in the lobby."),
])
def test_spreads_already_vague_stay_vague(read, world, prompt):
    (g,) = read(world, prompt).groups
    assert g.count.kind == "vague" and 2 <= g.count.value <= 8


@pytest.mark.parametrize("world,prompt,kind,value", [
    ("museum", "A handful of tourists sit on the gallery bench.", "vague", 4),
    ("mall", "A few shoppers linger by the fountain.", "vague", 3),
])
def test_rough_words_already_read_stay(read, world, prompt, kind, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == (kind, value)
