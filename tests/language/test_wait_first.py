"""A wait said before a queue belongs to the wait (language/wait_first.py): the group queues, its seconds
are spent first where it starts; a queue's own "for ten minutes" stays the queue's."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

FIRST = [
    ("hospital", "Four visitors sit in the main waiting room for five minutes before queuing at reception.",
     "main_waiting_room", 300.0),
    ("hospital", "Two porters join the queue at the pharmacy after waiting in the cafeteria for three minutes.",
     "cafeteria", 180.0),
    ("station", "Three commuters hang about by the departure board for 40 seconds, then join the queue at the ticket "
                "office.", "departure_board", 40.0),
    ("mall", "Five shoppers wait in the food court for half an hour and then line up at the information desk.",
     "food_court", 1800.0),
]
OWN = [
    ("hospital", "Ten patients queue at the pharmacy for ten minutes."),
    ("hospital", "Five people from the cafeteria queue at the pharmacy for three minutes."),
    ("station", "Eight travellers stand in line at the ticket office for two minutes, then wait by the departure board."),
]


@pytest.mark.parametrize("world, sentence, start, seconds", FIRST)
def test_a_wait_before_a_queue_is_spent_first_where_they_start(world, sentence, start, seconds):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert (group.intent, group.start, group.wait_seconds, group.waits_first) == ("queue", start, seconds, True)


@pytest.mark.parametrize("world, sentence", OWN)
def test_a_queues_own_length_is_not_a_wait_before_it(world, sentence):
    group = read_prompt(sentence, load_world(world)).groups[0]
    assert not group.waits_first
