"""People only watched by others (round 26): "Three or four spectators lean on the boards watching the
skaters go round", "two guards stand by the door watching the children run about". Those watched,
with no place of their own, are what the watchers look at, not a group of the scene.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.model import GroupReading
from grove_tui.language.sentence import Sentence

_WATCHING = frozenset("watch observe eye survey study regard admire".split())
_PLACE_PREPOSITIONS = frozenset("in into at to on onto by near from through across along past towards toward "
                                "inside outside around round behind beside".split())

_CLAUSE_ENDS = frozenset(", ; : . and but while whilst as then".split())


def _watched(s: Sentence, m: Mention) -> bool:
    """Whether the mention is only the object of someone's watching, or the subject of a bare verb
    after it ("watching the skaters go round"), with no place phrase of its own."""
    head = next((k for k in range(m.first, m.last + 1) if not m.first <= s.w[k].head <= m.last), None)
    if head is None:
        return False
    w = s.w[head]
    if w.dep == "dobj" and s.w[w.head].lemma in _WATCHING and w.head < m.first:
        clause = None
    elif w.dep == "nsubj" and s.w[w.head].dep in ("ccomp", "xcomp") and s.w[w.head].tag == "VB" and \
            s.w[s.w[w.head].head].lemma in _WATCHING and s.w[w.head].head < m.first:
        clause = w.head
    else:
        return False
    # a place of their own: "watching the skaters go round the rink" sets them on the rink
    for k in range(m.last + 1, s.n - 1):
        if s.low[k] in _CLAUSE_ENDS:
            break
        if s.low[k] in _PLACE_PREPOSITIONS and s.w[k + 1].pos in ("DET", "NOUN", "PROPN", "ADJ", "NUM"):
            return False
    return True


def without_watched(s: Sentence, mentions: Sequence[Mention],
                    read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups but those only watched by an earlier one (see the module doc)."""
    if len(read) < 2 or len(mentions) != len(read) or any(g.relation is not None for g in read):
        return tuple(read)
    return tuple(g for k, (m, g) in enumerate(zip(mentions, read)) if k == 0 or not _watched(s, m))
