"""Round 44: words for people the lexicon lacked, read in lists of groups: a compound on "-people"
("salespeople", "tradespeople"), "temp" and "busker"; and a listed word for people the parser takes for a
modifier of its own "-s" verb ("a temp wrestles with the ticket machines") heads its item."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,groups", [
    ("hospital", "Two tradespeople chat by the lifts, a temp waits at reception, and a busker plays near the main "
                 "entrance.", [("Two tradespeople", 2, "elevator_hall"), ("a temp", 1, "reception_desk"),
                               ("a busker", 1, "main_entrance")]),
    ("station", "A temp wrestles with the ticket machines, a pair of salespeople natter on platform 1, and a guard "
                "waits at the gateline.", [("A temp", 1, "ticket_machines"), ("a pair of salespeople", 2, "platform_1"),
                                           ("a guard", 1, "gateline")]),
])
def test_every_listed_person_is_a_group(read, world, prompt, groups):
    reading = read(world, prompt)
    assert [(g.who, g.count.value, g.location) for g in reading.groups] == groups


def test_a_salesperson_compound_alone(read):
    (g,) = read("office", "Three businesspeople walk from reception to the boardroom.").groups
    assert (g.count.value, g.start, g.destination) == (3, "reception", "boardroom")
