"""Where people are bound for (round 24): "wheels a pensioner through security, bound for A2",
"Fourteen pensioners bound for Scarborough queue at stand C".

- The place after "bound for" is where they are going: a thing that names it ("A2" is the gate's
  desk's alias too) stands for the zone that holds it, the area they are bound for.
- "bound for <a name>" before a verb the parser took for a noun ("Scarborough queue", a compound):
  the noun is the sentence's verb when the sentence has no other, and the lexicon knows it as one.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_BOUND = frozenset({"bound", "headed"})


def bound_zone(s: Sentence, at: int, match: PlaceMatch) -> tuple[PlaceMatch, str] | None:
    """The zone of a thing said after "bound for" at `at`, with the reason; None otherwise."""
    if at < 1 or at >= s.n or s.low[at] != "for" or s.low[at - 1] not in _BOUND or match.kind == "zone":
        return None
    return PlaceMatch(match.zone, "zone", match.zone, match.score, match.exact), f"bound for {match.name}: its zone"


def bound_verbs(words: list[Word]) -> list[Word]:
    """The parse with the verb after "bound for <name>" tagged as one when the parser took it for the
    name's noun and the sentence has no other finite verb."""
    out = list(words)
    for k in range(1, len(words) - 2):
        if words[k].lower not in _BOUND or words[k + 1].lower != "for":
            continue
        j = k + 2
        while j < len(words) and (words[j].pos == "PROPN" or words[j].text[:1].isupper()):  # "Scarborough" (JJ)
            j += 1
        if j == k + 2 or j >= len(words) or words[j].pos != "NOUN" or verb_lemma(words[j].lower) not in lx.INTENT_VERBS:
            continue
        sentence = words[j].sentence
        if any(w.sentence == sentence and w.i != k and w.tag in ("VBP", "VBZ", "VBD") for w in words):
            continue
        out[j] = replace(words[j], pos="VERB", tag="VBZ" if words[j].lower.endswith("s") else "VBP", dep="ROOT",
                         head=j)
        prev = out[j - 1]
        if prev.dep == "compound" and prev.head == j:
            out[j - 1] = replace(prev, dep="pobj", head=k + 1)  # "Scarborough": the name bound for
    return out
