"""The robot's errand from one person to another ("brings a chart from the nurse to the doctor in ward A")
keeps both people, however many words stand between them; and a place whose name holds a word for
people ("from the kitchen diner", "to the nurses' station") is a place there, no one in the scene."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,labels", [
    ("hospital", "The robot brings a chart from the nurse to the doctor in ward A.", {"nurse", "doctor"}),
    ("office", "The robot takes a parcel from the receptionist in the lobby over to the manager.",
     {"receptionist", "manager"}),
    ("library", "The robot carries a stack of books from the librarian at the issue desk to a student.",
     {"librarian", "student"}),
])
def test_both_people_of_the_errand(read, world, prompt, labels):
    reading = read(world, prompt)
    assert {g.label for g in reading.groups} == labels
    assert all(g.count.value == 1 for g in reading.groups)


@pytest.mark.parametrize("world,prompt,label,location", [
    ("residential", "The robot carries a tray from the kitchen diner to my father, who is reading on the balcony.",
     "father", "balcony"),
    ("hospital", "The robot wheels a trolley to the nurses' station past a porter, who is waiting in the corridor.",
     "porter", None),
])
def test_place_named_with_a_person_word(read, world, prompt, label, location):
    (group,) = read(world, prompt).groups
    assert group.label == label
    assert location is None or group.location == location


@pytest.mark.parametrize("world,prompt,label", [
    ("restaurant", "The robot brings a crate of wine from the cellar to the bar as the pair from the tennis club natter "
                   "over a coffee by the window.", "pair"),
    ("hotel", "The robot wheels towels from the laundry to the pool as the trio from the wedding party chat over a drink "
              "in the lobby.", "trio"),
])
def test_people_of_another_clause_keep_what_describes_them(read, world, prompt, label):
    """A phrase describing someone in another clause ("the couple from the tennis club") names no one else."""
    (group,) = read(world, prompt).groups
    assert group.label == label
