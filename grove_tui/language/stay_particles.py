"""A duration right after a verb of staying said with its particle: "hangs on 5 mins @ the nurse
station", "hangs around ten minutes by the door", "sits down 5 mins". A bare duration after a verb of
staying ("waits 15 minutes outside") is how long the stay lasts (language/clauses.py); with the
phrasal verb's particle between them it was read as no duration at all."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def after_a_stay(s: Sentence, i: int) -> bool:
    """Whether word i comes right after a verb of staying, or after such a verb and its particle."""
    if lx.INTENT_VERBS.get(s.verb(i - 1)) in lx.STATIONARY_INTENTS:
        return True
    verb = s.verb(i - 2) if i >= 2 else ""
    if lx.INTENT_VERBS.get(verb) not in (None, *lx.STATIONARY_INTENTS):
        return False  # "walk about 5 minutes from X to Y": about five minutes of walking, no stay
    return lx.PHRASAL_INTENTS.get((verb, s.low[i - 1])) in lx.STATIONARY_INTENTS
