"""A noun no list names is a person when it is the subject of a chore done to something ("a
fishmonger restocks the slab", "a yard hand hoses out the block", "the porter empties the bins"):
restocking, hosing, mopping, emptying or prepping
(round 60: "a keeper preps fish in the yard") is work people do, not things, and the verb has its object
after it. Without this such a clause named nobody, and in a list of clauses ("A does X, two B do Y,
and C do Z") its person was lost. A noun of the world's (a place or a thing), the robot, a hazard or
a time is still none ("the fountain empties" has no object), except a trade's word that names a
unit of the world too ("a fishmonger restocks the slab"), said with an article."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Chores people do to a thing: each takes an object ("restocks the shelves", "hoses down the deck").
CHORE_VERBS = frozenset(
    """restock stock replenish refill hose mop sweep wipe scrub polish dust hoover vacuum tidy clean
    rinse wash empty unload unpack bag shelve fillet gut debone slice chop peel stack sort fold iron
    fix mend repair varnish grease coil scrape swab sluice jetwash sharpen arrange garnish tally
    prep prepare portion weigh dice mince marinate knead decant measure label""".split())
# A trade's word the world also gives a room ("the fishmonger", "a florist") is still the person
# when it does a chore: a unit does not restock anything.
_TRADE_SUFFIXES = lx.AGENT_SUFFIXES + ("ent",)
_PARTICLES = frozenset("out down off up away over round around".split())
_DETERMINERS = frozenset("a an the two three four five six seven eight nine ten some".split())


def chore_subject(s: Sentence, i: int) -> bool:
    """Whether word i is a noun that does a chore to something: the parser's subject of a chore verb
    with an object, or a noun after "a/the/two" followed by a chore verb in "-s" (the parser may
    take "hoses" for a plural noun), then an optional particle and a determiner."""
    word = s.w[i]
    if word.pos not in ("NOUN", "PROPN"):
        return False
    lem = s.lemma(i)
    trade = i > 0 and s.low[i - 1] in ("a", "an", "the") and len(lem) >= 5 and lem.endswith(_TRADE_SUFFIXES)
    if not lem.isalpha() or (s.index.knows(lem) and not trade) or lem in lx.ROBOT_WORDS or lem in lx.NON_PEOPLE or \
            lem in lx.NON_PLACES or lem in lx.HAZARD_NOUNS or lem in lx.BUILDING_WORDS or lem in lx.DURATION_UNITS:
        return False
    if i > 0 and s.low[i - 1] in lx.ROBOT_WORDS:
        return False
    nxt = i + 1
    if nxt >= s.n or not _chore(s, nxt):
        return False
    obj = nxt + 1
    if obj < s.n and s.low[obj] in _PARTICLES:
        obj += 1  # "hoses out the block"
    if obj >= s.n or s.low[obj] not in _DETERMINERS and s.w[obj].pos not in ("NOUN", "ADJ"):
        return False  # an object must follow: "the fountain empties." is no one
    # The word heads its phrase: no noun after it but the verb; the phrase starts with a determiner
    # or number (or the sentence or a clause comma).
    before = i - 1
    while before >= 0 and s.w[before].pos in ("NOUN", "ADJ", "PROPN") and before >= i - 2:
        before -= 1
    return before < 0 or s.w[before].pos in ("DET", "NUM") or s.low[before] in (",", "and", "while")


def _chore(s: Sentence, k: int) -> bool:
    """Whether word k is a chore verb in any form ("restocks", "hoses", "empties", "mop")."""
    low = s.low[k]
    forms = {low, verb_lemma(low), s.lemma(k), low[:-1] if low.endswith("s") else low,
             low[:-2] if low.endswith("es") else low, low[:-3] + "y" if low.endswith("ies") else low}
    return bool(forms & CHORE_VERBS)
