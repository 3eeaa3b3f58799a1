"""Round 45: an imperative list of placed people keeps each group. A colloquial placing verb before a
name, a kin word or "the" ("Pop Dad on the couch and the twins by the cooker") places as "Put" does,
and a role said short in capitals after a word that counts people ("a pair of PCSOs") is people."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, first, second", [
    ("residential", "Pop Dad on the couch and the twins by the cooker.", ("sofa", 1), ("kitchen_counter", 2)),
    ("residential", "Plonk Grandad in the armchair, and two girls on the couch.", ("armchair", 1), ("sofa", 2)),
])
def test_colloquial_placing_of_a_name_keeps_both_groups(read, world, prompt, first, second):
    a, b = read(world, prompt).groups
    assert (a.location, a.count.value) == first and (b.location, b.count.value) == second


@pytest.mark.parametrize("world, prompt, second, n", [
    ("station", "Put a guard at the gateline and a pair of PCSOs by the ticket office.", "ticket_office", 2),
    ("hospice", "Put the chaplain in the quiet room and a trio of GPs at the meds trolley.", "drugs_trolley", 3),
])
def test_a_counted_abbreviated_role_is_a_second_group(read, world, prompt, second, n):
    _, b = read(world, prompt).groups
    assert (b.location, b.count.value) == (second, n)
