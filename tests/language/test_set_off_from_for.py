"""Setting off from a place for another (language/going_verbs.py): the place after "for" is where they go,
also when the place they leave stands between ("set off from the cattery for block B"); "for a chat" is
still what for."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("animal_shelter", "Nine walkers set off from the cattery for block B.", "cattery", "kennel_block_b"),
    ("hospital", "Two porters set off from the cafeteria for ward B.", "cafeteria", "ward_b"),
    ("station", "A family sets out from the ticket hall for platform 2.", "ticket_hall", "platform_2"),
])
def test_setting_off_from_a_place_for_another_goes_there(read, world, prompt, start, destination):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.start, group.destination) == ("walk", start, destination)


def test_setting_off_for_a_chat_is_a_purpose(read):
    group = read("hospital", "Two porters set off from the cafeteria for a chat.").groups[0]
    assert group.start == "cafeteria" and group.destination is None
