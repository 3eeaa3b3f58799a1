"""Round 49: people "got out" or "taken out" by a way out after a hazard evacuate from where they are to
it. A way out after "by" is the way, never the taker of a passive ("are taken out by the main entrance" is
no entrance taking anyone); a thing by a numbered place that starts smoking is still a thing giving off
smoke ("a printer behind counter 3 starts smoking"), and a person there who smokes is still no hazard."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "A fridge near bed 4 starts sparking, so the twenty visitors in the cafeteria are got out by the "
     "main entrance.", "cafeteria", "main_entrance"),
    ("hospital", "Smoke fills the kitchen, so the visitors in the cafeteria are taken out by the main entrance.",
     "cafeteria", "main_entrance"),
    ("passport_office", "A kettle behind counter 2 starts smoking, so the applicants in the counter hall get out "
     "through the emergency exit.", "waiting_area", "waiting_fire_exit"),
])
def test_people_got_out_by_a_way_after_a_hazard_evacuate(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.intent, g.start, g.destination) == ("evacuate", start, destination)


def test_a_person_smoking_by_a_numbered_place_is_no_hazard(read):
    groups = read("hospital", "A nurse near bed 4 starts smoking, so the visitors in the cafeteria walk to the "
                  "main entrance.").groups
    assert all(g.intent != "evacuate" for g in groups)
