"""One person said twice, the second name between commas, is one group (language/second_names.py); a list
of people set off by commas is still one group each."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

ONCE = [
    ("airport", "The pilot, Captain Ames, strolls to gate A2.", "gate_a2"),
    ("office", "Our receptionist, Mrs Patel, walks to the boardroom.", "boardroom"),
    ("airport", "The duty manager, a tall man called Pete, waits by gate A1.", None),
    ("hospital", "The ward sister, Sister Okoro, hurries to the pharmacy.", "pharmacy"),
    ("museum", "Our guide, a retired teacher named Joan, waits by the dinosaur skeleton.", None),
]


@pytest.mark.parametrize("world, sentence, destination", ONCE)
def test_a_second_name_between_commas_is_the_same_person(world, sentence, destination):
    reading = read_prompt(sentence, load_world(world))
    assert [(g.count.value) for g in reading.groups] == [1]
    if destination:
        assert reading.groups[0].destination == destination


LISTS = [
    ("airport", "A cleaner, a porter and two pilots walk to gate A1.", [1, 1, 2]),
    ("hospital", "The surgeon, a nurse, and a porter walk to the cafeteria.", [1, 1, 1]),
]


@pytest.mark.parametrize("world, sentence, counts", LISTS)
def test_a_list_set_off_by_commas_keeps_its_groups(world, sentence, counts):
    assert [g.count.value for g in read_prompt(sentence, load_world(world)).groups] == counts
