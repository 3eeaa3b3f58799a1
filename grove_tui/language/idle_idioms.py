"""Verbs of idling about that the parser takes for nouns (round 69): "a pair of teens mess about on the
rowing machines", "a couple of kids mess around by the climbing frame" ("mess" an apposition of the
people, the sentence left with no verb). Right after a plural word for the people and before "about",
"around" or "round", such a word is the clause's verb; the place after it is where they idle."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word

# Verbs of idling that go with "about"/"around" ("mess about", "muck around", "lark about", "horse around").
_IDLING = frozenset("mess muck lark fool horse faff mooch potter monkey goof mill loaf laze footle bum".split())
_PARTICLES = frozenset({"about", "around", "round"})


def as_idle_verbs(words: list[Word]) -> list[Word]:
    """The parse with a verb of idling taken for a noun tagged as the verb it is (module doc)."""
    out = list(words)
    for k, w in enumerate(words[:-1]):
        if k == 0 or w.pos == "VERB" or w.lower not in _IDLING or words[k + 1].lower not in _PARTICLES:
            continue
        prev = words[k - 1]
        if prev.pos not in ("NOUN", "PROPN", "PRON") or prev.tag not in ("NNS", "NNPS", "PRP"):
            continue  # "the mess about ...": no people before it
        if any(x.pos in ("VERB", "AUX") and x.sentence == w.sentence and x.dep == "ROOT" for x in words):
            continue  # the sentence has its verb: leave the parser's reading
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower, dep="ROOT", head=k)
        for j, x in enumerate(words):
            if x.sentence == w.sentence and x.dep == "ROOT" and j != k:
                out[j] = replace(out[j], dep="nsubj", head=k)  # "a pair of teens": the subject
    return out
