"""People "outside" a room set against others already in the zone outside it (round 47): "A dozen teens
lounge in the booths and a handful more hang about outside the chicken shop", "Two kids play on the
benches while their dad waits outside the ticket office". "Outside X" is otherwise the zone X's door
opens to (language/place_outside.py); but when an earlier clause of the sentence already put people in
that zone (or at a thing of it), reading the second group there too would erase the contrast the
sentence draws. The second group is then at X itself, the nearest place the sentence tells apart.
"In the corridor outside the ballroom", one phrase, is no contrast: a clause must lie between them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language.sentence import Sentence

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place

# Words that open a second clause between the two places ("... in the booths and a handful more ...").
_CLAUSE_WORDS = frozenset({"and", "while", "whilst", "but", "as", "whereas"})


def outside_contrasted(s: Sentence, at: int, outside: str, earlier: Sequence[Place]) -> bool:
    """Whether "outside"/"in front of" at `at`, read as the zone `outside`, is set against an earlier
    clause's place in that very zone."""
    if s.low[at] not in ("outside", "in"):
        return False
    for p in earlier:
        if p.match is None or p.index >= at or s.w[p.index].sentence != s.w[at].sentence:
            continue
        if p.prep not in ("in", "at", "on", "by", "inside", "near", "beside", "around"):
            continue
        if (p.match.zone or p.match.name) != outside:
            continue
        if any(s.low[x] in _CLAUSE_WORDS or s.low[x] == "," for x in range(max(p.end, p.index + 1), at)):
            return True
    return False
