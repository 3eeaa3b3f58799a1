"""A bare person typed as a chat item after "+" or "and", doing something said by any "-ing" verb of
what people do ("hangin about", "hovering round"), is a group of its own; the final g chat drops is
written back first ("queuin", "sittin")."""

import pytest


@pytest.mark.parametrize("world,prompt,first,second", [
    ("airport", "4 passengers sittin at gate A2 + cleaner hangin about @ the café",
     ("passenger", 4, "gate_a2"), ("cleaner", 1, "cafe")),
    ("museum", "5 kids queuin at the cafe + guard hangin round the main hall",
     ("kid", 5, "cafe"), ("guard", 1, "great_hall")),
    ("hospital", "a nurse in the lobby and porter hovering round the pharmacy",
     ("nurse", 1, "entrance_lobby"), ("porter", 1, "pharmacy")),
])
def test_a_bare_person_doing_something_is_a_group(read, world, prompt, first, second):
    a, b = read(world, prompt).groups
    assert (a.label, a.count.value, a.location) == first
    assert (b.label, b.count.value, b.location) == second


def test_a_room_named_by_an_ing_word_is_no_doing(read):
    groups = read("office", "3 devs in the kitchen and boss waiting in the meeting room").groups
    assert [g.label for g in groups][-1] == "boss"
