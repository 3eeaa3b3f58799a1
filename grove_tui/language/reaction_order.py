"""Which reaction to the robot a clause gives when it names the robot twice ("waves at the robot and
then follows it"), and going "after" the robot by a verb no list names ("toddles after it")."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.second_verbs import second_verb
from grove_tui.language.sentence import Sentence

# Looking is what people do first, and any act that follows it is the reaction ("stares at the robot,
# then runs away from it": avoid); coming over, then following, is more of the same act. A later
# reaction of this order replaces an earlier one; between avoiding, blocking and coming closer the
# first said stays (neither is a step on the other).
_STEPS = ("look", "approach", "follow")


def later_reaction(earlier: str | None, later: str | None) -> str | None:
    """The reaction of one person to the robot said twice: the later if the earlier was only looking
    or it goes further along look -> approach -> follow ("waves at the robot and toddles after it":
    follow), else the earlier."""
    if earlier is None or (earlier == "look" and later is not None):
        return later
    if later in _STEPS and earlier in _STEPS and _STEPS.index(later) > _STEPS.index(earlier):
        return later
    return earlier


# Making a picture of something: of the robot, it is looking at it ("an artist sketches the robot");
# of anything else, a place's thing ("sketches the whale skeleton"), so no verb of the robot's lists.
DEPICTING_VERBS = frozenset("sketch draw paint admire doodle".split())


def depicts(s: Sentence, i: int, r: int) -> bool:
    """Whether word i is a verb of depicting whose object is the robot at r ("sketches the robot")."""
    return verb_in(s, i, DEPICTING_VERBS) and all(s.low[j] in lx.DETERMINERS for j in range(i + 1, r)) and \
        s.low[r] in lx.ROBOT_WORDS | {"it"}


def stops_for(s: Sentence, i: int, r: int) -> str | None:
    """What "stop" at i says of the robot at r: stopping an activity when it passes ("stop whispering
    when the robot passes": no reaction, "skip") or stopping to let it by ("stops to let the robot
    cross", "stops for the robot": making way, "avoid"); None when "stop" is something else."""
    if s.verb(i) not in ("stop", "pause", "halt", "wait") or i + 1 >= r:
        return None
    nxt = s.low[i + 1]
    if nxt.endswith("ing") and s.verb(i) == "stop":
        return "skip"  # "stop whispering": the verb after is what they stop doing
    if nxt == "to" and i + 2 < r and s.verb(i + 2) in ("let", "allow"):
        return "avoid"
    if nxt == "for" and s.verb(i) != "wait" and all(s.low[j] in lx.DETERMINERS for j in range(i + 2, r)):
        return "avoid"  # not "waits for the robot": waiting for it gives way only "to let" it by
    return None


def goes_after(s: Sentence, i: int, r: int) -> bool:
    """Whether word i, a verb (by the parser, the lexicon, or its place after "and"), goes "after"
    the robot at r ("trots after the robot", "toddles after it"): following it."""
    k = i + 1
    if k >= r or s.low[k] != "after":
        return False
    if any(s.low[j] not in lx.DETERMINERS for j in range(k + 1, r)):
        return False  # "waits after the talk for the robot": something else comes after
    return s.w[i].pos == "VERB" or s.verb(i) != s.low[i] or second_verb(s, i)


def verb_in(s: Sentence, i: int, verbs: frozenset[str]) -> bool:
    """Whether word i is one of `verbs`, in its base form or its "-s" form, which the lexicon may not
    know and the small model may tag a noun ("a drunk shouts at the robot")."""
    word = s.low[i]
    return s.verb(i) in verbs or (word.endswith("s") and (word[:-1] in verbs or
                                                          word.endswith("es") and word[:-2] in verbs))
