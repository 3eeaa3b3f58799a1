"""A person of a chat list said with what they are doing and no verb (language/chat_ing_items.py): "teen doing
homework in bedroom 2, gran on the settee" is two people, each at their place; prose with a participle
("A nurse pushing a trolley walks ...") keeps its verb."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,locations", [
    ("residential", "toddler napping in the master bedroom, dad cooking in the kitchen", ["master_bedroom", "kitchen"]),
    ("residential", "lad reading in the kitchen, grandad on the balcony", ["kitchen", "balcony"]),
    ("office", "intern making tea in the kitchen, boss in her office, bot on patrol", ["kitchen", "manager_office"]),
])
def test_each_verbless_chat_item_of_a_person_is_a_group(read, world, prompt, locations):
    groups = read(world, prompt).groups
    assert [g.location for g in groups] == locations
    assert all(g.count.value == 1 for g in groups)


def test_a_participle_in_prose_keeps_the_verb(read):
    groups = read("hospital", "A nurse pushing a trolley walks to the pharmacy.").groups
    assert len(groups) == 1 and groups[0].destination == "pharmacy"
