"""Reactions to the robot said with an idiom or with the whole body, and reactions timed by the robot.

An idiom names the reaction whatever its object: "nearly jumps out of her skin", "does a double
take", "stops dead in his tracks" (Surprised: stopping to look), "hem the robot in", "box it in",
"shoo it away" (Threatening: blocking it), "scurries off", "leaps aside" (Scared: avoiding it). A
clause that the robot's own clause times ("As the robot trundles past, X ...", "X ... whenever the
robot comes near") reacts to the robot with any verb of shrinking or hiding too, even one with an
object of its own ("hides behind the sofa whenever the robot comes near").
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.fled_places import flees_to_a_place
from grove_tui.language.fronted_timers import fright_reaction, fronted_robot_timer
from grove_tui.language.hiding_moves import hides_by_moving
from grove_tui.language.robot_holds import HOLDING_IDIOMS
from grove_tui.language.robot_sticking import sticking_reaction
from grove_tui.language.time_phrases import time_phrase_end
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# "*" stands for one to three words of the clause (a possessive, "the robot", "it").
IDIOMS: dict[tuple[str, ...], str] = {
    ("jump", "out", "of", "*", "skin"): "look", ("leap", "out", "of", "*", "skin"): "look",
    ("do", "a", "double", "take"): "look", ("do", "a", "double-take"): "look", ("stop", "dead"): "look",
    ("stop", "in", "*", "track"): "look", ("freeze", "in", "*", "track"): "look", ("stop", "short"): "look",
    ("stand", "open-mouthed"): "look", ("jaw", "drop"): "look", ("rub", "*", "eye"): "look",
    ("hem", "*", "in"): "block", ("hem", "in"): "block", ("box", "*", "in"): "block", ("box", "in"): "block",
    ("fence", "*", "in"): "block", ("pen", "*", "in"): "block", ("wall", "*", "in"): "block",
    ("close", "in", "on"): "block", ("gang", "up", "on"): "block", ("shoo",): "block",
    ("wave", "*", "away"): "block", ("wave", "*", "off"): "block", ("chase", "*", "off"): "block",
    ("chase", "*", "away"): "block", ("drive", "*", "off"): "block", ("drive", "*", "away"): "block",
    ("scare", "*", "off"): "block", ("scare", "*", "away"): "block", ("see", "*", "off"): "block",
    ("dive", "out", "of", "the", "way"): "avoid", ("leap", "out", "of", "the", "way"): "avoid",
    ("jump", "out", "of", "the", "way"): "avoid", ("scramble", "out", "of", "the", "way"): "avoid",
    ("flatten", "*", "against"): "avoid", ("press", "*", "against"): "avoid", ("make", "*", "scarce"): "avoid",
    ("keep", "*", "distance"): "avoid", ("give", "*", "a", "wide", "berth"): "avoid",
    ("give", "*", "a", "berth"): "avoid", ("crowd", "round"): "approach", ("flock", "round"): "approach",
    ("take", "fright"): "avoid", ("take", "fright", "at"): "avoid",  # "takes fright at the robot and scurries off"
}
IDIOMS.update(HOLDING_IDIOMS)  # "stands his ground", "keeps a hand on the robot" (robot_holds.py)
# Verbs of a start or a stop that, timed by the robot, are stopping to look ("an old man freezes as ...").
_STARTLED_VERBS = frozenset("freeze gasp jump start startle gape gawp".split())
# Verbs of shrinking or hiding that, timed by the robot, are avoiding it whatever they take.
_SHRINKING_VERBS = frozenset("hide duck cower flinch recoil shrink retreat bolt scarper flee cringe".split())
# Words after any verb that make it a going away ("scurries off", "leaps aside", "darts back").
_AWAY_TAILS = frozenset("off away aside back".split())
# Words of time by which the robot's clause sets off a reaction ("while" is only at the same time).
_TIME_WORDS = frozenset("as when whenever once".split())


def _match(s: Sentence, i: int, idiom: tuple[str, ...], ownset: set[int]) -> bool:
    j = i
    for n, word in enumerate(idiom):
        if word == "*":
            nxt = idiom[n + 1]
            for k in range(j + 1, min(j + 4, s.n)):
                if k not in ownset and s.low[k] not in lx.ROBOT_WORDS:
                    return False
                if k - 1 >= j and (lemma(s.low[k]) == nxt or s.low[k] == nxt):
                    j = k
                    break
            else:
                return False
            continue
        if j >= s.n or (j not in ownset and not (n and s.low[j] in lx.ROBOT_WORDS)) or s.is_punct(j):
            return False
        if word not in (s.low[j], lemma(s.low[j]), s.w[j].lemma) and not (n == 0 and s.verb(j) == word):
            return False
        j += 1
    return True


def idiom_reaction(s: Sentence, own: Sequence[int]) -> str | None:
    """The reaction an idiom of the clause names ("jumps out of her skin", "hem the robot in")."""
    ownset = set(own)
    for i in own:
        if s.after_determiner(i) or _named_after_preposition(s, i):
            continue  # "a junior at the practice wall jumps in ...": a wall, not walling anyone in
        for idiom, interaction in IDIOMS.items():
            if _match(s, i, idiom, ownset):
                return interaction
    return sticking_reaction(s, own)  # "sticks to the robot like glue", "to keep the robot off the ice"


def _named_after_preposition(s: Sentence, i: int) -> bool:
    """Whether the word at i ends a noun phrase after a preposition ("at the practice wall", "by the
    garden wall"): a thing, never the verb of an idiom."""
    k = i - 1
    while k > 0 and i - k <= 3 and s.w[k].pos in ("NOUN", "PROPN", "ADJ") and not s.after_determiner(k + 1):
        k -= 1
    return k >= 1 and k < i and s.low[k] in ("the", "a", "an") and s.w[k - 1].pos == "ADP" and \
        s.w[i].pos in ("NOUN", "PROPN")


def timed_by_robot(s: Sentence, own: Sequence[int], robot_after: int | None) -> bool:
    """Whether the robot's clause times this one: it leads into one ("... as it passes"), or it opens
    the sentence with a word of time before the clause ("As the robot trundles past, ..."), or the
    clause's own words say "whenever the robot ..."."""
    if robot_after is not None:
        return s.low[robot_after - 1] in _TIME_WORDS
    if not own:
        return False
    sentence = s.w[own[0]].sentence
    for k in range(own[0]):
        if s.low[k] in _TIME_WORDS and s.w[k].sentence == sentence and (k == 0 or s.is_punct(k - 1)) and \
                any(s.low[r] in lx.ROBOT_WORDS for r in range(k + 1, min(k + 4, own[0]))):
            return True
    if fronted_robot_timer(s, own[0]):
        return True  # "The moment the robot nudges the door open, ...", "As soon as it rolls in, ..."
    return any((s.low[k] in _TIME_WORDS or time_phrase_end(s, k)) and  # "every time the robot beeps"
               any(s.low[r] in lx.ROBOT_WORDS for r in range(k + 1, min(k + 4, s.n))) for k in own)


def timed_reaction(s: Sentence, own: Sequence[int]) -> str | None:
    """A reaction with no robot for object in a clause the robot times: shrinking or hiding (avoid),
    going off or aside (avoid), a start or a freeze (look). Only words before any word of time."""
    for n, i in enumerate(own):
        if s.low[i] in _TIME_WORDS or time_phrase_end(s, i + 1):
            break
        if s.after_determiner(i) or s.w[i].pos not in ("VERB", "AUX", "NOUN", "ADJ", "PROPN"):
            continue
        v = s.verb(i) if s.w[i].pos in ("VERB", "AUX") else s.w[i].lemma  # "scurries" is tagged a noun at times
        if v in _SHRINKING_VERBS or lx.ROBOT_VERBS.get(v) == "avoid" or hides_by_moving(s, i) or \
                fright_reaction(s, i):
            return "avoid"
        nxt = own[n + 1] if n + 1 < len(own) else None
        if nxt == i + 1 and s.low[nxt] in _AWAY_TAILS and s.w[i].pos in ("VERB", "NOUN") and _ends(s, nxt + 1):
            return "avoid"  # "scurries off whenever ...", not "pour off platform 1" nor "go back to"
        if nxt == i + 1 and s.w[i].pos in ("VERB", "NOUN") and flees_to_a_place(s, i, nxt):
            return "avoid"  # "scurries off to the far corner once it appears" (fled_places.py)
        if v in _STARTLED_VERBS:
            return "look"
    return None


def _ends(s: Sentence, k: int) -> bool:
    """Whether a clause ends at k: the end, a stop, a word of time or a conjunction."""
    return k >= s.n or s.is_punct(k) or s.low[k] in _TIME_WORDS or s.low[k] in lx.CLAUSE_STARTERS or \
        s.low[k] in ("and", "but", "in", "with")
