"""Outcome checks (analysis/outcomes.py): every claim kind measured on hand-made runs.

Each check is run on a run where the outcome happens and on one where it does not: a check that
always said ✓ (or no check at all: the claim stays "not checked") fails the second test, one that
never did fails the first. The runs are built frame by frame on the clinic world, so what each
person does is exactly what the test says.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from grove_tui.analysis.metrics import Trajectories
from grove_tui.analysis.outcomes import OutcomeChecker, check_run
from grove_tui.scenario.events import SimEvent
from grove_tui.scenario.model import AgentSpec, RobotSpec, Scenario
from grove_tui.scenario.report import FAILS, HOLDS, UNCHECKED, Claim, GroundingReport, GroupGrounding, RobotGrounding

DT = 0.05


def scenario(n: int, robot: bool = True) -> Scenario:
    agents = tuple(AgentSpec(id=i, group=-1, start=(1.0, 1.0), goals=(), zone="lobby", tree=f"trees/agent_{i}.xml")
                   for i in range(1, n + 1))
    return Scenario("clinic", "normal", "test", 0, {}, agents,
                    RobotSpec((1.0, 4.0), (9.0, 4.0), path=((1.0, 4.0), (9.0, 4.0))) if robot else None)


def run(seconds: float, people, robot=None) -> Trajectories:
    """people(t) -> (N, 2) positions (NaN for absent); robot(t) -> (x, y) or None. Velocities and
    headings are the positions' own differences, as the recorder writes them."""
    t = np.arange(0.0, seconds + 1e-9, DT)
    pos = np.stack([np.asarray(people(x), dtype=float) for x in t])
    vel = np.gradient(pos, DT, axis=0)
    yaw = np.arctan2(vel[..., 1], vel[..., 0])
    r = rv = None
    if robot is not None:
        xy = np.stack([np.asarray(robot(x), dtype=float) for x in t])
        rv = np.gradient(xy, DT, axis=0)
        r = np.column_stack([xy, np.arctan2(rv[:, 1], rv[:, 0])])
    n = pos.shape[1]
    return Trajectories(t, np.arange(1, n + 1), pos, vel, yaw, np.full(n, -1), r, rv)


def check(clinic, claim: Claim, traj: Trajectories, events=(), members=(1, 2), robot_claims=()) -> Claim:
    group = GroupGrounding("people", "people", (claim,) if claim is not None else (), tuple(members))
    robot = RobotGrounding("cross", "the robot ...", tuple(robot_claims)) if robot_claims else None
    planned = GroundingReport("test", (group,), robot=robot)
    report = check_run(planned, scenario(traj.ids.size, traj.robot is not None), clinic, traj, list(events))
    assert report.checked
    if robot_claims:
        return report.robot.claims[0]
    return report.groups[0].claims[0]


def line(a, b, speed=1.0):
    """Walking from a to b at `speed`, then standing there."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    length = float(np.hypot(*(b - a)))

    def at(t):
        f = min(1.0, speed * t / length) if length else 1.0
        return a + (b - a) * f
    return at


def people(*walks):
    return lambda t: np.stack([w(t) for w in walks])


# ---- places -------------------------------------------------------------------------------------

def test_count_holds_when_everyone_is_in_the_run_and_fails_when_someone_is_missing(clinic):
    claim = Claim("count", "2", "2 people")
    both = run(2, people(line((1, 1), (1, 1)), line((2, 1), (2, 1))))
    assert check(clinic, claim, both).status == HOLDS
    one = run(2, lambda t: np.array([[1.0, 1.0], [np.nan, np.nan]]))
    assert check(clinic, claim, one).status == FAILS


def test_start_is_where_everyone_is_in_the_first_frame(clinic):
    claim = Claim("start", "lobby", "start in lobby", zone="lobby", share=1.0)
    assert check(clinic, claim, run(1, people(line((2, 2), (2, 2)), line((3, 2), (3, 2))))).status == HOLDS
    outcome = check(clinic, claim, run(1, people(line((2, 2), (2, 2)), line((20, 4), (20, 4)))))
    assert outcome.status == FAILS and "1/2 started in lobby" in outcome.evidence


def test_a_start_by_a_thing_says_the_zone_it_measures(clinic):
    # "four travellers wait at the meeting point": the start is checked in the thing's zone, and the
    # evidence says so (not "started in meeting_point" for people spawned 10 m from it)
    claim = Claim("start", "reception_desk", "start in lobby", zone="lobby", place="reception_desk", share=1.0)
    outcome = check(clinic, claim, run(1, people(line((2, 2), (2, 2)), line((3, 2), (3, 2)))))
    assert outcome.status == HOLDS and outcome.evidence == "2/2 started in lobby (where reception_desk is)"


def test_reach_counts_who_got_there_and_when(clinic):
    claim = Claim("reach", "pharmacy", "walk to pharmacy", zone="pharmacy", needs_seconds=40.0)
    to_pharmacy = people(line((4, 1), (16, 9)), line((5, 1), (17, 9)))
    reached = check(clinic, claim, run(40, to_pharmacy))
    assert reached.status == HOLDS and "2/2 reached pharmacy by t =" in reached.evidence
    stays = people(line((11, 4), (16, 9)), line((12, 4), (12, 4)))
    assert check(clinic, claim, run(60, stays)).status == FAILS
    # the run ends before the outcome can show: not checked, with the time it needs
    early = check(clinic, claim, run(3, to_pharmacy))
    assert early.status == UNCHECKED and "needs about 40 s" in early.evidence


def test_reach_is_not_a_cross_while_they_are_still_walking_on_to_it(clinic):
    # the estimate said 10 s, but the way is long: at the run's end one is still walking towards it
    claim = Claim("reach", "pharmacy", "walk to pharmacy", zone="pharmacy", needs_seconds=10.0)
    slow = people(line((4, 1), (16, 9), speed=1.0), line((4, 1), (16, 9), speed=0.25))
    outcome = check(clinic, claim, run(20, slow))
    assert outcome.status == UNCHECKED and "1 still walking on when the run ended" in outcome.evidence
    # a ✗ all the same when those walking on could not make it hold (a whole group asked, one stopped)
    one_stopped = people(line((4, 1), (6, 2)), line((4, 1), (16, 9), speed=0.25))
    assert check(clinic, claim, run(20, one_stopped)).status == FAILS
    # one who stopped short is a ✗ however short the run
    stopped = people(line((4, 1), (16, 9)), line((4, 1), (6, 2)))
    assert check(clinic, claim, run(20, stopped)).status == FAILS
    # walking on for three times the estimate and still not there: a ✗ (walking round in circles)
    circling = people(line((4, 1), (16, 9)), lambda t: np.array([4.0 + math.cos(t / 2), 2.0 + math.sin(t / 2)]))
    assert check(clinic, claim, run(31, circling)).status == FAILS


def test_reach_of_a_point_is_within_its_radius(clinic):
    claim = Claim("reach", "reception_desk", "walk to reception_desk", point=(5.0, 5.4), radius=1.5)
    assert check(clinic, claim, run(10, people(line((2, 1), (5, 5)), line((8, 1), (5.5, 4.5))))).status == HOLDS
    assert check(clinic, claim, run(10, people(line((2, 1), (5, 5)), line((8, 1), (8, 2))))).status == FAILS


def test_stay_is_staying_after_arriving(clinic):
    claim = Claim("stay", "cafeteria", "wait in cafeteria", zone="cafeteria")
    stayed = people(line((20, -3), (20, -3)), line((21, -3), (21, -3)))
    assert check(clinic, claim, run(20, stayed)).status == HOLDS
    leaves = people(line((20, -3), (20, -3)), line((21, -3), (21, 10), speed=1.0))
    assert check(clinic, claim, run(20, leaves)).status == FAILS


def test_stay_is_not_a_cross_while_they_are_still_walking_there(clinic):
    claim = Claim("stay", "pharmacy", "wait at pharmacy", zone="pharmacy", needs_seconds=10.0)
    slow = people(line((4, 1), (16, 9), speed=1.0), line((4, 1), (16, 9), speed=0.25))
    outcome = check(clinic, claim, run(20, slow))
    assert outcome.status == UNCHECKED and "still walking on" in outcome.evidence
    assert check(clinic, claim, run(20, people(line((4, 1), (16, 9)), line((4, 1), (5, 1))))).status == FAILS


def test_an_asked_wait_needs_a_run_as_long_as_the_wait(clinic):
    claim = Claim("stay", "cafeteria for 300 s", "wait", zone="cafeteria", seconds=300.0, needs_seconds=305.0)
    stayed = people(line((20, -3), (20, -3)), line((21, -3), (21, -3)))
    assert check(clinic, claim, run(30, stayed)).status == UNCHECKED


def test_an_asked_wait_is_judged_over_its_seconds_and_leaving_after_it_is_no_cross(clinic):
    # "wait in the cafeteria for 10 seconds and then walk to the pharmacy"
    claim = Claim("stay", "cafeteria for 10 s", "wait", zone="cafeteria", seconds=10.0, needs_seconds=15.0)

    def wait_then_go(x, stays):
        return lambda t: np.array([x, -3.0]) if t < stays else np.array([x, -3.0 + 1.5 * (t - stays)])
    waited = people(wait_then_go(20, 11.0), wait_then_go(21, 11.0))
    held = check(clinic, claim, run(30, waited))
    assert held.status == HOLDS and "of the 10 s after arriving" in held.evidence
    cut_short = people(wait_then_go(20, 11.0), wait_then_go(21, 1.0))  # out of it 5 s after arriving
    assert check(clinic, claim, run(30, cut_short)).status == FAILS


def test_an_asked_wait_by_a_thing_is_not_cut_short_by_passing_it_first(clinic):
    # "a family of four waits at the lounge seats for a minute then walks on": one of them walks past
    # the seats with the others (2.5 m from them for a few seconds), goes round the other way, comes
    # back and waits the minute there; the wait holds for them (on main: "3/4 stayed", a false ✗)
    claim = Claim("stay", "seats for 20 s", "wait at seats 20 s", place="seats", point=(20.0, -3.0), radius=3.0,
                  seconds=20.0, needs_seconds=40.0)

    def pass_then_come_back(t):
        if t < 10.0:
            return np.array([14.0 + 1.0 * t, -0.5])  # by the seats (2.5 m off) at t 4-8, on past them
        if t < 20.0:
            return np.array([24.0, -0.5])  # round the other side
        return np.array([20.0, -3.0])  # back, and waits there
    came_back = people(pass_then_come_back, line((20, -3), (20, -3)))
    held = check(clinic, claim, run(50, came_back))
    assert held.status == HOLDS, held.evidence
    # who never comes back to wait still fails
    passed_by = people(lambda t: np.array([14.0 + 1.0 * t, -0.5]) if t < 10.0 else np.array([24.0, -0.5]),
                       line((20, -3), (20, -3)))
    assert check(clinic, claim, run(50, passed_by)).status == FAILS


def test_wander_is_moving_around_inside_the_zone(clinic):
    claim = Claim("wander", "cafeteria", "wander in cafeteria", zone="cafeteria")

    def roam(phase):
        return lambda t: np.array([20 + 3 * math.cos(0.3 * t + phase), -3 + 3 * math.sin(0.3 * t + phase)])
    assert check(clinic, claim, run(30, people(roam(0.0), roam(2.0)))).status == HOLDS
    still = people(line((20, -3), (20, -3)), line((21, -3), (21, -3)))
    assert check(clinic, claim, run(30, still)).status == FAILS


def test_move_is_walking_somewhere(clinic):
    claim = Claim("move", "walk", "walk")
    assert check(clinic, claim, run(10, people(line((1, 1), (8, 1)), line((1, 3), (8, 3))))).status == HOLDS
    assert check(clinic, claim, run(10, people(line((1, 1), (1, 1)), line((1, 3), (1, 3))))).status == FAILS


def test_leave_is_being_out_of_the_place_at_some_time(clinic):
    claim = Claim("leave", "lobby", "walk out", zone="lobby")
    out = people(line((5, 4), (14, 4)), line((6, 4), (16, 4)))  # into the corridor
    held = check(clinic, claim, run(15, out))
    assert held.status == HOLDS and "2/2 left lobby" in held.evidence
    stay = people(line((5, 4), (8, 4)), line((6, 4), (14, 4)))
    assert check(clinic, claim, run(15, stay)).status == FAILS


def test_keep_out_is_never_setting_foot_in_the_place(clinic):
    claim = Claim("keep_out", "lobby", "plan round lobby", zone="lobby", share=1.0)
    # two walk along the corridor, east of the lobby; then one of them cuts back through it
    apart = people(line((14, 4), (18, 4)), line((16, 4), (19, 4)))
    held = check(clinic, claim, run(15, apart))
    assert held.status == HOLDS and "2/2 never in lobby" in held.evidence
    through = people(line((14, 4), (18, 4)), line((16, 4), (5, 4)))
    failed = check(clinic, claim, run(15, through))
    assert failed.status == FAILS and "1/2 never in lobby" in failed.evidence and "first in at" in failed.evidence


def test_pace_is_the_walking_speed_against_the_asked_band(clinic):
    slow = Claim("pace", "slow", "0.7 m/s", low=0.2, high=0.85)
    assert check(clinic, slow, run(10, people(line((1, 1), (9, 1), 0.6), line((1, 3), (9, 3), 0.6)))).status == HOLDS
    outcome = check(clinic, slow, run(10, people(line((1, 1), (9, 1), 1.3), line((1, 3), (9, 3), 1.3))))
    assert outcome.status == FAILS and "walking pace 1.3" in outcome.evidence


# ---- events -------------------------------------------------------------------------------------

def still(n=2):
    return run(5, lambda t: np.array([[2.0 + i, 2.0] for i in range(n)]))


def test_queue_is_joined_advanced_and_served_at_the_named_counter(clinic):
    claim = Claim("queue", "pharmacy", "queue at pharmacy_counter", place="pharmacy_counter")
    events = [SimEvent(1.0, 1, "queue_join", "pharmacy_counter"), SimEvent(1.0, 2, "queue_join", "pharmacy_counter"),
              SimEvent(12.0, 1, "queue_served", "pharmacy_counter"), SimEvent(12.5, 2, "queue_advance",
                                                                              "pharmacy_counter")]
    assert check(clinic, claim, still(), events).status == HOLDS
    elsewhere = [SimEvent(1.0, m, "queue_join", "coffee_counter") for m in (1, 2)]
    outcome = check(clinic, claim, still(), elsewhere)
    assert outcome.status == FAILS and "queued elsewhere: coffee_counter" in outcome.evidence
    nobody_served = events[:2]
    assert check(clinic, claim, still(), nobody_served).status == FAILS


def test_converse_needs_a_conversation_event_with_the_partners(clinic):
    claim = Claim("converse", "talk together", "circle", partners=(1, 2))
    talked = [SimEvent(8.0, 1, "conversation_start", "1,2"), SimEvent(8.0, 2, "conversation_start", "1,2")]
    assert check(clinic, claim, still(), talked).status == HOLDS
    with_strangers = [SimEvent(8.0, 1, "conversation_start", "1,5"), SimEvent(8.0, 2, "conversation_start", "2,6")]
    assert check(clinic, claim, still(), with_strangers).status == FAILS
    # a circle that started without its last arrival (the simulation's patience) is one circle once
    # it joins: everyone talked with everyone
    three = Claim("converse", "talk together", "circle", partners=(1, 2, 3))
    late = [SimEvent(60.0, 1, "conversation_start", "1,2"), SimEvent(60.0, 2, "conversation_start", "1,2"),
            SimEvent(75.0, 3, "conversation_start", "1,2,3")]
    held = check(clinic, three, still(3), late, members=(1, 2, 3))
    assert held.status == HOLDS and "3/3 talked" in held.evidence
    never = late[:2]
    assert check(clinic, three, still(3), never, members=(1, 2, 3)).status == FAILS


def test_evacuate_counts_who_is_out_and_through_which_exit(clinic):
    claim = Claim("evacuate", "main_entrance", "field", exits=("main_entrance",))
    out = [SimEvent(20.0, 1, "evacuated", "main_entrance"), SimEvent(24.0, 2, "evacuated", "main_entrance")]
    held = check(clinic, claim, still(), out)
    assert held.status == HOLDS and "2/2 out" in held.evidence and "t = 24.0 s" in held.evidence
    back_door = [SimEvent(20.0, 1, "evacuated", "back_exit"), SimEvent(24.0, 2, "evacuated", "back_exit")]
    assert check(clinic, claim, still(), back_door).status == FAILS
    assert check(clinic, Claim("evacuate", "any exit", "field"), still(), back_door).status == HOLDS


# ---- the robot ----------------------------------------------------------------------------------

ROBOT = line((1, 4), (9, 4), 0.8)


def test_robot_follow_is_keeping_close_while_it_moves(clinic):
    claim = Claim("robot_follow", "follow the robot", "ApproachRobot", distance=3.0)

    def behind(offset):
        return lambda t: ROBOT(t) - np.array([offset, 0.0])
    assert check(clinic, claim, run(10, people(behind(1.5), behind(2.0)), ROBOT)).status == HOLDS
    stay = people(line((1, 1), (1, 1)), line((2, 1), (2, 1)))
    assert check(clinic, claim, run(10, stay, ROBOT)).status == FAILS


def test_robot_approach_is_coming_within_reach(clinic):
    claim = Claim("robot_approach", "approach the robot", "ApproachRobot", distance=2.0)
    towards = people(line((5, 7), (5, 5)), line((6, 7), (6, 5)))
    held = check(clinic, claim, run(10, towards, ROBOT))
    assert held.status == HOLDS and "closest" in held.evidence
    away = people(line((5, 7.5), (5, 7.5)), line((6, 7.5), (6, 7.5)))
    assert check(clinic, claim, run(10, away, ROBOT)).status == FAILS


def test_robot_block_is_standing_in_its_path_and_slowing_it(clinic):
    claim = Claim("robot_block", "block the robot", "BlockRobot", distance=2.5, share=0.5)
    stopped = line((1, 4), (3, 4), 0.8)  # the robot stops at x = 3 ...
    blocker = people(line((4, 4), (4, 4)), line((8, 1), (8, 1)))  # ... with someone 1 m in front of it
    held = check(clinic, claim, run(10, blocker, stopped))
    assert held.status == HOLDS and "slowed it" in held.evidence
    # standing in its way while it drives on at full speed is not blocking it
    passing = people(lambda t: ROBOT(t) + np.array([1.0, 0.0]), line((8, 1), (8, 1)))
    assert check(clinic, claim, run(8, passing, ROBOT)).status == FAILS


def test_robot_avoid_is_moving_away_when_it_comes_near(clinic):
    claim = Claim("robot_avoid", "avoid the robot", "AvoidRobot", distance=4.0)

    def flee(x):
        return lambda t: np.array([x, 5.5 + max(0.0, 1.2 - abs(ROBOT(t)[0] - x)) * 1.5])
    assert check(clinic, claim, run(10, people(flee(5.0), flee(6.0)), ROBOT)).status == HOLDS
    stand = people(line((5, 5.5), (5, 5.5)), line((6, 5.5), (6, 5.5)))
    assert check(clinic, claim, run(10, stand, ROBOT)).status == FAILS


def test_robot_look_is_facing_it_while_in_sight(clinic):
    claim = Claim("robot_look", "look at the robot", "LookAtRobot", distance=10.0)
    trajectory = run(10, people(line((5, 6), (5, 6)), line((6, 6), (6, 6))), ROBOT)
    robot_xy = trajectory.robot[:, :2]
    facing = np.arctan2(robot_xy[:, None, 1] - trajectory.people[..., 1], robot_xy[:, None, 0] - trajectory.people[..., 0])
    looked = Trajectories(trajectory.t, trajectory.ids, trajectory.people, trajectory.people_vel, facing,
                          trajectory.groups, trajectory.robot, trajectory.robot_vel)
    assert check(clinic, claim, looked).status == HOLDS
    away = Trajectories(trajectory.t, trajectory.ids, trajectory.people, trajectory.people_vel, facing + math.pi,
                        trajectory.groups, trajectory.robot, trajectory.robot_vel)
    assert check(clinic, claim, away).status == FAILS


def test_follow_person_is_keeping_close_to_the_partners(clinic):
    claim = Claim("follow_person", "follow the nurse", "walk with nurse", partners=(3,), distance=3.0)
    nurse = line((1, 3), (9, 3))
    close = run(10, people(lambda t: nurse(t) - [1.0, 0.0], lambda t: nurse(t) - [2.0, 0.0], nurse))
    assert check(clinic, claim, close).status == HOLDS
    apart = run(10, people(line((1, 1), (1, 1)), line((2, 1), (2, 1)), nurse))
    assert check(clinic, claim, apart).status == FAILS


def test_follow_person_counts_the_time_the_followed_walk(clinic):
    # the nurse walks 8 m in 8 s and then stands for 22 s; the two behind keep up on the way and then
    # stand 6 m off: following is being close on the way, not standing beside her at the end
    claim = Claim("follow_person", "follow the nurse", "walk with nurse", partners=(3,), distance=3.0)
    nurse = line((1, 3), (9, 3))

    def behind(k):
        return lambda t: nurse(t) - [k, 0.0] if t < 8.5 else np.array([3.0 - k, 3.0])
    held = check(clinic, claim, run(30, people(behind(1.0), behind(2.0), nurse)))
    assert held.status == HOLDS and "of the time they walked" in held.evidence
    lagging = check(clinic, claim, run(30, people(line((1, 1), (2, 1)), line((1, 2), (2, 2)), nurse)))
    assert lagging.status == FAILS


def test_follow_person_takes_a_column_behind_them_as_following(clinic):
    # five walk in single file 1.5 m apart behind the nurse: the tail is 7.5 m back, yet with her
    claim = Claim("follow_person", "follow the nurse", "walk with nurse", partners=(6,), distance=3.0)
    nurse = line((8, 3), (18, 3))
    column = [(lambda k: lambda t: nurse(t) - [1.5 * k, 0.0])(k) for k in range(1, 6)]
    held = check(clinic, claim, run(10, people(*column, nurse)), members=(1, 2, 3, 4, 5))
    assert held.status == HOLDS and "5/5" in held.evidence
    # the same column 6 m back from her: a column, but not with her
    apart = [(lambda k: lambda t: nurse(t) - [4.5 + 1.5 * k, 0.0])(k) for k in range(1, 6)]
    assert check(clinic, claim, run(10, people(*apart, nurse)), members=(1, 2, 3, 4, 5)).status == FAILS


def test_the_robots_own_claims(clinic):
    reach = Claim("robot_reach", "corridor", "drive to corridor", zone="corridor")
    via = Claim("robot_via", "lobby", "drive through lobby", zone="lobby")
    stay = Claim("robot_stay", "where it is", "wait", point=(1.0, 4.0), radius=1.0)
    patrol = Claim("robot_patrol", "corridor", "patrol", point=(15.0, 4.0), radius=1.0)
    crossing = line((2, 4), (15, 4), 1.0)
    drive = run(20, people(line((1, 1), (1, 1)), line((2, 1), (2, 1))), crossing)
    assert check(clinic, None, drive, robot_claims=(reach,)).status == HOLDS
    assert check(clinic, None, drive, robot_claims=(via,)).status == HOLDS
    assert check(clinic, None, drive, robot_claims=(stay,)).status == FAILS
    assert check(clinic, None, drive, robot_claims=(patrol,)).status == FAILS  # it never came back

    def there_and_back(t):
        return crossing(t) if t <= 13 else crossing(13) + np.array([-(t - 13), 0.0])
    round_trip = run(30, people(line((1, 1), (1, 1)), line((2, 1), (2, 1))), there_and_back)
    assert check(clinic, None, round_trip, robot_claims=(patrol,)).status == HOLDS
    parked = run(20, people(line((1, 1), (1, 1)), line((2, 1), (2, 1))), line((1, 4), (1, 4)))
    assert check(clinic, None, parked, robot_claims=(stay,)).status == HOLDS
    assert check(clinic, None, parked, robot_claims=(reach,)).status == FAILS
    follow = Claim("robot_follow_person", "follow the people", "follow", partners=(1,), distance=3.0)
    ahead = run(10, people(lambda t: crossing(t) + [1.5, 0.0], line((2, 1), (2, 1))), crossing)
    assert check(clinic, None, ahead, robot_claims=(follow,)).status == HOLDS
    far = run(20, people(line((8, 1), (8, 1)), line((2, 1), (2, 1))), line((1, 4), (1, 4)))
    assert check(clinic, None, far, robot_claims=(follow,)).status == FAILS


def test_a_robot_wait_with_asked_seconds_needs_them_at_the_place(clinic):
    # "the robot waits at reception for two minutes": a 20 s run there is no ✓ (run it longer), a
    # 130 s run there is, and leaving after 30 s of a 130 s run is a ✗
    stay = Claim("robot_stay", "reception for 120 s", "wait", point=(1.0, 4.0), radius=1.0, seconds=120.0,
                 needs_seconds=125.0)
    bystanders = people(line((1, 1), (1, 1)), line((2, 1), (2, 1)))
    short = check(clinic, None, run(20, bystanders, line((1, 4), (1, 4))), robot_claims=(stay,))
    assert short.status == UNCHECKED and "run it longer" in short.evidence
    whole = check(clinic, None, run(130, bystanders, line((1, 4), (1, 4))), robot_claims=(stay,))
    assert whole.status == HOLDS

    def leaves(t):
        return np.array([1.0, 4.0]) if t < 30 else np.array([min(1.0 + (t - 30), 15.0), 4.0])
    assert check(clinic, None, run(130, bystanders, leaves), robot_claims=(stay,)).status == FAILS


# ---- streaming ----------------------------------------------------------------------------------

def test_chunks_give_the_same_report_as_the_whole_run(clinic):
    claims = (Claim("reach", "pharmacy", "walk", zone="pharmacy"), Claim("move", "walk", "walk"),
              Claim("pace", "fast", "fast", low=1.15, high=3.0))
    planned = GroundingReport("test", (GroupGrounding("people", "people", claims, (1, 2)),))
    whole = run(40, people(line((11, 4), (16, 9)), line((12, 4), (17, 9), 1.4)))
    sc = scenario(2, robot=False)
    once = check_run(planned, sc, clinic, whole, [])
    checker = OutcomeChecker(planned, sc, clinic)
    checker.set_ids(whole.ids)
    for k in range(0, whole.frames, 37):  # blocks that do not line up with the sampling
        sl = slice(k, k + 37)
        checker.add(Trajectories(whole.t[sl], whole.ids, whole.people[sl], whole.people_vel[sl],
                                 whole.people_yaw[sl], whole.groups, None, None))
    assert checker.result([]).groups == once.groups


def test_asking_for_the_live_report_midway_changes_nothing_of_the_final_one(clinic):
    # the app asks for the checked report again and again while a run plays: a probe must only read
    claim = Claim("follow_person", "follow the nurse", "walk with nurse", partners=(3,), distance=3.0)
    planned = GroundingReport("test", (GroupGrounding("people", "people", (claim,), (1, 2)),))
    nurse = line((1, 3), (9, 3))
    whole = run(20, people(lambda t: nurse(t) - [1.0, 0.0], line((1, 1), (1, 1)), nurse))
    sc = scenario(3, robot=False)
    once = check_run(planned, sc, clinic, whole, [])
    checker = OutcomeChecker(planned, sc, clinic)
    checker.set_ids(whole.ids)
    for k in range(0, whole.frames, 50):
        sl = slice(k, k + 50)
        checker.add(Trajectories(whole.t[sl], whole.ids, whole.people[sl], whole.people_vel[sl],
                                 whole.people_yaw[sl], whole.groups, None, None))
        checker.result([], partial=True)
    assert checker.result([]).groups == once.groups


def test_the_robot_passes_people_only_while_they_are_there(clinic):
    """robot_passes ("drives through the queue"): within reach of one of them in the place; a queue's
    people count from their joining it, so passing the counter before anyone queues is no passing."""
    crowd = Claim("robot_passes", "through the people in lobby", "drive through", zone="lobby", partners=(1, 2),
                  distance=2.0)
    crossing = line((1, 4), (15, 4), 1.0)  # along y = 4 through the lobby, in it until t = 9
    near = run(20, people(line((5, 5), (5, 5)), line((6, 5.5), (6, 5.5))), crossing)
    assert check(clinic, None, near, robot_claims=(crowd,)).status == HOLDS
    far = run(20, people(line((5, 7.5), (5, 7.5)), line((6, 7.5), (6, 7.5))), crossing)
    missed = check(clinic, None, far, robot_claims=(crowd,))
    assert missed.status == FAILS and "closest 3.5 m" in missed.evidence
    queue = replace(crowd, place="reception_desk")
    late = [SimEvent(12.0, 1, "queue_join", "reception_desk"), SimEvent(12.5, 2, "queue_join", "reception_desk")]
    assert check(clinic, None, near, events=late, robot_claims=(queue,)).status == FAILS  # gone before they queued
    early = [SimEvent(1.0, 1, "queue_join", "reception_desk")]
    assert check(clinic, None, near, events=early, robot_claims=(queue,)).status == HOLDS
    none = check(clinic, None, near, events=(), robot_claims=(queue,))
    assert none.status == FAILS and "nobody queued" in none.evidence


def test_the_robots_keep_out_is_its_own_trajectory_never_in_the_place(clinic):
    """keep_out in the robot's row ("drives along the corridor, avoiding the pharmacy") is measured on the
    robot, not on a group of nobody: never in the room holds once its drive is over, in it is ✗."""
    keep = Claim("keep_out", "pharmacy", "drive round pharmacy", zone="pharmacy", place="pharmacy", share=1.0,
                 needs_seconds=12.0)
    still = people(line((1, 1), (1, 1)), line((2, 1), (2, 1)))
    along = run(20, still, line((1, 4), (9, 4), 1.0))  # stays in the lobby, reaches its goal (9, 4)
    kept = check(clinic, None, along, robot_claims=(keep,))
    assert kept.status == HOLDS and "never in pharmacy" in kept.evidence
    into = run(20, still, line((1, 4), (17, 10), 1.5))  # through the corridor into the pharmacy
    went = check(clinic, None, into, robot_claims=(keep,))
    assert went.status == FAILS and "was in pharmacy at t =" in went.evidence
    short = run(5, still, line((1, 4), (9, 4), 0.5))  # neither in nor at its goal yet: too soon to tell
    assert check(clinic, None, short, robot_claims=(keep,)).status == UNCHECKED
