""""The twenty or so X" in a second clause counts people whatever X is ("jumpers" at a trampoline park are
people, not clothes): the count after its article, and a lone "the power fails" before it is no person."""

import pytest


@pytest.mark.parametrize("world,prompt,value", [
    ("trampoline_park", "The power fails and the forty or so jumpers in the foam pit pour out through the side fire exit.", 40),
    ("trampoline_park", "The music cuts out and the thirty or so jumpers on the main court spill out through the side fire exit.", 30),
    ("trampoline_park", "The alarm trips and the twenty or so jumpers in the dodgeball cage pour out through the side fire exit.", 20),
])
def test_the_n_or_so_of_an_unknown_kind_is_their_count(read, world, prompt, value):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("approximate", value)


def test_a_lone_unnamed_subject_is_still_one(read):
    (group,) = read("hospital", "The visiting hairdresser comes over to ward 2.").groups
    assert group.count.value == 1
