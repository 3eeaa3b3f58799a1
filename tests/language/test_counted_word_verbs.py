"""A verb of going after a word of a count ("half a dozen peel off", "a handful duck into") is the count's
verb: the part moves off from the fronted whole (language/counted_verbs.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,whole,part", [
    ("hospital", "Of the twenty or so nurses chatting on the ward, a handful duck into the canteen.", 20, 3),
    ("station", "Of the forty commuters milling on the concourse, a dozen drift over to the ticket office.", 40, 12),
    ("museum", "Of the thirty-odd pupils lingering in the lobby, half a dozen peel off to the cafe.", 30, 6),
])
def test_counted_word_verb_is_a_moving_part(read, world, prompt, whole, part):
    reading = read(world, prompt)
    first, second = reading.groups
    assert first.count.value == whole
    assert second.count.value == part
    assert second.intent == "walk"
    assert second.destination is not None
