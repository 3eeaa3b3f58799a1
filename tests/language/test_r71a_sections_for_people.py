"""A section for a kind of person the world lacks ("the kids' section" where the only section is the
reference section) is refused (language/named_kinds.py); "the children's toilets" are the toilets."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, place", [
    ("library", "Two toddlers toddle off to the children's section.", None),  # its only section is for reference
    ("library", "A mum takes her teens to the teen section.", None),
    ("bookshop", "Two toddlers toddle off to the kids' section.", "childrens_section"),
    ("museum", "Two little boys run to the children's toilets.", "toilets"),
])
def test_a_section_for_a_kind_of_person_the_world_lacks_is_refused(read, world, prompt, place):
    reading = read(world, prompt)
    assert reading.groups[0].destination == place
    assert bool(reading.unknown_places) == (place is None)
