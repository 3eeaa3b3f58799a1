"""What someone bids on, buys or came for (round 54): "having lost out on the Georgian bureau she came for",
"a dealer bids on the oak dresser", "misses out on the walnut clock", "makes an offer on the vase". The
phrase is a thing, no place, so nothing to refuse when the world lacks it: it follows a verb of bidding
or of losing out ("bid on", "bid for", "lose out on", "miss out on", "an offer on", "haggle over"), or a
relative clause after it says someone came for, bought or wanted it ("the bureau she came for")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_BIDDING = frozenset("bid outbid bet gamble splurge haggle pounce".split())
_LOSING_OUT = frozenset("lose miss".split())
_OFFERS = frozenset("bid offer bet".split())
_PRONOUNS = frozenset("she he they we i you someone everyone".split())
_WANTING = frozenset("come buy want bid covet eye seek win lose fancy purchase order choose pick".split())


def _base(s: Sentence, i: int) -> str:
    """The verb at i in its base form ("missed": "miss", "lost": "lose", "came": "come")."""
    return s.verb(i) if s.w[i].pos in ("VERB", "AUX") else verb_lemma(s.low[i])


def a_thing_bid_on(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k, after the preposition at `at`, is a thing bid on or come for (see the doc)."""
    low = s.low
    if prep in ("on", "for", "over") and at >= 1:
        before = _base(s, at - 1)
        if before in _BIDDING or lemma(low[at - 1]) in _OFFERS and prep == "on":
            return True  # "bids on the dresser", "an offer on the vase", "haggles over the clock"
        if prep == "on" and low[at - 1] == "out" and at >= 2 and _base(s, at - 2) in _LOSING_OUT:
            return True  # "lost out on the bureau", "misses out on the clock"
    end = k
    while end < s.n and s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN"):
        end += 1
    if end == k or end + 1 >= s.n:
        return False
    if low[end] in ("that", "which") and end + 2 < s.n:
        end += 1
    return low[end] in _PRONOUNS and _base(s, end + 1) in _WANTING and \
        not (end + 2 < s.n and low[end + 2] in ("to", "into", "from", "in", "at"))
