"""Plural verbs of crowding the small parser takes for a collective noun (round 58): "eleven trainee
medics crowd round the station", "nine student nurses huddle around the desk". Read as a noun, "crowd"
heads the subject ("medics crowd", eleven crowds) and the group is counted eleven times over. A bare
verb of crowding right after a plural noun, with "round", "around" or "about" next and no verb before it
in its clause, is the clause's verb; the plural noun before it is its subject."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word
from grove_tui.language.subject_phrases import with_the_subject

_GATHERING = frozenset("crowd cluster throng huddle gather mass bunch swarm flock press mob congregate "
                       "jostle".split())
_ROUND = frozenset({"round", "around", "about"})
_VERBS = frozenset({"VERB", "AUX"})
_BREAKS = frozenset({",", ";", ":"})


def as_plural_gathering_verbs(words: list[Word]) -> list[Word]:
    """The parse with a bare verb of crowding, taken for a noun after a plural noun, made the verb (module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if w.lower not in _GATHERING or out[k].pos in _VERBS or k < 2 or k + 1 >= len(out):
            continue
        before, after = out[k - 1], out[k + 1]
        if after.lower not in _ROUND or after.sentence != w.sentence or before.sentence != w.sentence:
            continue
        if before.tag not in ("NNS", "NNPS") or before.pos not in ("NOUN", "PROPN"):
            continue  # "the crowd round the stage": a noun after its article
        first = k
        while first > 0 and out[first - 1].sentence == w.sentence and out[first - 1].lower not in _BREAKS:
            first -= 1
        if any(out[j].pos in _VERBS for j in range(first, k)):
            continue  # "they watch the fans crowd round": a verb already
        out = with_the_subject(out, k, k - 1)
        out[k] = replace(out[k], tag="VBP", lemma=w.lower)
        if after.pos != "ADP":
            out[k + 1] = replace(out[k + 1], pos="ADP", tag="IN", dep="prep", head=k)
    return out
