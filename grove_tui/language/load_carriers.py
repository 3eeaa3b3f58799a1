"""What carries a load moved by hand is no place (round 53): "wheels a grandfather clock on a sack
truck from the warehouse to the yard", "carts the soil in a wheelbarrow to the beds", "brings the
drinks on a tray to table six". After a verb of moving a thing by hand, "on a"/"in a" and a noun of a
carrier (a truck, barrow, dolly, tray) that the world has no place of its own for names what the load
rides on: nothing to refuse, no place anyone is at.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.hauled_loads import LOAD_VERBS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Nouns of things a load is wheeled, pulled or carried on (the head of the phrase).
CARRIER_NOUNS = frozenset("""trolley truck cart barrow wheelbarrow dolly handcart wagon waggon sledge sled sleigh
    pallet skid tray platter stretcher gurney hod crate cradle""".split())
_MOVING_VERBS = LOAD_VERBS | lx.LEADING_VERBS | frozenset("carry bring deliver ferry shift lift hoist balance".split())
_REACH = 7  # words back from the preposition to the verb


def load_carrier(s: Sentence, at: int, lemmas: tuple[str, ...] | list[str]) -> bool:
    """Whether the phrase of "on"/"in" at `at` (lemmas) names what a load moved by hand rides on (module doc)."""
    if not lemmas or lemmas[-1] not in CARRIER_NOUNS or s.low[at] not in ("on", "in", "onto"):
        return False
    found = s.index.match(tuple(lemmas))
    if found is not None and found.exact:
        return False  # the world's own "loading trolley bay": a place
    for x in range(at - 1, max(-1, at - 1 - _REACH), -1):
        if s.is_punct(x) or s.low[x] in ("and", "but", "while", "then"):
            return False
        w = s.low[x]
        said = {verb_lemma(w), s.verb(x), w[:-1] if w.endswith("s") else w}  # "carts": a verb the lemmas miss
        if said & _MOVING_VERBS and s.w[x].pos in ("VERB", "NOUN", "PROPN"):
            return True
    return False
