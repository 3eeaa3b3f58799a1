"""A glance is not a stare: what "look at the robot" asks of the run and of the report.

The reading says a group looks at the robot (robot_interaction "look"); language/look_spans.py says for how
long, from the group's own verb:

- a glance ("glance at the robot as it passes", "look at the robot", "notice it", "take a photo of it"): at
  least once, for a short while. People with something else to do turn to it once, briefly
  (SurprisedNav for GLANCE_REACTION seconds, once), and go on; the report checks one look of at least
  GLANCE_SECONDS while it was within reach of their eyes (analysis/outcomes.py, a look claim with `seconds`).
- a stare ("stare at the robot", "watch it", "keep looking at it", "... the whole time"): most of the time it
  is near. Their reaction fires again every time the robot is near (not once), and the report checks that
  they faced it for LOOK_SHARE of the time it was within LOOK_RANGE (a look claim without `seconds`).

People whose whole activity is looking at the robot stare at it all the time (LookAtRobot); when they only
glance ("two cleaners glance at the robot as it passes") they stand where they are and turn to it once, briefly,
when it comes near (`glancing`).
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.scenario.reach import GLANCE_SECONDS, LOOK_RANGE, LOOK_SHARE
from grove_tui.generation.draft import DraftNode
from grove_tui.language.look_spans import GLANCE, look_span
from grove_tui.language.model import GroupReading
from grove_tui.scenario.report import FAILS, Claim

GLANCE_REACTION = 4.0  # seconds a glance turns a busy person to the robot
STARE_REACTION = 30.0  # seconds of one stare; it starts again while the robot is near


def glance_or_stare(tree: DraftNode, group: GroupReading) -> DraftNode:
    """The SurprisedNav of a looking group's reaction around its routine, as long as its look (module doc);
    any other tree unchanged."""
    span = look_span(group)
    if span is None:
        return tree
    ports = {"beh_duration": GLANCE_REACTION, "only_once": True} if span == GLANCE else \
        {"beh_duration": STARE_REACTION, "only_once": False}
    return _with_ports(tree, "SurprisedNav", ports)


def glancing(group: GroupReading, seconds: float) -> DraftNode | None:
    """The tree of people whose whole activity is a glance at the robot: they stand `seconds` and turn to it
    once when it comes within LOOK_RANGE; None for anyone else (a stare is LookAtRobot)."""
    if look_span(group) != GLANCE:
        return None
    cue = DraftNode("IsRobotClose", {"threshold": LOOK_RANGE})
    look = DraftNode("SurprisedNav", {"beh_duration": GLANCE_REACTION, "only_once": True})
    reaction = DraftNode("Sequence", {}, (cue, DraftNode("ForceFailure", {}, (look,))))
    stand = DraftNode("Wait", {"duration": seconds})
    if group.together:
        stand = DraftNode("Sequence", {}, (DraftNode("JoinGroup", {}), stand))
    return DraftNode("ReactiveFallback", {}, (reaction, stand))


def _with_ports(tree: DraftNode, node: str, ports: dict[str, float | bool]) -> DraftNode:
    children = tuple(_with_ports(c, node, ports) for c in tree.children)
    own = {**tree.ports, **ports} if tree.node == node else tree.ports
    return DraftNode(tree.node, dict(own), children)


def look_claim(claim: Claim, group: GroupReading) -> Claim:
    """A look claim as long as the sentence's look: one look of GLANCE_SECONDS for a glance, LOOK_SHARE of
    the time the robot is near for a stare."""
    span = look_span(group)
    if span is None or claim.status == FAILS:
        return claim
    if span == GLANCE:
        return replace(claim, asked="look at the robot at least once (a glance)", seconds=GLANCE_SECONDS)
    return replace(claim, asked=f"look at the robot most of the time it is near (a stare: {LOOK_SHARE:.0%})",
                   seconds=None)
