"""Round 72: a place said by what is done there, after "from where", ends at a particle of the way then
"to" ("... from where the parcels get sorted over to the loading bay"): the destination's words are not
read as part of the activity (from_where)."""

from __future__ import annotations

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


def test_a_particle_before_to_starts_the_destination():
    g = read_prompt("Two drivers wheel a cage from where the parcels get sorted over to the canteen.",
                    load_world("eval/understanding/worlds/parcel_depot.yaml")).groups[0]
    assert (g.start, g.destination) == ("sorting_floor", "canteen")
