"""A thing of someone's in a describing clause with its verb left out (round 31): "heads for the room
where her fingerprints are scanned and her photo taken", "the desk where his bags are weighed and his
temperature taken". The second passive has no "is", so the parser makes "her photo" the subject of
"taken" and the photo a person. A possessive and a word that names no person, right before a past
participle after "and" or a comma, is a thing done to the person already said: no group."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

_POSSESSIVES = frozenset("her his their its my our your".split())


def _a_person_word(low: str, lemma: str) -> bool:
    return any(w in lx.PERSON_NOUNS or w in lx.KIN_NAMES or w in lx.GENERIC_PEOPLE for w in (low, lemma))


def _described_thing(s: Sentence, m: Mention) -> bool:
    if m.relation is not None or s.low[m.first] not in _POSSESSIVES or m.last - m.first > 3 or m.first == 0:
        return False
    if s.low[m.first - 1] not in ("and", ",", "or"):
        return False
    if any(_a_person_word(s.low[j], s.lemma(j)) for j in range(m.first + 1, m.last + 1)):
        return False  # "and his son taken to ...": a person
    after = m.last + 1
    return after < s.n and s.w[after].tag in ("VBN", "VBD")  # "taken", or "checked" the parser calls past


def without_described_things(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but things done to someone in a clause with its verb left out, when someone else is named."""
    dropped = [k for k, m in enumerate(mentions) if _described_thing(s, m)]
    if not dropped or len(dropped) == len(mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
