"""What a carried thing holds is no activity ("lug a bag of shopping to the boat", "carry a basket of washing
out to the line"): an "-ing" word that is the object of "of" after a thing's noun is that thing's contents,
not what the people do there, so it casts no intent (language/clauses.py, the verb candidates)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def contents_of_thing(s: Sentence, i: int) -> bool:
    """Whether the word at i is what a thing holds, "of" after a non-person noun ("a bag of shopping")."""
    if i < 2 or s.low[i - 1] != "of" or not s.low[i].endswith("ing"):
        return False
    head = s.w[i - 2]
    return head.pos == "NOUN" and not s.is_punct(i - 2) and s.w[i - 2].dep != "nsubj"
