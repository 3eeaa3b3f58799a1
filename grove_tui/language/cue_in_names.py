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
