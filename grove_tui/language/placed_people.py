"""A person placed by an imperative, said by a name or a kin word (round 26): "Put Mum on the settee
and leave the robot in the kitchen", "Put Grandad on a bench by the fountain", "Place Tom Hale at the
front desk", "Put a florist by the entrance". The object of the sentence's opening "Put" or "Place"
with a place after it is one person when a capitalised name or a kin word says them, or a noun
whose ending only people's names have ("-ist", "-ian", "-keeper"); since round 27 also after "Stick"
or "Plant" and after "and", and a doer's word that is no thing ("a fiddler"), a role said short ("a
lab tech") or in capitals ("a PCSO").
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.hyphened_modifiers import modified_start, modifier_count
from grove_tui.language.placed_and_names import placed_after_and

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# "Have" opens a placing order too ("Have a mall cop by the fountain and two teens in the shop").
_PLACING = frozenset({"put", "place", "position", "sit", "seat", "stick", "plant", "station", "post", "pop", "have"})
# Words ending as a doer's name that are things ("Put a heater in the lounge", "Stick a poster by the door").
_DOER_THINGS = frozenset("poster heater speaker banner marker sticker container computer printer trailer router "
                         "monitor sensor motor cooler fryer toaster timer counter corner cover flower tower folder "
                         "binder ladder hamper locker charger scanner projector radiator elevator escalator generator "
                         "detector extinguisher planter feeder buzzer hanger cooker blender mixer burner boiler "
                         "freezer drawer shower slipper sweater jumper trainer poker cracker burger paper water "
                         "letter number order border filter meter barrier register calendar sticker cylinder "
                         "heater holder dumpster container server answer mirror door floor cushion pillow".split())
# Roles said short that no list keeps ("a lab tech", "a sound tech").
_SHORT = frozenset({"tech", "techie", "temp", "rep", "medic", "sarge", "copper", "cop"})
_WHERE = frozenset("on at in by near beside behind inside outside next".split())


def placed_person(s: Sentence, i: int) -> bool:
    """Whether word i heads the object of an opening placing imperative that names a person."""
    w = s.w[i]
    if placed_after_and(s, i):
        return True  # "Put three visitors in the canteen and Tom at reception"
    if w.dep != "dobj" or w.head == i or not s.low[i].isalpha() or len(s.low[i]) < 3:
        return False
    verb = w.head
    if s.low[verb] not in _PLACING or not (verb == 0 or s.is_punct(verb - 1) or s.low[verb - 1] in ("and", "then")) \
            or s.w[verb].tag != "VB":
        return False
    if i + 1 >= s.n or s.low[i + 1] not in _WHERE:
        return False
    if not any(s.index.knows(s.lemma(k)) for k in range(i + 2, min(i + 6, s.n))):
        return False  # "Put Starbucks on the map": no place of the world after it
    if s.low[i] in lx.NON_PEOPLE or s.low[i] in lx.ROBOT_WORDS or s.index.knows(s.lemma(i)):
        return False
    first = i
    while first > verb + 1 and s.w[first - 1].head == i and s.w[first - 1].tag == "NNP":
        first -= 1  # "Tom Hale"
    if first == verb + 1 and s.low[i] in lx.KIN_NAMES:
        return True  # "Put Mum on the settee"
    if first == verb + 1 and w.tag == "NNP" and s.w[i].text[:1].isupper() and s.w[i].text[1:].islower():
        return True  # "Put Grandad ...", "Place Tom Hale ..."
    if s.low[first - 1] in ("a", "an", "one") and s.low[i].endswith(lx.STRONG_AGENT_SUFFIXES):
        return True
    return _placed_role(s, verb, i)


def _placed_role(s: Sentence, verb: int, i: int) -> bool:
    """A role no list keeps, placed (round 27): "Put a fiddler on the concourse seats", "Stick one
    lab tech at the centrifuge", "Stick a PCSO behind the front counter": a word ending as a doer's
    name ("-er", "-or", "-ant") that is no thing, a role said short, or one in capitals, opened by
    "a", "an" or "one" with at most one noun before it."""
    first = modified_start(s, i, verb + 1)  # "a lab tech", "a street fiddler", "a night-shift replenisher"
    if s.low[first - 1] not in ("a", "an", "one") or modifier_count(s, first, i) > 1 or s.low[i] in _DOER_THINGS or \
            s.lemma(i) in lx.NON_PEOPLE or s.lemma(i) in lx.CARRYING_THINGS:
        return False
    text = s.w[i].text
    return (s.low[i].endswith(("er", "or", "ant")) and len(s.low[i]) >= 6) or s.low[i] in _SHORT or \
        (text.isalpha() and text.isupper() and 2 <= len(text) <= 5)
