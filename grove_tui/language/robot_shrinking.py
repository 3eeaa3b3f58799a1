"""Going away from the robot by any verb of moving or shrinking (round 31): "scurries away from the
robot", "a toddler skitters back from it", "slinks off away from the robot", "cringes away from it".
The verb may be one the lexicon lacks, or one the small parser tags a noun ("scurries"); what reads it
is the tail "away from" / "back from" / "clear of" right before the robot, with only determiners
between. Read for language/robot_motion.py."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Words that go away from what follows: "away from", "back from", "off away from", "well away from".
AWAY_FROM_TAILS = (("away", "from"), ("back", "from"), ("off", "away", "from"), ("right", "away", "from"),
                   ("well", "away", "from"), ("back", "away", "from"), ("quickly", "away", "from"),
                   ("off", "from"), ("clear", "of"), ("well", "clear", "of"))
# Verbs of shrinking or moving away that the manner-of-walking list lacks.
SHRINKING_VERBS = frozenset("shrink cringe wince quail cower recoil flinch shy edge inch sidle slink slope shuffle "
                            "scramble scarper skedaddle bolt scoot withdraw retreat pull draw lean step back "
                            "shift twist turn swerve veer duck dodge leap jump spring hop hobble limp "
                            "stagger stumble totter lurch".split())
# Words of direction or haste that may stand between the verb and its tail: "leaps backwards away from
# the robot", "springs hastily clear of it".
_BETWEEN = frozenset("backwards backward back quickly hastily hurriedly swiftly smartly nervously warily "
                     "sharply abruptly suddenly instinctively".split())


def _moving_word(s: Sentence, i: int) -> bool:
    word = s.low[i]
    if s.after_determiner(i) or word in lx.ROBOT_WORDS:
        return False
    stems = {word, s.verb(i), s.w[i].lemma.lower()}
    if word.endswith("ies"):
        stems.add(word[:-3] + "y")  # "scurries", "shies"
    if word.endswith("es"):
        stems.add(word[:-2])
    if word.endswith("s"):
        stems.add(word[:-1])
    from grove_tui.language.robot_motion import MANNER_VERBS
    return bool(stems & (SHRINKING_VERBS | MANNER_VERBS)) or s.w[i].pos == "VERB"


# Verbs of running off that go away from what follows a bare "from": "bolt from the robot", "flee from it"
# ("walks from the robot's dock" is a start, not a flight).
FLEEING_VERBS = frozenset("bolt flee run dash scarper scurry scuttle scamper race sprint rush hurry dart skedaddle "
                          "retreat recoil shrink cower flinch cringe hare leg".split())


def _flees(s: Sentence, i: int) -> bool:
    word = s.low[i]
    stems = {word, s.verb(i), s.w[i].lemma.lower(), word[:-1], word[:-2], word[:-3] + "y"}
    return not s.after_determiner(i) and bool(stems & FLEEING_VERBS)


def _the_robot_itself(s: Sentence, r: int) -> bool:
    """The robot at r is the thing itself, not a word of another ("the robot bay", "the robot's dock")."""
    return r + 1 >= s.n or (s.w[r + 1].pos not in ("NOUN", "PROPN") and s.low[r + 1] not in ("'s", "’s"))


def shrinks_from(s: Sentence, ownset: set[int], i: int, r: int) -> bool:
    """Whether the verb at i goes away from the robot at r ("scurries away from the robot", "bolt from it")."""
    if not _moving_word(s, i):
        return False
    first = i + 1
    while first < r and s.low[first] in _BETWEEN and first in ownset and \
            not any(tuple(s.low[first:first + len(t)]) == t for t in AWAY_FROM_TAILS):
        first += 1  # "leaps backwards away from it" (the "back" of "back from it" is the tail's own)
    tails = AWAY_FROM_TAILS + ((("from",),) if _flees(s, i) and _the_robot_itself(s, r) else ())
    for start in dict.fromkeys((i + 1, first)):
        for tail in tails:
            end = start + len(tail)
            if tuple(s.low[start:end]) == tail and all(k in ownset for k in range(i + 1, end)) and end <= r and \
                    all(s.low[k] in lx.DETERMINERS for k in range(end, r)):
                return True
    return False
