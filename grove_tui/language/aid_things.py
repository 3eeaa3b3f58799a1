"""Walking aids and shopping trolleys named by a person's word (round 44): "Dorothy inches her walker
from her room to the conservatory" (a walking frame), "a pensioner with a tartan shopper trundles across"
(a shopping trolley), "Mum steers the stroller to the lift" (a pushchair). Said as someone's own, after
"with", or as what a person moves, such a word is the thing: no second person following the first."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Person words that also name a thing people push or lean on.
AID_WORDS = frozenset({"walker", "shopper", "stroller"})
_OWNERS = frozenset({"her", "his", "their", "my", "our", "your", "its"})
_ARTICLES = frozenset({"a", "an", "the"})


def aid_thing(s: Sentence, i: int) -> bool:
    """Whether the word at i is a walking aid or trolley said as a thing (module doc)."""
    if s.low[i] not in AID_WORDS:
        return False
    k = i - 1
    while k >= 0 and s.w[k].pos in ("ADJ", "NOUN", "PROPN", "VERB") and s.low[k] not in _OWNERS | _ARTICLES and i - k <= 2:
        k -= 1  # "her old walker", "a tartan shopper", "a folding stroller"
    if k < 0:
        return False
    if s.low[k] in _OWNERS:
        return s.w[i].dep in ("dobj", "obj", "pobj") or (k > 0 and s.low[k - 1] == "with")  # "inches her walker"
    return s.low[k] in _ARTICLES and k > 0 and s.low[k - 1] in ("with", "behind", "pushing", "pulling")
