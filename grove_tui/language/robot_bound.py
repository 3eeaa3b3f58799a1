"""The robot's own trip said after what it does on the way: "The robot weaves through a swarm of
schoolkids milling under the whale skeleton, bound for the café", "... on its way to ward B". The
people's verb ("milling") must not make the robot's task a round, and the place after "bound for"
is where the robot goes: a crossing to it, the places said on the way passed through."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Protocol

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import GroupReading, RobotReading
from grove_tui.language.place_phrases import Place
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_BOUND = frozenset({"bound", "headed", "heading", "making"})
_TOWARD = frozenset({"for", "to", "towards", "toward"})


class _Clause(Protocol):
    tokens: list[int]
    verb: int | None


def _bound_at(s: Sentence, tokens: Sequence[int], verb: int | None) -> int | None:
    """The index of the word after which the robot's goal is said ("bound for", "on its way to",
    "en route to"), when it is not the robot's own verb."""
    for k in tokens:
        if k == verb or k + 1 >= s.n:
            continue
        if s.low[k] in _BOUND and s.low[k + 1] in _TOWARD and (verb is None or k > verb) and s.low[k - 1] == ",":
            return k + 1
        if s.low[k] == "way" and k >= 2 and s.low[k - 2] == "on" and s.low[k - 1] in ("its", "his", "her") \
                and s.low[k + 1] in _TOWARD:
            return k + 1
        if s.low[k] == "route" and k >= 1 and s.low[k - 1] == "en" and s.low[k + 1] in _TOWARD:
            return k + 1
    return None


def bound_trip(s: Sentence, found: Sequence[_Clause], places: Mapping[str, Place]) -> str | None:
    """The place the robot is bound for when said after its verb of going ("weaves through ...,
    bound for the café"); None when no such phrase, or the robot's verb is one of staying or following."""
    for rc in found:
        if rc.verb is None:
            continue
        verb = s.verb(rc.verb)
        if verb in lx.ROBOT_WAIT_VERBS | lx.ROBOT_FOLLOW_VERBS | lx.ROBOT_PATROL_VERBS:
            continue
        at = _bound_at(s, rc.tokens, rc.verb)
        if at is None:
            continue
        after = [p for p in places.values() if p.match is not None and p.index >= at and p.index in rc.tokens]
        if after:
            first = min(after, key=lambda p: p.index)
            return first.match.name if first.match is not None else None
    return None


def people_passed_stay(s: Sentence, robot: RobotReading | None, found: Sequence[_Clause],
                       read: tuple[GroupReading, ...]) -> tuple[GroupReading, ...]:
    """The people the robot passes on a trip said after them ("threads through teenagers hanging
    around the fountain, headed for the cinema") stay where they are: the trip is the robot's, not theirs."""
    if robot is None or robot.task != "cross" or robot.destination is None:
        return read
    if not any(rc.verb is not None and s.verb(rc.verb) not in lx.ROBOT_WAIT_VERBS | lx.ROBOT_FOLLOW_VERBS
               and _bound_at(s, rc.tokens, rc.verb) is not None for rc in found):
        return read
    tokens = [i for rc in found for i in rc.tokens if rc.verb is not None and i > rc.verb]
    doing = [lx.INTENT_VERBS.get(verb_lemma(s.low[i])) for i in tokens if s.w[i].tag == "VBG"]
    intent = next((d for d in doing if d not in (None, "walk", "evacuate")), "wait")
    out: list[GroupReading] = []
    for g in read:
        here = g.location or g.start
        if g.destination == robot.destination and here is not None and here in robot.via and g.text == g.who:
            g = replace(g, intent=intent if g.intent == "walk" else g.intent, start=None, destination=None, location=here)
        out.append(g)
    return tuple(out)
