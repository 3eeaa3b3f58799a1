"""Pilot tests of the whole flow: setup -> generate (real pipeline) -> inspect -> play -> export."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from helpers.app import (
    first_frame,
    generate_to_inspect,
    generate_to_simulation,
    PROMPT,
    FakeLLM,
    fake_llm_session,
    map_laid_out,
    test_settings,
    wait_until,
)
from textual.widgets import Static, TextArea

from grove_tui.tui.app import GroveApp
from grove_tui.services.session import GroveSession
from grove_tui.tui.screens.export import ExportResultScreen
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.screens.simulation import SimulationScreen
from grove_tui.tui.widgets.bt_tree import BTTree
from grove_tui.tui.widgets.map_view import MapView

pytestmark = pytest.mark.anyio



@pytest.mark.slow
async def test_generate_inspect_play_and_export(tmp_path):
    llm = FakeLLM()
    app = GroveApp(fake_llm_session(tmp_path / "runs", llm), test_settings(tmp_path))
    async with app.run_test(size=(100, 30)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        assert llm.requests >= 1
        scenario = inspect.generated.scenario
        assert len(scenario.agents) == 6
        assert inspect.generated.bundle_dir.joinpath("scenario.yaml").is_file()

        # the tree: group -> agents -> nodes with ports
        tree = inspect.query_one("#bt-tree", BTTree)
        group = tree.root.children[0]
        assert "patient" in str(group.label) and "×6" in str(group.label)
        agent_node = group.children[0]
        assert agent_node.data.kind == "agent"
        labels = [str(n.label) for n in agent_node.children[0].children]
        assert any(label.startswith("GoTo") and "target=pharmacy_counter" in label for label in labels)

        # moving through the tree highlights the agent's route on the map
        world_map = inspect.query_one("#inspect-map", MapView)
        await wait_until(pilot, lambda: inspect._selected_node is not None and inspect._selected_node.kind == "agent",
                         what="first agent highlighted")
        # The map may still be settling into its final size; compare against the unhighlighted
        # overlay drawn on the raster the map is showing now, not on an earlier one.
        await map_laid_out(pilot, world_map)
        plain_styles = world_map.raster.compose(inspect._overlay)[1]
        assert (world_map._styles != plain_styles).any(), "the agent's route is not highlighted"
        assert "agent 1" in str(inspect.query_one("#node-detail", Static).render())
        await pilot.press("down", "down")
        await wait_until(pilot, lambda: inspect._selected_node.kind == "node", what="a tree node highlighted")
        assert inspect._selected_node.name in str(inspect.query_one("#node-detail", Static).render())

        # XML toggle
        await pilot.press("x")
        xml = inspect.query_one("#xml", TextArea)
        assert xml.display and "<BehaviorTree" in xml.text
        await pilot.press("x")
        assert not xml.display and tree.display

        # play
        await pilot.press("p")
        await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation screen")
        sim = app.screen
        await first_frame(pilot, sim)
        first = sim.controller.latest.frame
        # 8x: fast, and far from the run's end (it pauses itself there, about a minute in)
        await pilot.press("right_square_bracket", "right_square_bracket", "right_square_bracket")
        await pilot.press("space")
        await wait_until(pilot, lambda: sim.controller.latest.frame.t >= 5.0, timeout=60, what="5 simulated seconds")
        await pilot.press("space")
        await wait_until(pilot, lambda: not sim.controller.latest.playing, what="paused")
        frame = sim.controller.latest.frame
        assert not np.allclose(np.asarray(frame.pos), np.asarray(first.pos)), "agents did not move"
        assert sim.frames_drawn > 0
        await wait_until(pilot, lambda: sim._shown_serial == sim.controller.latest.serial, what="the paused frame drawn")
        status = str(sim.query_one("#sim-status", Static).render())
        assert "paused" in status and "t =" in status
        await wait_until(pilot, lambda: sim.metrics_step == sim.controller.latest.frame.step, what="counters")
        assert "goal_reach_rate" in str(sim.query_one("#counters", Static).render())
        # the selected agent's runtime tree shows live statuses
        sim_tree = sim.query_one("#sim-tree", BTTree)
        await wait_until(pilot, lambda: bool(sim_tree._status), what="live tree status")
        assert set(sim_tree._status.values()) <= {"IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED"}

        # export
        await pilot.press("e")
        await wait_until(pilot, lambda: isinstance(app.screen, ExportResultScreen)
                         and bool(app.screen.query("#export-files")), timeout=60, what="export dialog")
        files = {f.kind: f for f in app.screen.files}
        assert (files["bundle"].path / "scenario.yaml").is_file()
        assert files["trajectories"].path.is_file(), files["trajectories"].note
        assert files["metrics"].path.is_file(), files["metrics"].note
        assert files["events"].path.is_file(), files["events"].note
        assert files["hunav"].path.is_file() and files["hunav"].path.name.endswith(".yaml"), files["hunav"].note
        assert files["picture"].path.suffix == ".png" and files["picture"].path.is_file(), files["picture"].note
        assert str(app.screen.out_dir).startswith(str(tmp_path / "exports"))
        shown = str(app.screen.query_one("#export-files", Static).render())
        assert str(app.screen.out_dir) in str(app.screen.query_one("#export-title", Static).render())
        assert "✓ bundle" in shown and "bundle/metrics.json" in shown and "bundle/trajectories.csv" in shown
        # every format is either written or says why not, in the dialog
        for exported in files.values():
            assert exported.path.exists()
            if exported.note.startswith("failed"):
                assert exported.note[:40] in shown
        await pilot.press("escape")
        assert isinstance(app.screen, SimulationScreen)
        await pilot.press("escape")
        assert isinstance(app.screen, InspectScreen)


@pytest.mark.slow
async def test_simulation_controls_step_speed_select_and_drive_the_robot(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        step0 = sim.controller.latest.frame.step
        await pilot.press("n", "n", "n")
        await wait_until(pilot, lambda: sim.controller.latest.frame.step == step0 + 3, what="three steps")
        await pilot.press("right_square_bracket")
        await wait_until(pilot, lambda: sim.controller.speed == 2.0, what="2x")
        await pilot.press("left_square_bracket", "left_square_bracket", "left_square_bracket")
        await wait_until(pilot, lambda: sim.controller.speed == 0.25, what="0.25x")
        await pilot.press("c")
        assert sim._colour_mode == "behavior"
        await pilot.press("c")
        assert sim._colour_mode == "group"
        first = sim._selected_agent
        await pilot.press("a")
        assert sim._selected_agent != first
        await pilot.press("A")
        assert sim._selected_agent == first
        if sim.generated.scenario.robot is not None:
            start = sim.controller.latest.frame.robot
            for _ in range(4):
                await pilot.press("up")
                await pilot.press("n")
            await wait_until(pilot, lambda: sim.controller.latest.manual_robot, what="manual robot")
            await pilot.press("space")
            await wait_until(pilot, lambda: sim.controller.latest.frame.robot[1] > start[1] + 0.05, what="robot moves up")
            await pilot.press("r")
            await wait_until(pilot, lambda: not sim.controller.latest.manual_robot, what="robot back on its path")


@pytest.mark.slow
async def test_a_planning_error_from_the_model_answer_is_shown_with_a_hint(tmp_path):
    # The draft names a spawn that does not exist in this world: the pipeline must refuse it.
    bad = FakeLLM("2 ghosts from nowhere: GoTo(nowhere)")
    app = GroveApp(fake_llm_session(tmp_path / "runs", bad), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        await pilot.press(*PROMPT, "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
        error = app.screen.query_one("#gen-error", Static)
        await wait_until(pilot, lambda: bool(error.display), timeout=60, what="error shown")
        text = str(error.render())
        assert "failed" in text and "→" in text
        assert not isinstance(app.screen, InspectScreen)


def _embedded_model_available() -> bool:
    try:
        from grove_tui.llm.registry import embedded_model_path

        return Path(embedded_model_path()).is_file()
    except Exception:
        return False


@pytest.mark.slow
@pytest.mark.skipif(not _embedded_model_available(), reason="the embedded GGUF is not installed")
async def test_generate_with_the_embedded_model_through_the_real_pipeline(tmp_path, monkeypatch):
    # The retrieval index is built once per machine in the user's cache, as `grove` does.
    if os.environ.get("GROVE_TEST_CACHE_DIR"):
        monkeypatch.setenv("GROVE_CACHE_DIR", os.environ["GROVE_TEST_CACHE_DIR"])
    else:
        monkeypatch.delenv("GROVE_CACHE_DIR", raising=False)
    session = GroveSession.for_app(runs_dir=tmp_path / "runs")
    app = GroveApp(session, test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app, "ten patients queue at the pharmacy counter", timeout=400)
        scenario = inspect.generated.scenario
        assert scenario.agents, "the embedded model's scenario has no agents"
        assert scenario.models["bt"].endswith(".gguf")
        assert inspect.generated.bundle_dir.joinpath("generation.json").is_file()
        await pilot.press("p")
        await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation screen")
        sim = app.screen
        await first_frame(pilot, sim, timeout=180)
        await pilot.press("f", "space")
        await wait_until(pilot, lambda: sim.controller.latest.frame.t >= 2.0, timeout=60, what="2 simulated seconds")


@pytest.mark.slow
async def test_emergency_scenarios_show_velocity_field_arrows_on_the_inspect_map(tmp_path):
    from grove_tui.tui.widgets import map_raster as mr

    draft = "8 visitors from entrance_lobby: Sequence(FollowVelocityField(main_entrance))"
    app = GroveApp(fake_llm_session(tmp_path / "runs", FakeLLM(draft)), test_settings(tmp_path, preset="emergency"))
    async with app.run_test(size=(120, 40)) as pilot:
        inspect = await generate_to_inspect(pilot, app, "eight visitors evacuate the lobby")
        assert inspect.generated.result.fields, "the emergency preset planned no velocity field"
        world_map = inspect.query_one("#inspect-map", MapView)
        arrows = world_map._chars[world_map._styles == mr.FIELD]
        assert len(arrows) > 50
        assert set(map(chr, arrows)) <= set(mr.ARROWS)
