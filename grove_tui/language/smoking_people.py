"""Someone who smokes is no fire (round 29): "a sous-chef smokes beside the service entrance", "the
porter smokes by the bins while two fans hurry to the lifts". The small parser takes "smokes" after
one person for a plural noun, and the noun "smoke" is a hazard that makes hurrying an evacuation;
"smokes" or "smoking" right after a person's noun (the subject's own word) is their verb."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_FORMS = frozenset("smokes smoking".split())


def smoked_by_someone(s: Sentence, i: int) -> bool:
    """Whether the word at i is someone's smoking, right after a person's noun (module doc)."""
    if s.low[i] not in _FORMS or i == 0:
        return False
    prev = s.low[i - 1]
    return prev in lx.PERSON_NOUNS or prev.rstrip("s") in lx.PERSON_NOUNS or prev in ("who", "they", "he", "she")
