"""A subject with an adverb between it and its verb (round 27): "Mum quickly walks to the kitchen",
"Grandad deliberately stands his ground", "Old Tom stubbornly waits by the fountain". A word for
one person with no article is a subject only when a verb follows it; a manner or time adverb said
between the two ("quickly", "still", "just") does not make it any less the verb's subject."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Adverbs said before a verb that do not end in "-ly".
_PLAIN_ADVERBS = frozenset("still just already always often usually also soon finally eventually again "
                           "sometimes meanwhile now".split())
# "-ly" words that are no adverbs of the verb ("an only child", "the early shift").
_NOT_ADVERBS = frozenset("only early daily weekly monthly yearly elderly family friendly lonely ugly holy "
                         "lovely silly jolly".split())


def past_adverbs(s: Sentence, k: int) -> int:
    """The last adverb after word k that stands between k and a verb (k itself when there is none):
    "Mum [quickly] walks" gives the index of "quickly"."""
    j = k
    while j + 2 < s.n and j - k < 2 and s.w[j + 1].pos == "ADV" and s.w[j + 1].dep == "advmod" and \
            (s.low[j + 1].endswith("ly") and s.low[j + 1] not in _NOT_ADVERBS or s.low[j + 1] in _PLAIN_ADVERBS) and \
            s.w[j + 1].head > j + 1 and s.w[s.w[j + 1].head].pos in ("VERB", "AUX"):
        j += 1
    return j
