"""Group and count classes of round 36, each with sentences of its own over at least two worlds (none
from the understanding sets): a plural no list names, counted by "a dozen" with kind words between
("a dozen rugby juniors"), or going by a verb the parser takes for a name ("juniors clatter from ...")."""

from __future__ import annotations

import pytest


# ---- 1. "a dozen" and kind words before a plural no list names -------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("hospital", "A dozen rugby juniors clatter from the cafeteria to the main entrance.", 12),
    ("station", "A dozen cub scouts clatter from the ticket hall to platform 2.", 12),
    ("mall", "A dozen cub scouts trundle into the food court.", 12),
    ("mall", "A dozen chess juniors clatter into the food court.", 12),
    ("ice_rink", "A dozen cub scouts walk from the café to the west gate.", 12),
    ("hotel", "A dozen hockey juniors walk from the lobby to the restaurant.", 12),
])
def test_a_dozen_of_an_unlisted_kind_is_twelve(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert (g.count.kind, g.count.value) == ("exact", value)


# ---- guards: readings that must stay as they were --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,value", [
    ("ice_rink", "Twelve hockey juniors walk from the café to the west gate.", 12),
    ("mall", "A dozen teenagers clatter from the food court to the main entrance.", 12),
    ("mall", "Two chess juniors walk to the food court.", 2),
    ("mall", "Thirty under-11 footballers clatter into the food court.", 30),
])
def test_counted_kinds_keep_their_count(read, world, prompt, value):
    (g,) = read(world, prompt).groups
    assert g.count.value == value
