"""World files beyond the limits fail fast with one located problem; big valid worlds load in seconds."""

from __future__ import annotations

import time

import numpy as np
import pytest

from grove_tui.navigation.grid import GridError, OccupancyGrid, build_grid
from grove_tui.world import WorldError, check_world_file, load_world, parse_world
from grove_tui.world.loader import MAX_ZONES

HEADER = "name: w\nzones:\n"
ROOM = "  - {name: z, type: r, boundary: [[0,0],[4,0],[4,4],[0,4]], doors: [{name: d, position: [2,0], width: 1, leads_to: outside}]}\n"


def only_problem(text: str) -> str:
    started = time.process_time()  # this process's own work: the wall clock counted the other tests' (6.7 s at load 4)
    world, problems = parse_world(text, "w.yaml")
    assert time.process_time() - started < 5.0, "a limit must be checked before the expensive work"
    assert world is None and len(problems) == 1, problems
    return problems[0].message


def test_alias_bomb_is_refused_without_expanding_it():
    levels = "a: &a [x,x,x,x,x,x,x,x,x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [" + ",".join(["*" + chr(97 + i)] * 9) + "]\n" for i in range(8))
    assert "expands to more than" in only_problem(levels + "name: w\nzones: *i\n")


def test_recursive_alias_is_named():
    assert "recursive alias" in only_problem("name: w\nzones: &x [*x]\n")


@pytest.mark.parametrize("text", ["name: w\nzones: " + "[" * 10000 + "]" * 10000,
                                  "name: w\nzones:\n" + "".join("  " * i + "- \n" for i in range(3000))])
def test_deep_nesting_is_refused(text):
    assert "nests more than" in only_problem(text)


def test_5000_digit_integer_is_out_of_range():
    assert "5,000 digits" in only_problem(HEADER + "  - {name: z, type: r, boundary: [[0,0],[" + "9" * 5000 + ",0],[1,1]]}\n")


@pytest.mark.parametrize("number", ["9" * 400, "9" * 400 + ".5", "1.0e400", "-.inf"])
def test_huge_coordinates_are_out_of_range(number):
    message = only_problem(HEADER + "  - {name: z, type: r, boundary: [[0,0],[" + number + ",0],[1,1]]}\n")
    assert "within +-10000 m" in message and len(message) < 200


def test_a_world_too_large_for_a_grid_fails_the_check_not_the_allocation():
    text = HEADER + ("  - {name: z, type: r, boundary: [[-9000,-9000],[9000,-9000],[9000,9000],[-9000,9000]], "
                     "doors: [{name: d, position: [10,-9000], width: 1, leads_to: outside}]}\n")
    assert "25,000,000 cells" in only_problem(text)


def test_zone_count_limit():
    text = HEADER + "".join(f"  - {i}\n" for i in range(MAX_ZONES + 1))
    assert f"at most {MAX_ZONES:,}" in only_problem(text)


def test_device_and_oversized_world_files_are_refused(tmp_path):
    problems = check_world_file("/dev/zero")
    assert len(problems) == 1 and "is a device, not a file" in problems[0].message
    big = tmp_path / "big.yaml"
    with big.open("wb") as handle:
        handle.truncate(33 * 1024 * 1024)
    with pytest.raises(WorldError, match="limit is 32.0 MB"):
        load_world(big)


def big_world(columns: int, rows: int, size: float = 2.0) -> str:
    """A valid world of columns x rows square rooms: each row a chain of doors, rows joined at column 0."""
    lines = ["name: big", "zones:"]
    for r in range(rows):
        for c in range(columns):
            x0, y0 = c * size, r * size
            doors = []
            if c + 1 < columns:
                doors.append(f"{{name: d_{r}_{c}_e, position: [{x0 + size}, {y0 + size / 2}], width: 0.9, leads_to: z_{r}_{c + 1}}}")
            if r + 1 < rows and c == 0:
                doors.append(f"{{name: d_{r}_{c}_n, position: [{x0 + size / 2}, {y0 + size}], width: 0.9, leads_to: z_{r + 1}_{c}}}")
            if r == 0 and c == 0:
                doors.append(f"{{name: exit_main, position: [{x0 + size / 2}, {y0}], width: 0.9, leads_to: outside}}")
            lines.append(f"  - {{name: z_{r}_{c}, type: room, boundary: [[{x0}, {y0}], [{x0 + size}, {y0}], "
                         f"[{x0 + size}, {y0 + size}], [{x0}, {y0 + size}]], doors: [{', '.join(doors)}]}}")
    return "\n".join(lines) + "\n"


@pytest.mark.slow
def test_20000_zones_load_in_seconds_not_minutes():
    # All-pairs checks took over 180 s here; the spatial indexes make it about 10 s of CPU. CPU time,
    # not wall clock: on a shared machine the wall clock says more about the neighbours than the code.
    text = big_world(100, 200)
    started = time.process_time()
    world, problems = parse_world(text, "big.yaml")
    elapsed = time.process_time() - started
    assert problems == [] and len(world.zones) == 20_000
    assert elapsed < 60.0, f"{elapsed:.1f} s"


def test_spatial_index_still_finds_overlaps_and_doubled_doors_among_many_zones():
    text = big_world(30, 30)
    # One extra zone overlapping a room far from the first, and a door declared from both sides.
    text += ("  - {name: intruder, type: room, boundary: [[41, 41], [43, 41], [43, 43], [41, 43]]}\n")
    text = text.replace("doors: [{name: d_10_10_e,", "doors: [{name: d_10_11_w, position: [22.0, 21.0], width: 0.9, leads_to: z_10_11}, {name: d_10_10_e,")
    world, problems = parse_world(text, "big.yaml")
    messages = " | ".join(problem.message for problem in problems)
    assert "zone 'intruder' overlaps zone 'z_20_20'" in messages
    assert "overlaps door 'd_10_11_w'" in messages or "overlaps door 'd_10_10_e'" in messages


def test_grid_larger_than_the_limit_is_refused_before_allocating():
    # 400 m x 400 m passes the world check (a 16-million-cell grid at 0.1 m) but not at 0.01 m.
    world, problems = parse_world(HEADER + ROOM.replace("4,0],[4,4],[0,4]", "400,0],[400,400],[0,400]"), "w.yaml")
    assert problems == []
    with pytest.raises(GridError, match="over the limit of 100,000,000 cells"):
        build_grid(world, resolution=0.01)


def save_grid(path, **overrides):
    values = dict(origin=np.array([0.0, 0.0]), resolution=np.float64(0.1), inflation=np.float64(0.35),
                  occupied=np.packbits(np.zeros(100, dtype=bool)), shape=np.array([10, 10]), world_name=np.str_("w"))
    values.update(overrides)
    np.savez_compressed(path, **values)
    return path


@pytest.mark.parametrize("overrides, message", [
    ({"resolution": np.float64(0.0)}, "resolution must be"),
    ({"origin": np.array([np.nan, 0.0])}, "origin must be"),
    ({"shape": np.array([10**9, 10**9])}, "over the limit"),
    ({"shape": np.array([100, 100])}, "cells stored"),
])
def test_broken_grid_files_give_grid_errors(tmp_path, overrides, message):
    path = save_grid(tmp_path / "grid.npz", **overrides)
    with pytest.raises(GridError, match=message):
        OccupancyGrid.load(path)


def test_truncated_grid_file_is_a_grid_error(tmp_path):
    path = save_grid(tmp_path / "grid.npz")
    path.write_bytes(path.read_bytes()[:200])
    with pytest.raises(GridError, match="not a readable .npz"):
        OccupancyGrid.load(path)
    assert OccupancyGrid.load(save_grid(tmp_path / "ok.npz")).shape == (10, 10)


def test_velocity_field_zip_bomb_is_refused_from_the_headers(tmp_path):
    import zipfile

    from grove_tui.navigation.velocity_field import FieldFileError, VelocityField

    bomb = tmp_path / "field.npz"
    header = np.lib.format.header_data_from_array_1_0(np.zeros((1, 1, 2), dtype=np.float32))
    header["shape"] = (6000, 6000, 2)  # 288 MB of float32 unpacked
    with zipfile.ZipFile(bomb, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        with archive.open("vectors.npy", "w", force_zip64=True) as member:
            np.lib.format.write_array_header_1_0(member, header)
            chunk = bytes(1 << 22)
            for _ in range(72):
                member.write(chunk)
    assert bomb.stat().st_size < 2_000_000
    started = time.perf_counter()
    with pytest.raises(FieldFileError, match="unpacks to 288.0 MB; the limit is 256.0 MB"):
        VelocityField.load(bomb)
    assert time.perf_counter() - started < 1.0


# -- issue 35: `worlds check` refuses what `generate` cannot use ------------------------------------------------


def test_a_boundary_of_more_points_than_generation_can_use_fails_the_check(tmp_path):
    """200,000 points passed the check and crashed `generate` (exit 139, GEOS's recursion in shapely.simplify)."""
    from grove_tui.world.loader import MAX_POLYGON_POINTS

    count = MAX_POLYGON_POINTS + 1_000  # bench/hostile.py runs the 200,000-point file through the CLI
    points = ", ".join(f"[{20 * i / count:.5f}, {0.01 * (i % 2)}]" for i in range(count))
    text = HEADER + ("  - {name: z, type: r, boundary: [" + points + ", [20, 10], [0, 10]], "
                     "doors: [{name: d, position: [0, 5], width: 1, leads_to: outside}]}\n")
    world, problems = parse_world(text, "w.yaml")  # not timed: the YAML itself takes seconds on a busy machine
    assert world is None and len(problems) == 1, problems
    message = problems[0].message
    assert f"{count + 2:,} points; at most {MAX_POLYGON_POINTS:,} per polygon" in message and len(message) < 200


def test_a_world_beyond_the_coordinates_trees_can_carry_fails_the_check():
    """A world near 99,999 m passed the check, then failed generation at 'GoTo port x above maximum 10000'."""
    from grove_tui.bt.format.manifest import NODES

    text = HEADER + ("  - {name: z, type: r, boundary: [[99990,0],[99999,0],[99999,9],[99990,9]], "
                     "doors: [{name: d, position: [99995,0], width: 1, leads_to: outside}]}\n")
    world, problems = parse_world(text, "w.yaml")
    assert world is None and problems and all("within +-10000 m" in p.message for p in problems)
    assert NODES["GoTo"].port("x").max == 10_000.0  # the same bound


@pytest.mark.slow
def test_long_wall_lines_are_simplified_without_deep_recursion(tmp_path):
    """An 80,000-vertex zigzag wall overflowed the C stack in shapely.simplify; it runs in a child process
    so a crash fails this test instead of ending the suite."""
    import subprocess
    import sys

    code = ("import numpy as np, shapely\n"
            "from grove_tui.world.model import _drop_collinear\n"
            "i = np.arange(80_000, dtype=float)\n"
            "line = shapely.LineString(np.c_[i / 800.0, (i % 2) * 0.01])\n"
            "out = _drop_collinear(shapely.MultiLineString([line, shapely.LineString([(0, 5), (1, 5), (2, 5)])]))\n"
            "print(int(shapely.get_num_coordinates(out)))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-500:]
    assert 80_000 <= int(done.stdout) <= 80_000 + 2 + 40  # every zigzag vertex kept, the straight run's middle dropped


def test_a_file_that_is_not_a_world_is_not_quoted_back(tmp_path):
    """`worlds check` on a link to a private file printed the file's lines in its errors."""
    secret = tmp_path / "shadow"
    secret.write_text("root:$6$SECRETHASH:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n")
    link = tmp_path / "w.yaml"
    link.symlink_to(secret)
    problems = check_world_file(link)
    assert len(problems) == 1 and "not a world file" in problems[0].message
    assert all("SECRET" not in str(p) and "daemon" not in str(p) for p in problems)
    # A world with one odd key still names it when it is a word, and hides it when it is not.
    listed = parse_world(HEADER.replace("zones:", "zonse: 1\nzones:") + ROOM + "'root:x:0:0': 1\n", "w.yaml")[1]
    assert any("'zonse' (did you mean 'zones'?)" in p.message for p in listed)
    assert all("root:x" not in str(p) for p in listed)
