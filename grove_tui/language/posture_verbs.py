"""Verbs of lying or lolling about (round 28): "a dozen firefighters sprawl across the sofas", "two
teens loll on the beanbags", "the night shift flop onto the settees", "a porter slouches against the
wall". A body laid out at rest is waiting there, not going; "across" with such a verb says where it
lies, not a way through. Said with "into", "to" or "off" ("slouches into the kitchen") it is a gait."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of a body laid out or slumped at rest (the lexicon has "lounge", "perch", "sit" and "rest").
POSTURE_VERBS = frozenset("sprawl loll slouch slump recline flop lie lay kip snuggle curl sprawled lolled "
                          "slouched reclined flopped".split())
# Words after such a verb that make it a way of going ("slouches into the kitchen", "lolls off to bed").
_GOING_TAILS = frozenset("into to towards toward out off away over back through along past".split())
# Forms the lexicon's lemmas may leave as they are.
_FORMS = {"sprawls": "sprawl", "sprawling": "sprawl", "lolls": "loll", "lolling": "loll", "slouches": "slouch",
          "slouching": "slouch", "reclines": "recline", "reclining": "recline", "flops": "flop",
          "flopping": "flop", "lies": "lie", "lying": "lie", "kips": "kip", "kipping": "kip", "curls": "curl"}


def posture_intent(s: Sentence, i: int) -> str | None:
    """"wait" for a verb of lying or lolling about at i, not a noun ("a lie-in") nor "lay THING"."""
    if s.after_determiner(i):
        return None
    w = s.low[i]
    v = _FORMS.get(w) or verb_lemma(w)
    if v not in POSTURE_VERBS and s.verb(i) not in POSTURE_VERBS:
        return None
    if i + 1 < s.n and s.low[i + 1] in _GOING_TAILS:
        return None  # "the teenager slouches into the kitchen": a gait, going there
    if v in ("lie", "lay", "curl") or s.verb(i) in ("lie", "lay", "curl"):
        # "lies" and "curl" only as a body at rest: a place word or "down"/"up"/"about" next
        nxt = s.low[i + 1] if i + 1 < s.n else ""
        if nxt not in ("down", "up", "about", "around", "on", "in", "across", "along", "by", "beside", "under"):
            return None
    return "wait"
