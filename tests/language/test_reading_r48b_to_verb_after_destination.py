"""A second "to" right after where someone goes opens why they go, even when the parser calls its verb a
noun and a bare object follows ("to chair committee", "to minute staff meetings"); a place named in full
after it is still a place."""

import pytest


@pytest.mark.parametrize("world,prompt,purpose", [
    ("office", "A manager hurries to the boardroom to chair committee.", "chair committee"),
    ("office", "A manager hurries to the boardroom to minute staff meetings.", "minute staff meetings"),
    ("student_union", "Priya hurries to MR2 to chair student council.", "chair student council"),
])
def test_a_to_verb_after_a_destination_is_a_purpose(read, world, prompt, purpose):
    (group,) = read(world, prompt).groups
    assert purpose in (group.purpose or "")


def test_a_verb_with_its_determiner_stays_a_purpose(read):
    (group,) = read("office", "A manager walks to the kitchen to make the tea.").groups
    assert group.destination == "kitchen" and "make the tea" in (group.purpose or "")
