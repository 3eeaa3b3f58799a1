"""Where people are from, said between them and their verb (round 54): "thirty infants from the village
school traipse across to the goats", "two porters from the day ward hurry to the cafeteria". A phrase
after "from" that follows a word for people and ends right before the clause's verb says who they are;
when the world lacks it, there is nothing to refuse (a place the world has is still read as usual).
A participle may describe the phrase's noun ("skippers from a visiting rally are lining up", round 55)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def _participle_before_noun(s: Sentence, i: int) -> bool:
    """A participle that describes the next noun ("a visiting rally", "a travelling circus")."""
    return s.w[i].tag in ("VBG", "VBN") and i + 1 < s.n and s.w[i + 1].pos in ("NOUN", "PROPN", "ADJ")


def who_they_are_from(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k, after "from" at `at`, sits between a word for people and their verb."""
    if prep != "from" or at < 1 or s.w[at - 1].pos not in ("NOUN", "PROPN") or \
            s.lemma(at - 1) not in lx.PERSON_NOUNS:
        return False
    end = k
    while end < s.n and (s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or s.low[end] in ("'s", "’s") or
                         _participle_before_noun(s, end)):
        end += 1
    return end > k and end < s.n and s.w[end].pos in ("VERB", "AUX") and s.w[end].tag != "VBG"
