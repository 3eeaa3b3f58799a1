"""That a group stays where the sentence puts it, claimed and checked on the run.

"Two friends talk in the great hall", "students study at the reading tables and keep out of the robot's
way", "a guard stands by the door and watches the robot": the sentence places them and says nothing of
leaving, so they spend the run (or the asked while) there. A plain wait already gets a stay claim; a
group that talks there, or whose own words only react to the robot where they are, got a start (or a
conversation) but nothing that they stay. `stay_claims` adds it: the group spends most of the run (the
probe's STAY_SHARE of the time after arriving), or the asked while, in the place's zone.

A group that keeps away from the robot gives way inside the zone it stands in (crowd/keep_in_place.py),
a few metres off its spot, so its stay is judged on the zone, never on the spot alone: stepping aside
for the robot is what the sentence asked, not leaving. Looking at the robot does not move anyone.

Plain data in, claims out; generation/reconcile.py calls it last for every group.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace

from grove_tui.scenario.report import Claim
from grove_tui.world.model import World

STAY_NEEDS = 30.0  # seconds after the arrival before a stay over "most of the run" can be told
IN_PLACE_REACTIONS = ("avoid", "look")  # reactions that keep the person where they are (a step aside at most)
MOVING_KINDS = ("reach", "evacuate", "leave", "queue", "move", "wander", "follow_person", "robot_follow",
                "robot_approach", "robot_block")  # claims of groups that go somewhere: no stay of their own


def stay_claims(claims: Sequence[Claim], *, reaction: str | None, place: str | None, spawn: str, world: World,
                eta: Callable[[str | None], float], seconds: float | None, talks: bool, goes_on: bool) -> list[Claim]:
    """`claims` with the group's stay where the sentence puts it: added for a group that talks there or
    only reacts in place, and judged on the zone for one that keeps away from the robot.

    `reaction` the group's robot interaction; `place` where the sentence puts it (location, else start);
    `spawn` the zone it starts in; `eta` the time its slowest member needs to get to a place; `seconds`
    an asked while; `talks` its activity is a conversation; `goes_on` it walks on somewhere afterwards."""
    out = [_zone_stay(c, world) if c.kind == "stay" and reaction == "avoid" else c for c in claims]
    if goes_on or any(c.kind in ("stay", *MOVING_KINDS) for c in out):
        return out
    if not talks and reaction not in IN_PLACE_REACTIONS:
        return out
    zone = (world.zone_of_place(place) if place else None) or spawn
    if not zone:
        return out
    asked = f"{place or zone}" + (f" for {seconds:g} s" if seconds else " (most of the run)")
    what = "talk" if talks else "stand" if reaction == "look" else "stay, stepping aside for the robot"
    claim = Claim("stay", asked, f"{what} in {zone}", zone=zone, place=zone,
                  needs_seconds=round(eta(place or zone) + (seconds or STAY_NEEDS), 1), seconds=seconds)
    return out + [claim]


def _zone_stay(claim: Claim, world: World) -> Claim:
    """A stay at a spot, judged on the spot's zone: keeping away from the robot steps off the spot."""
    if claim.point is None or not claim.place:
        return claim
    zone = world.zone_of_place(claim.place)
    if not zone:
        return claim
    return replace(claim, zone=zone, place=zone, point=None, radius=0.0,
                   plan=f"{claim.plan} (in {zone}: they step aside there for the robot)")
