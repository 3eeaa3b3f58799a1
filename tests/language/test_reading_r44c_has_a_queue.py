"""A queue said as something a place has, with more said after it ("toy shop till has a line of 3,
security guy stood near info desk", "the pharmacy counter has a queue of about ten patients, and a
porter waits by the lifts"): the queue is at its place, not at the next group's. Real spaCy, real
worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, count, location, other", [
    ("mall", "toy shop till has a line of 3, security guy stood near info desk", 3, "toy_till", "information_desk"),
    ("mall", "The toy shop till has a queue of 3 and a guard stands near the info desk.", 3, "toy_till", "information_desk"),
    ("hospital", "The pharmacy counter has a queue of about ten patients, and a porter waits by the lifts.", 10,
     "pharmacy_counter", "elevator_hall"),
    ("station", "ticket office has a long line of 12, two staff chatting on platform 1", 12, "ticket_office", "platform_1"),
])
def test_the_queue_is_at_the_place_that_has_it(read, world, prompt, count, location, other):
    queue, second = read(world, prompt).groups
    assert (queue.intent, queue.count.value, queue.location) == ("queue", count, location)
    assert second.location == other


def test_a_queue_said_alone_is_unchanged(read):
    (queue,) = read("museum", "The cloakroom has a queue of nine people.").groups
    assert (queue.count.value, queue.location) == (9, "cloakroom")
