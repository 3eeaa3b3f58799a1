"""An aside in brackets that qualifies the group before it (round 18): "Three commuters (all men) wait
at ...", "two guards (both women) walk ...". The words inside name the same people again, all of
them, so they are no group of their own.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Words that open an aside about all of the group before it.
_ALL_OF_THEM = frozenset("all both each every mostly most".split())


def _aside(s: Sentence, before: Mention, m: Mention) -> bool:
    """Whether m is a bracketed aside right after `before`: "(all men)"."""
    opening = m.first - 1
    if opening < 1 or s.low[opening] not in ("(", "[", ",") or before.last != opening - 1:
        return False
    if s.low[m.first] not in _ALL_OF_THEM:
        return False
    closing = "," if s.low[opening] == "," else {"(": ")", "[": "]"}[s.low[opening]]
    return m.last + 1 < s.n and s.low[m.last + 1] == closing


def without_asides(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but the bracketed asides about the group before each."""
    dropped = [k for k in range(1, len(mentions)) if _aside(s, mentions[k - 1], mentions[k])]
    if not dropped or any(m.relation is not None for k, m in enumerate(mentions) if k not in dropped):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
