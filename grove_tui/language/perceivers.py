"""Someone who only perceives or reports what sets the scene off (round 18): "someone smells burning
in the lab and all fifteen researchers leave", "a guard notices smoke in the computer lab and the
students evacuate". The perceiver does nothing of their own in the scene, so they are no group; the
place of the perception is where the people who leave start from.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.mention import Mention
from grove_tui.language.model import GroupReading
from grove_tui.language.sentence import Sentence
from grove_tui.language.watching_posts import perceives_nothing

# Verbs of perceiving or reporting something, not of going anywhere.
PERCEIVING = frozenset("smell notice spot see hear sense detect discover report realise realize witness "
                       "observe sniff glimpse".split())
# What the people who leave do.
_LEAVING = frozenset({"evacuate", "walk"})


def _only_perceives(s: Sentence, m: Mention) -> bool:
    """Whether the person phrase is the subject of a perceiving verb and of no other verb of its own."""
    head = next((k for k in range(m.first, m.last + 1) if s.w[k].dep in ("nsubj", "nsubjpass")
                 and not m.first <= s.w[k].head <= m.last), None)
    # the small parser may read the person as a modifier of its verb ("a technician spots")
    verb = s.w[head].head if head is not None else m.last + 1
    if verb >= s.n:
        return False
    if s.w[verb].lemma not in PERCEIVING or s.w[verb].pos != "VERB":
        return False
    if perceives_nothing(s, verb):
        return False  # "two instructors spotting by the cave": at a post, no thing perceived
    # "notices smoke and walks out": a second verb of theirs, with no subject of its own
    for w in s.w:
        if w.head == verb and w.dep == "conj" and w.pos in ("VERB", "AUX") and \
                not any(x.head == w.i and x.dep in ("nsubj", "nsubjpass") for x in s.w):
            return False
    return True


def without_perceivers(s: Sentence, mentions: Sequence[Mention],
                       read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups without those who only perceive (when others are there); the place of the perception
    is the start of the next group who leave from nowhere said."""
    if len(read) < 2 or len(mentions) > len(read):
        return tuple(read)
    dropped: list[int] = []
    out = list(read)
    for k, m in enumerate(mentions):
        if not _only_perceives(s, m) or any((g.relation or "").endswith(f":{k}") for g in read):
            continue
        where = read[k].location or read[k].start
        later = next((j for j in range(k + 1, len(read)) if j not in dropped), None)
        if later is None:
            continue
        g = out[later]
        if where is not None and g.intent in _LEAVING and g.start is None and g.location is None:
            out[later] = replace(g, start=where)
        dropped.append(k)
    if not dropped or len(dropped) == len(read):
        return tuple(read)
    new_index = {old: new for new, old in enumerate(k for k in range(len(out)) if k not in dropped)}
    kept: list[GroupReading] = []
    for old, g in enumerate(out):
        if old in dropped:
            continue
        kind, _, parent = (g.relation or "").partition(":")
        if parent.isdigit():
            g = replace(g, relation=f"{kind}:{new_index[int(parent)]}" if int(parent) in new_index else None)
        kept.append(g)
    return tuple(kept)
