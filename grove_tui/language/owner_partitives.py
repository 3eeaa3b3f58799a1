"""A named owner in a partitive (round 58): "both of Mrs Patel's granddaughters", "two of Mr Shah's
sons", "all three of Dr Ahmed's students". The owner's name and its "'s" stand where "her" stands in
"both of her granddaughters": the people after it are the owner's own, one group, not a part and a
whole. The name is one to three capitalised words ("Mrs Patel", "Tom"), then the possessive."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_POSSESSIVES = frozenset({"'s", "’s", "'", "’"})


def named_owner_end(s: Sentence, k: int) -> int | None:
    """The index of the "'s" after a name starting at k ("Mrs Patel's"), or None."""
    j = k
    while j < s.n and j < k + 3 and s.w[j].text[:1].isupper() and s.w[j].pos in ("PROPN", "NOUN") \
            and s.low[j] not in _POSSESSIVES:
        j += 1
    if j == k or j + 1 >= s.n or s.low[j] not in _POSSESSIVES:
        return None
    return j
