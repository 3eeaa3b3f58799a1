"""Someone who moves another person along, said in an aside set off by commas (round 40): "A porter,
pushing a woman in labour in a wheelchair, hurries to ...", "a nurse, wheeling an old man, heads to
...". The comma stands between the person and the verb of taking someone along; the person moved is a
group of their own that goes where the mover goes, as without the commas."""

from __future__ import annotations

from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence


def aside_leader(s: Sentence, people: People, k: int) -> int | None:
    """The person word before the comma at `k` when an aside about them opens there with a verb in
    "-ing": "A porter, pushing ...", "the nurse, wheeling ..."; else None ("the lifts, pushing ...":
    no person before the comma)."""
    if k < 1 or s.low[k] != "," or k + 1 >= s.n or s.w[k + 1].tag != "VBG":
        return None
    j = k - 1
    return j if people.is_person_noun(j) else None
