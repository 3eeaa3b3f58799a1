"""Verbs of crowding the small parser takes for plural nouns (round 33): "a class of twenty crowds about
the robot", "a party of ten clusters round the robot", "a class of thirty throngs around it", "the
group huddles round the bot". Read as nouns, "twenty crowds" is the subject's tail and the clause has
no verb, so the group only waits. An "-s" verb of crowding, right before "round", "around" or "about",
with no verb before it in its sentence, is the phrase's verb; its subject is the phrase's head (the
noun before "of", or the word before the verb)."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word
from grove_tui.language.subject_phrases import with_the_subject

_GATHERING = frozenset("crowds clusters throngs huddles gathers masses bunches swarms flocks presses "
                       "mobs congregates jostles".split())
_ROUND = frozenset({"round", "around", "about"})
_VERBS = frozenset({"VERB", "AUX"})


def as_gathering_verbs(words: list[Word]) -> list[Word]:
    """The parse with a verb of crowding, taken for a plural noun, tagged a verb (module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if w.lower not in _GATHERING or out[k].pos in _VERBS or k == 0 or k + 1 >= len(out):
            continue
        if out[k + 1].lower not in _ROUND or out[k + 1].sentence != w.sentence:
            continue
        first = k
        while first > 0 and out[first - 1].sentence == w.sentence and out[first - 1].lower not in (",", ";", ":"):
            first -= 1
        before = range(first, k)
        if not before or any(out[j].pos in _VERBS for j in before):
            continue  # "they wait where the crowds round the stage are": a verb before it
        of = next((j for j in before if out[j].lower == "of"), None)
        heads = [j for j in range(first, of if of is not None else k) if out[j].pos in ("NOUN", "PROPN", "NUM")]
        if not heads:
            continue
        out = with_the_subject(out, k, heads[-1])
        if of is not None and of + 1 < k and out[of + 1].pos == "NUM":  # "of twenty": the count, not "twenty crowds"
            out[of + 1] = replace(out[of + 1], dep="pobj", head=of)
    return out


def gathering_verb(words: list[Word], k: int) -> bool:
    """Whether the word at k is a verb of crowding this pass tagged (no person noun: "twenty crowds")."""
    w = words[k]
    return w.lower in _GATHERING and w.pos == "VERB" and w.dep == "ROOT"
