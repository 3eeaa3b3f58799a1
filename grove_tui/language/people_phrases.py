"""Three questions about people asked where mentions are found (language/mentions.py), kept out of
people.py: whether a word names everyone somewhere with no kind ("everyone", "whoever is in the café"),
whether "his/her ..." after "with" are people of their own or members of the subject, and whether a
person word is the first of two subjects joined by "and"."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import quantifier
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.verbless_pairs import second_of_a_placed_pair
from grove_tui.language.joined_names import joined_first_name


def whole_zone_pronoun(s: Sentence, at: int) -> bool:
    """Whether the word at `at` names everyone somewhere, with no kind of people: "everyone",
    "anyone waiting on platform 1", "whoever is in the café", "those who are in the lobby"."""
    low = s.low
    if low[at] in ("everyone", "everybody", "anyone", "anybody", "whoever"):
        return not (at > 0 and low[at - 1] in ("not", "n't", "hardly", "barely"))
    return low[at] == "those" and at + 1 < s.n and low[at + 1] == "who"


def companions(s: Sentence, people: People, with_at: int) -> bool:
    """Whether "his/her ..." after "with" at `with_at` are people of their own, not members of the
    subject: the subject is one person ("a mother with her two kids", "an old man with his
    daughter"), not a family or a group whose own members they are ("families ... with their
    children", "a school group with its teachers")."""
    for k in range(with_at - 1, -1, -1):
        if s.w[k].sentence != s.w[with_at].sentence or s.low[k] in (";", ":"):
            return False
        if people.is_person_noun(k):
            word = s.lemma(k)
            return word == s.low[k] and word not in lx.IMPLIED_RANGES and word not in lx.TOGETHER_COLLECTIVES \
                and word not in lx.FAMILY_PLURALS
    return False


def coordinated_person(s: Sentence, people: People, head: int) -> bool:
    """Whether a person word is joined by "and" to another person phrase ("Mum and two kids
    walk", "Mum and Dad chat"): the first of two subjects, though no verb follows it."""
    if second_of_a_placed_pair(s, people, head) or joined_first_name(s, head):
        return True  # "Mum and Dad at the table": the second of the two, with no verb either; "Priya, Tom and Alice chat"
    if head + 2 >= s.n or s.low[head + 1] != "and":
        return False
    q = quantifier(s, head + 2)
    start = q.end if q is not None else s.skip(head + 2, lx.DETERMINERS)
    return start < s.n and people.person_head(start, counted=q is not None) is not None
