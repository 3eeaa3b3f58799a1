"""A look tied to the moment the robot passes is checked in that moment, not at any time.

"A guide looks up as the robot passes the desk": the look claim was checked as a glance at any time the
robot was within LOOK_RANGE, and in one run the robot was within 10 m of the guide for 2 s and never came by
the desk while they looked, yet the look read ✓. A reaction the sentence ties to the robot passing
(language/passing_moment.py) now carries that moment: the claim's `moment` is "pass", and its `point` the
place passed (within PASS_AT of it), else the people themselves (within PASS_BY of them). The probe
(analysis/outcomes._RobotLookProbe) counts only looks in those frames and says when the robot passed and
when they looked.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.analysis.outcomes import PASS_AT, PASS_BY
from grove_tui.generation.draft import DraftNode
from grove_tui.language.model import GroupReading, PromptReading
from grove_tui.language.passing_moment import passing_moment
from grove_tui.scenario.report import Claim
from grove_tui.world.model import Door, Entity, World



def _point(world: World, place: str) -> tuple[float, float] | None:
    try:
        obj = world.find(place)
    except Exception:
        return None
    if isinstance(obj, Entity):
        return obj.interaction_point
    if isinstance(obj, Door):
        return obj.inward_point(0.6)
    return None  # a zone: the people themselves are the moment's place


def cued_as_it_passes(tree: DraftNode, group: GroupReading, reading: PromptReading) -> DraftNode:
    """A look tied to the robot passing turns them to it as it passes (within PASS_AT), not as soon as it is
    within a look's 10 m: a glance cued at 10 m fired at t = 0 and was over before the robot came by the desk."""
    moment = passing_moment(reading.prompt, group, reading.robot) if group.robot_interaction == "look" else None
    if moment is None:
        return tree
    # as it passes a place: within PASS_AT; as it passes them: within PASS_BY, the window the look is checked in
    # (cued at PASS_AT, queueing patients the robot passed at 4.2 m never turned: 2/6 looked)
    return _cued(tree, PASS_AT if moment.place else PASS_BY)


def _cued(tree: DraftNode, reach: float) -> DraftNode:
    ports = dict(tree.ports)
    if tree.node == "IsRobotClose" and float(ports.get("threshold", 0.0)) > reach:
        ports["threshold"] = reach
    return DraftNode(tree.node, ports, tuple(_cued(c, reach) for c in tree.children))


def passing_looks(claims: list[Claim], group: GroupReading, reading: PromptReading, world: World) -> list[Claim]:
    """The group's look claim tied to the moment the robot passes, when the sentence ties it there."""
    if not any(c.kind == "robot_look" for c in claims):
        return claims
    moment = passing_moment(reading.prompt, group, reading.robot)
    if moment is None:
        return claims
    point = _point(world, moment.place) if moment.place else None
    out = []
    for c in claims:
        if c.kind != "robot_look":
            out.append(c)
            continue
        if point is None and moment.place and world.zone_of_place(moment.place) == moment.place:
            # "as it passes the gateline", a zone: while the robot is in it, not near them anywhere
            out.append(replace(c, asked=c.asked + f", as the robot passes {moment.place}", moment="pass",
                               place=moment.place, point=None))
        elif point is not None:
            out.append(replace(c, asked=c.asked + f", as the robot passes {moment.place}", moment="pass",
                               place=moment.place, point=(round(point[0], 3), round(point[1], 3)), radius=PASS_AT))
        else:
            out.append(replace(c, asked=c.asked + ", as the robot passes them", moment="pass", radius=PASS_BY,
                               distance=PASS_BY))  # checked within PASS_BY of them, cued there
    return out
