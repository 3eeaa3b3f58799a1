"""What a purpose of getting ready is for (issue 29): "stroll to the dining room to set up for dinner",
"head to the hall to get ready for the concert", "go backstage to prepare for the show". The purpose's
phrase ended at "for", so only "to set up" was kept and the occasion was lost. After a verb of readying
(prepare, ready, set up, gear up, warm up, ...), a "for" whose phrase names no place of the world, no time
span and no person is what they get ready for: part of the purpose. "get ready for the gate" (a place)
is left to the place reader."""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.stays import stay_after_for
from grove_tui.language.tokens import lemma

_READY = frozenset({"prepare", "prepares", "preparing", "prepared", "ready", "readies", "readying", "set"})
_UP_VERBS = frozenset("set gear warm tool suit tidy clean clear lay kit".split())  # "set up", "gear up"


def readied_for(s: Sentence, said_from: int, at: int, names_place: Callable[[int], bool],
                is_person_noun: Callable[[int], bool]) -> bool:
    """Whether "for" at `at`, right after a purpose of readying said from `said_from`, opens the occasion
    readied for (module doc)."""
    if at + 1 >= s.n or s.low[at] != "for" or not 0 <= said_from < at:
        return False
    said = s.low[said_from:at]
    readying = any(w in _READY and (w != "set" or k + 1 == len(said)) for k, w in enumerate(said)) or any(
        said[k + 1] == "up" and lemma(w) in _UP_VERBS for k, w in enumerate(said[:-1]))
    if not readying or stay_after_for(s, at + 1) is not None:
        return False  # "set up for a while": a stay
    k = at + 1
    while k < s.n and (s.low[k] in lx.DETERMINERS or s.w[k].pos in ("ADJ", "NUM")):
        k += 1
    return k < s.n and s.w[k].pos in ("NOUN", "PROPN") and not names_place(at + 1) and not is_person_noun(k)
