"""Round 6 on people and clauses, each class with sentences of its own over at least two worlds (none
from the understanding sets): a job the lexicon lacks is one person, not a crowd; "two of the six
developers" are part of a group that stays; what the robot's verb asks of it (charging is waiting);
a room left with a verb on it ("locks her office"); people moved by others ("are ushered to");
the robot's followers and approachers; a person named only as whom a group follows."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


def read(worlds, world, prompt):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == (), reading.unknown_places
    return reading


# ---- 1. a job the lexicon lacks ----------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,label,field,place", [
    ("hospital", "The locksmith waits at reception.", "locksmith", "location", "reception_desk"),
    ("hospital", "Before his break the sonographer leaves radiology and heads to the cafeteria.", "sonographer",
     "destination", "cafeteria"),
    ("office", "An ergonomist walks from the kitchen to the boardroom.", "ergonomist", "destination", "boardroom"),
    ("mall", "The glazier goes to the food court.", "glazier", "destination", "food_court"),
    ("museum", "At closing time the conservationist leaves her workshop and walks to the café.", "conservationist",
     "destination", "cafe"),
    ("residential", "The plasterer waits in the kitchen.", "plasterer", "location", "kitchen"),
])
def test_a_job_no_list_names_is_one_person(worlds, world, prompt, label, field, place):
    g, = read(worlds, world, prompt).groups
    assert (g.label, g.count.value, g.count.kind) == (label, 1, "exact")
    assert getattr(g, field) == place


@pytest.mark.parametrize("world,prompt,label", [
    ("hospital", "Radiographers leave their department and go to the cafeteria.", "radiographer"),
    ("station", "Several horticulturalists wait on platform 1.", "horticulturalist"),
])
def test_the_plural_of_a_job_no_list_names_stays_a_crowd(worlds, world, prompt, label):
    g, = read(worlds, world, prompt).groups
    assert g.label == label and g.count.kind == "vague" and g.count.value > 1


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The elevator arrives at the entrance lobby."),
    ("airport", "The shuttle leaves gate A1."),
])
def test_a_machine_that_goes_is_nobody(worlds, world, prompt):
    g, = read_prompt(prompt, worlds[world]).groups
    assert g.label == "person" and g.confidence_of("group") is not None


def test_a_machine_beside_people_adds_no_group(worlds):
    g, = read(worlds, "office", "Ten engineers wait in the kitchen while the printer goes quiet.").groups
    assert (g.label, g.count.value) == ("engineer", 10)
