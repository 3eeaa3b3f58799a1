"""Role words no list holds, told by how English makes a word for a person (round 30): "both quiz
contestants leave", "the crew chief walks", "a greeter by the leaflet stand". A noun ending as names
for people do ("-ant", "-ist", "-ee", "-eer": contestant, florist, trainee, auctioneer; "-er", "-or":
greeter, invigilator; or a head word such as "chief"), opened by "the", "a", "an", "both", a
possessive or a number, is a person where a person stands: the subject of a verb of going, staying or
doing what people do, or one more placed by "and" before a place ("... and a greeter by the stand").
Words so made that name things ("restaurant", "coffee", "printer") and the world's own names are not."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_SURE_ENDINGS = ("ant", "ist", "ee", "eer")
_AGENT_ENDINGS = ("er", "or")
_HEADS = frozenset("chief boss deputy supremo".split())
_OPENERS = frozenset("the a an both our their his her my your its this that these those".split())
# Words so made that name things, not people.
_THINGS = frozenset("""restaurant plant elephant pendant implant pageant sealant coolant lubricant pollutant
    descant croissant coffee toffee settee committee jubilee marquee dungaree puree lychee frisbee
    tee spree list twist wrist mist fist gist playlist checklist wishlist shortlist waitlist
    computer printer scanner container trailer tanker steamer scooter tractor helicopter freighter cruiser
    liner stroller heater cooler freezer poster folder letter number order paper river water corner counter
    centre center tower power shower dinner winter summer other monitor elevator escalator generator
    radiator ventilator projector detector calculator refrigerator corridor door floor mirror sector
    motor meter metre charger speaker router locker hamper hanger burger timer marker sticker banner
    cracker blender toaster kettle boiler fryer dryer washer dishwasher trolley barrier border carrier
    bumper buffer cylinder ladder platter saucer cover matter layer quarter theatre theater chamber
    harbour harbor anchor arbor arbour flavour flavor colour color favour favor error horror mirror
    honour honor labour labor vapour vapor tumour""".split())


def _opened(s: Sentence, i: int) -> bool:
    first = i
    while first > 0 and s.w[first - 1].head == i and s.w[first - 1].dep in ("compound", "amod", "nmod") and \
            s.w[first - 1].pos in ("NOUN", "PROPN", "ADJ"):
        first -= 1  # "both quiz contestants", "the crew chief"
    if first == 0:
        return False
    before = s.low[first - 1]
    return before in _OPENERS or before in ("'s", "’s") or s.w[first - 1].pos == "NUM"


def _where_a_person_stands(s: Sentence, i: int) -> bool:
    word = s.w[i]
    if word.dep == "nsubj" and word.head != i:
        verb = s.verb(word.head)
        return s.w[word.head].pos in ("VERB", "AUX") and verb not in lx.THING_VERBS and (
            verb in lx.INTENT_VERBS or verb in lx.HUMAN_SUBJECT_VERBS or verb in lx.PEOPLE_GOING_VERBS
            or verb in lx.FAST_WORDS or verb in lx.SLOW_WORDS)  # "the sommelier darts into ..." 
    # "... and a greeter by the leaflet stand": one more placed, a place after
    return word.dep == "conj" and i + 1 < s.n and s.low[i + 1] in lx.PLACE_PREPOSITIONS and \
        any(s.low[k] == "and" for k in range(max(0, i - 4), i))


def suffix_role(s: Sentence, i: int) -> bool:
    """Whether word i is a person by its role word's ending (see the module doc)."""
    return role_shaped(s, i) and _opened(s, i) and _where_a_person_stands(s, i)


def role_shaped(s: Sentence, i: int, adjective: bool = False) -> bool:
    """Whether word i is made as a word for a person is (its ending, no thing's word, no verb of a
    person before it), wherever it stands; an adjective by the parser's tag too when `adjective`."""
    low, lem = s.low[i], s.lemma(i)
    noun = s.w[i].pos in ("NOUN", "PROPN") or (s.w[i].pos == "ADJ" and (adjective or s.w[i].dep == "nsubj"))
    if not low.isalpha() or not noun or lem in _THINGS or low in _THINGS or \
            lem in lx.NON_PEOPLE or lem in lx.NON_PLACES or lem in lx.COMPOUND_THINGS or lem in lx.ROBOT_WORDS:
        return False
    if not (lem in _HEADS or (len(lem) >= 6 and lem.endswith(_SURE_ENDINGS + _AGENT_ENDINGS))):
        return False
    if names_a_place(s.index, lem) or (i > 0 and s.w[i].text[:1].isupper() and s.w[i].pos == "PROPN"):
        return False
    verb = verb_lemma(low)
    if verb in lx.INTENT_VERBS or verb in lx.PEOPLE_GOING_VERBS or verb in lx.HUMAN_SUBJECT_VERBS or \
            (i > 0 and (s.low[i - 1] in lx.PERSON_NOUNS or s.lemma(i - 1) in lx.PERSON_NOUNS)
             and s.lemma(i - 1) not in lx.IMPLIED_RANGES and lem not in _HEADS):
        return False  # "a cleaner wanders in the corridor": the person's verb, taken for a noun
    return True


def collective_modifies_role(s: Sentence, k: int) -> bool:
    """Whether the collective at k only says whose role the next word is ("a crew manager", "the team
    leader", "the shift supervisor"): one person, the second word the head, not a crew that manages."""
    return k + 1 < s.n and s.lemma(k) in lx.IMPLIED_RANGES and s.w[k].dep == "compound" and \
        s.w[k].head == k + 1 and s.w[k + 1].tag == "NN"
