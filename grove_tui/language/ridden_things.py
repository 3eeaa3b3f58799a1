"""What people ride, float or glide on as they go, and what carries the load they push (issue 29):
"kids drift round the river on rubber rings", "a porter wheels the bags on a cart", "two teens cruise along the prom on their scooters", "a boy bobs
about on a lilo". After "on", with no
"the" (bare, "a", or whose), a thing people ride is how they go, no place: never the world's rack of rings
or bike stand. A posture or a workout before it ("sits on a bike", "pedals on the exercise bikes") leaves
the phrase to the reader, as does "the" ("on the rings" of a gym); round 69, so does a thing that stays
put ("pts on exercise bikes", "on a static bike") where the world has such things."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Things people ride or float on, by their lemma.
_RIDDEN = frozenset("ring lilo inflatable float tube tyre dinghy bodyboard surfboard paddleboard board bike "
                    "bicycle scooter skateboard skate rollerblade horse pony donkey sledge toboggan "
                    "unicycle trike tricycle segway hoverboard".split())
# Things that carry what people push or pull ("pushes the bags on a cart", "wheels the boxes on a
# trolley"): how the load goes, no place, as a ridden thing is how its rider goes.
_CARRIERS = frozenset("cart trolley barrow wheelbarrow handcart dolly gurney stretcher sack truck".split())
_OWNERS = frozenset("a an their his her my our your its".split())
# Verbs that keep people in one spot on the thing: the phrase may be a place of the world.
_STILL = frozenset("sit stand lie lounge perch wait pedal train exercise work rest sprawl kneel".split())
_BREAKS = frozenset({",", ";", ".", "and", "while", "as", "when", "then", "but"})
# Words that make a ridden thing one that stays put (round 69): "exercise bikes", "a static bike".
_STATIONARY = frozenset("exercise static stationary spin gym indoor rowing".split())


def ridden_on(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after "on" at `at` is a thing people ride as they go (module doc)."""
    if prep != "on" or k >= s.n:
        return False
    j = k + 1 if s.low[k] in _OWNERS else k
    while j < s.n and s.w[j].pos == "ADJ" or j + 1 < s.n and s.w[j].pos == "NOUN" and s.w[j + 1].pos == "NOUN":
        j += 1  # "rubber rings", "inflatable rings"
    if j >= s.n or lemma(s.low[j]) not in _RIDDEN | _CARRIERS or j + 1 < s.n and s.w[j + 1].pos == "NOUN":
        return False
    first = k + 1 if s.low[k] in _OWNERS else k
    if any(s.low[x] in _STATIONARY for x in range(first, j)) and s.index.knows(lemma(s.low[j])):
        return False  # "pts on exercise bikes" where the world has bikes: ridden nowhere
    x = at - 1
    while x >= 0 and s.low[x] not in _BREAKS:
        if verb_lemma(s.low[x]) in _STILL or s.low[x].rstrip("s") in _STILL or s.lemma(x) in _STILL:
            return False
        x -= 1
    return True
