"""People who flee a hazard that starts at a thing (a machine, a till, a fountain pump) start in the thing's
room, not at the thing: they were all over the room when the smoke came. A start a group says itself
("from the vending machine") stays the thing. Real spaCy, real worlds."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world, prompt, start", [
    ("museum", "Smoke pours out of the gift shop till and the shoppers hurry out by the main entrance.", "gift_shop"),
    ("hospital", "Smoke billows from a vending machine in the cafeteria and the diners escape through the main entrance.",
     "cafeteria"),
    ("mall", "Sparks fly from the fountain pump and the shoppers nearby flee through the north entrance.", "main_atrium"),
    ("office", "Smoke pours from the coffee machine and the staff evacuate by the fire exit.", "kitchen"),
])
def test_people_fleeing_a_hazard_at_a_thing_start_in_its_room(worlds, world, prompt, start):
    group = read_prompt(prompt, worlds[world], seed=0).groups[0]
    assert group.intent == "evacuate"
    assert group.start == start


@pytest.mark.parametrize("world, prompt, start", [
    ("hospital", "Two visitors walk from the vending machine to the main entrance.", "vending_machine"),
    ("office", "A smell of burning comes from the coffee machine and two interns walk from reception to the exit.",
     "reception"),
])
def test_a_start_the_group_says_itself_is_kept(worlds, world, prompt, start):
    assert read_prompt(prompt, worlds[world], seed=0).groups[0].start == start
