"""Collectives said with their size or by their own name (round 35):

- a member collective sized with "of" and a number, no person noun after it: "the cast of 14 escape",
  "a troupe of eight walk", "a squad of 20 jog": so many members ("the 14 cast members");
- a part of a named team, watch or crew: "Six of Blue Watch dash", "three of Team Kestrel wait",
  "two of Red Crew": so many of its members ("Six Blue Watch members").

Both are written out before the sentence is parsed, so the count is read as any "twelve porters"."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                        ("couple", "pair", "handful", "dozens")), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
# Collectives whose members act together; "crew" and "shift" are read with their size already.
_SIZED = "cast|troupe|band|team|squad|choir|gang|troop|delegation|ensemble|chorus|posse|orchestra"
# Words after "the cast of 14" that show no person noun follows (a verb, a place word, a clause break).
_SIZED_RE = re.compile(r"\b([Tt]he|[Aa]n?|[Tt]heir|[Oo]ur|[Hh]is|[Hh]er)\s+(" + _SIZED + r")\s+of\s+(" + _NUMBER +
                       r")\b(?=\s*(?:[,.;!?]|$|\s+(?:on|in|at|by|near|from|inside|outside|who|that|all|still|"
                       r"then|and)\b|\s+[a-z]+(?:s|ed)?\b))", re.IGNORECASE)
# Named teams: a capitalised name ending in a word for a team ("Blue Watch", "Team Kestrel", "Red Crew").
_TEAM_WORDS = "Watch|Team|Crew|Squad|Shift|Unit|Company|Platoon|Section|Troop|Patrol|House|Group"
_NAMED_RE = re.compile(r"\b((?i:" + _NUMBER + r"))\s+of\s+((?:(?:[A-Z][\w'-]*)\s+){0,2}(?:" + _TEAM_WORDS +
                       r")(?:\s+[A-Z][\w'-]*)?)\b(?!\s+(?:members?|people|staff)\b)")
_TEAM_FIRST = re.compile(r"^(?:" + _TEAM_WORDS + r")\s+[A-Z]")


def _person_follows(text: str, end: int) -> bool:
    """Whether a person noun follows at `end` ("a team of 5 nurses"), perhaps after one word that
    describes them ("a gang of ten excited kids", "a squad of 20 junior nurses"), no verb."""
    m = re.match(r"\s+([a-z-]+)(?:\s+([a-z]+))?", text[end:])
    if m is None:
        return False
    if m.group(2) and _person_word(m.group(2)) and not _person_word(m.group(1)) and \
            m.group(1) not in lx.STOPWORDS and verb_lemma(m.group(1)) not in _PEOPLE_VERBS:
        return True
    return _person_word(m.group(1))


_PEOPLE_VERBS = frozenset(lx.INTENT_VERBS) | lx.HUMAN_SUBJECT_VERBS | lx.THING_VERBS


def _person_word(word: str) -> bool:
    return word in lx.PERSON_NOUNS or (word.endswith("s") and word[:-1] in lx.PERSON_NOUNS) or \
        (word.endswith("es") and word[:-2] in lx.PERSON_NOUNS) or word in lx.GENERIC_PEOPLE


def _sized(m: re.Match[str]) -> str:
    if _person_follows(m.string, m.end()):
        return m.group(0)
    det = m.group(1)
    det = "the" if det.lower() in ("a", "an") else det  # "a troupe of eight": "the eight troupe members"
    if m.group(1)[0].isupper():
        det = det[0].upper() + det[1:]
    return f"{det} {m.group(3)} {m.group(2).lower()} members"


def _named(m: re.Match[str]) -> str:
    name = m.group(2)
    if not (name.split()[-1] in _TEAM_WORDS.split("|") or _TEAM_FIRST.match(name)):
        return m.group(0)
    return f"{m.group(1)} {name} members"


def with_counted_collectives(text: str) -> str:
    """The text with sized and named collectives written as so many members (see the module doc)."""
    return _NAMED_RE.sub(_named, _SIZED_RE.sub(_sized, text))
