"""A first name ending in "s" keeps its "s" in the group's label (language/one_name.py through
people.label): "Agnes" is agnes, not "agne"; "James" is james."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


@pytest.mark.parametrize("world, sentence, label", [
    ("hospital", "Agnes shuffles from the lobby to the pharmacy.", "agnes"),
    ("station", "Doris waits in the waiting room.", "doris"),
    ("office", "Charles walks from reception to the boardroom.", "charles"),
])
def test_a_name_in_s_keeps_its_s(world, sentence, label):
    group, = read_prompt(sentence, load_world(world)).groups
    assert (group.label, group.count.value) == (label, 1)


def test_two_names_in_s_are_two_people():
    groups = read_prompt("Agnes and James wait by the fountain.", load_world("mall")).groups
    assert [(g.label, g.count.value) for g in groups] == [("agnes", 1), ("james", 1)]
