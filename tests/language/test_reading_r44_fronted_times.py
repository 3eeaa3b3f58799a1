"""Round 44: a fronted time with no comma after it ("During the Friday changeover a courier wheels ...",
"After the quarterly review a courier ...") keeps the people after it: the list's first item is a group
of its own, and the others keep their own places. A fronted clause ("After the boss leaves the interns
chat") and a time already set off by a comma read as before."""

from __future__ import annotations

import pytest

_REST = "a courier wheels a stack of boxes over to reception, two developers chat in the kitchen, and the boss " \
        "waits in her office."


@pytest.mark.parametrize("front", ["During the Friday changeover", "After the quarterly review",
                                   "Following the Monday stand-up"])
def test_a_fronted_time_keeps_the_first_item(read, front):
    groups = read("office", f"{front} {_REST}").groups
    assert [g.who for g in groups] == ["a courier", "two developers", "the boss"]
    assert (groups[0].intent, groups[0].destination) == ("walk", "reception")
    assert groups[1].destination is None and groups[2].destination is None


@pytest.mark.parametrize("world,prompt,who", [
    ("office", "After the boss leaves the interns chat in the kitchen.", "the interns"),
    ("hospital", "After the night shift, two nurses leave through the main entrance.", "two nurses"),
    ("hospital", "During the fire drill everyone in the cafeteria leaves by the main entrance.", "everyone"),
])
def test_other_fronted_words_read_as_before(read, world, prompt, who):
    groups = read(world, prompt).groups
    assert groups and groups[-1].who.lower().startswith(who)
