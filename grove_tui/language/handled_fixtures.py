"""Fixtures people busy themselves with (round 39): "two mechanics tinker with the pinsetters", "a
technician fiddles about with the projector", "a couple check out the SUV", "a nurse checks the drugs
trolley" (round 51). The verb says people are at
the thing they handle or look over, so its "with" ("out") is a place preposition of where they are, when
the words after it name a place of the world; "tinker with his phone" (no place) stays no place."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language.tokens import lemma, verb_lemma

# Verbs of handling a thing, taking "with" ("tinker with", "fiddle about with", "tamper with").
_WITH_VERBS = frozenset("tinker fiddle tamper fuss mess wrestle struggle potter faff fool muck play toy "
                        "busy".split())
# Verbs taking "out" or "over" for looking a thing over ("check out the SUV", "look over the boiler").
_LOOKING_VERBS = {"out": frozenset({"check", "scope", "suss"}), "over": frozenset({"look", "check", "go", "pore"})}
# Verbs of looking a thing over with no particle ("a nurse checks the drugs trolley", "a steward inspects
# the lifeboat"): they are the robot's verbs too ("inspects the robot"), but with a place of the world for
# their object, people are at the thing they check.
CHECKING_VERBS = frozenset("check inspect examine investigate recheck".split())
# Verbs of looking long at a thing, the robot's verbs of looking too ("photographs the robot"): with a
# fixture of the world for their object, people are at it ("eighteen engineers studying the whale skeleton").
STUDYING_VERBS = frozenset("study scrutinise scrutinize photograph film sketch".split())
_IN_BETWEEN = frozenset({"about", "around", "away", "themselves", "himself", "herself", "itself"})
_ARTICLES = frozenset({"the", "a", "an", "one", "some", "those", "these", "that", "this", "both", "all"})


def handled_at(low: Sequence[str], i: int, knows: Callable[[str], bool]) -> bool:
    """Whether the word at i ("with", "out", "over") is where people are, at the fixture they handle
    or look over: after such a verb (past "about", "around"), before a place of the world."""
    word = low[i]
    if word != "with" and word not in _LOOKING_VERBS:
        return False
    j = i - 1
    while j > 0 and word == "with" and low[j] in _IN_BETWEEN:
        j -= 1
    if j < 0:
        return False
    verbs = _WITH_VERBS if word == "with" else _LOOKING_VERBS[word]
    if _bases(low[j]).isdisjoint(verbs):
        return False
    k = i + 1
    while k < len(low) and low[k] in _ARTICLES | {"of"}:
        k += 1
    if k >= len(low) or k == i + 1 and word != "with":
        return False  # "check out" with no article ("check out early") is leaving
    return knows(lemma(low[k]))


def _bases(word: str) -> set[str]:
    """The base forms `word` may be inflected from by its ending ("tinkers", "fiddled", "messing")."""
    bases = {word, verb_lemma(word)}
    for ending in ("es", "s", "ing", "ed", "d"):
        if word.endswith(ending) and len(word) > len(ending) + 2:
            stem = word[: -len(ending)]
            bases |= {stem, stem + "e"}
            if len(stem) > 2 and stem[-1] == stem[-2]:
                bases.add(stem[:-1])  # "fussed": "fuss"; "tinned": "tin"
    return bases
