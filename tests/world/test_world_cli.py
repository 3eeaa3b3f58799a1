"""`grove worlds list|show|check` through click's test runner, plus the map renderer."""

from __future__ import annotations

from helpers.paths import REPO, TEST_DATA

from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.world import load_world
from grove_tui.world.render import WorldCanvas, fit_projection, render_world_text

BAD = TEST_DATA / "worlds_bad"
ROOT = REPO


def run(*args):
    result = CliRunner().invoke(main, ["worlds", *args], catch_exceptions=False)
    return result


def test_list_shows_the_four_worlds():
    result = run("list")
    assert result.exit_code == 0
    for name in ("hospital", "office", "residential", "airport"):
        assert name in result.output
    assert "64 x 44 m" in result.output


def test_show_hospital_draws_walls_doors_labels_and_entities():
    result = run("show", "hospital", "--width", "128")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0].startswith("hospital")
    body = "\n".join(lines)
    for label in ("entrance_lobby", "pharmacy", "main_corridor", "ward_corridor", "cafeteria"):
        assert label in body
    assert "┌" in body and "┘" in body and "│" in body  # walls
    assert "╌" in body and "┆" in body  # doors
    assert "━" in body and "┃" in body  # exits
    assert "R" in body and "V" in body and "B" in body  # reception desk, vending machine, beds
    assert "vending machine" in body  # legend
    assert max(len(line) for line in lines[:60]) <= 128


def test_show_lists_rois_on_request():
    result = run("show", "office", "--width", "90", "--rois")
    assert result.exit_code == 0
    assert "coffee_machine" in result.output and "Regions of interest" in result.output


def test_show_unknown_world_fails_with_the_known_names():
    result = run("show", "hotel")
    assert result.exit_code != 0
    assert "no shipped world named 'hotel'" in result.output and "hospital" in result.output


def test_check_prints_every_problem_and_exits_non_zero():
    bad = BAD / "many_problems.yaml"
    result = run("check", str(bad))
    assert result.exit_code == 1
    text = " ".join(result.output.split())
    assert "4 problems" in text
    for path, line in (("zones[0].doors[0].width", 8), ("zones[0].doors[1].leads_to", 9),
                       ("zones[0].entities[0].interaction_point", 14), ("zones[1].doors", 15)):
        assert f"many_problems.yaml:{line}: {path}:" in text


def test_check_accepts_good_files_and_names():
    result = run("check", str(ROOT / "worlds" / "office.yaml"), "hospital")
    assert result.exit_code == 0, result.output
    assert result.output.count("ok ") == 2


def test_check_reports_broken_yaml():
    result = run("check", str(BAD / "broken_yaml.yaml"))
    assert result.exit_code == 1
    assert "broken_yaml.yaml:7: (document): broken YAML" in " ".join(result.output.split())


def test_check_exits_2_when_a_file_cannot_be_read_and_still_checks_the_others(tmp_path):
    # Linters' convention: 1 is "problems found", 2 is "could not read the input"; the highest wins.
    not_utf8 = tmp_path / "latin1.yaml"
    not_utf8.write_bytes(b"name: caf\xe9\n")
    big = tmp_path / "big.yaml"
    with big.open("wb") as handle:
        handle.truncate(33 * 1024 * 1024)  # sparse: over the limit on paper, nothing to read
    for unreadable, reason in ((tmp_path / "missing.yaml", "does not exist"), ("/dev/zero", "is a device, not a file"),
                               (tmp_path, "is a folder, not a file"), (not_utf8, "is not UTF-8 text"),
                               (big, "the limit is 32.0 MB"), ("hotel", "no shipped world named 'hotel'")):
        result = run("check", str(unreadable))
        assert result.exit_code == 2, (unreadable, result.output)
        (line,) = result.stderr.splitlines()
        assert line.startswith("error: ") and str(unreadable) in line and reason in line, line
        assert result.stdout == ""
    result = run("check", str(tmp_path / "missing.yaml"), str(BAD / "many_problems.yaml"), "hospital")
    assert result.exit_code == 2
    assert "4 problems" in result.stdout and "ok " in result.stdout  # the readable files were checked
    assert result.stderr.count("error: ") == 1


def test_render_fits_the_requested_size_and_keeps_proportions():
    world = load_world("hospital")
    text = render_world_text(world, 80, 30)
    lines = text.plain.split("\n")
    assert len(lines) <= 30 and max(len(line) for line in lines) <= 80
    wide = render_world_text(world, 120).plain.split("\n")
    # 64 x 44 m with cells twice as tall as wide: rows ~ columns * 44 / 64 / 2.
    assert abs(len(wide) - 120 * 44 / 64 / 2) <= 3


def test_projection_round_trip_and_markers():
    world = load_world("residential")
    canvas = WorldCanvas(world, 60)
    row, col = canvas.projection.to_cell(7.5, 6.0)
    x, y = canvas.projection.to_world(row, col)
    assert abs(x - 7.5) <= canvas.projection.cell_width and abs(y - 6.0) <= canvas.projection.cell_height
    plain = canvas.render([(7.5, 6.0, "@", "bold magenta")]).plain.split("\n")
    assert plain[row][col] == "@"
    assert fit_projection((0, 0, 10, 10), 40).columns <= 40
