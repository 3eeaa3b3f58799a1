"""Where a thing someone holds came from (round 44): "lined up at the till clutching mugs from the seconds
shelf", "sits by the window holding a leaflet from the rack", "waves a flyer from the info stand". The
"from" phrase hangs off the thing held, not the person, who is not there and never goes there, so a
place the world lacks is no place to refuse. Verbs of carrying ("carries mugs from the shelf to the
till") are routes, not holding, and are not here."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of holding or looking at a thing in one's hands, which move nobody.
HOLDING_VERBS = frozenset("clutch hold grip clasp cradle hug brandish wave juggle balance nurse admire examine "
                          "inspect study read browse peruse flick flip sip nibble munch clench".split())


def origin_of_held(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the "from" phrase from k names where a thing held came from (see the module doc): a
    verb of holding, its object of one to four words with no person or place preposition in it, then
    "from"."""
    if prep != "from" or at < 2 or s.low[at] != "from":
        return False
    for v in range(at - 2, max(-1, at - 6), -1):
        if s.is_punct(v) or s.w[v].pos in ("ADP", "CCONJ", "SCONJ", "AUX"):
            return False
        if (verb_lemma(s.low[v]) in HOLDING_VERBS or s.verb(v) in HOLDING_VERBS) and s.w[v].pos in ("VERB", "NOUN") and \
                all(s.w[x].pos in ("DET", "ADJ", "NOUN", "NUM", "PRON") and s.w[x].tag != "PRP" for x in range(v + 1, at)) \
                and s.w[at - 1].pos == "NOUN":
            return True
    return False
