"""The robot following someone while that person goes somewhere, said with the person's route in an "as"
clause: "the robot tails Grandpa as he shuffles from the kitchen to the den", "the robot follows Mum while
she walks over to the utility room". The route is the person's own (and so the robot's), but the "as"
clause hangs on the robot's sentence, which keeps only the following. The sentence is said again with the
person first: "Grandpa shuffles from the kitchen to the den as the robot tails him", a wording read right
(the person walks that route, the robot follows them). Read before the rest (language/reading.py)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.passive_escort import _ROUTE_WORDS

_OBJECT_PRONOUN = {"he": "him", "she": "her", "they": "them"}
_WHILE = frozenset({"as", "while", "whilst"})
_ENDS = frozenset({".", ";", "!", "?", "but", "then"})
# At most this many words name the person followed ("the little lad in the red coat").
_PERSON_WORDS = 7


def followed_route_first(text: str, words: Sequence[Word]) -> str | None:
    """The text with the followed person's route said first (module doc); None when not so said."""
    for verb in words:
        if verb.lemma not in lx.ROBOT_FOLLOW_VERBS or verb.i < 1 or verb.pos != "VERB" or \
                words[verb.i - 1].lower not in lx.ROBOT_WORDS:
            continue
        conj = next((w for w in words[verb.i + 2:verb.i + 2 + _PERSON_WORDS] if w.lower in _WHILE), None)
        if conj is None or conj.i + 2 >= len(words) or words[conj.i + 1].lower not in _OBJECT_PRONOUN:
            continue
        if any(w.lower in (",", "and") or w.sentence != verb.sentence for w in words[verb.i + 1:conj.i]):
            continue
        moves = words[conj.i + 2]
        if moves.pos != "VERB":
            continue
        end = next((w.i for w in words[moves.i + 1:] if w.lower in _ENDS or w.sentence != verb.sentence), len(words))
        if not {w.lower for w in words[moves.i + 1:end]} & (_ROUTE_WORDS - {"over", "up", "down", "back"}):
            continue
        robot_start = verb.i - 1
        if robot_start > 0 and words[robot_start - 1].lower in ("the", "our", "a"):
            robot_start -= 1
        person = text[words[verb.i + 1].start:words[conj.i - 1].end]
        route = text[moves.start:words[end - 1].end].rstrip(" ,")
        robot = text[words[robot_start].start:verb.end]
        robot = robot[:1].lower() + robot[1:] if robot_start == 0 else robot
        person = person[:1].upper() + person[1:] if robot_start == 0 else person
        said = f"{person} {route} {conj.lower} {robot} {_OBJECT_PRONOUN[words[conj.i + 1].lower]}"
        return text[:words[robot_start].start] + said + text[words[end - 1].end:]
    return None
