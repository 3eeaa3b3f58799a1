"""Classes the fifth fresh set found, each with sentences of its own over at least two worlds (none
from the understanding sets): chat signs ("@ the desk", "~20"), people "in line" with no verb,
"N more at X" doing what the group before does, places a sentence calls by another word or by what
happens there, and phrases after a place preposition that are no place ("your bags", "the agenda")."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.language.text import normalise


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


@pytest.mark.parametrize("typed,expected", [
    ("5 kids @ the fountain", "5 kids at the fountain"),
    ("~20 people @gate 3", "about 20 people at gate 3"),
    ("approx ~ 12 ppl", "approximately about 12 people"),
    ("mail bob@example.org or ~/notes", "mail bob@example.org or ~/notes"),
])
def test_chat_signs_are_words(typed, expected):
    assert normalise(typed) == expected


@pytest.mark.parametrize("world,prompt,location,value,kind", [
    ("hospital", "~15 ppl in line @ the pharmacy counter", "pharmacy_counter", 15, "approximate"),
    ("mall", "about a dozen shoppers in line at the express till", "express_till", 12, "approximate"),
    ("station", "8 commuters in a queue @ the ticket office", "ticket_office", 8, "exact"),
    ("airport", "twenty travellers in line at check-in counter A", "check_in_counter_a", 20, "exact"),
])
def test_people_in_line_with_no_verb_queue(worlds, world, prompt, location, value, kind):
    g, = read(worlds, world, prompt).groups
    assert (g.intent, g.location, g.count.value, g.count.kind) == ("queue", location, value, kind)


@pytest.mark.parametrize("world,prompt,first,second", [
    ("mall", "A dozen shoppers queue at the express till, 3 more at the coffee counter.", "express_till",
     "coffee_counter"),
    ("station", "Ten commuters queue at the ticket office, two more at the ticket machines.", "ticket_office",
     "ticket_machines"),
    ("hospital", "Six patients wait in the main waiting room and 3 more in the second waiting room.",
     "main_waiting_room", "outpatient_waiting"),
])
def test_more_of_a_group_with_no_verb_do_as_it_does(worlds, world, prompt, first, second):
    a, b = read(worlds, world, prompt).groups
    assert b.relation == "more_of:0" and b.intent == a.intent and (a.location, b.location) == (first, second)
