"""Two role words no list holds, joined by "and" before their verb ("the curator and the restorer walk",
"the anaesthetist and radiographer wait"): each made as a word for a person is ("-or", "-er", "-ist",
"-ier"), and the small parser calls one of them a modifier or an adjective; each is one person of their
own (language/coordinated_roles.py), not a vague crowd nor one of the two lost."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,labels,place", [
    ("museum", "The curator and the restorer walk from the cafe to the entrance hall.", ["curator", "restorer"],
     "entrance_hall"),
    ("hospital", "The anaesthetist and radiographer wait by the lifts.", ["anaesthetist", "radiographer"],
     "elevator_hall"),
    ("hotel", "The concierge and the sommelier walk from the lobby to the bar.", ["concierge", "sommelier"], "bar"),
    ("garden_centre", "The florist and the landscaper stroll from the cafe to the tills.", ["florist", "landscaper"],
     "tills"),
])
def test_two_role_words_joined_by_and_are_two_people(read, world, prompt, labels, place):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == labels
    assert all(g.count.value == 1 and place in (g.destination, g.location) for g in groups)
