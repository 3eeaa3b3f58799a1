"""Draw what a Foxglove MCAP export holds, top-down, as a stand-in for a screenshot of Foxglove's 3D panel
(Foxglove itself cannot run on the machine the docs are made on: no display, no network).

    PYTHONPATH=. python docs/foxglove_view.py scene.mcap docs/foxglove.png [--at SECONDS]

Only the file is read, with `mcap` and the protobuf schemas it carries: for each topic the latest
message at or before `--at` (what Foxglove shows at that playback time), then the /map Grid, /world,
/paths, /fields, /people and /robot SceneUpdates are drawn with matplotlib.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib.patches import Circle, FancyArrow  # noqa: E402
from mcap.reader import make_reader  # noqa: E402
from mcap_protobuf.decoder import DecoderFactory  # noqa: E402


def latest(path: Path, at_ns: int) -> dict[str, object]:
    shown: dict[str, object] = {}
    with path.open("rb") as handle:
        reader = make_reader(handle, decoder_factories=[DecoderFactory()])
        for _schema, channel, message, decoded in reader.iter_decoded_messages(ending_at=at_ns):
            shown[channel.topic] = decoded
    return shown


def rgba(c) -> tuple[float, float, float, float]:
    return (c.r, c.g, c.b, c.a)


def yaw(q) -> float:
    return 2 * math.atan2(q.z, q.w)


def draw(shown: dict[str, object], out: Path, title: str) -> None:
    fig, ax = plt.subplots(figsize=(10, 6.4))
    grid = shown.get("/map")
    if grid is not None:
        rows = len(grid.data) // grid.row_stride
        cells = np.frombuffer(grid.data, dtype=np.uint8).reshape(rows, grid.column_count)
        x0, y0 = grid.pose.position.x, grid.pose.position.y
        ax.imshow(cells, origin="lower", cmap="Greys", vmin=0, vmax=3, interpolation="nearest", zorder=0,
                  extent=(x0, x0 + grid.column_count * grid.cell_size.x, y0, y0 + rows * grid.cell_size.y))
    for topic in ("/world", "/paths", "/fields", "/people", "/robot"):
        update = shown.get(topic)
        if update is None:
            continue
        for entity in update.entities:
            for cube in entity.cubes:  # walls, furniture, obstacles: their footprints, seen from above
                p, a = cube.pose.position, yaw(cube.pose.orientation)
                c, s = math.cos(a), math.sin(a)
                hx, hy = cube.size.x / 2, cube.size.y / 2
                corners = [(p.x + u * c - v * s, p.y + u * s + v * c) for u, v in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))]
                ax.add_collection(PolyCollection([corners], facecolors=[rgba(cube.color)], edgecolors="none", zorder=3))
            for tri in entity.triangles:  # filled tops, if a file has them
                pts = np.array([[q.x, q.y] for q in tri.points]).reshape(-1, 3, 2)
                ax.add_collection(PolyCollection(pts, facecolors=[rgba(tri.color)], edgecolors="none", zorder=2))
            for line in entity.lines:
                pts = np.array([[q.x, q.y] for q in line.points])
                if not len(pts):
                    continue
                width = max(0.4, line.thickness * 12)
                if line.type == 2:  # LINE_LIST: pairs
                    ax.add_collection(LineCollection(pts.reshape(-1, 2, 2), colors=[rgba(line.color)],
                                                     linewidths=width, zorder=4))
                else:
                    if line.type == 1:  # LINE_LOOP
                        pts = np.vstack([pts, pts[:1]])
                    ax.plot(pts[:, 0], pts[:, 1], color=rgba(line.color), linewidth=width, zorder=4)
            for text in entity.texts:
                ax.text(text.pose.position.x, text.pose.position.y, text.text, fontsize=6, ha="center",
                        va="center", color=rgba(text.color), zorder=5)
            for sphere in entity.spheres:
                ax.add_patch(Circle((sphere.pose.position.x, sphere.pose.position.y), sphere.size.x / 2,
                                    color=rgba(sphere.color), zorder=5))
            for cylinder in entity.cylinders:
                ax.add_patch(Circle((cylinder.pose.position.x, cylinder.pose.position.y), cylinder.size.x / 2,
                                    facecolor=rgba(cylinder.color), edgecolor="white", linewidth=0.4, zorder=7))
            for arrow in entity.arrows:
                p, a = arrow.pose.position, yaw(arrow.pose.orientation)
                length = arrow.shaft_length + arrow.head_length
                ax.add_patch(FancyArrow(p.x, p.y, math.cos(a) * length, math.sin(a) * length, width=0.05,
                                        head_width=arrow.head_diameter, head_length=arrow.head_length,
                                        length_includes_head=True, color="black", zorder=8))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mcap", type=Path)
    parser.add_argument("png", type=Path)
    parser.add_argument("--at", type=float, default=10.0, help="playback time in seconds")
    args = parser.parse_args()
    shown = latest(args.mcap, int(args.at * 1e9))
    draw(shown, args.png, f"{args.mcap.name} at t = {args.at:g} s: topics {', '.join(sorted(shown))}")
    print(args.png)


if __name__ == "__main__":
    main()
