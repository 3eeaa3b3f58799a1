"""Round 44: a request typed as chat is the order it asks for ("can u add that + a busker by the gateline":
add a busker there), and a queue said by its place first with its length ("ticket office q is like 15 deep
rn") is that many people queueing there; "like" before a line's length is a filler, "rn" and "atm" say
now."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,queue,where,second,at", [
    ("station", "ticket office q is like 15 deep rn, can u add that + a busker by the gateline", 15, "ticket_office",
     "a busker", "gateline"),
    ("hospital", "pharmacy queue is 12 long, can you add a porter near the lifts", 12, "pharmacy", "a porter",
     "elevator_hall"),
    ("mall", "cinema line's about 20 deep atm, can u stick a guard by the fountain", 20, "cinema_lobby", "a guard",
     "fountain"),
])
def test_a_chat_queue_and_a_request(read, world, prompt, queue, where, second, at):
    first, other = read(world, prompt).groups
    assert (first.count.value, first.intent, first.location) == (queue, "queue", where)
    assert (other.who, other.count.value, other.location) == (second, 1, at)


def test_a_like_before_a_count_of_people_is_still_about(read):
    (g,) = read("food_court", "like 40 teens in the seating hall").groups
    assert (g.count.kind, g.count.value) == ("approximate", 40)


def test_a_polite_order_alone(read):
    (g,) = read("station", "could you pls put 2 guards at the gateline").groups
    assert (g.count.value, g.location) == (2, "gateline")
