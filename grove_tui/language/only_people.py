"""People said with "only": "the only people in the ward are two nurses", "the only visitor in the
gallery is a student" (the people named after the verb are the group, and nobody else is there),
and "the only nurse on the ward walks to the pharmacy" (one nurse, the subject herself)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence

_ONLY_WORDS = frozenset({"people", "person", "ones", "one"})


def names_the_only(s: Sentence, people: People, k: int, other: bool) -> bool:
    """Whether "only" at k starts a phrase of people ("the only people", "the only visitor"); with
    `other` false, "the only other person" is not one (one more person, not everyone)."""
    j = k + 1
    if j < s.n and s.low[j] == "other":
        if not other:
            return False
        j += 1
    return j < s.n and (s.low[j] in _ONLY_WORDS or people.person_head(j, counted=False) == j)


def only_people_before(s: Sentence, people: People, p: int, other: bool) -> bool:
    """Whether p's sentence says "the only people"/"the only visitor" before p (see names_the_only)."""
    sentence = s.w[p].sentence
    return any(s.low[k] == "only" and names_the_only(s, people, k, other)
               for k in range(p) if s.w[k].sentence == sentence)


def the_only_mention(s: Sentence, people: People, at: int) -> Mention | None:
    """The mention of "the only nurse ... walks": the subject itself (one person, or some for a
    plural); None when the phrase is the subject of "is"/"are" (the people named after it are the
    group) or names no one."""
    j = s.skip(at + 2, {"other"})
    head = people.person_head(j, counted=False) if j < s.n and s.low[j] not in _ONLY_WORDS else None
    if head is None:
        return None
    verb = s.w[head].head
    if s.w[head].dep in ("nsubj", "nsubjpass") and s.verb(verb) == "be":
        return None  # "the only visitor in the gallery is a student": the student is the group
    label = people.label(head)
    if s.lemma(head) == s.low[head] and not people.plural_word(head):
        return Mention(at, head, s.span(at, head), label, Count("exact", 1, 1, 1))
    low, high = lx.BARE_PLURAL_RANGE
    return Mention(at, head, s.span(at, head), label, Count("vague", s.choose(low, high, f"{at}:only"), low, high))
