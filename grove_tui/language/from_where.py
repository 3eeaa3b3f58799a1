"""Where a place said by what is done there ends when it is the start of a walk: "from where the mail gets
sorted | to the vans", "from where the coaches park | into the hall". The clause after "from where" is the
origin only; a "to" (or "into", "towards") that then names a place by a determiner starts the
destination, so the destination's words are not read as part of the activity (round 49). A particle of
the way before it starts the destination too ("from where the furniture gets mended | across to the
hall", "over to", "back into"; round 72)."""

from __future__ import annotations

from collections.abc import Sequence

_TO = frozenset({"to", "into", "towards", "toward", "onto"})
_PARTICLES = frozenset("across over back up down round around through along out".split())
_DETERMINERS = frozenset({"the", "a", "an", "their", "his", "her", "its", "our", "my", "your", "this", "that"})


def from_where_ends(low: Sequence[str], first: int, at: int) -> bool:
    """Whether the word at `at` ends the clause that starts at `first` (after its marker, "where"), because
    the clause is said after "from" ("from where", "from the room where") and the word starts the
    destination ("to the vans")."""
    k = at + 1 if low[at] in _PARTICLES and at + 1 < len(low) and low[at + 1] in _TO else at
    if not (at > first + 1 and low[k] in _TO and k + 1 < len(low) and low[k + 1] in _DETERMINERS):
        return False
    if first >= 1 and low[first - 1] in ("where", "wherever", "that", "which"):
        return "from" in low[max(0, first - 5):first - 1]  # "from where", "from the place where"
    return "from" in low[max(0, first - 4):first]  # "from the spot they leave bags"
