"""Social Force Model kernels (lightsfm / HuNavSim flavour) compiled with numba.

Everything that runs per agent per step lives here; `crowd.py` owns the state and calls
`advance` once per `Crowd.step(n)`, so no Python runs inside the n steps.

Forces follow robotics-upo/lightsfm `sfm.hpp` as HuNavSim uses it:
desired w_g (v0 e - v) / tau, Moussaid social force, obstacle force summed over wall
segments, group gaze / coherence / repulsion, speed clipped to v0, yaw held when slow.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

# OpenMP threads otherwise spin at every barrier; on cores shared with other work (the TUI, a
# model, other processes) that spinning steals the time the other thread needs. Measured on
# 2 shared cores at 10,000 agents: 0.49M agent-steps per CPU-second spinning, 0.69M passive.
# Takes effect only if libgomp is not loaded yet; an explicit setting wins.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

import numba as nb  # noqa: E402
import numpy as np  # noqa: E402

from grove_tui.navigation.velocity_field import sample_field  # noqa: E402
from grove_tui.settings import PEDESTRIAN_MODELS  # noqa: E402

MODE_GOALS = 0
MODE_FIELD = 1
MODE_STOP = 2
MODE_FACE = 3

# How a pedestrian perceives the robot (HuNavSim agent_manager.cpp, section 3 of the reference).
ROBOT_AS_AGENT = 0      # Regular: the robot is one more SFM agent
ROBOT_AS_OBSTACLE = 1   # Impassive: the robot is an obstacle point
ROBOT_IGNORED = 2       # reacting behaviours that do not see the robot in their forces
ROBOT_FEARED = 3        # Scared: ignored as an agent, plus the "other" repulsion away from it

FACE_POINT = 0
FACE_AGENT = 1
FACE_ROBOT = 2

# Layout of the float64 parameter vector handed to the kernels.
P_LAMBDA = 0
P_GAMMA = 1
P_N = 2
P_NPRIME = 3
P_EPSILON = 4
P_TAU = 5
P_SIGMA_OBS = 6
P_CUTOFF = 7
P_WALL_RANGE = 8
P_GAZE = 9
P_COHERENCE = 10
P_REPULSION = 11
P_YAW_HOLD = 12
P_CLEARANCE = 13
P_TURN_RATE = 14
P_BODY = 15
P_SKIP = 16
P_HOLD = 17
P_FRICTION = 18
P_DENSITY_RADIUS = 19
# Periodic x (Crowd(periodic=...)): the period and where it starts; 0 = walls only.
P_PERIOD = 20
P_PERIOD_X0 = 21
P_ROBOT_SIGMA = 22
P_BODY_FRACTION = 23
P_COUNT = 24

# Layout of the robot state vector.
R_X = 0
R_Y = 1
R_VX = 2
R_VY = 3
R_YAW = 4
R_RADIUS = 5
R_MAX_SPEED = 6
R_PRESENT = 7
R_COMMANDED = 8
R_CMD_VX = 9
R_CMD_VY = 10
R_PATH_INDEX = 11
R_COUNT = 12

# Layout of one row of field metadata.
F_OX = 0
F_OY = 1
F_RES = 2
F_H = 3
F_W = 4
F_EXIT_X = 5
F_EXIT_Y = 6
F_COUNT = 7

# Layout of the wall bucket grid metadata.
W_OX = 0
W_OY = 1
W_CELL = 2
W_NX = 3
W_NY = 4
W_COUNT = 5

ROBOT_WAYPOINT_TOLERANCE = 0.1
_BACKOFF = 1e-4          # metres kept between a blocked agent and the wall it hit
_TINY = 1e-12
_GOLDEN_ANGLE = 2.399963229728653
# A standing person braces: the pull back to its spot may reach this multiple of the walking
# drive (w_goal v0 / tau). Its speed stays clipped to v0, so it steps back no faster than it walks.
# At 1x walkers shoved waiting people over 0.3 m (tests/simulation/test_physics_waiting.py).
HOLD_BRACE = 3.0
# No nnan/ninf: the kernels rely on isfinite checks to keep every value finite.
_FASTMATH = {"nsz", "arcp", "contract", "afn", "reassoc"}


# The pedestrian models a user can pick by name (SFMParams.named).
SFM_MODELS = PEDESTRIAN_MODELS


@dataclass(frozen=True)
class SFMParams:
    """lightsfm defaults with HuNavSim's overrides (social 5, factors 2/10/5/20)."""

    goal_weight: float = 2.0
    obstacle_weight: float = 10.0
    # How fast the wall repulsion fades (m): HFV 2000's B_w = 0.08 m, as JuPedSim's SFM. lightsfm's
    # 0.2 m pushed people 0.15 m off both walls of a 0.8 m bottleneck, which then passed 0.99 persons
    # per second (1.23 per metre): below the laboratory band (analysis/empirical.py); at 0.08 m, 1.18 per s.
    obstacle_sigma: float = 0.08
    # The same fade for the robot seen as an obstacle (Impassive) and for the fear of it (Scared):
    # HuNavSim's 0.2 m in both models, so reactions to the robot stay HuNavSim's.
    robot_sigma: float = 0.2
    social_weight: float = 5.0
    # Scale of the extra repulsion from the robot for agents in ROBOT_FEARED (HuNavSim Scared).
    other_weight: float = 20.0
    group_gaze: float = 3.0
    group_coherence: float = 2.0
    group_repulsion: float = 1.0
    lambda_: float = 2.0
    gamma: float = 0.35
    n: float = 2.0
    n_prime: float = 3.0
    # Shifts theta by epsilon * B so two agents exactly head-on (theta == 0, sign 0) still sidestep.
    epsilon: float = 0.005
    tau: float = 0.5
    cutoff: float = 3.0
    # 10 exp(-1 / 0.08) < 4e-5 (lightsfm: 10 exp(-2 / 0.2) < 5e-4): walls further than this
    # contribute nothing measurable.
    wall_range: float = 1.0
    yaw_hold_speed: float = 0.07
    # Agents end every step at least this fraction of their radius away from any wall: 0.9 keeps a
    # body at most 3.5 cm (radius 0.35) into a wall; at 0.5 a dense crowd pressed bodies 12 cm in.
    # A fraction of the radius, not of the body (body_fraction): as a fraction of the 0.23 m body,
    # people stood 2 cm deeper in the planner's margin along walls, where the exit fields point
    # away from the wall, and RiMEA 9's corner doors drained 1-3 s later.
    wall_clearance: float = 0.9
    # HuNavSim 2.0 turns 0.2*pi per behaviour tick; at a 10 Hz tick that is 2*pi rad/s.
    face_turn_rate: float = 2.0 * math.pi
    goal_tolerance: float = 0.1
    # Body compression (1/s^2: force per kg per metre of overlap) acting only while two bodies, or a
    # body and a wall, overlap: Helbing, Farkas & Vicsek 2000, k = 1.2e5 kg/s^2 for an 80 kg person,
    # as JuPedSim's SFM. Not in lightsfm, whose Moussaid force let bodies overlap by 34 cm of 50 and
    # walls by 12 cm (issue 19). SFMParams.lightsfm() gives lightsfm's forces exactly (tests/crowd/test_sfm.py).
    body_weight: float = 1.2e5 / 80.0
    # Sliding friction (1/(m s)) along the contact tangent while bodies overlap: a tenth of HFV 2000's
    # kappa = 2.4e5 kg/(m s) for 80 kg, which models panicking crowds crushing into a door: with it,
    # 150 people left a 0.8 m bottleneck at 0.76 per second, half what laboratory crowds manage
    # (analysis/empirical.py). It still slows a jammed doorway (RiMEA 12).
    friction_weight: float = 2.4e4 / 80.0
    # Speed falls with the density ahead as in Weidmann 1993 (RiMEA test 4): the desired speed is
    # scaled by 1 - exp(-1.913 (1/rho - 1/5.4)), rho counted in the half disc of this radius in
    # front of the agent. 0 turns it off (lightsfm: a dense crowd walks at free speed, issue 19).
    density_radius: float = 1.5
    # Social terms exp(-x) with x above this (below 3.4e-4 of their peak at 8) are skipped
    # before the atan2 and exp; math.inf evaluates every pair within the cutoff.
    social_skip_exponent: float = 8.0
    # The body that touches others and walls (contact compression and friction, the wall force) has
    # this fraction of the agent's radius. The radius (product default 0.25 m) is the envelope the
    # planner keeps clear of walls; the body is as wide as the shoulders, 0.46 m (Weidmann 1993),
    # so 0.23 m at the default. With 0.25 m bodies, people reaching a 0.8 m door mouth side by side
    # both touched its jambs and blocked each other for 1-2 s every few people: 0.8 m passed
    # 1.30 persons/(m s), under the laboratory band (analysis/empirical.py; docs/BENCHMARKS.md).
    body_fraction: float = 0.92
    # Seconds in which a waiting person (MODE_STOP, MODE_FACE; queueing people are pulled back to
    # their slot by the goal force; walkers who arrived give way as before) would walk back to the spot where it stopped (spring stiffness w_goal / (tau hold_time));
    # 0 turns holding off (lightsfm: standing agents are
    # only damped and drift metres when walkers push past, issue 19).
    hold_time: float = 0.1

    @classmethod
    def lightsfm(cls, **overrides: float) -> SFMParams:
        """lightsfm's (HuNavSim's) forces exactly, as Gazebo runs them: soft bodies, no holding."""
        values = dict(epsilon=0.0, body_weight=0.0, body_fraction=1.0, friction_weight=0.0, hold_time=0.0, density_radius=0.0,
                      social_skip_exponent=math.inf, wall_clearance=0.5, obstacle_sigma=0.2, wall_range=2.0)
        values.update(overrides)
        return cls(**values)

    @classmethod
    def named(cls, name: str) -> SFMParams:
        """A pedestrian model by name: "grove" (default, RiMEA-oriented contacts) or "lightsfm"."""
        if name not in SFM_MODELS:
            raise ValueError(f"unknown pedestrian model {name!r}; choose one of {', '.join(SFM_MODELS)}")
        return cls.lightsfm() if name == "lightsfm" else cls()

    def __post_init__(self) -> None:
        for name in ("obstacle_sigma", "robot_sigma", "gamma", "tau", "cutoff", "wall_range"):
            if getattr(self, name) <= 0:
                raise ValueError(f"SFMParams.{name} must be > 0, got {getattr(self, name)!r}")
        if not 0.0 < self.body_fraction <= 1.0:
            raise ValueError(f"SFMParams.body_fraction must be in (0, 1], got {self.body_fraction!r}")

    def factors(self) -> tuple[float, float, float, float]:
        return (self.goal_weight, self.obstacle_weight, self.social_weight, self.other_weight)

    def as_array(self) -> np.ndarray:
        out = np.zeros(P_COUNT, dtype=np.float64)
        out[P_LAMBDA] = self.lambda_
        out[P_GAMMA] = self.gamma
        out[P_N] = self.n
        out[P_NPRIME] = self.n_prime
        out[P_EPSILON] = self.epsilon
        out[P_TAU] = self.tau
        out[P_SIGMA_OBS] = self.obstacle_sigma
        out[P_ROBOT_SIGMA] = self.robot_sigma
        out[P_CUTOFF] = self.cutoff
        out[P_WALL_RANGE] = self.wall_range
        out[P_GAZE] = self.group_gaze
        out[P_COHERENCE] = self.group_coherence
        out[P_REPULSION] = self.group_repulsion
        out[P_YAW_HOLD] = self.yaw_hold_speed
        out[P_CLEARANCE] = self.wall_clearance
        out[P_TURN_RATE] = self.face_turn_rate
        out[P_BODY] = self.body_weight
        out[P_SKIP] = self.social_skip_exponent
        out[P_HOLD] = self.hold_time
        out[P_FRICTION] = self.friction_weight
        out[P_DENSITY_RADIUS] = self.density_radius
        out[P_BODY_FRACTION] = self.body_fraction
        return out


# --------------------------------------------------------------------------- geometry


@nb.njit(cache=True)
def _closest_on_segment(px, py, ax, ay, bx, by):
    """Closest point on segment ab to p and its parameter t in [0, 1]."""
    ex = bx - ax
    ey = by - ay
    len2 = ex * ex + ey * ey
    if len2 <= _TINY:
        return ax, ay, 0.0
    t = ((px - ax) * ex + (py - ay) * ey) / len2
    if t < 0.0:
        t = 0.0
    elif t > 1.0:
        t = 1.0
    return ax + t * ex, ay + t * ey, t


@nb.njit(cache=True)
def _orient(ax, ay, bx, by, cx, cy):
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@nb.njit(cache=True)
def _crossing_parameter(x0, y0, x1, y1, ax, ay, bx, by):
    """Parameter s in [0, 1] where motion p0->p1 first touches wall ab, or -1 if it does not.

    Touching counts as crossing: an agent must never end on the wall line itself.
    """
    o1 = _orient(ax, ay, bx, by, x0, y0)
    o2 = _orient(ax, ay, bx, by, x1, y1)
    if (o1 > 0.0 and o2 > 0.0) or (o1 < 0.0 and o2 < 0.0):
        return -1.0
    o3 = _orient(x0, y0, x1, y1, ax, ay)
    o4 = _orient(x0, y0, x1, y1, bx, by)
    if (o3 > 0.0 and o4 > 0.0) or (o3 < 0.0 and o4 < 0.0):
        return -1.0
    denom = o1 - o2
    if denom == 0.0:
        # Collinear with the wall line: moving along it. Block only if the path overlaps the segment.
        ex = bx - ax
        ey = by - ay
        len2 = ex * ex + ey * ey
        if len2 <= _TINY:
            return -1.0
        t0 = ((x0 - ax) * ex + (y0 - ay) * ey) / len2
        t1 = ((x1 - ax) * ex + (y1 - ay) * ey) / len2
        if max(t0, t1) < 0.0 or min(t0, t1) > 1.0:
            return -1.0
        if 0.0 <= t0 <= 1.0 or t1 == t0:
            return 0.0
        # Head-on along the wall's line: blocked where the motion reaches the wall's nearer end.
        return ((0.0 if t0 < 0.0 else 1.0) - t0) / (t1 - t0)
    s = o1 / denom
    if s < 0.0:
        s = 0.0
    elif s > 1.0:
        s = 1.0
    return s


@nb.njit(cache=True)
def _wall_cell(x, y, wall_meta):
    nx = int(wall_meta[W_NX])
    ny = int(wall_meta[W_NY])
    cx = int(math.floor((x - wall_meta[W_OX]) / wall_meta[W_CELL]))
    cy = int(math.floor((y - wall_meta[W_OY]) / wall_meta[W_CELL]))
    if cx < 0 or cy < 0 or cx >= nx or cy >= ny:
        return -1
    return cy * nx + cx


@nb.njit(cache=True)
def _earliest_hit(x0, y0, x1, y1, walls, wall_meta, wall_start, wall_items, scan_all):
    """Earliest wall touched by motion p0->p1: (s, wall index) or (2.0, -1)."""
    best_s = 2.0
    best_w = -1
    if scan_all:
        for w in range(walls.shape[0]):
            s = _crossing_parameter(x0, y0, x1, y1, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3])
            if s >= 0.0 and s < best_s:
                best_s = s
                best_w = w
        return best_s, best_w
    cell = _wall_cell(x0, y0, wall_meta)
    if cell < 0:
        return best_s, best_w
    for k in range(wall_start[cell], wall_start[cell + 1]):
        w = wall_items[k]
        s = _crossing_parameter(x0, y0, x1, y1, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3])
        if s >= 0.0 and (s < best_s or (s == best_s and w < best_w)):
            best_s = s
            best_w = w
    return best_s, best_w


@nb.njit(cache=True)
def _wall_normal_towards(w, px, py, walls):
    """Unit normal of wall w pointing to the side of p (left normal when p is on the line)."""
    ax = walls[w, 0]
    ay = walls[w, 1]
    ex = walls[w, 2] - ax
    ey = walls[w, 3] - ay
    length = math.sqrt(ex * ex + ey * ey)
    if length <= _TINY:
        dx = px - ax
        dy = py - ay
        d = math.sqrt(dx * dx + dy * dy)
        if d <= _TINY:
            return 1.0, 0.0
        return dx / d, dy / d
    nx = -ey / length
    ny = ex / length
    if (px - ax) * nx + (py - ay) * ny < 0.0:
        return -nx, -ny
    return nx, ny


@nb.njit(cache=True)
def resolve_motion(x0, y0, x1, y1, vx, vy, clearance, walls, wall_meta, wall_start, wall_items):
    """Move p0 towards p1 without ever crossing or touching a wall; slide along walls that block.

    Returns the end point and the velocity with every into-wall component removed.
    p0 is assumed to be on a legal side (never on a wall line), which this function preserves.
    """
    if walls.shape[0] == 0:
        return x1, y1, vx, vy
    reach = wall_meta[W_CELL]
    sx = x0
    sy = y0
    ex = x1
    ey = y1
    # Where the straight motion first stops short of a wall: its chord from p0 is verified free.
    first_x = x1
    first_y = y1
    first_hit = True
    for _ in range(4):
        mx = ex - sx
        my = ey - sy
        length = math.sqrt(mx * mx + my * my)
        if length <= _TINY:
            break
        scan_all = length > reach
        s, w = _earliest_hit(sx, sy, ex, ey, walls, wall_meta, wall_start, wall_items, scan_all)
        if w < 0:
            break
        nx, ny = _wall_normal_towards(w, sx, sy, walls)
        # Stop short on the already verified part of the path, then slide tangentially.
        back = _BACKOFF / length
        s_safe = s - back
        if s_safe < 0.0:
            s_safe = 0.0
        cx = sx + s_safe * mx
        cy = sy + s_safe * my
        if first_hit:
            first_x = cx
            first_y = cy
            first_hit = False
        rx = ex - cx
        ry = ey - cy
        into = rx * nx + ry * ny
        if into < 0.0:
            rx -= into * nx
            ry -= into * ny
        vin = vx * nx + vy * ny
        if vin < 0.0:
            vx -= vin * nx
            vy -= vin * ny
        sx = cx
        sy = cy
        ex = cx + rx
        ey = cy + ry
    # After 4 hits the last slide may still be blocked; verify the final leg once more.
    if ex != sx or ey != sy:
        mx = ex - sx
        my = ey - sy
        scan_all = math.sqrt(mx * mx + my * my) > reach
        s, w = _earliest_hit(sx, sy, ex, ey, walls, wall_meta, wall_start, wall_items, scan_all)
        if w >= 0:
            ex = sx
            ey = sy
    if clearance > 0.0:
        ex, ey = _keep_clearance(ex, ey, clearance, walls, wall_meta, wall_start, wall_items)
    # A step is recorded as the straight chord p0 -> end; a slide around one wall can make that chord
    # clip the tip of another. Then the step ends where the straight motion first stopped instead.
    if ex != x0 or ey != y0:
        mx = ex - x0
        my = ey - y0
        scan_all = math.sqrt(mx * mx + my * my) > reach
        s, w = _earliest_hit(x0, y0, ex, ey, walls, wall_meta, wall_start, wall_items, scan_all)
        if w >= 0:
            ex = first_x
            ey = first_y
    return ex, ey, vx, vy


@nb.njit(cache=True)
def _keep_clearance(x, y, clearance, walls, wall_meta, wall_start, wall_items):
    """Push p out to `clearance` from the nearest walls, never through any wall."""
    for _ in range(2):
        cell = _wall_cell(x, y, wall_meta)
        if cell < 0:
            return x, y
        best_d = clearance
        best_w = -1
        best_cx = 0.0
        best_cy = 0.0
        for k in range(wall_start[cell], wall_start[cell + 1]):
            w = wall_items[k]
            cx, cy, _t = _closest_on_segment(x, y, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3])
            d = math.sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy))
            if d < best_d or (d == best_d and best_w >= 0 and w < best_w):
                best_d = d
                best_w = w
                best_cx = cx
                best_cy = cy
        if best_w < 0:
            return x, y
        if best_d > _TINY:
            nx = (x - best_cx) / best_d
            ny = (y - best_cy) / best_d
        else:
            nx, ny = _wall_normal_towards(best_w, x, y, walls)
        tx = best_cx + nx * clearance
        ty = best_cy + ny * clearance
        s, w = _earliest_hit(x, y, tx, ty, walls, wall_meta, wall_start, wall_items, False)
        if w >= 0:
            return x, y
        x = tx
        y = ty
    return x, y


def bucket_walls(walls: np.ndarray, cell: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bucket wall segments into square cells: each cell lists every wall within `cell` of it.

    Any query point then finds all walls within `cell` metres by reading its own cell only.
    Returns (meta, starts, items) with starts of length nx*ny+1 (CSR).
    """
    walls = np.ascontiguousarray(walls, dtype=np.float64).reshape(-1, 4)
    if walls.shape[0] == 0:
        meta = np.array([0.0, 0.0, cell, 1.0, 1.0], dtype=np.float64)
        return meta, np.zeros(2, dtype=np.int32), np.zeros(0, dtype=np.int32)
    xmin = float(min(walls[:, 0].min(), walls[:, 2].min())) - cell
    ymin = float(min(walls[:, 1].min(), walls[:, 3].min())) - cell
    xmax = float(max(walls[:, 0].max(), walls[:, 2].max())) + cell
    ymax = float(max(walls[:, 1].max(), walls[:, 3].max())) + cell
    nx = int(math.ceil((xmax - xmin) / cell)) + 1
    ny = int(math.ceil((ymax - ymin) / cell)) + 1
    meta = np.array([xmin, ymin, cell, float(nx), float(ny)], dtype=np.float64)
    starts, items = _bucket_walls_kernel(walls, meta)
    return meta, starts, items


@nb.njit(cache=True)
def _segment_rect_distance(ax, ay, bx, by, x0, y0, x1, y1):
    """Distance between segment ab and the axis-aligned rectangle [x0, x1] x [y0, y1]."""
    if (x0 <= ax <= x1 and y0 <= ay <= y1) or (x0 <= bx <= x1 and y0 <= by <= y1):
        return 0.0
    best = 1e300
    corners_x = (x0, x1, x1, x0)
    corners_y = (y0, y0, y1, y1)
    for e in range(4):
        cx0 = corners_x[e]
        cy0 = corners_y[e]
        cx1 = corners_x[(e + 1) % 4]
        cy1 = corners_y[(e + 1) % 4]
        if _crossing_parameter(ax, ay, bx, by, cx0, cy0, cx1, cy1) >= 0.0:
            return 0.0
        qx, qy, _t = _closest_on_segment(ax, ay, cx0, cy0, cx1, cy1)
        d = math.sqrt((ax - qx) ** 2 + (ay - qy) ** 2)
        if d < best:
            best = d
        qx, qy, _t = _closest_on_segment(bx, by, cx0, cy0, cx1, cy1)
        d = math.sqrt((bx - qx) ** 2 + (by - qy) ** 2)
        if d < best:
            best = d
        qx, qy, _t = _closest_on_segment(cx0, cy0, ax, ay, bx, by)
        d = math.sqrt((cx0 - qx) ** 2 + (cy0 - qy) ** 2)
        if d < best:
            best = d
    return best


@nb.njit(cache=True)
def _bucket_walls_kernel(walls, meta):
    ox = meta[W_OX]
    oy = meta[W_OY]
    cell = meta[W_CELL]
    nx = int(meta[W_NX])
    ny = int(meta[W_NY])
    counts = np.zeros(nx * ny + 1, dtype=np.int32)
    for phase in range(2):
        if phase == 1:
            total = 0
            for c in range(nx * ny):
                n = counts[c]
                counts[c] = total
                total += n
            counts[nx * ny] = total
            items = np.empty(total, dtype=np.int32)
            fill = counts[:nx * ny].copy()
        for w in range(walls.shape[0]):
            ax = walls[w, 0]
            ay = walls[w, 1]
            bx = walls[w, 2]
            by = walls[w, 3]
            c0 = max(int(math.floor((min(ax, bx) - cell - ox) / cell)), 0)
            c1 = min(int(math.floor((max(ax, bx) + cell - ox) / cell)), nx - 1)
            r0 = max(int(math.floor((min(ay, by) - cell - oy) / cell)), 0)
            r1 = min(int(math.floor((max(ay, by) + cell - oy) / cell)), ny - 1)
            for r in range(r0, r1 + 1):
                for c in range(c0, c1 + 1):
                    x0 = ox + c * cell
                    y0 = oy + r * cell
                    if _segment_rect_distance(ax, ay, bx, by, x0, y0, x0 + cell, y0 + cell) <= cell:
                        if phase == 0:
                            counts[r * nx + c] += 1
                        else:
                            items[fill[r * nx + c]] = w
                            fill[r * nx + c] += 1
    return counts, items


# The wall distance field: per square cell, a lower bound on the distance from any point of the
# cell to the nearest wall (exact segment-to-square distance, capped). Most people are farther
# from every wall than their wall range, or than their step plus clearance: one lookup then
# replaces the per-segment loops of the wall force and of the wall-respecting move, and the
# result is the same bit for bit (those loops would find no wall). Measured on bench/sfm.py's
# room at 1,000 and 10,000 people: walls and moves were three quarters of the per-agent pass.
FREE_CELL = 0.25          # metres
FREE_MAX_CELLS = 4_000_000


def wall_distance_field(walls: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """(meta [ox, oy, cell, nx, ny, reach], flat float32 lower bounds capped at `reach`) over the walls'
    bounding box grown by `reach`; points outside it are at least `reach` from every wall."""
    walls = np.ascontiguousarray(walls, dtype=np.float64).reshape(-1, 4)
    if walls.shape[0] == 0:
        return np.array([0.0, 0.0, 1.0, 1.0, 1.0, reach]), np.full(1, reach, dtype=np.float32)
    xmin = float(min(walls[:, 0].min(), walls[:, 2].min())) - reach
    ymin = float(min(walls[:, 1].min(), walls[:, 3].min())) - reach
    xmax = float(max(walls[:, 0].max(), walls[:, 2].max())) + reach
    ymax = float(max(walls[:, 1].max(), walls[:, 3].max())) + reach
    cell = max(FREE_CELL, math.sqrt((xmax - xmin) * (ymax - ymin) / FREE_MAX_CELLS))
    nx = int(math.ceil((xmax - xmin) / cell)) + 1
    ny = int(math.ceil((ymax - ymin) / cell)) + 1
    meta = np.array([xmin, ymin, cell, float(nx), float(ny), reach], dtype=np.float64)
    return meta, _wall_distance_kernel(walls, meta, reach)


@nb.njit(cache=True)
def _wall_distance_kernel(walls, meta, reach):
    ox = meta[W_OX]
    oy = meta[W_OY]
    cell = meta[W_CELL]
    nx = int(meta[W_NX])
    ny = int(meta[W_NY])
    free = np.full(nx * ny, reach, dtype=np.float32)
    for w in range(walls.shape[0]):
        ax = walls[w, 0]
        ay = walls[w, 1]
        bx = walls[w, 2]
        by = walls[w, 3]
        c0 = max(int(math.floor((min(ax, bx) - reach - ox) / cell)), 0)
        c1 = min(int(math.floor((max(ax, bx) + reach - ox) / cell)), nx - 1)
        r0 = max(int(math.floor((min(ay, by) - reach - oy) / cell)), 0)
        r1 = min(int(math.floor((max(ay, by) + reach - oy) / cell)), ny - 1)
        for r in range(r0, r1 + 1):
            for c in range(c0, c1 + 1):
                x0 = ox + c * cell
                y0 = oy + r * cell
                d = _segment_rect_distance(ax, ay, bx, by, x0, y0, x0 + cell, y0 + cell)
                # float32 rounds to nearest: step down one ulp so the bound stays a lower bound
                value = np.float32(d)
                if value > d:
                    value = np.nextafter(value, np.float32(0.0))
                if value < free[r * nx + c]:
                    free[r * nx + c] = value
    return free


@nb.njit(cache=True, inline="always")
def _wall_free(x, y, free_meta, free):
    """A lower bound on the distance from (x, y) to the nearest wall (capped at the field's reach)."""
    cx = int(math.floor((x - free_meta[W_OX]) / free_meta[W_CELL]))
    cy = int(math.floor((y - free_meta[W_OY]) / free_meta[W_CELL]))
    nx = int(free_meta[W_NX])
    if cx < 0 or cy < 0 or cx >= nx or cy >= int(free_meta[W_NY]):
        return free_meta[5]  # the field covers every point closer than its reach to a wall
    return np.float64(free[cy * nx + cx])


def wall_endpoint_owners(walls: np.ndarray) -> np.ndarray:
    """(M, 2) bool: whether wall m owns its start / end point.

    Polygon edges share corners; without ownership an agent at a corner would feel the same
    closest point once per edge. Each distinct endpoint is owned by the first wall touching it.
    """
    walls = np.asarray(walls, dtype=np.float64).reshape(-1, 4)
    owners = np.zeros((walls.shape[0], 2), dtype=np.bool_)
    seen: set[tuple[float, float]] = set()
    for m in range(walls.shape[0]):
        for end in range(2):
            key = (round(float(walls[m, 2 * end]), 6), round(float(walls[m, 2 * end + 1]), 6))
            if key not in seen:
                seen.add(key)
                owners[m, end] = True
    return owners


# --------------------------------------------------------------------------- fields


# --------------------------------------------------------------------------- forces


@nb.njit(cache=True, inline="always")
def _fast_atan2(y, x):
    """atan2 within 3e-11 rad: one division, then an odd degree-23 fit of atan on [0, 1].

    libm's atan2 costs a third of a social-force pair; the fit keeps the kernel equal to
    lightsfm to 1e-9 (tests/crowd/test_sfm.py) at a fifth less time per step.
    """
    ax = abs(x)
    ay = abs(y)
    mx = max(ax, ay)
    if mx == 0.0:
        return 0.0
    a = min(ax, ay) / mx
    s = a * a
    s2 = s * s
    s4 = s2 * s2
    s8 = s4 * s4
    q01 = 0.999999999549741 - 0.3333332776390596 * s
    q23 = 0.19999807871878367 - 0.14282689309481986 * s
    q45 = 0.11084431362845919 - 0.0894373147066482 * s
    q67 = 0.07148925896316664 - 0.0526013517930382 * s
    q89 = 0.03231716811204399 - 0.014773298847288617 * s
    q1011 = 0.0043120015004095005 - 0.0005905210158095912 * s
    r = a * ((q01 + s2 * q23) + s4 * (q45 + s2 * q67) + s8 * (q89 + s2 * q1011))
    if ay > ax:
        r = 1.5707963267948966 - r
    if x < 0.0:
        r = 3.141592653589793 - r
    if math.copysign(1.0, y) < 0.0:  # -0.0 too, as libm: atan2(-0.0, -1) is -pi
        r = -r
    return r


_POW2 = np.array([2.0 ** -k for k in range(0, 1023)])


@nb.njit(cache=True, inline="always")
def _fast_exp(x):
    """exp(x) for x <= 0 within 1e-12 relative: 2^-k times a degree-10 series on |r| <= ln2 / 2.

    The social force's two exps per neighbour dominate a step; libm's exp is a call with
    special-case handling that this kernel never needs.
    """
    if x < -700.0:
        return 0.0
    k = int(-x * 1.4426950408889634 + 0.5)
    r = x + k * 0.6931471805599453
    r2 = r * r
    # Estrin's scheme: shorter dependency chains than Horner for the same terms.
    p01 = 1.0 + r
    p23 = 0.5 + r * (1.0 / 6.0)
    p45 = 1.0 / 24.0 + r * (1.0 / 120.0)
    p67 = 1.0 / 720.0 + r * (1.0 / 5040.0)
    p89 = 1.0 / 40320.0 + r * (1.0 / 362880.0)
    r4 = r2 * r2
    p = (p01 + r2 * p23) + r4 * ((p45 + r2 * p67) + r4 * (p89 + r2 * (1.0 / 3628800.0)))
    return p * _POW2[k]


@nb.njit(cache=True)
def _tie_break_direction(i, j):
    """Direction from i to j when they coincide: fixed per pair and opposite for the two."""
    a = _GOLDEN_ANGLE * (min(i, j) * 7919 + max(i, j))
    ux = math.cos(a)
    uy = math.sin(a)
    if i > j:
        return -ux, -uy
    return ux, uy


@nb.njit(cache=True)
def _social_force(px, py, vx, vy, qx, qy, wx, wy, i, j, params):
    """Moussaid force on an agent at p (velocity v) from one at q (velocity w), unweighted."""
    dx = qx - px
    dy = qy - py
    dist = math.sqrt(dx * dx + dy * dy)
    if dist > _TINY:
        ex = dx / dist
        ey = dy / dist
    else:
        ex, ey = _tie_break_direction(i, j)
    lam = params[P_LAMBDA]
    ix = lam * (vx - wx) + ex
    iy = lam * (vy - wy) + ey
    ilen = math.sqrt(ix * ix + iy * iy)
    if ilen <= _TINY:
        ix = ex
        iy = ey
        ilen = 1.0
    ix /= ilen
    iy /= ilen
    theta = math.atan2(ix * ey - iy * ex, ix * ex + iy * ey)
    b = params[P_GAMMA] * ilen
    theta += params[P_EPSILON] * b
    t_angle = params[P_N] * b * theta
    t_velocity = params[P_NPRIME] * b * theta
    f_v = -math.exp(-dist / b - t_velocity * t_velocity)
    sign = 0.0
    if theta > 0.0:
        sign = 1.0
    elif theta < 0.0:
        sign = -1.0
    f_a = -sign * math.exp(-dist / b - t_angle * t_angle)
    # interaction direction times f_v plus its left normal (-iy, ix) times f_a
    return f_v * ix - f_a * iy, f_v * iy + f_a * ix


@nb.njit(cache=True)
def _point_obstacle_force(px, py, ox, oy, radius, weight, sigma, i):
    dx = px - ox
    dy = py - oy
    d = math.sqrt(dx * dx + dy * dy)
    if d > _TINY:
        ux = dx / d
        uy = dy / d
    else:
        a = _GOLDEN_ANGLE * i
        ux = math.cos(a)
        uy = math.sin(a)
    mag = weight * math.exp(-(d - radius) / sigma)
    return mag * ux, mag * uy


@nb.njit(cache=True)
def _turn_towards(current, target, max_step):
    diff = target - current
    diff = math.atan2(math.sin(diff), math.cos(diff))
    if diff > max_step:
        diff = max_step
    elif diff < -max_step:
        diff = -max_step
    out = current + diff
    return math.atan2(math.sin(out), math.cos(out))


# --------------------------------------------------------------------------- cell list


@nb.njit(cache=True)
def _build_cells(pos, active, min_cell, period, period_x0):
    """Counting-sort cell list of the active agents (cells at least `min_cell` wide).

    Cells are numbered major row by major row (c = major * n_minor + minor), the major axis being
    the longer side of the crowd's bounding box, so that bands of major rows split a crowd into
    many similar parts whatever its shape. With `period` > 0 the x axis is periodic on
    [period_x0, period_x0 + period): x is then the major axis and its cells tile the period exactly.
    Within a cell, agents keep their index order. Returns (order, starts, rank, n_major, n_minor, cell)
    with order[k] the k-th agent in cell order and rank its inverse (rank[i] = k, -1 if inactive).
    """
    n = pos.shape[0]
    count = 0
    xmin = 1e300
    ymin = 1e300
    xmax = -1e300
    ymax = -1e300
    for i in range(n):
        if active[i]:
            count += 1
            x = pos[i, 0]
            y = pos[i, 1]
            if x < xmin:
                xmin = x
            if x > xmax:
                xmax = x
            if y < ymin:
                ymin = y
            if y > ymax:
                ymax = y
    if count == 0:
        xmin = 0.0
        ymin = 0.0
        xmax = 0.0
        ymax = 0.0
    cell = min_cell
    limit = max(4 * count, 64)
    if period > 0.0:
        xmin = period_x0
        nx = max(int(period / cell), 1)
        cell_x = period / nx
        ny = int((ymax - ymin) / cell) + 1
        major_is_x = True
    else:
        nx = int((xmax - xmin) / cell) + 1
        ny = int((ymax - ymin) / cell) + 1
        while nx * ny > limit:
            # Scattered agents would make a huge, nearly empty grid; wider cells keep it O(N).
            cell *= 1.5
            nx = int((xmax - xmin) / cell) + 1
            ny = int((ymax - ymin) / cell) + 1
        cell_x = cell
        major_is_x = (xmax - xmin) > (ymax - ymin)
    n_major = nx if major_is_x else ny
    n_minor = ny if major_is_x else nx
    cell_of = np.full(n, -1, dtype=np.int32)
    starts = np.zeros(nx * ny + 1, dtype=np.int32)
    for i in range(n):
        if active[i]:
            cx = min(max(int((pos[i, 0] - xmin) / cell_x), 0), nx - 1)
            cy = min(max(int((pos[i, 1] - ymin) / cell), 0), ny - 1)
            c = cx * ny + cy if major_is_x else cy * nx + cx
            cell_of[i] = c
            starts[c + 1] += 1
    for c in range(nx * ny):
        starts[c + 1] += starts[c]
    fill = starts[:nx * ny].copy()
    order = np.empty(count, dtype=np.int32)
    # rank[i]: agent i's place k in the cell order (-1 inactive), the inverse of order
    rank = cell_of  # reused: cell_of[i] is not needed once i's place is known
    for i in range(n):
        c = cell_of[i]
        if c >= 0:
            order[fill[c]] = i
            rank[i] = fill[c]
            fill[c] += 1
    return order, starts, rank, n_major, n_minor, min(cell, cell_x)


# --------------------------------------------------------------------------- robot


@nb.njit(cache=True)
def _advance_robot(robot, robot_path, dt, params, walls, wall_meta, wall_start, wall_items):
    if robot[R_PRESENT] == 0.0:
        return
    x = robot[R_X]
    y = robot[R_Y]
    vmax = robot[R_MAX_SPEED]
    vx = 0.0
    vy = 0.0
    if robot[R_COMMANDED] != 0.0:
        vx = robot[R_CMD_VX]
        vy = robot[R_CMD_VY]
        speed = math.sqrt(vx * vx + vy * vy)
        if speed > vmax and speed > 0.0:
            vx *= vmax / speed
            vy *= vmax / speed
    elif robot_path.shape[0] > 0:
        k = int(robot[R_PATH_INDEX])
        last = robot_path.shape[0] - 1
        while True:
            gx = robot_path[k, 0]
            gy = robot_path[k, 1]
            d = math.sqrt((gx - x) ** 2 + (gy - y) ** 2)
            if k < last and d <= max(ROBOT_WAYPOINT_TOLERANCE, vmax * dt):
                k += 1
                continue
            break
        robot[R_PATH_INDEX] = k
        if d > _TINY:
            speed = min(vmax, d / dt)
            vx = speed * (gx - x) / d
            vy = speed * (gy - y) / d
    nx_, ny_, vx, vy = resolve_motion(x, y, x + vx * dt, y + vy * dt, vx, vy,
                                      params[P_CLEARANCE] * robot[R_RADIUS],
                                      walls, wall_meta, wall_start, wall_items)
    robot[R_X] = nx_
    robot[R_Y] = ny_
    robot[R_VX] = vx
    robot[R_VY] = vy
    if math.sqrt(vx * vx + vy * vy) >= params[P_YAW_HOLD]:
        robot[R_YAW] = math.atan2(vy, vx)


# --------------------------------------------------------------------------- the step
#
# A step runs in passes over the agents in cell order (k = position in the cell list, i = order[k]):
#   1. _prepare_step (serial): the robot, group centres, the cell list, the bands;
#   2. _gather: each agent's state and desired direction into one row of `nstate` (k-indexed,
#      so the pair loop reads neighbours from contiguous memory), accumulators cleared;
#   3. _pair_band: every pair within the cutoff once (Newton's third law: the Moussaid force,
#      the body contact and the sliding friction are antisymmetric, f_ji = -f_ij), adding to both
#      agents' accumulators;
#   4. _integrate: per agent, the desired drive, the robot, walls, groups, Weidmann's slowing,
#      integration and the wall-respecting move;
#   5. _separate_band / _apply_separation: the few-centimetre overlaps left, in Jacobi passes;
#   6. _commit: the new state scattered back to agent order.
# A pair is visited from the cell of its first agent: the same cell (later agents) and the
# "forward" cells (same major row, larger minor index; the next `span` major rows). Bands of
# `span` major rows then write only into themselves and the band after, so the even bands run
# in parallel, then the odd ones: no two threads write one accumulator, and every agent's sums
# are added in the same order on any number of threads (serial and parallel results are equal).

# Columns of the gathered neighbour state, one row per agent in cell order.
S_X = 0
S_Y = 1
S_VX = 2
S_VY = 3
S_R = 4
S_EX = 5    # unit desired direction, (0, 0) without one
S_EY = 6
S_DIR = 7   # 1.0 when the agent has a desired direction
S_COUNT = 8

# Columns of the per-agent pair accumulators.
A_SX = 0    # Moussaid social force, unweighted (each agent applies its own social factor)
A_SY = 1
A_CX = 2    # body compression plus sliding friction
A_CY = 3
A_AHEAD = 4  # neighbours in the half disc ahead within the density radius
A_GAP = 5    # narrowest gap to any body within the cutoff (a lower bound otherwise)
A_COUNT = 6


@nb.njit(cache=True)
def _prepare_step(dt, params, pos, vel, radius, active, group_start, group_members, group_cx, group_cy, group_n,
                  robot, robot_path, walls, wall_meta, wall_start, wall_items, rmax):
    """The serial part of a step: move the robot, group centres, the cell list and its bands."""
    _advance_robot(robot, robot_path, dt, params, walls, wall_meta, wall_start, wall_items)
    n_groups = group_start.shape[0] - 1
    for g in range(n_groups):
        sx = 0.0
        sy = 0.0
        cnt = 0
        for k in range(group_start[g], group_start[g + 1]):
            j = group_members[k]
            if active[j]:
                sx += pos[j, 0]
                sy += pos[j, 1]
                cnt += 1
        group_n[g] = cnt
        if cnt > 0:
            group_cx[g] = sx / cnt
            group_cy[g] = sy / cnt
    # Half-cutoff cells: the block scanned is 31% smaller than with cutoff-wide cells, which
    # matters in jams where most scanned candidates lie beyond the cutoff. At least two radii
    # wide, so that touching bodies always sit in the same or neighbouring cells (_separate_band).
    min_cell = max(0.5 * params[P_CUTOFF], 2.0 * rmax + 1e-6)
    order, starts, rank, n_major, n_minor, cell = _build_cells(pos, active, min_cell,
                                                               params[P_PERIOD], params[P_PERIOD_X0])
    span = int(math.ceil(params[P_CUTOFF] / cell - 1e-9))
    n_bands = (n_major + span - 1) // span
    return order, starts, rank, n_major, n_minor, span, n_bands


@nb.njit(cache=True)
def _desired_direction(i, m, px, py, goals, goal_len, goal_front, goal_radius, field_slot, field_vectors,
                       field_meta):
    """(has direction, ex, ey): towards the front goal, or along the agent's velocity field."""
    if m == MODE_GOALS:
        f = goal_front[i]
        if f < goal_len[i]:
            gx = goals[i, f, 0] - px
            gy = goals[i, f, 1] - py
            gd = math.sqrt(gx * gx + gy * gy)
            if gd > goal_radius[i] and gd > _TINY:
                return True, gx / gd, gy / gd
    elif m == MODE_FIELD:
        fs = field_slot[i]
        if fs >= 0:
            dxe = field_meta[fs, F_EXIT_X] - px
            dye = field_meta[fs, F_EXIT_Y] - py
            if dxe * dxe + dye * dye > goal_radius[i] * goal_radius[i]:
                sxv, syv = sample_field(field_vectors[fs], field_meta[fs, F_OX], field_meta[fs, F_OY],
                                        field_meta[fs, F_RES], px, py)
                sl = math.sqrt(sxv * sxv + syv * syv)
                if sl > 1e-6:
                    return True, sxv / sl, syv / sl
    return False, 0.0, 0.0


@nb.njit(cache=True)
def _gather(i0, i1, params, rank, pos, vel, radius, mode, goals, goal_len, goal_front, goal_radius,
            field_slot, field_vectors, field_meta, nstate, acc, rmax):
    """The gathered state rows and cleared accumulators of agents i0..i1.

    Agent-wise passes walk the agents in index order and write their row k = rank[i]: the agent
    arrays are read in order and only one row is written out of order.
    """
    gap0 = params[P_CUTOFF] - rmax
    body = params[P_BODY_FRACTION]
    for i in range(i0, i1):
        k = rank[i]
        if k < 0:
            continue
        px = pos[i, 0]
        py = pos[i, 1]
        has_dir, ex, ey = _desired_direction(i, mode[i], px, py, goals, goal_len, goal_front, goal_radius,
                                             field_slot, field_vectors, field_meta)
        nstate[k, S_X] = px
        nstate[k, S_Y] = py
        nstate[k, S_VX] = vel[i, 0]
        nstate[k, S_VY] = vel[i, 1]
        nstate[k, S_R] = radius[i] * body  # the body, not the envelope (SFMParams.body_fraction)
        nstate[k, S_EX] = ex
        nstate[k, S_EY] = ey
        nstate[k, S_DIR] = 1.0 if has_dir else 0.0
        acc[k, A_SX] = 0.0
        acc[k, A_SY] = 0.0
        acc[k, A_CX] = 0.0
        acc[k, A_CY] = 0.0
        acc[k, A_AHEAD] = 0.0
        acc[k, A_GAP] = gap0 - radius[i] * body


@nb.njit(cache=True, inline="always")
def _neighbour_cell(M, m, dM, dm, n_major, n_minor, period):
    """Flat index of the cell (M + dM, m + dm) and the x shift that brings its agents next to
    row M (non-zero only across a periodic seam); -1 outside the grid."""
    mm = m + dm
    if mm < 0 or mm >= n_minor:
        return -1, 0.0
    MM = M + dM
    shift = 0.0
    if MM >= n_major:
        if period <= 0.0:
            return -1, 0.0
        MM -= n_major
        shift = period
    return MM * n_minor + mm, shift


# Pairs are processed in chunks: a scalar scan collects the pairs within the cutoff (indices and
# offsets), one branch-free loop over the chunk computes every pair's terms (numba/LLVM turn it into
# SIMD: 4 or 8 pairs per instruction, square roots and divisions included), and a scalar loop adds
# them to both agents. The scalar loop this replaced spent most of its time waiting on one divider.
_PAIR_CHUNK = 512


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy", inline="always")
def _exp_nonpositive(x):
    """_fast_exp without branches (for the SIMD loop); arguments below -700 give ~1e-304, not 0."""
    x = max(x, -700.0)
    k = int(-x * 1.4426950408889634 + 0.5)
    r = x + k * 0.6931471805599453
    r2 = r * r
    p01 = 1.0 + r
    p23 = 0.5 + r * (1.0 / 6.0)
    p45 = 1.0 / 24.0 + r * (1.0 / 120.0)
    p67 = 1.0 / 720.0 + r * (1.0 / 5040.0)
    p89 = 1.0 / 40320.0 + r * (1.0 / 362880.0)
    r4 = r2 * r2
    p = (p01 + r2 * p23) + r4 * ((p45 + r2 * p67) + r4 * (p89 + r2 * (1.0 / 3628800.0)))
    return p * _POW2[k]


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy", inline="always")
def _atan2_branchless(y, x):
    """_fast_atan2 without branches (for the SIMD loop): the same polynomial, selects for the octants."""
    ax = abs(x)
    ay = abs(y)
    a = min(ax, ay) / max(max(ax, ay), 1e-300)
    s = a * a
    s2 = s * s
    s4 = s2 * s2
    s8 = s4 * s4
    q01 = 0.999999999549741 - 0.3333332776390596 * s
    q23 = 0.19999807871878367 - 0.14282689309481986 * s
    q45 = 0.11084431362845919 - 0.0894373147066482 * s
    q67 = 0.07148925896316664 - 0.0526013517930382 * s
    q89 = 0.03231716811204399 - 0.014773298847288617 * s
    q1011 = 0.0043120015004095005 - 0.0005905210158095912 * s
    r = a * ((q01 + s2 * q23) + s4 * (q45 + s2 * q67) + s8 * (q89 + s2 * q1011))
    r = 1.5707963267948966 - r if ay > ax else r
    r = 3.141592653589793 - r if x < 0.0 else r
    return math.copysign(r, y)


# Per-pair inputs and outputs of _pair_terms, one contiguous column each (SIMD loads need them).
Q_DX = 0      # offset to the second agent (a unit tie-break direction for coincident bodies)
Q_DY = 1
Q_TINY = 2    # 1.0 for coincident bodies: they count as 0 apart
Q_DVX = 3     # first agent's velocity minus the second's
Q_DVY = 4
Q_RSUM = 5    # sum of the radii
Q_EXI = 6     # desired directions of the first and the second agent
Q_EYI = 7
Q_EXJ = 8
Q_EYJ = 9
Q_IN = 10
O_SX = 0      # social force on the first agent (the second gets minus)
O_SY = 1
O_CX = 2      # contact force on the first agent (the second gets minus)
O_CY = 3
O_AHEAD_I = 4  # the second is ahead of the first / the first ahead of the second (within the density radius)
O_AHEAD_J = 5
O_GAP = 6
O_OUT = 7


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy")
def _pair_terms(count, params, dxs, dys, tinys, dvxs, dvys, rsums, exis, eyis, exjs, eyjs,
                osx, osy, ocx, ocy, oai, oaj, ogap):
    """Every term of pairs 0..count-1 from their columns (Q_*) into their output columns (O_*),
    branch-free so that the loop runs in SIMD lanes (error_model="numpy": no division checks to
    branch on; separate arrays: LLVM vectorizes only what it can prove does not overlap)."""
    lam = params[P_LAMBDA]
    gamma = params[P_GAMMA]
    inv_gamma = 1.0 / gamma
    epsilon = params[P_EPSILON]
    n_angle = params[P_N]
    n_vel = params[P_NPRIME]
    body = params[P_BODY]
    friction = params[P_FRICTION]
    density_radius = params[P_DENSITY_RADIUS]
    skip_exponent = params[P_SKIP]
    for p in range(count):
        dx = dxs[p]
        dy = dys[p]
        norm = math.sqrt(dx * dx + dy * dy)
        inv = 1.0 / norm
        ux = dx * inv
        uy = dy * inv
        dist = norm * (1.0 - tinys[p])
        near = dist < density_radius
        oai[p] = 1.0 if (near and ux * exis[p] + uy * eyis[p] > 0.0) else 0.0
        oaj[p] = 1.0 if (near and ux * exjs[p] + uy * eyjs[p] < 0.0) else 0.0
        gap = dist - rsums[p]
        ogap[p] = gap
        # body compression and sliding friction (HFV 2000), zero unless the bodies overlap
        overlap = max(-gap, 0.0)
        dvx = dvxs[p]
        dvy = dvys[p]
        slide = dvx * uy - dvy * ux
        ocx[p] = -body * overlap * ux - friction * overlap * slide * uy
        ocy[p] = -body * overlap * uy + friction * overlap * slide * ux
        # Moussaid's social force: interaction direction, its angle to the neighbour, two decays
        ix = lam * dvx + ux
        iy = lam * dvy + uy
        ilen = math.sqrt(ix * ix + iy * iy)
        degenerate = ilen <= _TINY
        ix = ux if degenerate else ix
        iy = uy if degenerate else iy
        ilen = 1.0 if degenerate else ilen
        inv_ilen = 1.0 / ilen
        b = gamma * ilen
        q = dist * inv_ilen * inv_gamma
        ix *= inv_ilen
        iy *= inv_ilen
        theta = _atan2_branchless(ix * uy - iy * ux, ix * ux + iy * uy) + epsilon * b
        ta = n_angle * b * theta
        tv = n_vel * b * theta
        ta2 = ta * ta
        tv2 = tv * tv
        # terms below exp(-skip_exponent) of their peak are left out, as in the scalar kernels
        keep = 1.0 if (q <= skip_exponent and q + min(ta2, tv2) <= skip_exponent) else 0.0
        f_v = -_exp_nonpositive(-q - tv2) * keep
        sign = 1.0 if theta > 0.0 else (-1.0 if theta < 0.0 else 0.0)
        f_a = -sign * _exp_nonpositive(-q - ta2) * keep
        # interaction direction times f_v plus its left normal (-iy, ix) times f_a;
        # the pair seen from the second agent has both directions reversed and the same angle
        osx[p] = f_v * ix - f_a * iy
        osy[p] = f_v * iy + f_a * ix


# The same pair terms in single precision (Crowd(precision="float32")): every constant is a
# float32 global, so no operand widens the lanes to float64 and a 512-bit register holds 16 pairs.
_F32 = np.float32
_POW2_32 = np.array([2.0 ** -k for k in range(0, 150)], dtype=np.float32)
_H0, _H1, _H2, _H6, _H24 = _F32(0.0), _F32(1.0), _F32(0.5), _F32(1.0 / 6.0), _F32(1.0 / 24.0)
_H120, _H720, _LN2, _LOG2E = _F32(1.0 / 120.0), _F32(1.0 / 720.0), _F32(0.6931471805599453), _F32(1.4426950408889634)
_LOW32 = _F32(-87.0)
_A1, _A3, _A5, _A7 = _F32(0.99997726), _F32(-0.33262347), _F32(0.19354346), _F32(-0.11643287)
_A9, _A11 = _F32(0.05265332), _F32(-0.01172120)
_HALF_PI32, _PI32, _TINY32, _EPS32 = _F32(math.pi / 2), _F32(math.pi), _F32(1e-12), _F32(1e-30)


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy", inline="always")
def _exp_nonpositive32(x):
    """exp(x), x <= 0, in float32 (relative error ~2e-7): 2^-k times a degree-6 series on |r| <= ln2 / 2."""
    x = max(x, _LOW32)
    k = int(-x * _LOG2E + _H2)
    r = x + _F32(k) * _LN2
    p = _H1 + r * (_H1 + r * (_H2 + r * (_H6 + r * (_H24 + r * (_H120 + r * _H720)))))
    return p * _POW2_32[k]


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy", inline="always")
def _atan2_branchless32(y, x):
    """atan2 in float32 (error ~1e-5 rad): an odd degree-11 fit on [0, 1] and selects for the octants."""
    ax = abs(x)
    ay = abs(y)
    a = min(ax, ay) / max(max(ax, ay), _EPS32)
    s = a * a
    r = a * (_A1 + s * (_A3 + s * (_A5 + s * (_A7 + s * (_A9 + s * _A11)))))
    r = _HALF_PI32 - r if ay > ax else r
    r = _PI32 - r if x < _H0 else r
    return math.copysign(r, y)


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy")
def _pair_terms32(count, params, dxs, dys, tinys, dvxs, dvys, rsums, exis, eyis, exjs, eyjs,
                  osx, osy, ocx, ocy, oai, oaj, ogap):
    """_pair_terms on float32 columns, computed in float32 (see _F32)."""
    lam = _F32(params[P_LAMBDA])
    gamma = _F32(params[P_GAMMA])
    inv_gamma = _H1 / gamma
    epsilon = _F32(params[P_EPSILON])
    n_angle = _F32(params[P_N])
    n_vel = _F32(params[P_NPRIME])
    body = _F32(params[P_BODY])
    friction = _F32(params[P_FRICTION])
    density_radius = _F32(params[P_DENSITY_RADIUS])
    skip_exponent = _F32(min(params[P_SKIP], 1e30))
    for p in range(count):
        dx = dxs[p]
        dy = dys[p]
        norm = math.sqrt(dx * dx + dy * dy)
        inv = _H1 / norm
        ux = dx * inv
        uy = dy * inv
        dist = norm * (_H1 - tinys[p])
        near = dist < density_radius
        oai[p] = _H1 if (near and ux * exis[p] + uy * eyis[p] > _H0) else _H0
        oaj[p] = _H1 if (near and ux * exjs[p] + uy * eyjs[p] < _H0) else _H0
        gap = dist - rsums[p]
        ogap[p] = gap
        overlap = max(-gap, _H0)
        dvx = dvxs[p]
        dvy = dvys[p]
        slide = dvx * uy - dvy * ux
        ocx[p] = -body * overlap * ux - friction * overlap * slide * uy
        ocy[p] = -body * overlap * uy + friction * overlap * slide * ux
        ix = lam * dvx + ux
        iy = lam * dvy + uy
        ilen = math.sqrt(ix * ix + iy * iy)
        degenerate = ilen <= _TINY32
        ix = ux if degenerate else ix
        iy = uy if degenerate else iy
        ilen = _H1 if degenerate else ilen
        inv_ilen = _H1 / ilen
        b = gamma * ilen
        q = dist * inv_ilen * inv_gamma
        ix *= inv_ilen
        iy *= inv_ilen
        theta = _atan2_branchless32(ix * uy - iy * ux, ix * ux + iy * uy) + epsilon * b
        ta = n_angle * b * theta
        tv = n_vel * b * theta
        ta2 = ta * ta
        tv2 = tv * tv
        keep = _H1 if (q <= skip_exponent and q + min(ta2, tv2) <= skip_exponent) else _H0
        f_v = -_exp_nonpositive32(-q - tv2) * keep
        sign = _H1 if theta > _H0 else (-_H1 if theta < _H0 else _H0)
        f_a = -sign * _exp_nonpositive32(-q - ta2) * keep
        osx[p] = f_v * ix - f_a * iy
        osy[p] = f_v * iy + f_a * ix


from numba.extending import overload as _overload  # noqa: E402


def _terms_for(precision):
    """The pair-terms kernel for the precision array's dtype (resolved when numba compiles the caller)."""
    return _pair_terms32 if precision.dtype == np.float32 else _pair_terms


@_overload(_terms_for)
def _terms_for_overload(precision):
    chosen = _pair_terms32 if precision.dtype == nb.float32 else _pair_terms
    return lambda precision: chosen


@nb.njit(cache=True)
def _add_pair_terms(count, first, second, pout, acc):
    """Each pair's terms onto both agents' accumulators, in pair order."""
    for p in range(count):
        k = first[p]
        kk = second[p]
        acc[k, A_SX] += pout[O_SX, p]
        acc[k, A_SY] += pout[O_SY, p]
        acc[kk, A_SX] -= pout[O_SX, p]
        acc[kk, A_SY] -= pout[O_SY, p]
        acc[k, A_CX] += pout[O_CX, p]
        acc[k, A_CY] += pout[O_CY, p]
        acc[kk, A_CX] -= pout[O_CX, p]
        acc[kk, A_CY] -= pout[O_CY, p]
        acc[k, A_AHEAD] += pout[O_AHEAD_I, p]
        acc[kk, A_AHEAD] += pout[O_AHEAD_J, p]
        gap = pout[O_GAP, p]
        if gap < acc[k, A_GAP]:
            acc[k, A_GAP] = gap
        if gap < acc[kk, A_GAP]:
            acc[kk, A_GAP] = gap


@nb.njit(cache=True)
def _pair_band(band, params, order, starts, n_major, n_minor, span, nstate, acc, precision, search_only=False):
    """Every pair within the cutoff whose first agent lies in `band` (span major rows), once.

    `search_only` finds the pairs and stops there (the profiler times the search apart). The pair
    columns take `precision`'s dtype (float32 halves what the search writes and doubles the SIMD
    lanes that read it; the sums stay float64)."""
    cutoff = params[P_CUTOFF]
    cutoff2 = cutoff * cutoff
    period = params[P_PERIOD]
    M0 = band * span
    M1 = min(M0 + span, n_major)
    # the cells a pair is looked for in, from the cell of its first agent: itself, then forward
    n_cells = 1 + span + span * (2 * span + 1)
    near = np.empty(n_cells, dtype=np.int64)
    near_shift = np.empty(n_cells)
    capacity = 0
    first = np.empty(capacity, dtype=np.int32)
    second = np.empty(capacity, dtype=np.int32)
    pin = np.empty((Q_IN, capacity), dtype=precision.dtype)
    pout = np.empty((O_OUT, capacity), dtype=precision.dtype)
    count = 0
    for c in range(M0 * n_minor, M1 * n_minor):
        if starts[c] == starts[c + 1]:
            continue
        M = c // n_minor
        m = c - M * n_minor
        cells = 0
        reach = 0
        for s in range(n_cells):
            if s == 0:
                dM = 0
                dm = 0
            elif s <= span:
                dM = 0
                dm = s
            else:
                dM = 1 + (s - span - 1) // (2 * span + 1)
                dm = (s - span - 1) % (2 * span + 1) - span
            cc, shift = _neighbour_cell(M, m, dM, dm, n_major, n_minor, period)
            if cc >= 0 and starts[cc] < starts[cc + 1]:
                near[cells] = cc
                near_shift[cells] = shift
                cells += 1
                reach += starts[cc + 1] - starts[cc]
        most = (starts[c + 1] - starts[c]) * reach
        if count + most > capacity:
            if count > 0 and not search_only:
                _terms_for(precision)(count, params, pin[Q_DX], pin[Q_DY], pin[Q_TINY], pin[Q_DVX], pin[Q_DVY], pin[Q_RSUM],
                            pin[Q_EXI], pin[Q_EYI], pin[Q_EXJ], pin[Q_EYJ], pout[O_SX], pout[O_SY], pout[O_CX],
                            pout[O_CY], pout[O_AHEAD_I], pout[O_AHEAD_J], pout[O_GAP])
                _add_pair_terms(count, first, second, pout, acc)
            count = 0
            if most > capacity:
                capacity = max(most, _PAIR_CHUNK)
                first = np.empty(capacity, dtype=np.int32)
                second = np.empty(capacity, dtype=np.int32)
                pin = np.empty((Q_IN, capacity), dtype=precision.dtype)
                pout = np.empty((O_OUT, capacity), dtype=precision.dtype)
        for k in range(starts[c], starts[c + 1]):
            xi = nstate[k, S_X]
            yi = nstate[k, S_Y]
            vxi = nstate[k, S_VX]
            vyi = nstate[k, S_VY]
            ri = nstate[k, S_R]
            exi = nstate[k, S_EX]
            eyi = nstate[k, S_EY]
            for t in range(cells):
                cc = near[t]
                shift = near_shift[t]
                for kk in range(k + 1 if cc == c else starts[cc], starts[cc + 1]):
                    dx = nstate[kk, S_X] + shift - xi
                    dy = nstate[kk, S_Y] - yi
                    d2 = dx * dx + dy * dy
                    if d2 > cutoff2:
                        continue
                    first[count] = k
                    second[count] = kk
                    if d2 > _TINY * _TINY:
                        pin[Q_DX, count] = dx
                        pin[Q_DY, count] = dy
                        pin[Q_TINY, count] = 0.0
                    else:
                        pin[Q_DX, count], pin[Q_DY, count] = _tie_break_direction(order[k], order[kk])
                        pin[Q_TINY, count] = 1.0
                    pin[Q_DVX, count] = vxi - nstate[kk, S_VX]
                    pin[Q_DVY, count] = vyi - nstate[kk, S_VY]
                    pin[Q_RSUM, count] = ri + nstate[kk, S_R]
                    pin[Q_EXI, count] = exi
                    pin[Q_EYI, count] = eyi
                    pin[Q_EXJ, count] = nstate[kk, S_EX]
                    pin[Q_EYJ, count] = nstate[kk, S_EY]
                    count += 1
    if count > 0 and not search_only:
        _terms_for(precision)(count, params, pin[Q_DX], pin[Q_DY], pin[Q_TINY], pin[Q_DVX], pin[Q_DVY], pin[Q_RSUM],
                    pin[Q_EXI], pin[Q_EYI], pin[Q_EXJ], pin[Q_EYJ], pout[O_SX], pout[O_SY], pout[O_CX],
                    pout[O_CY], pout[O_AHEAD_I], pout[O_AHEAD_J], pout[O_GAP])
        _add_pair_terms(count, first, second, pout, acc)


# Points spread evenly over the unit half disc ahead (x forward, y to the left): 3 rings of equal
# area, 8 directions each. _visible_share asks which of them a wall hides.
_AHEAD_SAMPLES = np.array([(math.sqrt((k + 0.5) / 3.0) * math.cos(-0.5 * math.pi + math.pi * (m + 0.5) / 8.0),
                            math.sqrt((k + 0.5) / 3.0) * math.sin(-0.5 * math.pi + math.pi * (m + 0.5) / 8.0))
                           for k in range(3) for m in range(8)])


@nb.njit(cache=True)
def _visible_share(px, py, ex, ey, reach, walls, wall_meta, wall_start, wall_items):
    """Share of the half disc of radius `reach` ahead of p (along unit e) that no wall hides from p.

    Next to a wall, part of the disc in which one counts the people ahead lies behind it, where
    nobody can be: the density is their count over the area left (in a 4 m corridor, counting
    over the whole disc made people walk 21 % faster than Weidmann at 3 per m^2).
    """
    cell = _wall_cell(px, py, wall_meta)
    if cell < 0 or wall_start[cell] == wall_start[cell + 1]:
        return 1.0
    visible = 0
    for s in range(_AHEAD_SAMPLES.shape[0]):
        a = _AHEAD_SAMPLES[s, 0] * reach
        b = _AHEAD_SAMPLES[s, 1] * reach
        sx = px + a * ex - b * ey
        sy = py + a * ey + b * ex
        hidden = False
        for kk in range(wall_start[cell], wall_start[cell + 1]):
            w = wall_items[kk]
            if _crossing_parameter(px, py, sx, sy, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3]) >= 0.0:
                hidden = True
                break
        if not hidden:
            visible += 1
    return visible / _AHEAD_SAMPLES.shape[0]


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy")
def _integrate(i0, i1, dt, params,
               rank, pos, vel, yaw, radius, desired_speed, factors, mode, active,
               group_slot, group_start, group_members, group_cx, group_cy, group_n,
               goals, goal_len, goal_front, goal_radius, cyclic,
               face_kind, face_ref, face_point, anchor,
               robot_interaction, robot,
               walls, wall_owner, wall_meta, wall_start, wall_items, free_meta, wall_free,
               nstate, acc, npos, nvel, nyaw):
    """Forces and integration for agents i0..i1; each writes only its own row k = rank[i] of npos,
    nvel, nyaw (and its anchor and goal front). acc[k, A_GAP] is left as the start gap."""
    n = pos.shape[0]
    cutoff = params[P_CUTOFF]
    cutoff2 = cutoff * cutoff
    tau = params[P_TAU]
    sigma = params[P_SIGMA_OBS]
    robot_sigma = params[P_ROBOT_SIGMA]
    robot_range = 10.0 * robot_sigma  # exp(-10) of the peak: nothing measurable beyond
    wall_range = params[P_WALL_RANGE]
    half_pi = 0.5 * math.pi
    body = params[P_BODY]
    friction = params[P_FRICTION]
    density_radius = params[P_DENSITY_RADIUS]
    # people per m^2 = count in the half disc ahead / its area
    density_area = 0.5 * math.pi * density_radius * density_radius
    robot_present = robot[R_PRESENT] != 0.0
    rx = robot[R_X]
    ry = robot[R_Y]
    rvx = robot[R_VX]
    rvy = robot[R_VY]
    rrad = robot[R_RADIUS]
    for i in range(i0, i1):
        k = rank[i]
        if k < 0:
            continue
        px = nstate[k, S_X]
        py = nstate[k, S_Y]
        vx = nstate[k, S_VX]
        vy = nstate[k, S_VY]
        ri = nstate[k, S_R]
        ex = nstate[k, S_EX]
        ey = nstate[k, S_EY]
        has_dir = nstate[k, S_DIR] != 0.0
        v0 = desired_speed[i]
        w_goal = factors[i, 0]
        w_obs = factors[i, 1]
        w_soc = factors[i, 2]
        w_other = factors[i, 3]
        m = mode[i]

        # desired force
        if has_dir:
            fx = w_goal * (v0 * ex - vx) / tau
            fy = w_goal * (v0 * ey - vy) / tau
            anchor[i, 0] = math.nan
        else:
            fx = -vx / tau
            fy = -vy / tau
            hold = params[P_HOLD]
            if robot_interaction[i] == ROBOT_FEARED or not (m == MODE_STOP or m == MODE_FACE):
                # only waiting people (Wait, Converse, facing) own a spot; a frightened one gives it up
                anchor[i, 0] = math.nan
            elif hold > 0.0 and math.isnan(anchor[i, 0]) and vx * vx + vy * vy < params[P_YAW_HOLD] ** 2:
                # The spot is where plain damping (-v / tau) brought it to rest, as in lightsfm:
                # holding changes how a waiting person resists pushes, not where it stops.
                anchor[i, 0] = px
                anchor[i, 1] = py
            if hold > 0.0 and not math.isnan(anchor[i, 0]):
                # Pushed off its spot, a waiting person is pulled back by a critically damped spring
                # (no rocking about the spot), so walkers cannot shove it around.
                stiffness = w_goal / (tau * hold)
                hx = stiffness * (anchor[i, 0] - px)
                hy = stiffness * (anchor[i, 1] - py)
                hs = math.sqrt(hx * hx + hy * hy)
                brace = HOLD_BRACE * w_goal * v0 / tau
                if hs > brace and hs > 0.0:
                    hx *= brace / hs
                    hy *= brace / hs
                extra_damping = 2.0 * math.sqrt(max(stiffness, 0.0)) - 1.0 / tau
                if extra_damping > 0.0:
                    hx -= extra_damping * vx
                    hy -= extra_damping * vy
                fx += hx
                fy += hy

        # neighbours: the pair pass summed the social force and the contacts
        sfx = acc[k, A_SX]
        sfy = acc[k, A_SY]
        fx += acc[k, A_CX]
        fy += acc[k, A_CY]
        ahead = acc[k, A_AHEAD]

        # the robot, as HuNavSim's behaviours perceive it
        if robot_present:
            # people keep their whole radius from the robot, not only the body: the robot's contact
            # metrics (HuNavSim's robot-on-person collisions) count at the radius
            rr = radius[i]
            ri_mode = robot_interaction[i]
            rdx = rx - px
            rdy = ry - py
            rd2 = rdx * rdx + rdy * rdy
            if rd2 < (rr + rrad) * (rr + rrad):
                # the bodies touch, whatever the person makes of the robot (a reaction that takes the
                # robot out of the social forces, approaching it, fearing it): nobody walks through it
                rd = math.sqrt(rd2)
                overlap = rr + rrad - rd
                if rd > _TINY:
                    fx -= body * overlap * rdx / rd
                    fy -= body * overlap * rdy / rd
            if ri_mode == ROBOT_AS_AGENT:
                if rd2 <= cutoff2:
                    ax_, ay_ = _social_force(px, py, vx, vy, rx, ry, rvx, rvy, i, -1, params)
                    sfx += ax_
                    sfy += ay_
            elif ri_mode == ROBOT_AS_OBSTACLE:
                if rd2 <= (robot_range + rr) * (robot_range + rr):
                    ax_, ay_ = _point_obstacle_force(px, py, rx, ry, rr, w_obs, robot_sigma, i)
                    fx += ax_
                    fy += ay_
            elif ri_mode == ROBOT_FEARED:
                rd = math.sqrt(rd2)
                gap = rd - rr
                if gap < 0.05:
                    gap = 0.05
                mag = w_other * robot_sigma / gap
                if rd > _TINY:
                    fx -= mag * rdx / rd
                    fy -= mag * rdy / rd
                else:
                    a = _GOLDEN_ANGLE * i
                    fx += mag * math.cos(a)
                    fy += mag * math.sin(a)
        fx += w_soc * sfx
        fy += w_soc * sfy
        clear = _wall_free(px, py, free_meta, wall_free)
        if has_dir and ahead > 0.0 and density_radius > 0.0:
            # Weidmann's fundamental diagram, normalised to 1 at free flow: the drive aims at the
            # slower speed (lowering v0 in w_goal (v0 e - v) / tau)
            # the people counted stand in the part of the half disc no wall hides. One counts oneself
            # as half a person: in a crowd each person holds about 1/rho of the floor, and half of
            # one's own share lies in the half disc ahead, where nobody else's centre can be; the
            # count of the others alone is rho A - 1/2 (without the half, the corridor's crowd
            # walked 11-16 % faster than Weidmann at 2-4 per m^2; with it, within 4 % at 0.5-4)
            share = 1.0
            if clear < density_radius:
                share = _visible_share(px, py, ex, ey, density_radius, walls, wall_meta, wall_start, wall_items)
            rho = (ahead + 0.5) / max(share * density_area, 0.05 * density_area)
            slow = 0.0
            if rho < 5.4:
                # _fast_exp, not math.exp: the same bits in the serial and the parallel kernel
                slow = 1.0 - _fast_exp(-1.913 * (1.0 / rho - 1.0 / 5.4))
            fx -= w_goal * v0 * (1.0 - slow) * ex / tau
            fy -= w_goal * v0 * (1.0 - slow) * ey / tau

        # obstacle force summed over nearby wall segments
        wc = _wall_cell(px, py, wall_meta) if clear <= wall_range + ri else -1
        if wc >= 0:
            for kk in range(wall_start[wc], wall_start[wc + 1]):
                w = wall_items[kk]
                cx, cy, t = _closest_on_segment(px, py, walls[w, 0], walls[w, 1], walls[w, 2], walls[w, 3])
                if (t <= 0.0 and not wall_owner[w, 0]) or (t >= 1.0 and not wall_owner[w, 1]):
                    continue
                dx = px - cx
                dy = py - cy
                d = math.sqrt(dx * dx + dy * dy)
                if d > wall_range + ri:
                    continue
                if d > _TINY:
                    ux = dx / d
                    uy = dy / d
                else:
                    ux, uy = _wall_normal_towards(w, px, py, walls)
                mag = w_obs * math.exp(-(d - ri) / sigma)
                if d < ri:
                    # body against the wall: compression out of it and friction along it (HFV 2000)
                    mag += body * (ri - d)
                    slide = vx * -uy + vy * ux
                    fx += friction * (ri - d) * slide * uy
                    fy -= friction * (ri - d) * slide * ux
                fx += mag * ux
                fy += mag * uy

        # group gaze, coherence and repulsion (lightsfm non-paper version)
        g = group_slot[i]
        if g >= 0 and group_n[g] >= 2:
            cnt = group_n[g]
            gcx = group_cx[g]
            gcy = group_cy[g]
            if has_dir:
                ocx = (cnt * gcx - px) / (cnt - 1) - px
                ocy = (cnt * gcy - py) / (cnt - 1) - py
                onorm = math.sqrt(ocx * ocx + ocy * ocy)
                if onorm > _TINY:
                    dot = ex * ocx + ey * ocy
                    cosang = dot / onorm
                    if cosang > 1.0:
                        cosang = 1.0
                    elif cosang < -1.0:
                        cosang = -1.0
                    if math.acos(cosang) > half_pi:
                        fx += params[P_GAZE] * dot * ex
                        fy += params[P_GAZE] * dot * ey
            rcx = gcx - px
            rcy = gcy - py
            dist = math.sqrt(rcx * rcx + rcy * rcy)
            soft = params[P_COHERENCE] * (math.tanh(dist - (cnt - 1) / 2.0) + 1.0) / 2.0
            fx += soft * rcx
            fy += soft * rcy
            rep_x = 0.0
            rep_y = 0.0
            for kk in range(group_start[g], group_start[g + 1]):
                j = group_members[kk]
                if j == i or not active[j]:
                    continue
                dx = px - pos[j, 0]
                dy = py - pos[j, 1]
                if math.sqrt(dx * dx + dy * dy) < ri + radius[j] * params[P_BODY_FRACTION]:
                    rep_x += dx
                    rep_y += dy
            fx += params[P_REPULSION] * rep_x
            fy += params[P_REPULSION] * rep_y

        # integrate, clip to the desired speed
        nvx = vx + fx * dt
        nvy = vy + fy * dt
        speed = math.sqrt(nvx * nvx + nvy * nvy)
        if speed > v0:
            if speed > 0.0:
                nvx *= v0 / speed
                nvy *= v0 / speed
            else:
                nvx = 0.0
                nvy = 0.0
        if not (math.isfinite(nvx) and math.isfinite(nvy)):
            nvx = 0.0
            nvy = 0.0
        # the clearance is a share of the radius (the envelope), not of the body
        if clear > (abs(nvx) + abs(nvy)) * dt + params[P_CLEARANCE] * radius[i] + 1e-9:
            # no wall within reach of this step: resolve_motion would return the straight move
            qx = px + nvx * dt
            qy = py + nvy * dt
        else:
            qx, qy, nvx, nvy = resolve_motion(px, py, px + nvx * dt, py + nvy * dt, nvx, nvy,
                                              params[P_CLEARANCE] * radius[i],
                                              walls, wall_meta, wall_start, wall_items)
        npos[k, 0] = qx
        npos[k, 1] = qy
        nvel[k, 0] = nvx
        nvel[k, 1] = nvy

        # heading
        yi = yaw[i]
        if m == MODE_FACE:
            kind = face_kind[i]
            tx = face_point[i, 0]
            ty = face_point[i, 1]
            valid = True
            if kind == FACE_AGENT:
                jr = face_ref[i]
                if jr >= 0 and jr < n:
                    tx = pos[jr, 0]
                    ty = pos[jr, 1]
                else:
                    valid = False
            elif kind == FACE_ROBOT:
                if robot_present:
                    tx = rx
                    ty = ry
                else:
                    valid = False
            ddx = tx - qx
            ddy = ty - qy
            if valid and ddx * ddx + ddy * ddy > _TINY:
                yi = _turn_towards(yi, math.atan2(ddy, ddx), params[P_TURN_RATE] * dt)
        elif math.sqrt(nvx * nvx + nvy * nvy) >= params[P_YAW_HOLD]:
            yi = math.atan2(nvy, nvx)
        nyaw[k] = yi

        # the front goal pops (or cycles) once inside its radius; a final goal stays as the front
        if m == MODE_GOALS:
            f = goal_front[i]
            nl = goal_len[i]
            if f < nl:
                gx = goals[i, f, 0] - qx
                gy = goals[i, f, 1] - qy
                if gx * gx + gy * gy <= goal_radius[i] * goal_radius[i]:
                    if cyclic[i]:
                        goal_front[i] = (f + 1) % nl
                    elif f + 1 < nl:
                        goal_front[i] = f + 1


@nb.njit(cache=True)
def _slack_after_moves(n_active, nstate, npos, acc, slack):
    """slack[k] = start gap of k minus its own step; returns the largest step anyone took.

    Two bodies closed in by at most the sum of their steps: one whose slack exceeds every other
    step (the largest) still does not touch anyone at its new position.
    """
    largest = 0.0
    for k in range(n_active):
        dx = npos[k, 0] - nstate[k, S_X]
        dy = npos[k, 1] - nstate[k, S_Y]
        step = math.sqrt(dx * dx + dy * dy)
        slack[k] = acc[k, A_GAP] - step
        if step > largest:
            largest = step
    return largest


@nb.njit(cache=True, fastmath=_FASTMATH, error_model="numpy")
def _separate_band(band, order, starts, n_major, n_minor, span, period, nstate, where, push, slack, clear_limit):
    """Half of each overlap at `where`, for every touching pair whose first agent lies in `band`,
    added to both agents' `push` (opposite ways). Contact needs cells of at least two radii: the
    cells are half the cutoff wide, so touching bodies are in the same or a neighbouring cell.
    A pair with either slack above clear_limit cannot touch: it is skipped."""
    M0 = band * span
    M1 = min(M0 + span, n_major)
    for c in range(M0 * n_minor, M1 * n_minor):
        if starts[c] == starts[c + 1]:
            continue
        M = c // n_minor
        m = c - M * n_minor
        for k in range(starts[c], starts[c + 1]):
            if slack[k] > clear_limit + 1e-9:  # a nanometre spare for rounding
                continue
            xi = where[k, 0]
            yi = where[k, 1]
            ri = nstate[k, S_R]
            pxi = 0.0
            pyi = 0.0
            for s in range(5):
                if s == 0:
                    cc = c
                    shift = 0.0
                else:
                    dM = 0 if s == 1 else 1
                    dm = 1 if s == 1 else s - 3
                    cc, shift = _neighbour_cell(M, m, dM, dm, n_major, n_minor, period)
                    if cc < 0:
                        continue
                for kk in range(k + 1 if s == 0 else starts[cc], starts[cc + 1]):
                    if slack[kk] > clear_limit + 1e-9:
                        continue
                    dx = xi - where[kk, 0] - shift
                    dy = yi - where[kk, 1]
                    reach = ri + nstate[kk, S_R]
                    d2 = dx * dx + dy * dy
                    if d2 >= reach * reach:
                        continue
                    d = math.sqrt(d2)
                    if d > _TINY:
                        ux = dx / d
                        uy = dy / d
                    else:
                        ux, uy = _tie_break_direction(order[k], order[kk])
                        ux = -ux
                        uy = -uy
                    share = 0.5 * (reach - d)
                    pxi += share * ux
                    pyi += share * uy
                    push[kk, 0] -= share * ux
                    push[kk, 1] -= share * uy
            push[k, 0] += pxi
            push[k, 1] += pyi


@nb.njit(cache=True)
def _apply_separation(k0, k1, params, nstate, where, push, out,
                      walls, wall_meta, wall_start, wall_items, free_meta, wall_free):
    """Each agent moves by its push, never through a wall; returns how many moved (pushes are cleared)."""
    moved = 0
    for k in range(k0, k1):
        px = where[k, 0]
        py = where[k, 1]
        sx = push[k, 0]
        sy = push[k, 1]
        if sx != 0.0 or sy != 0.0:
            clearance = params[P_CLEARANCE] * nstate[k, S_R] / params[P_BODY_FRACTION]  # of the radius
            if _wall_free(px, py, free_meta, wall_free) > abs(sx) + abs(sy) + clearance + 1e-9:
                qx = px + sx
                qy = py + sy
            else:
                qx, qy, _vx, _vy = resolve_motion(px, py, px + sx, py + sy, 0.0, 0.0, clearance,
                                                  walls, wall_meta, wall_start, wall_items)
            out[k, 0] = qx
            out[k, 1] = qy
            push[k, 0] = 0.0
            push[k, 1] = 0.0
            moved += 1
        else:
            out[k, 0] = px
            out[k, 1] = py
    return moved


@nb.njit(cache=True)
def _commit(i0, i1, params, rank, pos, vel, yaw, npos, nvel, nyaw, acc, min_gap):
    """The new state back in agent order; on a periodic crowd x wraps into the period. min_gap[i]: the
    narrowest gap between i's body and any other at the start of the step (inf when inactive)."""
    period = params[P_PERIOD]
    x0 = params[P_PERIOD_X0]
    for i in range(i0, i1):
        k = rank[i]
        if k < 0:
            min_gap[i] = np.inf
            continue
        min_gap[i] = acc[k, A_GAP]
        x = npos[k, 0]
        if period > 0.0:
            x = x0 + (x - x0) % period
        pos[i, 0] = x
        pos[i, 1] = npos[k, 1]
        vel[i, 0] = nvel[k, 0]
        vel[i, 1] = nvel[k, 1]
        yaw[i] = nyaw[k]


# Jacobi separation passes per step (even: they run in pairs): in a room pressed into a corner
# one left 8.7 cm overlaps, three 5.3 cm, four under 5.
SEPARATION_PASSES = 4


@nb.njit(cache=True)
def _pairs_serial(params, order, starts, n_major, n_minor, span, n_bands, nstate, acc, precision, search_only=False):
    """The pair pass on one thread, in the parallel pass's band order (even bands, then odd)."""
    for parity in range(2):
        for band in range(parity, n_bands, 2):
            _pair_band(band, params, order, starts, n_major, n_minor, span, nstate, acc, precision, search_only)


@nb.njit(cache=True)
def _separation_serial(params, n_active, order, starts, n_major, n_minor, span, n_bands, nstate, acc,
                       npos, spare, push, slack, walls, wall_meta, wall_start, wall_items, free_meta, wall_free):
    """The separation passes on one thread; the result ends in npos.

    The first pass skips whoever cannot touch anyone; later ones look at everyone. Passes run in
    pairs, there and back; a pass that moved nobody copied its input, so npos holds the result.
    """
    clear_limit = _slack_after_moves(n_active, nstate, npos, acc, slack)
    for _pair in range(SEPARATION_PASSES // 2):
        for parity in range(2):
            for band in range(parity, n_bands, 2):
                _separate_band(band, order, starts, n_major, n_minor, span, params[P_PERIOD],
                               nstate, npos, push, slack, clear_limit)
        if _apply_separation(0, n_active, params, nstate, npos, push, spare,
                             walls, wall_meta, wall_start, wall_items, free_meta, wall_free) == 0:
            break
        clear_limit = math.inf
        for parity in range(2):
            for band in range(parity, n_bands, 2):
                _separate_band(band, order, starts, n_major, n_minor, span, params[P_PERIOD],
                               nstate, spare, push, slack, clear_limit)
        if _apply_separation(0, n_active, params, nstate, spare, push, npos,
                             walls, wall_meta, wall_start, wall_items, free_meta, wall_free) == 0:
            break


# Two drivers with the same body: on a loaded 2-core machine a thread barrier costs more than a
# small crowd's whole step, so Crowd runs small crowds serially. They are separate functions
# (not one factory) because numba's on-disk cache keys by function name and line. Both visit the
# bands in the same order (even, then odd), so their sums, and results, are bit for bit equal.
@nb.njit(cache=True)
def advance_serial(n_steps, dt, params,
                   pos, vel, yaw, radius, desired_speed, factors, mode, active,
                   group_slot, group_start, group_members,
                   goals, goal_len, goal_front, goal_radius, cyclic,
                   field_slot, field_vectors, field_meta,
                   face_kind, face_ref, face_point, anchor,
                   robot_interaction, robot, robot_path,
                   walls, wall_owner, wall_meta, wall_start, wall_items, free_meta, wall_free, block, min_gap, precision):
    """Run n_steps of the crowd on one thread; every array is updated in place."""
    n = pos.shape[0]
    n_groups = group_start.shape[0] - 1
    nstate = np.empty((n, S_COUNT))
    acc = np.empty((n, A_COUNT))
    npos = np.empty((n, 2))
    spare = np.empty((n, 2))
    push = np.zeros((n, 2))
    nvel = np.empty((n, 2))
    nyaw = np.empty(n)
    slack = np.empty(n)
    rmax = radius.max() if n else 0.0
    group_cx = np.zeros(max(n_groups, 1))
    group_cy = np.zeros(max(n_groups, 1))
    group_n = np.zeros(max(n_groups, 1), dtype=np.int64)
    for _step in range(n_steps):
        order, starts, rank, n_major, n_minor, span, n_bands = _prepare_step(
            dt, params, pos, vel, radius, active, group_start, group_members, group_cx, group_cy, group_n,
            robot, robot_path, walls, wall_meta, wall_start, wall_items, rmax)
        n_active = order.shape[0]
        _gather(0, n, params, rank, pos, vel, radius, mode, goals, goal_len, goal_front, goal_radius,
                field_slot, field_vectors, field_meta, nstate, acc, rmax)
        _pairs_serial(params, order, starts, n_major, n_minor, span, n_bands, nstate, acc, precision)
        _integrate(0, n, dt, params, rank, pos, vel, yaw, radius, desired_speed, factors, mode, active,
                   group_slot, group_start, group_members, group_cx, group_cy, group_n,
                   goals, goal_len, goal_front, goal_radius, cyclic, face_kind, face_ref, face_point, anchor,
                   robot_interaction, robot, walls, wall_owner, wall_meta, wall_start, wall_items,
                   free_meta, wall_free, nstate, acc, npos, nvel, nyaw)
        if params[P_BODY] > 0.0:
            _separation_serial(params, n_active, order, starts, n_major, n_minor, span, n_bands, nstate, acc,
                               npos, spare, push, slack, walls, wall_meta, wall_start, wall_items, free_meta, wall_free)
        _commit(0, n, params, rank, pos, vel, yaw, npos, nvel, nyaw, acc, min_gap)


@nb.njit(cache=True, parallel=True)
def advance_parallel(n_steps, dt, params,
                     pos, vel, yaw, radius, desired_speed, factors, mode, active,
                     group_slot, group_start, group_members,
                     goals, goal_len, goal_front, goal_radius, cyclic,
                     field_slot, field_vectors, field_meta,
                     face_kind, face_ref, face_point, anchor,
                     robot_interaction, robot, robot_path,
                     walls, wall_owner, wall_meta, wall_start, wall_items, free_meta, wall_free, block, min_gap, precision):
    """advance_serial with agent blocks of `block` rows and bands spread over threads.

    Per-agent passes write only their own rows; pair passes run the even bands together, then
    the odd ones, which write disjoint rows (see the top of this section). A periodic crowd's
    last band writes into the first: Crowd runs those serially.
    """
    n = pos.shape[0]
    n_groups = group_start.shape[0] - 1
    nstate = np.empty((n, S_COUNT))
    acc = np.empty((n, A_COUNT))
    npos = np.empty((n, 2))
    spare = np.empty((n, 2))
    push = np.zeros((n, 2))
    nvel = np.empty((n, 2))
    nyaw = np.empty(n)
    slack = np.empty(n)
    rmax = radius.max() if n else 0.0
    group_cx = np.zeros(max(n_groups, 1))
    group_cy = np.zeros(max(n_groups, 1))
    group_n = np.zeros(max(n_groups, 1), dtype=np.int64)
    for _step in range(n_steps):
        order, starts, rank, n_major, n_minor, span, n_bands = _prepare_step(
            dt, params, pos, vel, radius, active, group_start, group_members, group_cx, group_cy, group_n,
            robot, robot_path, walls, wall_meta, wall_start, wall_items, rmax)
        n_active = order.shape[0]
        n_blocks = (n_active + block - 1) // block
        n_agent_blocks = (n + block - 1) // block
        for b in nb.prange(n_agent_blocks):
            _gather(b * block, min((b + 1) * block, n), params, rank, pos, vel, radius, mode, goals,
                    goal_len, goal_front, goal_radius, field_slot, field_vectors, field_meta, nstate, acc, rmax)
        for parity in range(2):
            for t in nb.prange((n_bands - parity + 1) // 2):
                _pair_band(2 * t + parity, params, order, starts, n_major, n_minor, span, nstate, acc, precision)
        for b in nb.prange(n_agent_blocks):
            _integrate(b * block, min((b + 1) * block, n), dt, params, rank, pos, vel, yaw, radius,
                       desired_speed, factors, mode, active,
                       group_slot, group_start, group_members, group_cx, group_cy, group_n,
                       goals, goal_len, goal_front, goal_radius, cyclic, face_kind, face_ref, face_point, anchor,
                       robot_interaction, robot, walls, wall_owner, wall_meta, wall_start, wall_items,
                       free_meta, wall_free, nstate, acc, npos, nvel, nyaw)
        if params[P_BODY] > 0.0:
            clear_limit = _slack_after_moves(n_active, nstate, npos, acc, slack)
            for _pair in range(SEPARATION_PASSES // 2):
                for parity in range(2):
                    for t in nb.prange((n_bands - parity + 1) // 2):
                        _separate_band(2 * t + parity, order, starts, n_major, n_minor, span, params[P_PERIOD],
                                       nstate, npos, push, slack, clear_limit)
                moved = 0
                for b in nb.prange(n_blocks):
                    moved += _apply_separation(b * block, min((b + 1) * block, n_active), params, nstate, npos,
                                               push, spare, walls, wall_meta, wall_start, wall_items,
                                               free_meta, wall_free)
                if moved == 0:
                    break
                clear_limit = math.inf
                for parity in range(2):
                    for t in nb.prange((n_bands - parity + 1) // 2):
                        _separate_band(2 * t + parity, order, starts, n_major, n_minor, span, params[P_PERIOD],
                                       nstate, spare, push, slack, clear_limit)
                moved = 0
                for b in nb.prange(n_blocks):
                    moved += _apply_separation(b * block, min((b + 1) * block, n_active), params, nstate, spare,
                                               push, npos, walls, wall_meta, wall_start, wall_items,
                                               free_meta, wall_free)
                if moved == 0:
                    break
        # A serial copy costs less than another thread barrier.
        _commit(0, n, params, rank, pos, vel, yaw, npos, nvel, nyaw, acc, min_gap)


# --------------------------------------------------------------------------- profiling

# The phases of a step as profile_steps names them, in the order they run.
PROFILE_PHASES = ("cell list and robot", "gather state", "pair search (cells, distances)",
                  "pair terms (Moussaid, contacts, density) and sums", "per agent: drive, walls, groups, move",
                  "separation passes", "commit")


def profile_steps(n_steps, dt, params,
                  pos, vel, yaw, radius, desired_speed, factors, mode, active,
                  group_slot, group_start, group_members,
                  goals, goal_len, goal_front, goal_radius, cyclic,
                  field_slot, field_vectors, field_meta,
                  face_kind, face_ref, face_point, anchor,
                  robot_interaction, robot, robot_path,
                  walls, wall_owner, wall_meta, wall_start, wall_items, free_meta, wall_free, block, min_gap, precision):
    """advance_serial's steps with every pass timed in process CPU seconds: {phase: seconds}.

    The passes are the compiled ones, called from Python one by one (a few microseconds of call
    overhead each); the pair search runs once more on its own to split the pair pass's cost.
    The crowd ends exactly where advance_serial would have put it (tests/crowd/test_sfm.py).
    """
    import time

    cpu = time.process_time
    spent = dict.fromkeys(PROFILE_PHASES, 0.0)
    n = pos.shape[0]
    n_groups = group_start.shape[0] - 1
    nstate = np.empty((n, S_COUNT))
    acc = np.empty((n, A_COUNT))
    npos = np.empty((n, 2))
    spare = np.empty((n, 2))
    push = np.zeros((n, 2))
    nvel = np.empty((n, 2))
    nyaw = np.empty(n)
    slack = np.empty(n)
    rmax = radius.max() if n else 0.0
    group_cx = np.zeros(max(n_groups, 1))
    group_cy = np.zeros(max(n_groups, 1))
    group_n = np.zeros(max(n_groups, 1), dtype=np.int64)
    for _step in range(n_steps):
        t = cpu()
        order, starts, rank, n_major, n_minor, span, n_bands = _prepare_step(
            dt, params, pos, vel, radius, active, group_start, group_members, group_cx, group_cy, group_n,
            robot, robot_path, walls, wall_meta, wall_start, wall_items, rmax)
        n_active = order.shape[0]
        spent["cell list and robot"] += cpu() - t
        t = cpu()
        _gather(0, n, params, rank, pos, vel, radius, mode, goals, goal_len, goal_front, goal_radius,
                field_slot, field_vectors, field_meta, nstate, acc, rmax)
        spent["gather state"] += cpu() - t
        t = cpu()
        _pairs_serial(params, order, starts, n_major, n_minor, span, n_bands, nstate, acc, precision, True)
        search = cpu() - t
        t = cpu()
        _pairs_serial(params, order, starts, n_major, n_minor, span, n_bands, nstate, acc, precision)
        full = cpu() - t
        spent["pair search (cells, distances)"] += min(search, full)
        spent["pair terms (Moussaid, contacts, density) and sums"] += max(full - search, 0.0)
        t = cpu()
        _integrate(0, n, dt, params, rank, pos, vel, yaw, radius, desired_speed, factors, mode, active,
                   group_slot, group_start, group_members, group_cx, group_cy, group_n,
                   goals, goal_len, goal_front, goal_radius, cyclic, face_kind, face_ref, face_point, anchor,
                   robot_interaction, robot, walls, wall_owner, wall_meta, wall_start, wall_items,
                   free_meta, wall_free, nstate, acc, npos, nvel, nyaw)
        spent["per agent: drive, walls, groups, move"] += cpu() - t
        t = cpu()
        if params[P_BODY] > 0.0:
            _separation_serial(params, n_active, order, starts, n_major, n_minor, span, n_bands, nstate, acc,
                               npos, spare, push, slack, walls, wall_meta, wall_start, wall_items, free_meta, wall_free)
        spent["separation passes"] += cpu() - t
        t = cpu()
        _commit(0, n, params, rank, pos, vel, yaw, npos, nvel, nyaw, acc, min_gap)
        spent["commit"] += cpu() - t
    return spent
