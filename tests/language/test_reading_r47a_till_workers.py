"""People named by the till they work at ("two till operators chat at the information desk"): "till" is
their post, not "until"; the people, their count and their place are read, after a robot clause too.
"Waits till people leave" keeps its time word. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, count, location", [
    ("mall", "The robot waits by the fountain while two till operators chat at the information desk.", 2,
     "information_desk"),
    ("department_store", "The robot wheels a rail to menswear while three till assistants natter behind the "
                         "returns desk.", 3, "customer_services_desk"),
    ("supermarket", "Three till workers wait by the tills while the robot restocks the shelves.", 3, "checkouts"),
])
def test_till_workers_are_people_at_their_place(read, world, prompt, count, location):
    group = next(g for g in read(world, prompt).groups if g.who != "robot")
    assert (group.count.value, group.location) == (count, location)


def test_till_as_a_time_word_stays_a_time(read):
    group = read("mall", "Two shoppers wait by the fountain till people leave.").groups[0]
    assert group.count.value == 2 and group.location == "fountain"
