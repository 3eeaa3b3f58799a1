"""Round 46: an aid pushed in a fronted clause ("Pushing a wheelchair, a porter takes a patient from X to Y")
is how the one taken goes: the mover walks from X to Y, the one taken is a second group that follows."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, start, destination", [
    ("hospital", "Pushing one of the wheelchairs, a porter takes a patient from the pharmacy to the main entrance.",
     "pharmacy", "main_entrance"),
    ("airport", "Pushing a wheelchair, an attendant brings an elderly passenger from check-in to gate A1.",
     "check_in_hall", "gate_a1"),
    ("supermarket", "Pushing one of the store wheelchairs, a shop assistant takes a pensioner who came over faint "
     "from the pharmacy to the café.", "pharmacy", "cafe"),
])
def test_the_mover_keeps_the_way_and_the_one_taken_follows(read, world, prompt, start, destination):
    reading = read(world, prompt)
    assert [(g.intent, g.start, g.destination, g.count.value) for g in reading.groups] == [
        ("walk", start, destination, 1), ("follow", start, destination, 1)]


def test_a_pushed_thing_with_no_one_taken_stays_the_movers(read):
    reading = read("hospital", "Pushing a trolley, a porter walks to the pharmacy.")
    assert [(g.intent, g.destination) for g in reading.groups] == [("walk", "pharmacy")]
