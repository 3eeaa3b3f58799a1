"""Round 44 (r44b): what counted people no list names wear, after "in" ("nine cub scouts in party hats,
...", "ten brownies in party hats, giggling, ..."): clothing, not a place the world lacks
(language/worn_clothes.py)."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count,place", [
    ("museum", "Ten brownies in party hats, giggling, wait in the great hall.", 10, "great_hall"),
    ("bowling_alley", "The party, eight cub scouts in paper crowns, are eating in the booths.", 8, "booths"),
    ("zoo", "A gaggle of hens, twelve bridesmaids in pink sashes, crowd round the penguin pool.", 12, None),
])
def test_clothes_of_counted_people_are_no_place(read, world, prompt, count, place):
    reading = read(world, prompt)
    (group,) = reading.groups
    assert reading.unknown_places == ()
    assert group.count.value == count and (place is None or group.location == place)
