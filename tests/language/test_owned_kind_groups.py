"""A named owner before a group said with what kind it is owns the group and is no one of the scene
(language/role_words.py): "Mr Shah's art class, all twelve of them, ..." is one group of twelve."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt, n", [
    ("museum", "Mr Shah's book club, all twelve of them, wait in the cafe.", 12),
    ("museum", "Dr Ahmed's tour party, all fifteen of them, walk to the cafe.", 15),
    ("office", "Ms Reid's sales team, all eight of them, wait in the kitchen.", 8),
    ("art_gallery", "Mr Osei's GCSE art group, all fourteen of them, wait in the cafe.", 14),
])
def test_the_owner_of_a_kind_of_group_is_no_group(read, world, prompt, n):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", n)


def test_an_owned_thing_keeps_its_owner(read):
    groups = read("museum", "Mr Shah's sister waits in the cafe.").groups
    assert [g.count.value for g in groups] == [1]
