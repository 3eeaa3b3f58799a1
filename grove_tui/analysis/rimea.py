"""RiMEA verification tests (RiMEA e.V., Guideline for Microscopic Evacuation Analysis, v3) on GROVE's crowd.

Each test builds its geometry and people with `grove_tui.crowd.Crowd` (the kernel every scenario
runs on) at the product's step (dt 0.05 s) and returns a RimeaResult with the measured value and
whether it meets RiMEA's criterion. Tests 1, 4, 5, 6 and 7 are here; 9, 10, 11 and 12 need whole
buildings and are not implemented yet (issue 19). Run them with `grove validate rimea`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.sfm import MODE_STOP, SFMParams

DT = 0.05
RADIUS = 0.25


@dataclass(frozen=True)
class RimeaResult:
    test: int
    name: str
    measured: str
    criterion: str
    passed: bool


def _corridor(length: float, width: float, params: SFMParams) -> Crowd:
    walls = np.array([[-1.0, 0.0, length + 5.0, 0.0], [-1.0, width, length + 5.0, width],
                      [-1.0, 0.0, -1.0, width]])
    return Crowd(walls, params=params, dt=DT)


def test_1_corridor(params: SFMParams) -> RimeaResult:
    """One person, 1.33 m/s, walks 40 m of a 2 m corridor: 26-34 s."""
    crowd = _corridor(40.0, 2.0, params)
    i = crowd.add_agent((0.0, 1.0), radius=RADIUS, desired_speed=1.33, goals=[(60.0, 1.0)])
    while crowd.pos[i, 0] < 40.0 and crowd.time < 60.0:
        crowd.step(1)
    t = crowd.time
    return RimeaResult(1, "corridor 40 m at 1.33 m/s", f"{t:.1f} s", "26-34 s", 26.0 <= t <= 34.0)


def block_speed(density: float, params: SFMParams) -> float:
    """Mean speed of the middle of a block walking down a 4 m corridor at `density` persons/m^2."""
    width = 4.0
    walls = np.array([[-50.0, 0.0, 500.0, 0.0], [-50.0, width, 500.0, width]])
    crowd = Crowd(walls, params=params, dt=DT)
    spacing = 1.0 / math.sqrt(density)
    rows = max(int(width / spacing), 1)
    for c in range(int(30.0 / spacing)):
        for r in range(rows):
            y = (r + 0.5) * width / rows
            crowd.add_agent((c * spacing, y), radius=0.2, desired_speed=1.34, goals=[(1000.0, y)])
    crowd.step(int(2.0 / DT))
    start = crowd.pos[:, 0].copy()
    crowd.step(int(3.0 / DT))
    middle = (start > 10.0) & (start < 20.0)
    return float(np.mean(crowd.pos[middle, 0] - start[middle]) / 3.0)


def test_4_fundamental_diagram(params: SFMParams) -> RimeaResult:
    """Speed falls with density like Weidmann's curve; criterion of issue 19: v(3) <= 0.5 v(0.5)."""
    speeds = [block_speed(rho, params) for rho in (0.5, 1.0, 2.0, 3.0)]
    falling = all(a >= b for a, b in zip(speeds, speeds[1:]))
    return RimeaResult(4, "fundamental diagram 0.5/1/2/3 per m2", " / ".join(f"{v:.2f}" for v in speeds) + " m/s",
                       "falls; v(3) <= 0.5 v(0.5) (Weidmann 1.30/1.06/0.61/0.33)",
                       falling and speeds[3] <= 0.5 * speeds[0])


def test_5_premovement(params: SFMParams) -> RimeaResult:
    """Ten people in an 8 x 5 m room wait 10-100 s, then leave: each starts at its time, standing still before."""
    walls = np.array([[0, 0, 8, 0], [8, 0, 8, 2], [8, 3, 8, 5], [8, 5, 0, 5], [0, 5, 0, 0]], dtype=np.float64)
    crowd = Crowd(walls, params=params, dt=DT)
    times = np.linspace(10.0, 100.0, 10)
    starts = [(1.0 + 1.4 * (k % 5), 1.5 + 2.0 * (k // 5)) for k in range(10)]
    for p in starts:
        i = crowd.add_agent(p, radius=RADIUS, desired_speed=1.2)
        crowd.set_mode(i, MODE_STOP)
    moved_early = 0.0
    late = 0.0
    begun = [False] * 10
    while crowd.time < 105.0:
        for k in range(10):
            if not begun[k] and crowd.time + 1e-9 >= times[k]:
                begun[k] = True
                crowd.set_goals(k, [(9.0, 2.5), (12.0, 2.5)], goal_radius=0.3)
                crowd.set_mode(k, 0)
        crowd.step(1)
        for k in range(10):
            drift = math.dist(crowd.pos[k], starts[k])
            if not begun[k]:
                moved_early = max(moved_early, drift)
            elif crowd.time - times[k] > 2.0 and drift < 0.5:
                late = max(late, crowd.time - times[k])
    passed = moved_early <= 0.3 and late == 0.0
    return RimeaResult(5, "premovement 10-100 s", f"drift before start {100 * moved_early:.1f} cm",
                       "nobody leaves early (drift <= 0.3 m), everyone moves within 2 s", passed)


def test_6_corner(params: SFMParams) -> RimeaResult:
    """20 people walk round a left corner (2 m wide corridor): nobody passes through a wall."""
    # corridor east along y 0..2 to x 12, then north along x 10..12; measured to y 10.5 (RiMEA's
    # 10 m legs), the walls run on so that nobody crowds a dead end
    walls = np.array([[0, 0, 12, 0], [12, 0, 12, 40], [0, 2, 10, 2], [10, 2, 10, 40], [0, 0, 0, 2]],
                     dtype=np.float64)
    crowd = Crowd(walls, params=params, dt=DT)
    for k in range(20):
        crowd.add_agent((0.6 + 0.7 * (k // 2), 0.6 + 0.8 * (k % 2)), radius=RADIUS, desired_speed=1.2,
                        goals=[(11.0, 1.0), (11.0, 38.0)], goal_radius=0.5)
    inside = True
    while crowd.time < 60.0:
        crowd.step(1)
        x, y = crowd.pos[:, 0], crowd.pos[:, 1]
        legal = ((x > 0) & (x < 12) & (y > 0) & (y < 2)) | ((x > 10) & (x < 12) & (y > 0) & (y < 40))
        inside &= bool(legal.all())
        if (y > 10.5).all():
            break
    arrived = int((crowd.pos[:, 1] > 10.5).sum())
    return RimeaResult(6, "corner, 20 persons", f"{arrived}/20 round the corner in {crowd.time:.0f} s",
                       "all round, none through a wall", inside and arrived == 20)


def test_7_speed_distribution(params: SFMParams) -> RimeaResult:
    """50 people with desired speeds spread over 0.58-1.61 m/s (adults) walk at those speeds (+-5 %)."""
    rng = np.random.default_rng(7)
    speeds = rng.uniform(0.58, 1.61, 50)
    crowd = _corridor(1000.0, 2.0, params)
    for v in speeds:
        crowd.add_agent((0.0, 1.0), radius=RADIUS, desired_speed=float(v), goals=[(2000.0, 1.0)])
    measured = []
    for k in range(len(speeds)):
        # one at a time, alone in the corridor: the others are inactive and take no part
        for j in range(len(speeds)):
            crowd.set_active(j, j == k)
        crowd.step(int(2.0 / DT))
        x0 = float(crowd.pos[k, 0])
        crowd.step(int(5.0 / DT))
        measured.append((float(crowd.pos[k, 0]) - x0) / 5.0)
    error = float(np.max(np.abs(np.array(measured) / speeds - 1.0)))
    return RimeaResult(7, "speed distribution 0.58-1.61 m/s", f"worst {100 * error:.1f} % off",
                       "each walks its desired speed within 5 %", error <= 0.05)


TESTS: dict[int, Callable[[SFMParams], RimeaResult]] = {
    1: test_1_corridor, 4: test_4_fundamental_diagram, 5: test_5_premovement, 6: test_6_corner,
    7: test_7_speed_distribution,
}


def run_rimea(model: str = "grove", tests: tuple[int, ...] = tuple(TESTS)) -> list[RimeaResult]:
    params = SFMParams.named(model)
    return [TESTS[t](params) for t in tests]
