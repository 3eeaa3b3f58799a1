"""What a vehicle holds ("a coachload of fans", "a busload of pensioners", "a minibus of pupils") is a
number nobody said: its count is vague, in the range the vehicle holds, not implied by the word."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,low,high", [
    ("zoo", "A busload of pensioners shuffles from the entrance to the cafe.", 30, 50),
    ("airport", "a planeload of holidaymakers pours out of arrivals toward the taxi rank", 100, 180),
    ("cinema", "A minibus of pupils walks from the foyer into screen 1.", 10, 16),
    ("stadium", "A coachload of away fans troops from the gate to the stand.", 30, 50),
])
def test_a_vehicle_load_is_a_vague_count(read, world, prompt, low, high):
    groups = read(world, prompt).groups
    assert len(groups) == 1, groups
    count = groups[0].count
    assert (count.kind, count.low, count.high) == ("vague", low, high), count
    assert low <= count.value <= high
