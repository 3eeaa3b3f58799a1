"""What may follow a count said in apposition before the clause goes on (round 26): "ward A's patients,
six in all, ...", "the stag party, eleven lads in matching T-shirts, piles out ...", "the hen party, a
dozen women in sashes, ...", "the choir, thirty singers with their music, files in". A phrase that only
says how the counted people look or what they carry ("in ...", "with ...", "wearing ...") ends at the
comma and holds no verb of its own; past it the sentence goes on as after the count.

Round 69: a count said as a total ("nine volunteers in all", "twelve of them altogether") is how many the
group before it is, whatever noun it uses ("the Saturday guides, six volunteers in all, ...")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_TOTALS = (("in", "all"), ("in", "total"), ("all", "told"))
_DESCRIBING = frozenset("in with wearing carrying clutching holding sporting dressed from".split())
_LONGEST = 9


def after_apposed_count(s: Sentence, after: int) -> int:
    """The token after an apposed count's own words, from `after` (the token after its noun): past "in
    all" or "altogether", or past a describing phrase that runs to a comma."""
    if tuple(s.low[after:after + 2]) in _TOTALS:
        return after + 2  # "ward A's patients, six in all, make their way out"
    if after < s.n and s.low[after] == "altogether":
        return after + 1
    if after < s.n and s.low[after] in _DESCRIBING:
        for k in range(after + 1, min(after + _LONGEST, s.n)):
            if s.low[k] == ",":
                return k
            if s.is_punct(k) and s.low[k] != "-" or (s.w[k].tag in ("VBZ", "VBD", "VBP", "MD") and s.low[k] not in _DESCRIBING):
                break
    return after


def a_total(s: Sentence, after: int) -> bool:
    """Whether the words from `after` (the token after a count's noun) say it is a total ("in all",
    "in total", "all told", "altogether")."""
    return tuple(s.low[after:after + 2]) in _TOTALS or (after < s.n and s.low[after] == "altogether")
