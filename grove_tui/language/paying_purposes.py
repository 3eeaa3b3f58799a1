"""A purpose said by a participle of paying or buying right after the place (round 58): "lined up at the
pro's till paying green fees", "queue at the pharmacy collecting prescriptions", "wait at the box office
buying tickets". What they pay for or buy at the place is why they are there, as "wanting flea spray" is
(language/purpose_wanted.py); the participle was left unread and the group had no purpose. Only after a
word of a place of the world ("... at the kiosk buying ..."), so "a man buying coffee walks ..." is no
purpose of a place."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_PAYING = frozenset("paying buying purchasing ordering booking renewing collecting".split())


def _after_a_place(s: Sentence, end: int) -> bool:
    """Whether word `end` ends a place phrase: a place preposition a few words back, and a word of a place
    of the world in between ("at the pro's till", "by the box office")."""
    known = False
    for k in range(end, max(end - 6, 0), -1):
        if s.low[k] in lx.PLACE_PREPOSITIONS and k < end:
            return known
        if s.is_punct(k) or s.w[k].pos in ("VERB", "AUX", "PRON") or s.low[k] in lx.PERSON_NOUNS:
            return False
        known = known or s.index.knows(s.lemma(k)) or s.index.knows(s.low[k])
    return False


def paying_purpose(s: Sentence, i: int) -> tuple[int, int] | None:
    """(where the purpose's words start, where its object starts) for "<place> paying X", else None."""
    if s.low[i] not in _PAYING or i < 2 or i + 1 >= s.n:
        return None
    before = i - 2 if s.low[i - 1] == "," else i - 1
    if not _after_a_place(s, before):
        return None
    nxt = i + 1
    if s.low[nxt] == "for" and s.low[i] == "paying":
        nxt += 1  # "paying for their shopping"
    if nxt >= s.n or s.is_punct(nxt) or s.w[nxt].pos in ("ADP", "PART", "AUX", "VERB") or s.preposition(nxt) is not None:
        return None
    return i, nxt
