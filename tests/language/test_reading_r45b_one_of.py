"""One person out of people nobody counted ("One of the porters ...") is one group of one, no vague
whole beside it, as every held-out set that says it labels it; a whole said before or counted inside
is still the whole the one comes out of."""

import pytest


@pytest.mark.parametrize("world,prompt,label,start,destination", [
    ("hospital", "One of the nurses hurries from the pharmacy to the lobby.", "nurse", "pharmacy", "entrance_lobby"),
    ("airport", "One of the cleaners wanders over from the café to gate A2.", "cleaner", "cafe", "gate_a2"),
])
def test_one_of_people_nobody_counted_is_one_person(read, world, prompt, label, start, destination):
    (group,) = read(world, prompt).groups
    assert (group.label, group.count.value, group.relation) == (label, 1, None)
    assert (group.start, group.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,whole", [
    ("hospital", "Ten nurses wait in the lobby and one of the nurses walks to the pharmacy.", 10),
    ("museum", "One of the five guards walks to the main hall.", 5),
])
def test_one_of_a_whole_said_is_still_its_subset(read, world, prompt, whole):
    a, b = read(world, prompt).groups
    assert (a.count.value, b.count.value, b.relation) == (whole, 1, "subset_of:0")
