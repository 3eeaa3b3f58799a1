"""A list of people each placed on their own ("In dispatch: a marshal at the transport desk, four
loaders at the outbound pallets and a driver walking to the dock doors"): a participle right after
the last item's person ("a driver walking to ...") is that item's, not a verb the items before it
share, when each of them is said to be somewhere of its own."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.mention import Mention
    from grove_tui.language.sentence import Sentence


def own_participle(s: Sentence, m: Mention) -> bool:
    """Whether the word after mention m is a participle that describes it ("a driver walking to")."""
    nxt = m.last + 1
    if nxt < s.n and s.low[nxt] == "and":  # "..., pilot and co-pilot walking to B1": the pair's participle
        nxt += 1
        while nxt < s.n and nxt <= m.last + 6 and (s.w[nxt].pos in ("DET", "ADJ", "NOUN", "PROPN") or s.low[nxt] == "-") \
                and s.w[nxt].tag != "VBG":
            nxt += 1
    return 0 < m.first and nxt < s.n and s.w[nxt].tag == "VBG" and s.low[m.first - 1] in ("and", ",")
