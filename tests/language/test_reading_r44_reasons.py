"""Round 44: a reason said with "because" after what people do is their purpose ("walks to the counter
because his parcel needs weighing"); a fronted cause ("Because the lift is out, ...") and "because of" are
not."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,destination,said", [
    ("post_office", "A pensioner walks to the counter because his parcel needs weighing.", "post_office_counter",
     "parcel"),
    ("hospital", "Two nurses go to the cafeteria because they are hungry, and a porter waits by the lifts.",
     "cafeteria", "hungry"),
    ("airport", "A backpacker heads to the information desk because her flight has been cancelled.",
     "information_desk", "flight"),
])
def test_a_reason_is_the_purpose(read, world, prompt, destination, said):
    g = read(world, prompt).groups[0]
    assert (g.intent, g.destination) == ("walk", destination)
    assert said in (g.purpose or "")


def test_a_reason_ends_with_its_clause(read):
    groups = read("hospital", "Two nurses go to the cafeteria because they are hungry, and a porter waits by "
                              "the lifts.").groups
    assert len(groups) == 2 and groups[1].location == "elevator_hall" and not groups[1].purpose


def test_a_fronted_cause_is_no_purpose(read):
    (g,) = read("hospital", "Because the lift is out, two porters walk to the pharmacy.").groups
    assert g.destination == "pharmacy" and not (g.purpose or "").startswith("because")
