"""What a feeling is about is no place: "Furious about the sentence, ...", "Nervous about the interview,
a witness ...", "upset over the delay". The phrase after "about" or "over" right after an adjective
(past adverbs: "really angry about") is the feeling's topic, so a word the world lacks is not refused as
a place it lacks; a place the world has after it is still read (language/place_idioms.py)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Adverbs between a feeling and its "about" ("so cross about", "really worried about").
_DEGREE = frozenset("so really very quite too rather pretty a bit little still all".split())
# Participles of feeling ("worried about", "upset over"); a participle of placing ("scattered about the
# hall", "dotted about the foyer") still says where people are.
_FELT = frozenset("worried concerned upset bothered excited thrilled annoyed stressed confused pleased delighted "
                  "disappointed frustrated irritated incensed enraged outraged agitated puzzled amused embarrassed "
                  "distressed peeved riled fussed worked wound fired psyched gutted chuffed pumped hyped "
                  "heartbroken devastated shocked horrified baffled perplexed unsettled rattled".split())


def felt_about(s: Sentence, at: int) -> bool:
    """Whether the "about" / "over" at word `at` follows an adjective of feeling (its topic comes next)."""
    if at >= s.n or s.low[at] not in ("about", "over") or at < 1:
        return False
    x = at - 1
    while x > 0 and s.low[x] in _DEGREE:
        x -= 1
    if s.low[x] in ("up", "out") and x > 0:
        x -= 1  # "worked up about", "stressed out over"
    return (s.w[x].pos == "ADJ" and s.w[x].tag in ("JJ", "JJR", "JJS")) or s.low[x] in _FELT
