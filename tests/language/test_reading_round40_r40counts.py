"""Count classes of round 40, each with sentences of its own over at least two worlds (none from the
understanding sets): one person said with a contracted "is" or "has" ("Dad's snoozing on the couch",
"Sarah's been waiting at the desk", "Nan's asleep in the lounge") is that one person, not a possessive
that leaves a vague group of "people"."""

from __future__ import annotations

import pytest


# ---- 1. a person's "'s" that is "is" or "has" ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,who,intent", [
    ("residential", "Grandad's dozing in the armchair.", "Grandad", "wait"),
    ("residential", "Mum's cooking in the kitchen again.", "Mum", "wait"),
    ("hospital", "Sarah's waiting at the nurse station.", "Sarah", "wait"),
    ("hospital", "My brother's been sitting in the cafeteria for an hour.", "brother", "wait"),
    ("hospital", "Nan's asleep in the cafeteria.", "Nan", "wait"),
    ("mall", "Grandma's sitting by the fountain.", "Grandma", "wait"),
    ("station", "The cleaner's mopping the ticket hall.", "cleaner", "wander"),
])
def test_a_person_with_a_contracted_is_is_one_person(read, world, prompt, who, intent):
    (group,) = read(world, prompt).groups
    assert (group.count.kind, group.count.value) == ("exact", 1)
    assert who.lower() in group.who.lower()
    assert group.intent == intent


# ---- guards: a possessive keeps its owner out, and pronouns keep their reading ------------------------

@pytest.mark.parametrize("world,prompt,kind,value", [
    ("hospital", "Dad's walking stick is by the lifts and two nurses wait there.", "exact", 2),
    ("mall", "The manager's office is shut, so three cleaners wait by the fountain.", "exact", 3),
    ("station", "It's busy: forty commuters wait on platform 2.", "exact", 40),
    ("hospital", "There's a porter waiting by the lifts.", "exact", 1),
])
def test_possessives_and_pronouns_keep_their_reading(read, world, prompt, kind, value):
    groups = read(world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [(kind, value)]
