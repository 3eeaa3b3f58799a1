"""An adverb and a participle between a count and its people: "eight freshly jabbed pensioners",
"six newly qualified nurses". The parser may tag the participle a noun ("jabbed" as a compound), so
the adverb was not seen to describe anything and the count was lost (round 49)."""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.language.sentence import Sentence


def adverb_before_participle(s: Sentence, k: int, is_person: Callable[[int], bool]) -> bool:
    """Whether adverb k describes a participle after it that describes people after that, however
    the participle was tagged ("freshly jabbed pensioners")."""
    if s.w[k].pos != "ADV" or k + 2 >= s.n:
        return False
    part = s.low[k + 1]
    return part.isalpha() and part.endswith(("ed", "en")) and len(part) > 3 and is_person(k + 2) and \
        not s.w[k + 2].tag.startswith("VB")
