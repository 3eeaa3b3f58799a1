"""Some of a collective, said with "of" (round 32): "two of the crew dash out", "three of the team
wait", "a few of the staff leave", "two of the cast walk off". A collective of the people working or
performing together (a crew, a team, the staff, the cast) is no group of its own in the scene when
only a part of it is said to be there: the part is the one group, as many as said. A counted whole
("two of the six porters") or a plural person noun ("two of the guards") keeps its whole. So does not a
whole said as someone's own with no count (round 44: "three of her doctoral students", "six of their
parents"): the others of it are somewhere else, only the part is there."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.counts import Quantifier
    from grove_tui.language.sentence import Sentence

_OWNERS = frozenset({"their", "his", "her", "our", "my", "your"})

# Collectives named by what their members do together, each member one of them.
MEMBER_COLLECTIVES = frozenset("""crew team staff cast squad band gang troupe choir troop shift delegation
    committee panel workforce personnel orchestra ensemble chorus posse audience congregation""".split())


def collective_head(s: Sentence, start: int) -> int | None:
    """Word `start` when it is a member collective with no person noun after it ("of the cast walk"),
    else None."""
    if start >= s.n or s.lemma(start) not in MEMBER_COLLECTIVES or s.w[start].pos not in ("NOUN", "PROPN"):
        return None
    nxt = start + 1
    if nxt < s.n and s.w[nxt].pos in ("NOUN", "PROPN") and s.w[nxt].dep == "compound":
        return None  # "of the crew room": a place
    return start


def whole_unsaid(s: Sentence, of_at: int, head: int, counted_whole: bool) -> bool:
    """Whether the whole of "two of the crew" is left out of the scene: a member collective, singular,
    after "the" (or "our", "their") and the words naming its kind ("the kitchen staff"), with no count
    of its own."""
    return (not counted_whole and s.lemma(head) in MEMBER_COLLECTIVES and s.w[head].tag in ("NN", "NNP")
            and head >= of_at + 2 and all(s.w[j].pos in ("NOUN", "PROPN", "ADJ") for j in range(of_at + 2, head)))


def owned_whole(s: Sentence, k: int, inner: Quantifier | None) -> bool:
    """Whether the whole of "six of their parents" (its word at k) is someone's own people, with no count
    of its own: left out of the scene, the part is the group."""
    return (s.low[k] in _OWNERS or s.low[k] in ("'s", "’s")) and inner is None  # "two of Tom's sons"
