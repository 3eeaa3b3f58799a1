"""A thing carried from one place to another: "takes fresh towels from the laundry to room 108",
"fetches the post from reception to the office". After a verb of getting ("take", "fetch", "collect"),
"from" is where one stands to get a thing ("buys tickets from the machine"), unless a "to" follows
its place: then the thing is carried, and "from" is where the carrier starts."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.bare_places import bare_place_at
from grove_tui.language.cleared_out import cleared_from
from grove_tui.language.purpose_wanted import purpose_said
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

__all__ = ["bare_place_at", "carried_on", "from_is_where_got", "purpose_said"]  # read by language/clauses.py

_ONWARD = frozenset({"to", "into", "towards", "toward", "onto"})


def carried_on(s: Sentence, i: int) -> bool:
    """Whether the place after "from" at i is followed by where the thing goes ("... to room 108")."""
    end = s.phrase_end(i + 1)
    return end < s.n and s.low[end] in _ONWARD


def from_is_where_got(s: Sentence, i: int, own: Sequence[int]) -> bool:
    """Whether "from" at i is where a thing is got ("buy tickets from the machines"), a verb of getting
    a few words before it and no "to" after its place."""
    return (any(verb_lemma(s.low[k]) in lx.TRANSACTION_VERBS for k in own if i - 4 <= k < i) or
            cleared_from(s, i, own)) and not carried_on(s, i)
