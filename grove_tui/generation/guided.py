"""The people the robot guides, and the exit it takes them to.

"... the passengers evacuate while the robot guides them to the exit": the robot's clause names an
exit ("the exit") the reader may be unsure of, and the passengers' exit is chosen by walking distance
at post-processing. A robot that guides people goes where they go: its destination is the exit most of
the guided group use, whatever place a model picked for "the exit" on its own. The report then carries
a claim that the guided people went with the robot, measured like any reaction to it.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence

from grove_tui.language.model import PromptReading
from grove_tui.language.tokens import lemma

# Words for the people the clause points back to rather than names ("guides them", "leads everyone out").
_POINTING = frozenset({"them", "everyone", "everybody", "all", "him", "her", "us", "people"})
_ARTICLES = frozenset({"a", "an", "the", "group", "of", "some", "all"})

# People the robot guides out ("the robot guides them to the exit") follow it as followers do, for as
# long as it drives to their exit (planning writes the duration), hurrying up to this pace when they
# fall behind: ApproachRobot walks at max_vel * d / (d + closest_dist), which keeps them about 1.5 m
# behind a robot at GUIDING_VEL (1.2 m/s = 2.0 * 1.5 / 2.5).
GUIDED_CATCH_UP = 2.0
GUIDED_CLOSEST = 1.0
GUIDING_VEL = 1.2  # m/s the robot leads an evacuation at: a brisk walk, not its 0.8 m/s service pace
# People who follow or are guided by the robot walk to a place this far behind it (crowd/led_slots.py),
# not at it: converging on the robot they stepped in front of it and its collision monitor stalled it.
LED_BEHIND = 1.0


def guided_follow(duration: float = 0.0) -> tuple[str, dict[str, float]]:
    """The node and ports that keep guided people behind the robot for `duration` seconds."""
    return "ApproachRobot", {"closest_dist": GUIDED_CLOSEST, "max_vel": GUIDED_CATCH_UP, "duration": duration,
                             "behind": LED_BEHIND}


def guided_seconds(path: Sequence[tuple[float, float]], robot_vel: float) -> float:
    """How long guided people keep behind the robot: its drive along `path` and a moment more. Then
    they walk out on their own, the exit in sight: kept round a robot stopped at the door, they were
    pushed out past it as people who were not evacuating."""
    length = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
    return round(length / max(robot_vel, 0.1) + 2.0, 1)


def guided_index(reading: PromptReading) -> int | None:
    """The reading group the robot's clause leads, or None when it leads nobody: the group its words
    name (for "them", the reader names the group it points back to: language/guided_route.py), else one
    that follows the robot."""
    robot = reading.robot
    if robot is None or robot.task != "cross" or not robot.guides or not reading.groups:
        return None
    said = {lemma(w) for w in robot.guides.lower().split()} - _ARTICLES - _POINTING
    if said:
        for i, g in enumerate(reading.groups):
            if said & {lemma(w) for w in g.who.lower().split()}:
                return i
    followers = [i for i, g in enumerate(reading.groups) if g.robot_interaction == "follow"]
    if followers:
        return followers[0]
    return None  # a pronoun the reader found no group for, or people the reading has no group for


def guided_exit(reading: PromptReading, groups: Sequence[object], agents: Sequence[object]) -> str | None:
    """The exit most members of the group the robot guides leave by (post-processing's per-agent
    exit), or None when it guides nobody or they leave by no exit. `groups` and `agents` are
    post-processing's plans or views of them (read by `reading_index`, `index`, `group_index`, `exit`)."""
    index = guided_index(reading)
    if index is None:
        return None
    plans = {getattr(g, "index", None) for g in groups if getattr(g, "reading_index", None) == index}
    exits = [e for a in agents if getattr(a, "group_index", None) in plans and (e := getattr(a, "exit", None))]
    return Counter(exits).most_common(1)[0][0] if exits else None
