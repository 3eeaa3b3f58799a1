"""The robot among people: the people its own clause goes through, past or around ("the robot picks
its way through the crowd of commuters on the concourse", "rolls past the queue", "weaves around
them") stay where they are, a group there, and their place is one the robot passes (a via)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.model import GroupReading, RobotReading
from grove_tui.language.robot_passing_verbs import passing_verb
from grove_tui.language.sentence import Sentence

# "picks its way", "threads a path", "noses her way": a verb of going said with the way it makes.
_POSSESSIVES = frozenset("its his her their a the one".split())
_WAY_NOUNS = frozenset("way path route passage".split())


def its_way(s: Sentence, p: int) -> bool:
    """Whether word p is the way a verb of going makes, or its possessive ("threads its way through",
    "picks a path past"): words between the verb and what it goes through, not a thing it acts on."""
    if s.low[p] in _WAY_NOUNS:
        return p > 0 and s.low[p - 1] in _POSSESSIVES
    return s.low[p] in _POSSESSIVES and p + 1 < s.n and s.low[p + 1] in _WAY_NOUNS


# The robot's way on after the people it passes: "... past the queue at the gate towards the lifts".
_ONWARD = lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS | {"en", "for", "then", "and", ",", "before", "until",
                                                               "so"}
_AT = frozenset({"at", "in", "on", "by", "near", "beside", "outside", "inside", "around", "round", "next", "within"})


def met_people_words(s: Sentence, after: Sequence[int]) -> list[int]:
    """The words of the robot's clause after people it passes that say where they are, not where the
    robot goes on to ("squeezes past a group of pupils in the great hall on its way to the café":
    "in the great hall"); all of them when the people have a verb of their own ("passes two nurses
    chatting in the corridor")."""
    out: list[int] = []
    for n, i in enumerate(after):
        if s.w[i].tag in ("VBG", "VBZ", "VBP", "VBD") or s.low[i] in ("who", "that", "which"):
            return list(after)  # their own verb: "two nurses chatting in the corridor"
        if s.low[i] in _AT and n + 2 < len(after) and s.low[after[n + 1]] in ("its", "his", "her", "their"):
            break  # "on its way to", "in its path"
        if s.low[i] in _ONWARD:
            break
        out.append(i)
    return out


# Words of the robot going by people: "through the crowd", "past them", "around the queue".
_PASSING = frozenset("through past around round by between among amongst amid amidst".split())
# Nouns that name people already said by what they make: "the queue", "the crowd", "the group".
_GATHERINGS = frozenset("queue line crowd throng group gang huddle cluster knot bunch party".split())
_BACK_PRONOUNS = frozenset({"them", "him", "her", "everyone", "everybody", "people"})


def via_the_people_passed(s: Sentence, robot: RobotReading | None, clauses: Sequence[Sequence[int]],
                          mentions: Sequence[Mention], read: Sequence[GroupReading]) -> RobotReading | None:
    """The robot's reading with the places of the people it goes through, past or around said as a
    place it passes: "Thirty commuters queue at the ticket office while the robot rolls past the queue to
    the café" (via the ticket office), "... as the robot weaves around them" (via where they are)."""
    if robot is None or robot.task != "cross":
        return robot
    whos = {g.who: g for g in read}
    via = list(robot.via)
    passes: list[str] = []
    for tokens in clauses:
        inside = set(tokens)
        said = [whos[m.who] for m in mentions if m.who in whos and (m.last < tokens[0] or m.first in inside)]
        for i in tokens:
            if (s.low[i] not in _PASSING and not passing_verb(s, i)) or i + 1 not in inside:
                continue
            j = s.skip(i + 1, lx.DETERMINERS | lx.NP_MODIFIERS)
            group = _passed(s, j, said, mentions, whos) if j < s.n and j in inside else None
            if group is not None and group.location and group.who not in passes:
                passes.append(group.who)  # the people it goes through: the report checks it passes them
            if group is not None and group.location and group.location not in (
                    *via, robot.start, robot.destination, robot.location):
                via.append(group.location)
    return replace(robot, via=tuple(via), passes=tuple(passes)) if passes else robot


def _passed(s: Sentence, j: int, said: Sequence[GroupReading], mentions: Sequence[Mention],
            whos: dict[str, GroupReading]) -> GroupReading | None:
    """The group the words at j name: people said inside the robot's clause, a pronoun for the people
    said last, or "the queue"/"the crowd" of people said before."""
    own = next((whos.get(m.who) for m in mentions if m.first <= j <= m.last), None)
    if own is not None:
        return own
    word = s.low[j]
    if word in _BACK_PRONOUNS and said:
        return said[-1]
    if s.lemma(j) in _GATHERINGS and not (j + 1 < s.n and s.low[j + 1] == "of") and said:
        if s.lemma(j) in lx.QUEUE_COLLECTIVES:
            return next((g for g in reversed(said) if g.intent == "queue"), None)
        return said[-1]
    return None
