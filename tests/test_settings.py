"""One settings model: the file named by GROVE_CONFIG_FILE, GROVE_* variables, and one-line errors for bad ones."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT, SettingsError
from grove_tui.llm.registry import resolve_models
from grove_tui.settings import config_file, load_settings
from helpers.tiny_qwen3 import build_tiny_qwen3


@pytest.fixture()
def elsewhere(tmp_path, monkeypatch):
    """A config file outside the config dir, named by GROVE_CONFIG_FILE; the config dir holds another one."""
    for name in ("GROVE_MODEL", "GROVE_ROI_MODEL", "GROVE_BT_MODEL", "GROVE_LLM_THREADS"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("GROVE_CONFIG_DIR", str(tmp_path / "config_dir"))
    monkeypatch.setenv("GROVE_DATA_DIR", str(tmp_path / "data_dir"))
    (tmp_path / "config_dir").mkdir()
    (tmp_path / "config_dir" / "config.yaml").write_text("simulation:\n  fps: 10\n", encoding="utf-8")
    path = tmp_path / "project" / "grove.yaml"
    path.parent.mkdir()
    monkeypatch.setenv("GROVE_CONFIG_FILE", str(path))
    return path


def test_a_models_section_in_the_file_named_by_grove_config_file_picks_the_model(elsewhere):
    (elsewhere.parent / "models").mkdir()
    roi = build_tiny_qwen3(elsewhere.parent / "models" / "roi.gguf", context_length=1024)
    bt = build_tiny_qwen3(elsewhere.parent / "models" / "bt.gguf", context_length=2048)
    # Relative paths are read against the config file's folder, not the working directory.
    elsewhere.write_text("models:\n  roi: models/roi.gguf\n  bt: models/bt.gguf\n", encoding="utf-8")
    assert config_file() == elsewhere
    choices = resolve_models()
    assert (choices["roi"].path, choices["bt"].path) == (roi, bt)
    assert choices["bt"].source == f"{elsewhere} models.bt"
    # The file in the config dir is not read at all when GROVE_CONFIG_FILE names another one.
    assert load_settings().simulation.fps != 10


def test_the_environment_overrides_the_file_and_threads_come_from_settings(elsewhere, monkeypatch):
    from grove_tui.llm.local import default_threads

    elsewhere.write_text("llm_threads: 3\nsimulation:\n  fps: 12\n", encoding="utf-8")
    assert default_threads() == 3
    monkeypatch.setenv("GROVE_LLM_THREADS", "1")
    monkeypatch.setenv("GROVE_SIMULATION__FPS", "30")
    settings = load_settings()
    assert (settings.llm_threads, settings.simulation.fps) == (1, 30)
    assert default_threads() == 1


@pytest.mark.parametrize(("content", "message"), [
    (b"simulation: [fps: 20\n", "not valid YAML (line"),
    (b"ui:\n  theme: caf\xe9\n", "not UTF-8 text"),
    (b"ui: !!python/object/apply:os.system ['true']\n", "not valid YAML"),
    (b"simulaton:\n  fps: 20\n", "simulaton: Extra inputs are not permitted"),
    (b"simulation:\n  fsp: 20\n", "simulation.fsp: Extra inputs are not permitted"),
    (b"simulation:\n  fps: fast\n", "simulation.fps: Input should be a valid integer"),
    (b"- ui\n- generation\n", "expected a mapping of sections"),
    (b"model: qwen.gguf\n", "models: {roi: PATH, bt: PATH}"),
], ids=["not-yaml", "not-utf8", "python-tag", "unknown-section", "unknown-key", "bad-value", "a-list", "env-only-key"])
def test_a_bad_config_file_is_a_settings_error_naming_the_file(elsewhere, content, message):
    elsewhere.write_bytes(content)
    with pytest.raises(SettingsError) as caught:
        load_settings()
    assert str(elsewhere) in str(caught.value) and message in str(caught.value)
    assert caught.value.exit_code == EXIT_BAD_INPUT


def test_a_bad_grove_variable_names_the_variable(elsewhere, monkeypatch):
    monkeypatch.setenv("GROVE_LLM_THREADS", "abc")
    with pytest.raises(SettingsError, match="GROVE_LLM_THREADS='abc': llm_threads: Input should be a valid integer"):
        load_settings()


@pytest.mark.parametrize("args", [["models", "list"], ["generate", "--no-ui", "--world", "hospital", "--preset", "normal",
                                                       "--prompt", "two people walk", "--out", "OUT"]])
def test_the_cli_reports_a_bad_config_on_one_line_with_exit_2(elsewhere, monkeypatch, tmp_path, args):
    monkeypatch.setenv("GROVE_LLM_THREADS", "abc")
    elsewhere.write_text("simulation:\n  fps: 20\n", encoding="utf-8")
    args = [str(tmp_path / "out") if arg == "OUT" else arg for arg in args]
    result = CliRunner().invoke(main, args)
    assert result.exit_code == EXIT_BAD_INPUT, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: GROVE_LLM_THREADS='abc'"), result.stderr
    assert result.exception is None or isinstance(result.exception, SystemExit)


def test_the_app_refuses_a_bad_config_on_one_line_before_it_opens(elsewhere, capsys):
    from grove_tui.tui.app import run_app

    elsewhere.write_bytes(b"ui:\n  theme: [unclosed\n")
    assert run_app() == EXIT_BAD_INPUT
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {elsewhere}: not valid YAML"), lines
