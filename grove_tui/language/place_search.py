"""A place searched for: "hunting for the aquarium", "in search of the physio gym", "looking for the
loos" (round 23). People searching for a place by its name ("the ...") go there, and a place the
world lacks is refused, as after "head for"; searching for "a" thing ("a spare trolley"), or for a thing
in a place ("looks for the remote in the lounge"), is no place searched for."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Verbs of searching, by their base form: "hunts for", "searching for", "went looking for".
SEARCH_VERBS = frozenset({"hunt", "search", "look", "scout", "seek"})
_GERUNDS = frozenset(f"{v}ing" for v in SEARCH_VERBS) | {"seeking"}
_WITHIN = frozenset({"in", "inside", "on", "at", "under", "behind", "around", "among"})


def searched_for(s: Sentence, i: int) -> bool:
    """Whether the "for" (or the "of" of "in search of") at i names a place searched for by its name."""
    if i + 1 >= s.n or s.low[i + 1] != "the":
        return False
    end = s.phrase_end(i + 1)
    if end < s.n and s.low[end] in _WITHIN:
        return False  # "looks for the remote in the living room": a thing, searched for in a place
    if s.low[i] == "of":
        return i >= 2 and tuple(s.low[i - 2:i]) == ("in", "search")
    j = i - 1
    while j >= 0 and s.w[j].pos == "ADV":
        j -= 1  # "hunting around for", "looking everywhere for"
    # "hunting" may be tagged a noun ("from penguin beach hunting for"): its verb's base form still searches
    return s.low[i] == "for" and j >= 0 and (s.w[j].lemma.lower() in SEARCH_VERBS or s.low[j] in SEARCH_VERBS
                                             or s.low[j] in _GERUNDS)
