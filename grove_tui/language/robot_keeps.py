"""The robot staying put said with a verb of keeping and a noun of a post: "the robot holds (its)
position by the stairs", "keeps its station beside gate B1", "holds its ground", "takes up its post
at the door", "keeps watch over the lobby", "mans the desk": a wait where it is."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_KEEPING_VERBS = frozenset("hold keep maintain take assume man occupy mind".split())
_POST_NOUNS = frozenset("position station post ground spot place guard watch vigil sentry duty stance".split())
_BETWEEN = frozenset("its it's his her their a the up one's own".split())


def keeps_post(s: Sentence, verb: int | None) -> bool:
    """Whether the robot's verb at `verb` keeps a post: a verb of keeping, then within a few words
    ("its", "up") a noun of a post."""
    if verb is None or s.verb(verb) not in _KEEPING_VERBS:
        return False
    k = verb + 1
    while k < s.n and s.low[k] in _BETWEEN:
        k += 1
    return k < s.n and (s.low[k] in _POST_NOUNS or (s.w[k].lemma in _POST_NOUNS and s.w[k].pos == "NOUN"))
