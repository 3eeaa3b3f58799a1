"""A noun that says what kind a counted plural is (round 42): "nine cub scouts", "six choir boys",
"four ward clerks" after a count. The first noun names no person on its own and the plural after it is
read as people by the count ("nine scouts"); the two are one phrase, so the count belongs to it (not
to a group guessed from the plural alone, nor lost when the phrase stands in apposition: "the party,
nine cub scouts, ...")."""

from __future__ import annotations

from typing import Callable

from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.sentence import Sentence


def kind_before_counted(s: Sentence, k: int, j: int, counted: bool, is_person: Callable[[int], bool],
                        head_at: Callable[[int], int | None]) -> bool:
    """Whether word k, first after a count (j), is a singular noun naming the kind of the plural after it."""
    if not counted or k != j or k + 1 >= s.n or s.w[k].tag != "NN" or s.w[k + 1].tag != "NNS":
        return False
    if is_person(k) or names_a_place(s.index, s.lemma(k)) or s.index.knows(s.lemma(k)):
        return False  # "nine nurse practitioners" read already; "nine lobby chairs": a place's things
    return head_at(k + 1) == k + 1


def kind_before_hyphened(s: Sentence, k: int, j: int, counted: bool, head_at: Callable[[int], int | None]) -> bool:
    """Whether word k, first after a count (j), is a noun naming when or what kind ("fifty Saturday
    bargain-hunters", "thirty summer day-trippers") before a hyphened plural:
    the count is the plural's, not lost on the first noun (round 52)."""
    if not counted or k != j or k + 3 >= s.n or s.w[k].pos not in ("NOUN", "PROPN") or s.w[k].tag in ("NNS", "NNPS"):
        return False
    if s.low[k + 2] != "-" or names_a_place(s.index, s.lemma(k)) or s.index.knows(s.lemma(k)):
        return False
    return head_at(k + 1) == k + 3  # the parser may hang the count on the first noun ("twenty evening")
