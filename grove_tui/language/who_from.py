"""Where people are from, said between them and their verb (round 54): "thirty infants from the village
school traipse across to the goats", "two porters from the day ward hurry to the cafeteria". A phrase
after "from" that follows a word for people and ends right before the clause's verb says who they are;
when the world lacks it, there is nothing to refuse (a place the world has is still read as usual).
A participle may describe the phrase's noun ("skippers from a visiting rally are lining up", round 55).
Round 69: the parser may read the verb as the phrase's last noun ("pupils from a village primary file
out of the cloakroom", "cubs from the local pack troop into the hall"): a word the lexicon knows as a
verb of going, right before a particle or a place preposition, is the verb."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words after a verb of going misread as a noun that show it is the verb ("file out", "troop into").
_AFTER_GOING = frozenset("out in into across past through along off up down over back round around away "
                         "onto towards toward to from".split())


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
    if end > k + 1 and end < s.n and s.w[end - 1].pos == "NOUN" and s.low[end] in _AFTER_GOING and \
            lx.INTENT_VERBS.get(verb_lemma(s.low[end - 1])) in ("walk", "wander", "follow"):
        return True  # "from a village primary file out of": "file" is the verb
    return end > k and end < s.n and s.w[end].pos in ("VERB", "AUX") and s.w[end].tag != "VBG"
