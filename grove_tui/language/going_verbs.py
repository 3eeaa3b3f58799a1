"""Verbs of going the lexicon's lists read as waiting or wandering (round 18).

- "make for the café" is going there, as "head for" is;
- "takes her lunch to the staff room", "hauls the shopping through to the car park": taking a thing
  (not a person: someone moved by another is read elsewhere) to a place is the person walking there;
- a verb of wandering with where it goes ("strolls over to", "ambles across to", "wanders over to
  the pond") is a slow walk there, even after another verb of going ("steps out and strolls over
  to ..."); "mooch around", "potter about" stay wandering.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.posture_verbs import posture_intent
from grove_tui.language.sentence import Sentence
from grove_tui.language.taken_off import takes_a_thing_off
from grove_tui.language.tokens import verb_lemma

# Verbs of wandering the lexicon lacks ("mooch around the galleries").
MORE_WANDER_VERBS = frozenset("mooch mosey moseys mooching moseying mooched".split())
# Verbs of taking a thing along whose object is a thing carried, not a way ("takes her lunch to").
THING_TAKING_VERBS = frozenset("take cart ferry wheel tote".split())
# Particles between a verb of going and "to" ("strolls over to", "ambles across to", "through to").
_PARTICLES = frozenset("over across up down along back through round around off on out".split())
_TO = frozenset({"to", "into", "towards", "toward", "onto"})
_OBJECT_PRONOUNS = frozenset({"him", "them", "us", "me", "you", "everyone", "everybody"})


def more_verb_intent(s: Sentence, i: int) -> str | None:
    """The intent of a verb of going the lexicon lacks: "mooch" wanders; "take THING to X" walks."""
    v = s.verb(i)
    if v in MORE_WANDER_VERBS or s.low[i] in MORE_WANDER_VERBS:
        return "wander"
    if v in THING_TAKING_VERBS and (carries_a_thing_to(s, i) or takes_a_thing_off(s, i)):
        return "walk"  # "takes the bins off the patio": from there (taken_off.py)
    return posture_intent(s, i)  # "sprawl across the sofas", "loll on the beanbags"


def carries_a_thing_to(s: Sentence, i: int) -> bool:
    """Whether the verb at i takes a thing (no person) to a place: "takes her lunch to the lounge",
    "takes the post through to reception"."""
    k = i + 1
    if k >= s.n or s.low[k] in _OBJECT_PRONOUNS or (s.low[k] == "her" and s.w[k].tag == "PRP"):
        return False
    if any(s.w[x].head == i and s.w[x].dep.startswith("nsubj") and s.low[x] in lx.ROBOT_WORDS for x in range(i)):
        return False  # "the robot takes clean sheets to the spa": the robot's own task
    seen_noun = False
    for x in range(k, min(k + 6, s.n)):
        w = s.low[x]
        if w in _TO and s.low[x - 1] in ("next", "close", "up", "due"):
            return False  # "takes a seat next to the window": where, not whither
        if w in _TO or (w in _PARTICLES and x + 1 < s.n and s.low[x + 1] in _TO):
            to = x if w in _TO else x + 1
            return seen_noun and not s.verb_follows(to + 1)
        if s.is_punct(x) or s.lemma(x) in lx.PERSON_NOUNS or w in lx.PERSON_NOUNS:
            return False
        seen_noun = seen_noun or s.w[x].pos in ("NOUN", "PROPN")
    return False


def goes_to_after(s: Sentence, i: int) -> bool:
    """Whether the verb at i goes to somewhere right after it, past adverbs and one particle
    ("strolls over to the pond", "ambles slowly across to the café", "wanders into the shop")."""
    k = i + 1
    while k < s.n and s.w[k].pos == "ADV" and s.low[k] not in _PARTICLES:
        k += 1
    if k < s.n and s.low[k] in _PARTICLES and k + 1 < s.n and s.low[k + 1] in _TO:
        k += 1
    elif k < s.n and s.low[k] in _WAYS:
        k = _past_a_way(s, k + 1)
    return k < s.n and s.low[k] in _TO and not s.verb_follows(k + 1)


# Prepositions of the way taken before where one goes ("ambles down the central aisle to the loading bay"),
# and "from", where one sets off ("ambles from the market stalls to the fountain": a walk, issue 29).
_WAYS = frozenset("down along through across up past via from".split())


def _past_a_way(s: Sentence, k: int) -> int:
    """The word after a way's noun phrase from k ("the central aisle" in "down the central aisle to"),
    or k itself when no noun phrase stands there."""
    j = k
    while j < s.n and j < k + 5 and (s.w[j].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or s.low[j] in ("'s", "’s")):
        j += 1
    return j if j > k and s.w[j - 1].pos in ("NOUN", "PROPN") else k


def named_thing(s: Sentence, i: int) -> bool:
    """Whether the word at i is a noun a determiner leads up to, past adjectives after a verb ("hauls the
    weekly shop", "lugs her big shop"), so no verb even when the lexicon has one of its spelling."""
    k = i - 1
    while k > 0 and s.w[k].pos == "ADJ" and s.w[i].pos == "NOUN":
        k -= 1
    if k == i - 1:
        return s.after_determiner(i)
    return s.after_determiner(k + 1) and k >= 1 and s.w[k - 1].pos == "VERB"  # not "a cleaner mops", "a few more wait"


def sets_off_for(s: Sentence, i: int) -> bool:
    """Whether the "for" at i follows "set off" or "set out" ("set off for the aquarium"): where they go,
    as after "head for" ("set aside for worship" is what for); also past the place they set off from ("set off
    from the volunteers' room for kennel block B", round 69)."""
    if i >= 2 and verb_lemma(s.low[i - 2]) == "set" and s.low[i - 1] in ("off", "out"):
        return True
    if i + 1 >= s.n or s.low[i + 1] in ("a", "an", "some", "their", "his", "her", "my", "our", "lunch", "coffee"):
        return False  # "set off from the ward for a coffee": what for
    for k in range(i - 1, max(1, i - 8), -1):
        if s.low[k] in (",", ";", ".", "and", "then") or s.w[k].pos == "VERB":
            return False
        if s.low[k] == "from" and s.low[k - 1] in ("off", "out") and k >= 2 and verb_lemma(s.low[k - 2]) == "set":
            return True
    return False


def obliged_to(s: Sentence, i: int) -> bool:
    """Whether the "to" at i follows "have", "has" or "need" ("all 20 have to leave", "needs to go"): what
    they must do, which is what they do, no purpose; or a verb of refusing ("refuse to let it pass",
    "decline to move"): what they will not do, no purpose either."""
    if i >= 1 and s.verb(i - 1) in ("refuse", "decline"):
        return True
    return i >= 1 and s.low[i - 1] in ("have", "has", "had", "need", "needs", "needed") and \
        not (i >= 2 and s.low[i - 2] in ("will", "would", "might", "may"))
