"""People counted by the thing each moves ("three prams are pushed to the food court", "two
wheelchairs roll in"): a pram or a wheelchair goes nowhere alone, so each is a person, labelled by
who goes with it (a parent pushing a pram, a wheelchair user), not a group named "pram"."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# A thing a person moves with -> the label of the person it counts.
THING_PEOPLE: dict[str, str] = {
    "pram": "parent", "pushchair": "parent", "buggy": "parent", "stroller": "parent",
    "wheelchair": "wheelchair user", "mobility scooter": "scooter user",
}


def person_of_a_thing(noun: str) -> str | None:
    """The label of the person a thing's noun counts, else None."""
    return THING_PEOPLE.get(noun)


# Verbs a person does with the thing they move: "two wheelchairs roll to ...", "a pushchair goes ...".
_MOVING = frozenset("roll go come head move wheel trundle glide zoom queue wait line park make".split())
_WITH = frozenset({"with", "in", "on", "pushing", "pulling", "of"})


def moves_as_a_person(s: Sentence, i: int) -> bool:
    """Whether the thing at word i is the subject of going or waiting ("two wheelchairs roll to ...",
    "a pushchair goes ..."), even in a world with wheelchairs of its own; not the object of "with" or
    "in" ("a mum with a pram walks")."""
    if person_of_a_thing(s.lemma(i)) is None or i + 1 >= s.n or any(s.low[k] in _WITH for k in range(max(0, i - 2), i)):
        return False
    return s.w[i].dep in ("nsubj", "ROOT", "amod", "compound") and verb_lemma(s.low[i + 1]) in _MOVING
