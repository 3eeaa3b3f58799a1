"""Going to or after the robot by a verb of manner of walking (round 18): "two boys trot after the
robot", "a pair of interns scamper over to it", "an intern makes a beeline for the robot", "kids skip
along behind it". The small parser often tags these verbs a noun or an adjective ("trot", "scamper"),
so they are known here by their words; a verb of the lexicon's walking verbs counts as well. Going off
or away whenever the robot comes ("scurries off whenever the robot rolls near her") is avoiding it."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.robot_shrinking import shrinks_from
from grove_tui.language.sentence import Sentence

# Verbs of a manner of walking or running, whatever the parser tags them.
MANNER_VERBS = frozenset("trot scamper scurry scuttle skip hop bound toddle waddle mooch traipse trudge tramp plod "
                         "dart zip scoot patter sidle amble saunter stroll wander jog lope stride march tag tail "
                         "trail troop file skitter potter pad creep tiptoe sprint dash race rush hurry run walk "
                         "head go come wheel roll drift".split())
# Words after such a verb that go after the robot ("trots after it", "tags along behind the robot").
FOLLOW_TAILS = (("after",), ("along", "after"), ("along", "behind"), ("behind",), ("close", "behind"),
                ("right", "behind"), ("in", "the", "wake", "of"))
# Words after such a verb that go to it ("scampers over to it", "hurries straight for the robot").
APPROACH_TAILS = (("over", "to"), ("up", "to"), ("across", "to"), ("right", "up", "to"), ("straight", "for"),
                  ("straight", "to"), ("straight", "over", "to"), ("towards",), ("toward",), ("closer", "to"),
                  ("straight", "towards"))
# Phrases whose object the robot is that go to it whatever the verb: "makes a beeline for the robot".
APPROACH_PHRASES = (("make", "a", "beeline", "for"), ("make", "a", "bee", "line", "for"), ("beeline", "for"),
                    ("make", "straight", "for"), ("head", "straight", "for"), ("make", "a", "dash", "for"),
                    ("make", "a", "run", "for"), ("head", "for"), ("make", "for"), ("home", "in", "on"))


def _manner_verb(s: Sentence, i: int) -> bool:
    word = s.low[i]
    if s.after_determiner(i):
        return False  # "a trot", "the march"
    return s.verb(i) in MANNER_VERBS or word in MANNER_VERBS or (
        word.endswith("s") and (word[:-1] in MANNER_VERBS or word.endswith("es") and word[:-2] in MANNER_VERBS)) or \
        lx.INTENT_VERBS.get(s.verb(i)) in ("walk", "wander")


# Words after such a verb that go away from where they are ("scurries off", "scuttles away again").
AWAY_TAILS = (("off",), ("away",), ("off", "again"), ("away", "again"), ("straight", "off"))
# Words of time that make the robot's coming the reason ("whenever the robot rolls near her").
_WHEN = frozenset("when whenever as once if each every time the moment minute second soon".split())


def fled_when_it_comes(s: Sentence, ownset: set[int], i: int, r: int) -> bool:
    """Whether the manner of walking at i goes away whenever the robot at r comes ("a frightened girl
    scurries off whenever the robot rolls near her", "scuttles away as soon as it comes close"): avoiding it."""
    for tail in AWAY_TAILS:
        end = i + 1 + len(tail)
        if tuple(s.low[i + 1:end]) == tail and all(k in ownset for k in range(i + 1, end)) and end < r and \
                s.low[end] in _WHEN and all(s.low[k] in _WHEN or s.low[k] in lx.DETERMINERS for k in range(end, r)):
            return True
    return False


def _only_determiners(s: Sentence, a: int, r: int) -> bool:
    return all(s.low[j] in lx.DETERMINERS or s.low[j] in ("just", "right") for j in range(a, r))


def motion_reaction(s: Sentence, ownset: set[int], i: int, r: int) -> str | None:
    """"follow" or "approach" when the words from i go after or to the robot at r ("trot after the
    robot", "scamper over to it", "make a beeline for it"); None otherwise."""
    if s.low[r] not in lx.ROBOT_WORDS and s.low[r] != "it":
        return None  # "its dock": the robot's things
    for phrase in APPROACH_PHRASES:
        if s.phrase_words(i, len(phrase), ownset) == phrase and _only_determiners(s, i + len(phrase), r):
            return "approach"
    if shrinks_from(s, ownset, i, r):
        return "avoid"  # "scurries away from the robot", "cringes back from it" (robot_shrinking.py)
    if not _manner_verb(s, i):
        return None
    if fled_when_it_comes(s, ownset, i, r):
        return "avoid"
    for tails, interaction in ((FOLLOW_TAILS, "follow"), (APPROACH_TAILS, "approach")):
        for tail in tails:
            if tuple(s.low[i + 1:i + 1 + len(tail)]) == tail and all(k in ownset for k in range(i + 1, r)) and \
                    _only_determiners(s, i + 1 + len(tail), r):
                return interaction
    return None


def motion_reaction_before(s: Sentence, own: Sequence[int], since: int, r: int) -> str | None:
    """The reaction of the first word between `since` and the robot at r that goes after or to it."""
    ownset = set(own)
    for i in sorted(x for x in own if since < x < r):
        found = motion_reaction(s, ownset, i, r)
        if found is not None:
            return found
    return None


def goes_after_robot(s: Sentence, first: int) -> bool:
    """Whether the robot's phrase at `first` is what a manner of walking goes after ("trot after the
    robot round the bookshop"), not the subject of a clause "after" starts ("after the robot leaves")."""
    before = first - 1
    return before >= 1 and s.low[before] in ("after", "behind") and _manner_verb(s, before - 1) and \
        not s.is_punct(before - 1)
