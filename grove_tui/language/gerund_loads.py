"""A gerund that names a load is no verb (round 69): "Mum carries a basket of washing off the balcony",
"a porter lugs a bag of ironing out of the laundry". After a noun and "of", the parser's "-ing" word is
the thing in the basket or bag, and the particle it was given ("off", "out") is the preposition of the
place the carrier leaves: no verb acting on the place as its object ("washing off the balcony"), no
verb of work with its particle (worked_things.py)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.parser import Word
    from grove_tui.language.sentence import Sentence


def load_gerund(words: Sequence[Word], i: int) -> bool:
    """Whether word i is an "-ing" word after a noun and "of" ("a basket of washing")."""
    return 2 <= i < len(words) and words[i].tag == "VBG" and words[i - 1].lower == "of" and words[i - 2].pos == "NOUN"


def gerund_load(s: Sentence, i: int) -> bool:
    """load_gerund, in a sentence."""
    return load_gerund(s.w, i)
