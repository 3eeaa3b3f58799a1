"""A purpose whose verb is also a word of a place's name (round 44): "comes along to the nail bar to check
tomorrow's rota" where the spa's reception is also "check-in", "pops over to book the squash court" where a
desk is "bookings", "walks to the office to print her boarding pass". The word after "to" is the parser's
verb in its base form and an object follows it (a determiner, a possessive, a day's "'s"): a purpose, not
the place the single word names. A name of more than the verb ("to check-in", "to the check-in desk") is
still a place.

A phrasal verb's object after its particle is the purpose's too (round 44): "to stock up on IPA for the
weekend", "to read up on the exhibits", "to catch up with her sister". After "stock up", "read up", "catch up",
"on" or "with" opens what the purpose is about, not where it is done; a place of the world there ("to
sign up at reception") is still a place.

A reason said with "because" after what people do is why they do it, their purpose (round 44): "nips over to
the photo booth because her provisional licence needs a picture", "walks to the counter because his parcel
needs weighing". The clause runs to the next punctuation or clause word; "because of" (a cause: "because of
the fire in the kitchen") is left to the rules of causes."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import phrase_lemmas

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_POSSESSIVE_ENDS = frozenset({"'s", "’s"})


def verb_with_an_object(s: Sentence, k: int) -> bool:
    """Whether the word at k (after "to") is a verb in its base form with its object after it, and no
    place's name runs on past it (module doc)."""
    if k + 1 >= s.n or s.w[k].tag != "VB" or s.hyphen_inside(k + 1):
        return False
    nxt = s.low[k + 1]
    opens_object = nxt in lx.DETERMINERS or (k + 2 < s.n and s.low[k + 2] in _POSSESSIVE_ENDS
                                             and s.w[k + 1].pos in ("NOUN", "PROPN"))
    if not opens_object:
        return False
    if nxt in lx.DETERMINERS:
        return True  # "to check the rota": no name runs on over a determiner
    said = tuple(phrase_lemmas(s.low[k:k + 2]))
    return len(said) < 2 or not any(phrase[:2] == said for entry in s.index.entries for phrase in entry.phrases)


# Particles of phrasal verbs whose object a preposition opens ("stock up on", "catch up with").
_PARTICLES = frozenset({"up", "out", "in", "down", "back", "off"})
_ABOUT = frozenset({"on", "with", "about", "of"})


def particle_object(s: Sentence, at: int) -> bool:
    """Whether the preposition at `at` opens the object of the phrasal verb right before it ("stock up on
    IPA"), and no place of the world (module doc)."""
    if at < 2 or at + 1 >= s.n or s.low[at] not in _ABOUT or s.low[at - 1] not in _PARTICLES:
        return False
    if s.w[at - 2].pos != "VERB" and s.w[at - 2].tag != "VB":
        return False
    said = phrase_lemmas([s.low[at + 1]])
    return not (said and s.index.knows(said[0]))


# Words that end a reason's clause: the next clause of the sentence.
_CLAUSE_ENDS = frozenset({"and", "but", "while", "whilst", "then", "so", "whereas", "meanwhile"})


def reason_end(s: Sentence, at: int) -> int | None:
    """The end (exclusive) of a reason said with "because" at `at`, after a verb of the clause; else None
    (module doc)."""
    if s.low[at] != "because" or at + 2 >= s.n or s.low[at + 1] == "of":
        return None
    if not any(s.w[k].pos == "VERB" for k in range(at) if s.w[k].sentence == s.w[at].sentence):
        return None  # "Because the lift is out, ...": a fronted cause, before what anyone does
    end = at + 1
    while end < s.n and not (s.is_punct(end) and not s.hyphen_inside(end)) and s.low[end] not in _CLAUSE_ENDS:
        end += 1
    return end if end > at + 2 else None
