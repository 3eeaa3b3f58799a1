"""What the robot has to do (round 18): "the robot needs to wait by the pharmacy", "has to patrol the
hall", "is supposed to wait outside the cinema", "is meant to follow them", "gotta wait @ the desk".
The verb after such a phrase is the robot's task; the phrase's own verb ("need", "have", "be") is
none."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Phrases of obligation or plan, by the base form of their words, each ending before the task verb.
_OBLIGATIONS = (("need", "to"), ("have", "to"), ("got", "to"), ("get", "to"), ("got", "ta"), ("gotta",), ("ought", "to"),
                ("be", "supposed", "to"), ("be", "meant", "to"), ("be", "due", "to"), ("be", "going", "to"),
                ("be", "gonna"), ("be", "to"), ("be", "required", "to"), ("be", "expected", "to"),
                ("be", "told", "to"), ("be", "asked", "to"), ("be", "programmed", "to"), ("be", "set", "to"),
                ("be", "scheduled", "to"), ("be", "instructed", "to"))

# The first word's forms ("needs", "has", "is", "'s"), which the lexicon's verbs do not list.
_BASE = {"needs": "need", "needed": "need", "has": "have", "had": "have", "is": "be", "are": "be", "was": "be",
         "were": "be", "'s": "be", "’s": "be", "gets": "get", "will": "be"}


def obligation_verb(s: Sentence, j: int) -> int | None:
    """The index of the task verb after an obligation phrase starting at j ("needs to wait": the
    "wait"), or None when no such phrase starts there."""
    for phrase in _OBLIGATIONS:
        end = j + len(phrase)
        if end >= s.n:
            continue
        words = tuple(_BASE.get(w, w) if k == 0 else w for k, w in enumerate(s.low[j:end]))
        if words == phrase and s.verb_follows(end):
            return end
    return None


def before_obligation(s: Sentence, verb: int) -> int:
    """The word before an obligation phrase or a modal that ends right before the verb at `verb`
    ("the robot is meant to follow", "the robot should follow": the robot's word); `verb - 1`
    when none does."""
    for j in range(max(0, verb - 3), verb):
        if obligation_verb(s, j) == verb:
            return j - 1
    if verb >= 1 and s.w[verb - 1].tag == "MD":
        return verb - 2  # "should", "must", "will"
    return verb - 1
