"""Taking a thing off a place is going from there with it (round 69): "Dad takes the bins off the patio",
"a porter takes the trolley off the ward", "a keeper carts the hay bales off the yard". A verb of taking a
thing along (no person: someone moved by another is read elsewhere), its object, then "off" and a place
the world knows, is the taker walking from that place, as "takes her lunch to the lounge" walks there
(going_verbs.py); "takes the lid off the pan" names no place and stays what it was."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def takes_a_thing_off(s: Sentence, i: int) -> bool:
    """Whether the verb at i takes a thing off a place the world knows (module doc)."""
    seen_noun = False
    for x in range(i + 1, min(i + 7, s.n)):
        if s.is_punct(x) or s.lemma(x) in lx.PERSON_NOUNS or s.low[x] in lx.PERSON_NOUNS:
            return False
        if s.low[x] == "off" and seen_noun:
            k = s.skip(x + 1, lx.DETERMINERS)
            return k < s.n and s.index.knows(s.lemma(k))
        if s.low[x] in lx.PLACE_PREPOSITIONS:
            return False
        seen_noun = seen_noun or s.w[x].pos in ("NOUN", "PROPN")
    return False
