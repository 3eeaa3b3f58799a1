"""A feeling set before the subject that is no verb form ("Agog, two boys ...", "Wary, an old man in a
flat cap ...") is no one's name: one group, the people after it, in whatever they wear."""

import pytest


@pytest.mark.parametrize("world,prompt,value,label", [
    ("zoo", "Wary, an old man in a flat cap shuffles away from the robot.", 1, "man"),
    ("mall", "Agog, two boys in football kits stare at the robot.", 2, "boy"),
    ("hospital", "Nervous, a young nurse in green scrubs walks up to the robot.", 1, "nurse"),
    ("museum", "Awestruck, a little girl in a fairy costume trails after the robot.", 1, "girl"),
])
def test_a_fronted_feeling_word_is_no_person(read, world, prompt, value, label):
    (group,) = read(world, prompt).groups
    assert (group.count.value, group.label) == (value, label)


def test_a_name_before_its_apposition_is_still_a_person(read):
    (group,) = read("office", "Sam, a porter, walks to the kitchen.").groups
    assert group.count.value == 1
