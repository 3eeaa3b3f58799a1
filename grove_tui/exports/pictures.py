"""Pictures of a scenario for papers (PNG/SVG with matplotlib) and for the terminal (rich).

The figure shows the world (zones with labels, walls, doors, exits, entities), every agent's spawn,
goals and injected waypoints, velocity-field arrows, the robot's start, goal and path, and, when the
bundle was simulated, the trajectories. matplotlib is an optional extra (`grove-tui[plots]`).
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from rich.text import Text

from grove_tui.files import FileGuard, check_output_file, write_bytes_atomic
from grove_tui.errors import PictureError
from grove_tui.scenario.model import Scenario
from grove_tui.world import World

if TYPE_CHECKING:
    from grove_tui.navigation.velocity_field import VelocityField

# Written into every picture's metadata (PNG Software, SVG/PDF Creator): how a later `grove picture --out`
# knows the file there is its own to replace; any other file is kept unless the user passes --overwrite.
PICTURE_MARK = "grove-tui"
_MARK_WINDOW = 64 * 1024

# Colour-blind-safe cycle (Okabe-Ito) for groups; solo agents share a neutral grey.
GROUP_COLOURS = ("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#D55E00", "#F0E442", "#000000")
SOLO_COLOUR = "#555555"
RICH_GROUP_STYLES = ("bold cyan", "bold magenta", "bold green", "bold yellow", "bold blue", "bold red")


def _group_colour(group: int) -> str:
    return SOLO_COLOUR if group < 0 else GROUP_COLOURS[group % len(GROUP_COLOURS)]


def _load_fields(scenario: Scenario, bundle_dir: Path) -> dict[str, VelocityField]:
    from grove_tui.scenario.bundle import load_field

    return {fid: load_field(bundle_dir, fid, rel) for fid, rel in scenario.fields.items()}


def is_grove_picture(path: Path) -> bool:
    """A picture `grove picture` wrote: its metadata names GROVE (PNG text chunks and SVG metadata sit at the
    start of the file, a PDF's information dictionary at its end)."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(_MARK_WINDOW)
            handle.seek(max(0, os.fstat(handle.fileno()).st_size - _MARK_WINDOW))
            tail = handle.read(_MARK_WINDOW)
    except OSError:
        return False
    mark = PICTURE_MARK.encode()
    return mark in head or mark in tail


def draw_scenario(world: World, scenario: Scenario, bundle_dir: str | Path, out_path: str | Path, *,
                  trajectories: str | Path | None = None, title: str | None = None, dpi: int = 150,
                  overwrite: bool = False) -> Path:
    """Write a PNG, SVG or PDF (by suffix) of the scenario, with trajectories if a CSV is given.

    An existing file at `out_path` is replaced only when GROVE drew it (`is_grove_picture`) or with
    `overwrite`; never through a link, never a folder or a special file.
    """
    try:
        import matplotlib

        matplotlib.use("Agg", force=True)
        # SVG element ids come from a random salt unless one is set: keep pictures reproducible
        matplotlib.rcParams["svg.hashsalt"] = "grove-tui"
        import matplotlib.pyplot as plt
        from matplotlib.patches import Polygon as PolygonPatch
    except ImportError:
        raise PictureError("pictures need matplotlib: pip install 'grove-tui[plots]'") from None
    out = Path(out_path)
    fmt = out.suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise PictureError(f"{out}: picture format must be .png, .svg or .pdf")
    guard = FileGuard(owned=is_grove_picture, what="picture GROVE drew", overwrite=overwrite)
    check_output_file(out, **guard)  # before the drawing, not after it
    bundle = Path(bundle_dir)

    xmin, ymin, xmax, ymax = world.bounds()
    width_in = 10.0
    height_in = max(3.0, width_in * (ymax - ymin) / max(xmax - xmin, 1e-6))
    fig, ax = plt.subplots(figsize=(width_in, height_in + 0.6))
    try:
        for zone in world.zones:
            ax.add_patch(PolygonPatch(np.asarray(zone.boundary), closed=True, facecolor="#f4f1ea",
                                      edgecolor="none", zorder=0))
            cx, cy = zone.centroid
            ax.text(cx, cy, zone.name.replace("_", " "), ha="center", va="center", fontsize=6,
                    color="#8a8070", zorder=1)
        for entity in world.entities():
            ax.add_patch(PolygonPatch(np.asarray(entity.footprint), closed=True, facecolor="#d8cfc0",
                                      edgecolor="#a89880", linewidth=0.5, zorder=2))
        for obstacle in world.obstacles:
            ax.add_patch(PolygonPatch(np.asarray(obstacle.footprint), closed=True, facecolor="#b0a898",
                                      edgecolor="none", zorder=2))
        walls = world.walls()
        if walls.size:
            ax.plot(walls[:, [0, 2]].T, walls[:, [1, 3]].T, color="#222222", linewidth=1.2, zorder=3)
        for door in world.doors():
            ax.plot(*door.position, marker="s", markersize=4, color="#c0392b" if door.exit else "#27ae60", zorder=4)

        for fid, vf in _load_fields(scenario, bundle).items():
            h, w = vf.vectors.shape[:2]
            stride = max(1, int(round(1.5 / vf.resolution)))
            rows = np.arange(stride // 2, h, stride)
            cols = np.arange(stride // 2, w, stride)
            rr, cc = np.meshgrid(rows, cols, indexing="ij")
            u = vf.vectors[rr, cc, 0]
            v = vf.vectors[rr, cc, 1]
            keep = (u != 0) | (v != 0)
            xs = vf.origin[0] + (cc + 0.5) * vf.resolution
            ys = vf.origin[1] + (rr + 0.5) * vf.resolution
            ax.quiver(xs[keep], ys[keep], u[keep], v[keep], color="#7f8c8d", alpha=0.5, scale=60, width=0.0015,
                      zorder=5, label=None)

        if trajectories is not None:
            from grove_tui.analysis.metrics import Trajectories

            traj = Trajectories.from_csv(trajectories)
            for k, group in enumerate(traj.groups):
                pts = traj.people[:, k]
                pts = pts[np.isfinite(pts[:, 0])]
                ax.plot(pts[:, 0], pts[:, 1], color=_group_colour(int(group)), linewidth=0.7, alpha=0.8, zorder=6)
            if traj.robot is not None:
                r = traj.robot[np.isfinite(traj.robot[:, 0])]
                ax.plot(r[:, 0], r[:, 1], color="#000000", linewidth=1.4, linestyle="-", zorder=7)

        for agent in scenario.agents:
            colour = _group_colour(agent.group)
            route = np.asarray([agent.start, *agent.goals])
            if trajectories is None and len(route) > 1:
                ax.plot(route[:, 0], route[:, 1], color=colour, linewidth=0.6, linestyle=":", zorder=6)
                ax.plot(route[1:-1, 0], route[1:-1, 1], linestyle="none", marker=".", markersize=2.5, color=colour,
                        zorder=6)
            ax.plot(*agent.start, marker="o", markersize=3.5, color=colour, zorder=8)
            if agent.goals:
                ax.plot(*agent.goals[-1], marker="x", markersize=4, color=colour, zorder=8)
        if scenario.robot is not None:
            robot = scenario.robot
            if robot.path and trajectories is None:
                path = np.asarray(robot.path)
                ax.plot(path[:, 0], path[:, 1], color="black", linewidth=1.0, linestyle="--", zorder=7)
            ax.plot(*robot.start, marker="^", markersize=7, color="black", zorder=9)
            ax.plot(*robot.goal, marker="*", markersize=9, color="black", zorder=9)

        ax.set_xlim(xmin - 1, xmax + 1)
        ax.set_ylim(ymin - 1, ymax + 1)
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        heading = title or f"{world.name} · {scenario.preset} · {len(scenario.agents)} agents"
        ax.set_title(heading, fontsize=9)
        ax.text(0.0, -0.08, f"“{scenario.prompt}”", transform=ax.transAxes, fontsize=7, va="top", style="italic")
        fig.tight_layout()
        buffer = io.BytesIO()
        metadata = {"Software": PICTURE_MARK} if fmt == "png" else {"Creator": PICTURE_MARK}
        if fmt == "svg":
            metadata["Date"] = None  # type: ignore[assignment]  # reproducible: no time stamp
        fig.savefig(buffer, format=fmt, dpi=dpi, metadata=metadata)
    finally:
        plt.close(fig)
    return write_bytes_atomic(out, buffer.getvalue(), **guard)


def render_scenario_text(world: World, scenario: Scenario, width: int, height: int | None = None) -> Text:
    """The scenario on the terminal map: spawns by group, final goals, robot start and goal."""
    from grove_tui.world.render import render_world_text

    markers: list[tuple[float, float, str, str]] = []
    for agent in scenario.agents:
        style = "bold white" if agent.group < 0 else RICH_GROUP_STYLES[agent.group % len(RICH_GROUP_STYLES)]
        for x, y in agent.goals[:-1]:
            markers.append((x, y, "·", style))
        if agent.goals:
            markers.append((*agent.goals[-1], "x", style))
    for agent in scenario.agents:
        style = "bold white" if agent.group < 0 else RICH_GROUP_STYLES[agent.group % len(RICH_GROUP_STYLES)]
        markers.append((*agent.start, "o", style))
    if scenario.robot is not None:
        markers.append((*scenario.robot.start, "R", "bold reverse"))
        markers.append((*scenario.robot.goal, "G", "bold reverse"))
    return render_world_text(world, width, height, markers=markers)
