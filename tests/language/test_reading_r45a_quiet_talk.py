"""Round 45: people who talk quietly ("murmur", "whisper", "mutter", "confer") converse, as those who
chat do; they were read as waiting."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, where", [
    ("station", "Two porters mutter to each other by the ticket office.", "ticket_office"),
    ("station", "A couple whisper together at the gateline.", "gateline"),
    ("hospital", "Three consultants confer outside the pharmacy.", "pharmacy"),
])
def test_quiet_talk_is_conversation(read, world, prompt, where):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.count.value >= 2) == ("converse", True)
