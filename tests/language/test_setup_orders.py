"""An order that sets people up ("Set up ...", "Arrange ...", "Lay on ...") lists the groups joined by
"and" as any "Have ..." (language/setup_orders.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,counts", [
    ("hotel", "Arrange a choir of twelve in the lobby and three guards at the entrance.", [12, 3]),
    ("hospital", "Set up twenty patients in the waiting room and two nurses at the reception desk.", [20, 2]),
    ("station", "Lay on six stewards at the ticket office and a pair of cleaners on the concourse.", [6, 2]),
])
def test_setup_order_lists_groups(read, world, prompt, counts):
    reading = read(world, prompt)
    assert [g.count.value for g in reading.groups] == counts
    assert all(g.location is not None for g in reading.groups)
