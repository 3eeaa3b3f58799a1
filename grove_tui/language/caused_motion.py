"""Someone moved along by a verb no list of leading verbs has (round 23): "a nurse trundles a
patient on a trolley out of X-ray", "two officers march a suspect into interview room 1". A verb of
a person whose object is a person, then (after what that person rides in: "on a trolley", "in his
wheelchair") a word that starts a route, takes the person along that route: the object is a second
group that follows. So is a bare given name there ("a carer guides Doris from the lounge"): a word
the parser calls a proper noun, written with a capital (a world may name a room after it), is a
person when a verb of a person takes it along a route."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.route_particles import route_start
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words that start the route someone is taken along ("from ward A", "out of X-ray", "back to ...").
ROUTE_WORDS = frozenset("from out into onto to back through across towards toward".split())
# Verbs of a person with a person as object that move nobody ("sees a patient from the window",
# "calls a patient into room 2": sent, not taken; "follows a man out of ...": the subject goes after).
_NOT_TAKING = (lx.SENT_VERBS | lx.FOLLOWING_VERBS | lx.PERCEPTION_VERBS | lx.HUMAN_SUBJECT_VERBS | lx.TELLING_VERBS
               | lx.NEGATING_VERBS | lx.SEEN_OBJECT_VERBS | lx.SENDING_VERBS - lx.LEADING_VERBS
               | frozenset("meet see visit find watch avoid greet phone ring text email serve treat "
                           "expect await invite recognise recognize pass".split()))
_OWNERS = frozenset({"a", "an", "the", "his", "her", "their", "its", "my", "our"})


def route_after(s: Sentence, head: int) -> bool:
    """Whether a route starts right after the person at `head` (and the rest of a name, and what
    the person rides in): "Mr Reid out of ...", "a patient on a trolley out of ..."."""
    k = head + 1
    while k < s.n and s.w[k].pos == "PROPN" and s.w[k].text[:1].isupper():
        k += 1  # "Edith Baxter"
    if k + 1 < s.n and s.low[k] in ("in", "on"):
        j = s.skip(k + 1, _OWNERS)
        while j < s.n and s.w[j].pos == "ADJ":
            j += 1
        if j < s.n and s.lemma(j) in lx.CARRYING_THINGS:
            k = j + 1  # "in his wheelchair", "on a trolley"
    k = route_start(s, k)  # "Dorothy, on her frame, down to the lounge"
    if k + 1 >= s.n or s.low[k] not in ROUTE_WORDS:
        return False
    return s.w[k + 1].tag not in ("VB", "VBG")  # not "from leaving", "to wait"


def moves_along(s: Sentence, p: int, head: int) -> bool:
    """Whether the verb at p, a person's, takes the person at `head` (its object) along a route."""
    return taking_verb(s, p) and route_after(s, head)


def taking_verb(s: Sentence, p: int) -> bool:
    """Whether word p is a verb that may take its object along ("hustles", "trundles", "wheels")."""
    return verb_lemma(s.low[p]) in lx.LEADING_VERBS or (s.w[p].pos == "VERB" and s.verb(p) not in _NOT_TAKING)


def taken_name(s: Sentence, i: int) -> bool:
    """Whether word i is a bare given name a person's verb right before takes along a route ("a
    carer guides Doris from the lounge to the garden"); the caller checks the subject is a person."""
    w = s.w[i]
    if w.pos != "PROPN" or i < 2 or not w.text[:1].isupper() or not s.low[i].isalpha() or \
            s.low[i] in lx.ROBOT_WORDS:
        return False
    return (verb_lemma(s.low[i - 1]) in lx.LEADING_VERBS or moves_along(s, i - 1, i)) and route_after(s, i)
