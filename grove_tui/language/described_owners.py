"""Rooms whose owner the world names only in their description: "Office G07, Professor Lindqvist's",
"The office where the Consul, Ingrid Halvorsen, works". "Ingrid Halvorsen takes a folder from her
office", "Professor Lindqvist strolls down to her lab" mean that room, not any office or lab: the owner
is the nearest name said before the possessive in its sentence (a title and a name, or a first name and
a surname), and the room is the one zone whose description carries that surname and which is called
by the head ("office", "lab") in its names or its description."""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceEntry, PlaceMatch
from grove_tui.language.sentence import Sentence

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

# Words a capitalised word can be without naming anyone at the start of a sentence or after a comma.
_NOT_NAMES = frozenset({"the", "a", "an", "she", "he", "they", "her", "his", "their", "it", "we", "i", "you",
                        "then", "later", "meanwhile", "while", "when", "after", "before", "and", "but"})
_HIS = frozenset({"mr", "sir", "father", "uncle"})
_HER = frozenset({"mrs", "ms", "miss", "dame", "sister", "auntie"})


def surname_before(s: Sentence, at: int, pronoun: str) -> str | None:
    """The surname of the nearest named person said before word `at` in its sentence: "Lindqvist" of
    "Professor Lindqvist", "Halvorsen" of "Ingrid Halvorsen" (lower case); None when none is said."""
    x = at - 1
    while x >= 0 and s.w[x].sentence == s.w[at].sentence:
        word = s.w[x].text
        if word[:1].isupper() and word.isalpha() and s.low[x] not in _NOT_NAMES and s.w[x].pos == "PROPN" and \
                (x + 1 >= s.n or not s.w[x + 1].text[:1].isupper() or not s.w[x + 1].text.isalpha()):
            before = s.low[x - 1].rstrip(".") if x >= 1 else ""
            titled = before in lx.TITLES
            first = x >= 1 and s.w[x - 1].text[:1].isupper() and s.w[x - 1].pos == "PROPN" and before not in _NOT_NAMES
            if (pronoun == "her" and before in _HIS) or (pronoun == "his" and before in _HER):
                x -= 1
                continue
            if titled or first:
                return s.low[x]
        x -= 1
    return None


def _words(text: str) -> set[str]:
    return set(re.findall(r"[a-z0-9]+", text.lower()))


def owned_by_description(entries: Sequence[PlaceEntry], surname: str, head: str) -> PlaceEntry | None:
    """The one zone whose description names `surname` and which is called `head` by its names or its
    description; None when none or several are."""
    theirs = [e for e in entries if e.kind == "zone" and surname in _words(e.description)]
    called = [e for e in theirs if head in e.tokens] or [e for e in theirs if head in _words(e.description)]
    return called[0] if len(called) == 1 else None


def owned_by_described_name(s: Sentence, at: int, k: int, lemmas: Sequence[str]) -> Decided | None:
    """The room a possessive at word k names when the world says whose it is only in its
    description ("her office" of Ingrid Halvorsen: consul_office), else None."""
    if k >= s.n or s.low[k] not in ("her", "his", "their") or not lemmas:
        return None
    surname = surname_before(s, at, s.low[k])
    if surname is None:
        return None
    e = owned_by_description(s.index.entries, surname, lemmas[-1])
    if e is None:
        return None
    return (PlaceMatch(e.name, e.kind, e.zone, 1.0, True), 0.85,
            f"'{' '.join(lemmas)}' of {surname}, by the world's description: {e.name}", ())


def named_room(s: Sentence, at: int, pronoun: str, heads: Sequence[str]) -> PlaceEntry | None:
    """The room of the nearest named person before word `at` ("hers" of Mrs Whitfield: the zone
    whose names or description carry "Whitfield"), the heads said before deciding between several of
    theirs ("her office" ... "hers"); None when no name is said or no one room is theirs."""
    surname = surname_before(s, at, pronoun)
    if surname is None:
        return None
    theirs = [e for e in s.index.entries if e.kind == "zone" and (
        surname in _words(e.description) or any(surname in phrase for phrase in e.phrases))]
    if len(theirs) > 1:
        theirs = [e for e in theirs if any(h in e.tokens for h in heads)] or theirs
    return theirs[0] if len(theirs) == 1 else None


def owned_by_name_said(s: Sentence, k: int, lemmas: Sequence[str]) -> Decided | None:
    """The room a person's name and "'s" at word k names ("to Priya Shah's office", "Ms Shah's office",
    "Sophie's cabin", round 69) when the world says whose it is only in its description: the one zone whose
    description carries the name's last word said (else its first) and which is called by the head."""
    names: list[str] = []
    x = k
    while x < s.n and s.w[x].text[:1].isupper() and s.w[x].text.isalpha() and s.low[x] not in _NOT_NAMES:
        names.append(s.low[x].rstrip("."))
        x += 1
    if not names or x >= s.n or s.low[x] not in ("'s", "’s", "'", "’") or not lemmas:
        return None
    said = [w for w in names if w not in lx.TITLES and w not in _HIS | _HER]
    for name in reversed(said):
        e = owned_by_description(s.index.entries, name, lemmas[-1])
        if e is not None:
            return (PlaceMatch(e.name, e.kind, e.zone, 1.0, True), 0.85,
                    f"'{' '.join(lemmas)}' of {' '.join(names)}, by the world's description: {e.name}", ())
    return None


def said_owner_name(s: Sentence, k: int) -> bool:
    """Whether a person's name and "'s" start at word k, before the head of a room the world describes as
    theirs ("Priya Shah's office"): a place phrase, though it opens with no determiner and no place word."""
    x = k
    while x < s.n and s.w[x].text[:1].isupper() and s.w[x].text.isalpha() and s.low[x] not in _NOT_NAMES:
        x += 1
    return k < x and x + 1 < s.n and s.low[x] in ("'s", "’s", "'", "’") and \
        owned_by_name_said(s, k, (s.lemma(x + 1),)) is not None
