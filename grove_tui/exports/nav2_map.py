"""The world's occupancy grid as a nav2 map: `<name>.pgm` plus `<name>.yaml` (nav2_map_server format).

hunav_gazebo_wrapper's launch passes `maps/<environment_name>.yaml` to the robot's navigation
(launch/simulation.launch.py, `map_path`). map_server reads the YAML keys `image`, `mode`,
`resolution`, `origin` [x, y, yaw] (the lower-left corner of the image), `negate`, `occupied_thresh`
and `free_thresh`, and the image top row first (largest y). In trinary mode a pixel darker than
occupied_thresh is occupied and one lighter than free_thresh is free; here occupied cells are 0
(black) and free cells 254 (white), so nothing is unknown.

The grid is GROVE's occupancy grid *without* inflation (build_grid(world, resolution, 0)): nav2
inflates obstacles itself with the robot's footprint (its costmap inflation layer).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import yaml

if TYPE_CHECKING:
    from grove_tui.navigation.grid import OccupancyGrid

OCCUPIED_PIXEL = 0
FREE_PIXEL = 254


def map_image(occupied: np.ndarray) -> np.ndarray:
    """uint8 image rows top (largest y) to bottom of a (H, W) grid whose row 0 is the smallest y."""
    return np.where(np.asarray(occupied, dtype=bool)[::-1], OCCUPIED_PIXEL, FREE_PIXEL).astype(np.uint8)


def pgm_bytes(image: np.ndarray) -> bytes:
    """Binary PGM (P5), maxval 255."""
    height, width = image.shape
    return f"P5\n{width} {height}\n255\n".encode("ascii") + np.ascontiguousarray(image, dtype=np.uint8).tobytes()


def read_pgm(data: bytes) -> np.ndarray:
    """The image of a binary PGM written by pgm_bytes (for checks)."""
    fields: list[bytes] = []
    position = 0
    while len(fields) < 4:
        while data[position:position + 1].isspace():
            position += 1
        start = position
        while not data[position:position + 1].isspace():
            position += 1
        fields.append(data[start:position])
    position += 1  # the single whitespace after maxval
    if fields[0] != b"P5" or fields[3] != b"255":
        raise ValueError("not a binary 8-bit PGM")
    width, height = int(fields[1]), int(fields[2])
    return np.frombuffer(data[position:position + width * height], dtype=np.uint8).reshape(height, width)


def map_yaml(image_name: str, resolution: float, origin: tuple[float, float]) -> str:
    document = {
        "image": image_name,
        "mode": "trinary",
        "resolution": float(resolution),
        "origin": [float(origin[0]), float(origin[1]), 0.0],
        "negate": 0,
        "occupied_thresh": 0.65,
        "free_thresh": 0.25,
    }
    return yaml.safe_dump(document, sort_keys=False)


def write_nav2_map(grid: OccupancyGrid, folder: Path, name: str) -> tuple[Path, Path]:
    """Write `<name>.pgm` and `<name>.yaml` for `grid` into `folder`; returns both paths."""
    folder.mkdir(parents=True, exist_ok=True)
    pgm = folder / f"{name}.pgm"
    pgm.write_bytes(pgm_bytes(map_image(grid.occupied)))
    description = folder / f"{name}.yaml"
    description.write_text(map_yaml(pgm.name, grid.resolution, grid.origin), encoding="utf-8")
    return description, pgm
