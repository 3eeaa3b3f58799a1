"""An event or a club named like a place, round 33 (where people are or come from: "at", "from", "in",
"during"; "walks to the wedding" is still refused): "at the tea dance", "a lad from the Cub pack", "at
the coffee morning", "in the book club", "at the quiz night". The phrase after the preposition is
headed by a word for a gathering ("dance", "morning", "night", "club", "pack", "sale", "party") rather
than a room, so when the world has no place of that name there is nothing to refuse: people are at an
event, not in a place the world lacks. A place the world does have under the phrase ("the dance
studio", "the club room") is read as before: only the refusal is dropped.

The tagger sometimes runs the noun phrase on into the verb ("at the coffee morning stare at the
robot"): a gathering word followed only by words the lexicon knows as verbs still heads the phrase.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Words that head the name of a gathering, a club or a time of day's event, never a room.
GATHERING_HEADS = frozenset("""dance disco ball ceilidh barn-dance tea-dance morning afternoon evening night
    club pack troop brigade choir society circle guild league party sale fair fete fête bazaar jumble quiz
    bingo raffle tournament contest competition rehearsal recital matinee wedding funeral christening
    service mass evensong lecture seminar workshop session class lesson meeting meetup assembly ceremony
    celebration reunion gala festival show-and-tell playgroup storytime story-time bash shindig
    beano do""".split())
# Words for an event, for every pass that asks whether a phrase names one ("midway through the lecture",
# "ahead of the 3 pm show"): the gathering words and the shows, games, meals and services people attend.
EVENT_WORDS = GATHERING_HEADS | frozenset("""lecture concert gig match game show film movie screening performance
    play talk speech service tour party class lesson meeting session shift set race round practice rehearsal
    seminar tutorial briefing ceremony wedding disco visit workout drill interval opera ballet musical recital
    sermon mass auction matinee premiere finale encore overture act scene quiz exam meal dinner lunch banquet
    recording broadcast episode taping keynote presentation kickoff kick-off launch opening assembly
    workshop""".split())
# Words that, before a gathering word, make it a place's own name ("the night shelter", "the dance
# studio" is headed by "studio"; "the service desk" by "desk"), never said of an event.
_NOT_AFTER = frozenset("shift".split())
# Words that make a club a building people go to ("the night club", "the golf club"), not a club one is of.
_PLACE_CLUBS = frozenset("night golf country health social sports tennis jazz comedy strip working".split())


def names_an_event(s: Sentence, k: int) -> bool:
    """Whether the noun phrase from word k (after a place preposition) names a gathering or a club:
    its last noun, or its last noun before words that are only verbs, is a gathering word."""
    j = k
    while j < s.n and s.low[j] in lx.DETERMINERS:
        j += 1
    run: list[int] = []
    while j < s.n and s.w[j].pos in ("ADJ", "NOUN", "PROPN", "VERB") and not s.is_punct(j):
        run.append(j)
        j += 1
    for pos, i in enumerate(run):
        if lemma(s.low[i]) not in GATHERING_HEADS and s.low[i] not in GATHERING_HEADS:
            continue
        if pos == 0 and len(run) == 1 and s.low[i] in ("morning", "afternoon", "evening", "night"):
            return False  # "in the morning": a time, read elsewhere
        rest = run[pos + 1:]
        if s.low[i] == "club" and pos > 0 and s.low[run[pos - 1]] in _PLACE_CLUBS:
            return False
        verbs = all(_verb(s, x) for x in rest) or len(rest) == 1 and j < s.n and s.w[j].pos in ("ADP", "PART")
        if verbs and not any(s.low[x] in _NOT_AFTER for x in run):
            return pos > 0 or s.low[i] not in ("morning", "afternoon", "evening", "night")
    return False


def _verb(s: Sentence, x: int) -> bool:
    v = verb_lemma(s.low[x])
    return s.w[x].pos == "VERB" or v in lx.INTENT_VERBS or v in lx.ROBOT_VERBS
