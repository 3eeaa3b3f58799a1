"""How a clause's people move: their pace and whether they keep together.

A word of speed sets the pace ("hurries", "briskly", "dawdles"), but not when it is negated ("don't
run", "without hurrying", "not rushing": the plain pace) nor when it is a noun of the scenario itself
("for the rest of the run"). "In no hurry" and "no rush" are slow. A phrase of pace says it outright
with words the verb lists lack ("at a snail's pace", "at a brisk pace", "at a jog", "at full speed").
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words that negate a word of speed a few words on ("don't run", "never rushes", "without hurrying").
_NEGATIONS = frozenset({"not", "n't", "never", "without", "no", "nor", "dont", "don't", "stop", "stops"})
# What follows "at a"/"at" in a phrase of pace, by the pace it says.
_FAST_PACES = frozenset("brisk quick rapid fast good cracking swift jog run trot sprint gallop canter full "
                        "breakneck top double jogging running".split())
_SLOW_PACES = frozenset("snail slow leisurely gentle stroll crawl walking sedate relaxed steady shuffle "
                        "dawdle easy".split())
_PACE_NOUNS = frozenset({"pace", "speed", "clip", "rate", "tilt", "pelt", "jog", "trot", "run", "sprint", "crawl",
                         "stroll", "gallop", "canter", "shuffle", "dawdle"})
# A word of speed that is only the scenario or a spell of time after these ("the rest of the run").
_RUN_DETERMINERS = frozenset({"the", "this", "whole", "entire", "of"})
# Jogging is quicker than walking; it is no intent of its own beyond walking (the lexicon's).
_MORE_FAST = frozenset({"jog", "jogging", "jogs", "scurry", "scurries", "scurrying", "bustle", "bustles"}) | frozenset(
    "stampede hurtle careen pelt hotfoot hare".split())  # "stampede into the store": a rush


def _negated(s: Sentence, i: int, own: set[int]) -> bool:
    return any(k in own and s.low[k] in _NEGATIONS for k in range(max(0, i - 3), i))


def _pace_phrase(s: Sentence, own: Sequence[int]) -> str | None:
    """The pace an "at ... pace" phrase says ("at a snail's pace", "at a brisk pace", "at a jog")."""
    for i in own:
        if s.low[i] != "at":
            continue
        words = [s.low[k] for k in range(i + 1, min(i + 5, s.n))]
        end = next((t for t, w in enumerate(words) if w in _PACE_NOUNS), None)
        if end is None:
            continue
        said = {w for w in words[:end + 1] if w not in ("a", "an", "'s", "s")}
        if said & _SLOW_PACES:
            return "slow"
        if said & _FAST_PACES:
            return "fast"
    return None


def pace(s: Sentence, own: Sequence[int]) -> str:
    """The pace a clause's words say: "fast", "slow" or "normal"."""
    ownset = set(own)
    said = _pace_phrase(s, own)
    if said is not None:
        return said
    trigrams = s.trigrams(own)
    if ("in", "no", "hurry") in trigrams or any(s.low[i] == "no" and s.low[i + 1:i + 2] == ["rush"] for i in own):
        return "slow"
    kept = [i for i in own if not _negated(s, i, ownset)
            and not (s.low[i] == "run" and i > 0 and s.low[i - 1] in _RUN_DETERMINERS)]
    lemmas = {verb_lemma(s.low[i]) for i in kept} | {s.low[i] for i in kept}
    lemmas |= {w[:-3] + "y" if w.endswith("ies") else w[:-1] for w in lemmas if w.endswith("s")}  # "dawdles"
    if lemmas & (lx.FAST_WORDS | _MORE_FAST) or ("in", "a", "hurry") in trigrams:
        return "fast"
    if lemmas & lx.SLOW_WORDS or ("take", "their", "time") in {(verb_lemma(t[0]), *t[1:]) for t in trigrams}:
        return "slow"
    return "normal"


def together(s: Sentence, own: Sequence[int]) -> bool:
    """Whether the clause says its people keep together ("together", "as a group", "side by side")."""
    return bool({s.low[i] for i in own} & lx.TOGETHER_WORDS) or any(i in s.together_phrases for i in own)
