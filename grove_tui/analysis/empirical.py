"""GROVE's crowd against measurements of real crowds: `grove validate empirical`, beside RiMEA.

RiMEA's tests (analysis/rimea.py) are loose: test 4 only asks that speed falls with density. These
checks compare numbers with published experiments, whose values and sources live in
`data/empirical.yaml`:

- fundamental diagram: the mean speed in a corridor with no ends (periodic, 30 x 4 m) at 0.5, 1, 2,
  3 and 4 persons/m^2, within 15 % of Weidmann's (1993) speed-density relation;
- bottleneck: the specific flow through bottlenecks 0.8 to 2.4 m wide (2 m long, fed from a
  12 x 12 m room) inside the band of laboratory experiments and guidelines, and linear in width
  (Seyfried et al. 2009, Kretz et al. 2006, Liao et al. 2014);
- lanes: two crowds walking against each other in a corridor with no ends, mixed at random, sort
  themselves into lanes: the lane order parameter rises over a minute and ends well above the same
  people with shuffled directions (Zhang et al. 2012).

Everyone has the product's body radius (scenario.model.DEFAULT_AGENT_RADIUS) and Weidmann's free
speed 1.34 m/s; the crowd steps at the product's dt of 0.05 s.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from grove_tui.analysis import rimea
from grove_tui.crowd.crowd import Crowd
from grove_tui.crowd.sfm import SFMParams
from grove_tui.scenario.model import DEFAULT_AGENT_RADIUS

DATA_FILE = Path(__file__).resolve().parent / "data" / "empirical.yaml"
DT = 0.05
RADIUS = DEFAULT_AGENT_RADIUS

FD_DENSITIES = (0.5, 1.0, 2.0, 3.0, 4.0)
FD_TOLERANCE = 0.15
CORRIDOR_LENGTH = 30.0
CORRIDOR_WIDTH = 4.0
LANE_DENSITY = 1.0
LANE_SECONDS = 60.0


@lru_cache(maxsize=1)
def published() -> dict[str, Any]:  # Any: the package's own YAML of published figures, read as written
    """The published values (data/empirical.yaml)."""
    with open(DATA_FILE, encoding="utf-8") as handle:
        data: dict[str, Any] = yaml.safe_load(handle)  # Any: YAML as loaded
    return data


def weidmann_speed(density: float) -> float:
    """Weidmann's (1993) mean walking speed at `density` persons/m^2 (0 at and beyond rho_max)."""
    w = published()["weidmann_1993"]
    if density <= 0.0:
        return float(w["v_free"])
    if density >= w["rho_max"]:
        return 0.0
    return float(w["v_free"]) * (1.0 - math.exp(-float(w["gamma"]) * (1.0 / density - 1.0 / float(w["rho_max"]))))


@dataclass(frozen=True)
class EmpiricalResult:
    """One check: a one-line verdict for the table and the rows behind it."""

    check: str
    name: str
    measured: str
    criterion: str
    passed: bool
    rows: tuple[tuple[str, ...], ...] = field(default=())


# --------------------------------------------------------------------------- the corridor with no ends


def _corridor(params: SFMParams, precision: str = "float64", length: float = CORRIDOR_LENGTH,
              width: float = CORRIDOR_WIDTH) -> Crowd:
    # the walls run a little past both ends: people step across the seam before they wrap back
    walls = np.array([[-5.0, 0.0, length + 5.0, 0.0], [-5.0, width, length + 5.0, width]])
    return Crowd(walls, params=params, dt=DT, periodic_x=(0.0, length), precision=precision)


def _lattice(density: float, length: float, width: float) -> list[tuple[float, float]]:
    """round(density x area) places on a hexagonal lattice filling the corridor (people start evenly)."""
    count = int(round(density * length * width))
    spacing = math.sqrt(2.0 / (math.sqrt(3.0) * density))
    rows = max(1, int(round(width / (spacing * math.sqrt(3.0) / 2.0))))
    columns = int(math.ceil(count / rows))
    places = [((c + 0.5 * (r % 2)) * length / columns % length, (r + 0.5) * width / rows)
              for r in range(rows) for c in range(columns)]
    return places[:count]


def corridor_speed(density: float, params: SFMParams, *, transient: float = 20.0, measure: float = 20.0,
                   precision: str = "float64") -> float:
    """Mean walking speed along a 30 x 4 m corridor with no ends at `density` persons/m^2, once the
    start has been forgotten (`transient` seconds), averaged over `measure` seconds."""
    crowd = _corridor(params, precision)
    free = float(published()["weidmann_1993"]["v_free"])
    with warnings.catch_warnings():
        # at 4 per m^2 the outer rows start a centimetre inside the wall clearance; the crowd moves
        # them off the wall, which is all a lattice start needs (no warning per person)
        warnings.filterwarnings("ignore", message="agent spawn .* of a wall", category=UserWarning)
        for x, y in _lattice(density, CORRIDOR_LENGTH, CORRIDOR_WIDTH):
            crowd.add_agent((x, y), radius=RADIUS, desired_speed=free, goals=[(1e6, y)], goal_radius=0.3)
    crowd.step(int(round(transient / DT)))
    samples = []
    for _ in range(int(round(measure / DT)) // 10):
        crowd.step(10)
        samples.append(float(np.mean(crowd.vel[:, 0])))
    return float(np.mean(samples))


def fundamental_diagram(params: SFMParams, densities: tuple[float, ...] = FD_DENSITIES,
                        tolerance: float = FD_TOLERANCE) -> EmpiricalResult:
    """Speed against density in a corridor with no ends, against Weidmann (1993)."""
    rows = []
    worst = 0.0
    for density in densities:
        speed = corridor_speed(density, params)
        expected = weidmann_speed(density)
        off = speed / expected - 1.0 if expected > 0 else math.inf
        worst = max(worst, abs(off))
        rows.append((f"{density:g}", f"{speed:.2f}", f"{expected:.2f}", f"{100 * off:+.0f} %"))
    return EmpiricalResult(
        "fd", "speed-density, corridor with no ends",
        " / ".join(r[1] for r in rows) + f" m/s at {' / '.join(r[0] for r in rows)} per m2 (worst {100 * worst:.0f} % off)",
        f"within {100 * tolerance:.0f} % of Weidmann " + " / ".join(r[2] for r in rows),
        worst <= tolerance, tuple(rows))


# --------------------------------------------------------------------------- bottlenecks


BOTTLENECK_LENGTH = 2.0
ROOM = 12.0
PERSONS_PER_METRE = 120   # a steady flow needs more than ~115 per metre of width (Liao et al.)


def bottleneck_world(width: float) -> str:
    """A 12 x 12 m room, a bottleneck `width` wide and 2 m long in the middle of its east wall, a room after it."""
    half = width / 2.0
    middle = ROOM / 2.0
    end = ROOM + BOTTLENECK_LENGTH
    return rimea._room_yaml(f"bottleneck_{int(round(width * 100))}", [
        ("room_a", [(0, 0), (ROOM, 0), (ROOM, ROOM), (0, ROOM)],
         [("bottleneck_in", (ROOM, middle), width, "corridor", False)]),
        ("corridor", [(ROOM, middle - half), (end, middle - half), (end, middle + half), (ROOM, middle + half)],
         [("bottleneck_out", (end, middle), width, "room_b", False)]),
        ("room_b", [(end, 0), (end + 6.0, 0), (end + 6.0, ROOM), (end, ROOM)],
         [("exit", (end + 6.0, middle), ROOM, "outside", True)]),
    ])


def bottleneck_flow(width: float, params: SFMParams | rimea.JuPedSimModel) -> tuple[float, str]:
    """(steady flow into the bottleneck in persons/s, '' or what stopped people) for `width` metres:
    max(150, 120 per metre) people leave the room along the product's evacuation path."""
    people = max(150, int(round(PERSONS_PER_METRE * width)))
    world = rimea._load(bottleneck_world(width), f"bottleneck_{width:g}.yaml")
    starts = rimea._grid_of_people(0.6, ROOM - 0.6, 0.6, ROOM - 0.6, people, 2.0 * RADIUS + 0.02)
    run = rimea.evacuate(world, starts, ["exit"] * people, params, radius=RADIUS, limit=60.0 + 2.0 * people,
                         line_x=ROOM)
    return rimea._steady_flow(run.crossings), run.unfinished()


def linear_fit(widths: list[float], flows: list[float]) -> tuple[float, float, float]:
    """(slope, intercept, R^2) of the least-squares line through (width, flow)."""
    x = np.asarray(widths, dtype=float)
    y = np.asarray(flows, dtype=float)
    slope, intercept = np.polyfit(x, y, 1)
    residual = float(np.sum((y - (slope * x + intercept)) ** 2))
    spread = float(np.sum((y - y.mean()) ** 2))
    return float(slope), float(intercept), 1.0 - residual / spread if spread > 0 else 0.0


def bottleneck(params: SFMParams, widths: tuple[float, ...] | None = None) -> EmpiricalResult:
    """Specific flow against bottleneck width: inside the published band, flow linear in width."""
    data = published()["bottleneck"]
    low, high = (float(v) for v in data["band"])
    widths = tuple(float(w) for w in (widths or data["widths"]))
    flows, rows, stuck = [], [], []
    for width in widths:
        flow, unfinished = bottleneck_flow(width, params)
        flows.append(flow)
        if unfinished:
            stuck.append(f"{width:g} m: {unfinished}")
        rows.append((f"{width:g}", f"{flow:.2f}", f"{flow / width:.2f}"))
    specific = [f / w for f, w in zip(flows, widths)]
    inside = all(low <= s <= high for s in specific)
    slope, intercept, r2 = linear_fit(list(widths), flows) if len(widths) >= 2 else (0.0, 0.0, 1.0)
    linear = r2 >= 0.95
    measured = (" / ".join(f"{s:.2f}" for s in specific) + f" per m s at {' / '.join(f'{w:g}' for w in widths)} m; "
                f"J = {slope:.2f} b {intercept:+.2f} /s, R2 {r2:.3f}") + (f"; {'; '.join(stuck)}" if stuck else "")
    return EmpiricalResult("bottleneck", "bottleneck specific flow vs width", measured,
                           f"{low:g}-{high:g} per m s (guidelines to laboratory); R2 >= 0.95",
                           inside and linear and not stuck, tuple(rows))


# --------------------------------------------------------------------------- lanes


def lane_order(pos: np.ndarray, direction: np.ndarray, period: float) -> float:
    """Zhang et al.'s (2012) lane order parameter (Rex and Loewen 2007): the mean over people with
    someone in their lane (under 0.3 m to either side, 2 m ahead or behind) of
    ((same direction - opposite) / (same + opposite))^2; 1 for clean lanes."""
    values = []
    for i in range(len(pos)):
        dx = (pos[:, 0] - pos[i, 0] + period / 2.0) % period - period / 2.0
        dy = pos[:, 1] - pos[i, 1]
        lane = (np.abs(dy) < 0.3) & (np.abs(dx) < 2.0)
        lane[i] = False
        if lane.any():
            same = int(np.sum(direction[lane] == direction[i]))
            opposite = int(lane.sum()) - same
            values.append(((same - opposite) / (same + opposite)) ** 2)
    return float(np.mean(values)) if values else 0.0


def lane_formation(params: SFMParams, seconds: float = LANE_SECONDS, seed: int = 0) -> EmpiricalResult:
    """Counterflow at 1 person/m^2 in a 30 x 4 m corridor with no ends, directions mixed at random."""
    rng = np.random.default_rng(seed)
    crowd = _corridor(params)
    count = int(round(LANE_DENSITY * CORRIDOR_LENGTH * CORRIDOR_WIDTH))
    places: list[np.ndarray] = []
    while len(places) < count:  # random places at least a body and a bit apart
        p = rng.uniform((0.0, 0.3), (CORRIDOR_LENGTH, CORRIDOR_WIDTH - 0.3))
        if all(min(abs(p[0] - q[0]), CORRIDOR_LENGTH - abs(p[0] - q[0])) ** 2 + (p[1] - q[1]) ** 2 > 0.55 ** 2
               for q in places):
            places.append(p)
    direction = np.where(np.arange(count) % 2 == 0, 1, -1)
    rng.shuffle(direction)
    free = float(published()["weidmann_1993"]["v_free"])
    for p, d in zip(places, direction):
        crowd.add_agent((float(p[0]), float(p[1])), radius=RADIUS, desired_speed=float(rng.normal(free, 0.1)),
                        goals=[(1e6 * float(d), float(p[1]))], goal_radius=0.3)
    start = lane_order(crowd.pos, direction, CORRIDOR_LENGTH)
    late: list[float] = []
    shuffled: list[float] = []
    steps_per_second = int(round(1.0 / DT))
    rows = [("0", f"{start:.2f}")]
    for second in range(1, int(seconds) + 1):
        crowd.step(steps_per_second)
        value = lane_order(crowd.pos, direction, CORRIDOR_LENGTH)
        if second % 10 == 0:
            rows.append((f"{second}", f"{value:.2f}"))
        if second > seconds - 10:
            late.append(value)
            shuffled.append(lane_order(crowd.pos, rng.permutation(direction), CORRIDOR_LENGTH))
    end, random_end = float(np.mean(late)), float(np.mean(shuffled))
    passed = end >= start + 0.15 and end >= random_end + 0.2
    return EmpiricalResult("lanes", "lanes in counterflow, 1 per m2",
                           f"order {start:.2f} at the start, {end:.2f} in the last 10 s "
                           f"(shuffled directions: {random_end:.2f})",
                           "rises by 0.15 or more and ends 0.2 above shuffled directions", passed, tuple(rows))


CHECKS: dict[str, Callable[[SFMParams], EmpiricalResult]] = {
    "fd": fundamental_diagram, "bottleneck": bottleneck, "lanes": lane_formation,
}


def run_empirical(model: str = "grove", checks: tuple[str, ...] = tuple(CHECKS)) -> list[EmpiricalResult]:
    """Each check on the named pedestrian model's crowd."""
    params = SFMParams.named(model)
    return [CHECKS[name](params) for name in checks]
