"""A word that is part of a place's name here. An evacuation cue (round 44): "jog from the kit room out to
the smoke house in the drill yard" names the training yard by its alias "drill yard", and no drill is
on; "the alarm panel", "the escape room" of a world that has them are places too. A cue read as a cue
made every group in the prompt evacuate. A word for people (twenty-second session): "the robot ferries
soup from the kitchen diner to ..." names the kitchen by its alias, and no diner."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import phrase_lemmas


def in_a_place_name(s: Sentence, i: int) -> bool:
    """Whether word i starts a whole name or alias of a place of the world with the words after it."""
    for n in (3, 2):
        said = phrase_lemmas(s.low[i:i + n])
        match = s.index.match(said) if len(said) == n else None
        entry = s.index.entry(match.name) if match is not None and match.exact else None
        if entry is not None and tuple(said) in entry.phrases:
            return True
    return False


def person_word_in_a_place_name(s: Sentence, at: int) -> bool:
    """Whether the word at `at` is inside a place's whole name or alias of two words or more, said after a
    place's preposition ("from the kitchen diner", "to the nurses' station"): a word for people that names
    no one there."""
    for start in range(s.skip(at, lx.DETERMINERS), max(-1, at - 3), -1):
        before = start - 1
        while before > 0 and s.low[before] in lx.DETERMINERS:
            before -= 1
        if before >= 0 and s.low[before] in lx.PLACE_PREPOSITIONS and in_a_place_name(s, start):
            return True
    return False


def compound_place_refused(s: Sentence, at: int) -> bool:
    """Whether the words at `at`, right after "rather than" or "instead of", are a place named with a word
    for people as its modifier ("rather than the staff lounge", "instead of the kids' den") that the world
    may lack (round 69): the parser makes the people word a compound of the noun after it, the object
    of "than"/"of". No subject starts there, though the head is a verb too ("lounge")."""
    if at < 2 or (s.low[at - 2], s.low[at - 1]) not in lx.NEGATED_PLACE_PHRASES:
        return False
    k = s.skip(at, lx.DETERMINERS)
    while k + 1 < s.n and s.w[k].pos in ("NOUN", "PROPN", "ADJ") and s.w[k].dep in ("compound", "amod", "poss"):
        nxt = k + 2 if s.low[k + 1] in ("'s", "’s", "'", "’") else k + 1
        head = s.w[k].head
        if nxt < s.n and head >= nxt and s.w[head].pos == "NOUN" and s.w[head].dep in ("pobj", "dobj", "obj") \
                and s.w[head].head in (at - 1, at - 2):
            return True  # "the staff lounge": "lounge" the object of "than", "staff" its modifier
        k = nxt
    return False
