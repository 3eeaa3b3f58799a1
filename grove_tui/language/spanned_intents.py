"""Intents said by a phrase with words in between (round 72). Talk said by what is swapped, with a word
or two of what it is about ("swap holiday stories", "trade old war stories", "compare their exam notes"):
conversing, as "swap stories" is. People who snake or stretch back from a counter or a desk ("a dozen
patients snake back from the pharmacy hatch", "shoppers stretch back along the tills"): a queue whose
head is at that place, as "a queue snakes back from the desk" is."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_SWAPPING = frozenset("swap swaps swapped swapping exchange exchanges exchanged exchanging trade trades traded "
                      "trading share shares shared sharing compare compares compared comparing".split())
_TALK = frozenset("stories notes gossip news anecdotes jokes tales yarns memories".split())
_SNAKING = frozenset("snake snakes snaked snaking stretch stretches stretched stretching".split())
_FROM = frozenset({"from", "past", "along"})


def spanned_intent(s: Sentence, i: int) -> tuple[tuple[str, ...], str] | None:
    """The phrase from the verb at i and its intent, when it is one of the module doc's."""
    low = s.low
    if low[i] in _SWAPPING:
        for k in range(i + 2, min(i + 4, s.n)):  # one or two words of what the talk is about
            if low[k] in _TALK:
                between = range(i + 1, k)
                if all(s.w[x].pos in ("ADJ", "NOUN", "PROPN", "DET", "PRON", "NUM") and not s.is_punct(x)
                       for x in between):
                    return tuple(low[i:k + 1]), "converse"
                return None
    if low[i] in _SNAKING and i + 2 < s.n and low[i + 1] == "back" and low[i + 2] in _FROM:
        return tuple(low[i:i + 2]), "queue"
    return None
