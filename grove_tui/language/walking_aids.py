"""What someone walks with or sits in is no place (round 69): "a frail pensioner on a zimmer frame
freezes", "Mavis, with her walking frame, inches to the lift", "a lad on crutches", "patients in
wheelchairs line up at the hatch", "a man on a mobility scooter". After "on", "in" or "with", a phrase
whose head is a walking aid says how the person goes, not where they are: never read as a place
(a world with a "standing frame" or a "wheelchairs" store is not meant) nor refused. A frame is an aid
only when said so ("zimmer frame", "walking frame", "her frame"): "on the climbing frame" is a place."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Heads that name a walking aid by themselves.
_AIDS = frozenset("zimmer zimmers walker walkers rollator rollators crutch crutches wheelchair wheelchairs "
                  "walking-stick walking-sticks cane canes".split())
# Heads that are an aid only after one of these words ("a zimmer frame", "her walking stick", "his frame").
_SAID_AIDS = {"frame": frozenset("zimmer walking her his their my your own".split()),
              "frames": frozenset("zimmer walking their".split()),
              "stick": frozenset("walking her his their my your own".split()),
              "sticks": frozenset("walking their".split()),
              "scooter": frozenset("mobility".split()),
              "scooters": frozenset("mobility".split()),
              "chair": frozenset("wheel powered electric".split())}
_PREPOSITIONS = frozenset({"on", "in", "with"})


def walking_aid(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k, after "on"/"in"/"with" at `at`, is a walking aid (module doc)."""
    if prep not in _PREPOSITIONS or at < 1 or k >= s.n or s.low[at] not in _PREPOSITIONS:
        return False
    j = k
    while j < s.n and (s.low[j] in lx.DETERMINERS or s.low[j] in ("her", "his", "their", "my", "your", "own")
                       or s.w[j].pos == "ADJ" and s.low[j] not in _AIDS):
        j += 1
    end = j
    while end < s.n and end < j + 3 and (s.w[end].pos in ("NOUN", "PROPN", "ADJ") or s.low[end] == "-" or
                                         s.w[end].tag == "VBG" and end + 1 < s.n and s.w[end + 1].pos == "NOUN") \
            and not s.is_punct(end) and s.low[end] not in lx.PLACE_PREPOSITIONS:
        end += 1  # "a zimmer frame", "her old walking stick"
    if end == k:
        return False
    for x in range(j, end - 1):
        if (s.low[x] in _AIDS or s.low[x] in _SAID_AIDS) and _verb_like(s, x + 1):
            end = x + 1  # "patients in wheelchairs queue at ...": the verb the parser took for a noun
            break
    head = s.low[end - 1]
    if head in _AIDS:
        aid = head not in ("walker", "walkers") or s.low[at] != "in"
    else:
        before = s.low[end - 2] if end - 2 >= k else ""
        aid = head in _SAID_AIDS and before in _SAID_AIDS[head]
    if not aid:
        return False
    if end < s.n and s.low[end].isalpha() and s.index.knows(lemma(s.low[end])) and \
            s.w[end].pos in ("NOUN", "PROPN") and not _verb_like(s, end):
        return False  # "in the wheelchair bay": a place's own name goes on
    if s.low[at] == "in":
        return s.w[at - 1].pos in ("NOUN", "PROPN", "PRON") or s.lemma(at - 1) in lx.PERSON_NOUNS or \
            s.low[at - 1] in ("sits", "sat", "sitting", "seated")
    return True


def _verb_like(s: Sentence, i: int) -> bool:
    """Whether word i is a verb, or a word the lexicon knows as a verb of what people do ("queue")."""
    return i < s.n and (s.w[i].pos in ("VERB", "AUX") or lx.INTENT_VERBS.get(verb_lemma(s.low[i])) is not None
                        or s.low[i] in ("line", "lined"))
