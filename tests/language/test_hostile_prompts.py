"""Prompts that cannot describe a crowd are refused with a sentence, before any model runs."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from grove_tui.errors import PromptError
from grove_tui.generation.postprocess import check_population
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world


def refuse(prompt: str, preset: str = "emergency") -> str:
    """The checks GenerationPipeline.run makes before any model runs, in its order: the reading's
    problems, then the population against the selected places and the preset."""
    world = load_world("hospital")
    with pytest.raises(PromptError) as caught:
        reading = read_prompt(prompt, world)
        if reading.problems:
            raise PromptError(reading.problems[0])
        check_population(world, build_grid(world, 0.1), load_preset(preset),
                         select_rois(world, load_preset(preset), reading), reading)
    assert caught.value.exit_code == 2
    return str(caught.value)


@pytest.mark.parametrize("prompt, expected", [
    ("-5 people walk to the pharmacy", "'-5 people' is a negative number of people"),
    ("minus 3 nurses walk to the pharmacy", "is a negative number of people"),
    ("a billion people evacuate the cafeteria", "1000000000 people"),
    ("10 million people evacuate the cafeteria", "10000000 people"),
    ("🔥🔥🔥", "no words to read"),
    ("zero people evacuate the cafeteria", "'zero people' asks for nobody"),
    ("Nobody is in the cafeteria.", "nobody is there"),
])
def test_refused_with_a_reason(prompt, expected):
    assert expected in refuse(prompt)


@pytest.mark.parametrize("prompt, count", [("3-5 people walk to the pharmacy", (3, 5)),
                                           ("twenty-five patients queue at the pharmacy", (25, 25)),
                                           ("ten million visitors walk in", (10_000_000, 10_000_000))])
def test_ranges_hyphens_and_large_scales_are_read(prompt, count):
    g = read_prompt(prompt, load_world("hospital")).groups[0]
    assert (g.count.low, g.count.high) == count


@pytest.mark.parametrize("prompt", ["Ｔｅｎ ｐａｔｉｅｎｔｓ ｗａｌｋ ｔｏ ｔｈｅ ｐｈａｒｍａｃｙ", "👨‍👩‍👧‍👦 a family walks to the pharmacy",
                                    "2.5 people walk to the pharmacy"])
def test_full_width_letters_emoji_and_fractions_are_read_not_refused(prompt):
    world = load_world("hospital")
    reading = read_prompt(prompt, world)
    assert not reading.problems and reading.groups[0].destination == "pharmacy"
    assert 2 <= reading.groups[0].count.value <= 10


def test_stdout_on_dev_full_is_one_line_not_a_traceback():
    code = "import sys; sys.argv = ['grove', 'worlds', 'list']; from grove_tui.cli import main; main()"
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-c", code], stdout=full, stderr=subprocess.PIPE, text=True,
                              env={**os.environ}, timeout=120)
    assert done.returncode == 3
    assert done.stderr.strip().splitlines() == [
        "error: cannot write the output: No space left on device (hint: free some space or write somewhere else)"]


def test_an_unwritable_out_is_refused_before_any_work():
    from grove_tui.errors import OutputError
    from grove_tui.files import check_output_dir
    from grove_tui.scenario.bundle import is_bundle

    # root passes access() on /proc; only creating something there tells the truth.
    with pytest.raises(OutputError, match="cannot write there"):
        check_output_dir("/proc/grove-out", owned=is_bundle)


def test_a_device_named_as_a_world_file_is_not_called_missing():
    from grove_tui.errors import WorldError
    from grove_tui.world import load_world

    with pytest.raises(WorldError, match="is a device, not a file"):
        load_world("/dev/zero")


def test_a_config_alias_bomb_is_refused_not_expanded(tmp_path, monkeypatch):
    import time

    from grove_tui.errors import SettingsError
    from grove_tui.settings import load_settings

    levels = "a: &a [x,x,x,x,x,x,x,x,x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [" + ",".join(["*" + chr(97 + i)] * 9) + "]\n" for i in range(8))
    config = tmp_path / "config.yaml"
    config.write_text(levels + "ui:\n  theme: *i\n")
    monkeypatch.setenv("GROVE_CONFIG_FILE", str(config))
    started = time.perf_counter()
    with pytest.raises(SettingsError, match="expands to more than"):
        load_settings()
    assert time.perf_counter() - started < 5.0  # it hung (the error message repr'd the expansion)


def test_a_config_key_that_is_not_text_is_a_settings_error(tmp_path, monkeypatch):
    # Found by bench/fuzz.py: a `!!binary` key reached pydantic, which raised TypeError.
    from grove_tui.errors import SettingsError
    from grove_tui.settings import load_settings

    config = tmp_path / "config.yaml"
    config.write_text("!!binary AAAA: dark\nui:\n  theme: dark\n")
    monkeypatch.setenv("GROVE_CONFIG_FILE", str(config))
    with pytest.raises(SettingsError, match="is not a setting name"):
        load_settings()


def test_an_empty_config_key_is_a_settings_error(tmp_path, monkeypatch):
    # Found by bench/fuzz.py: `&anchor:` on a line of its own makes a None key.
    from grove_tui.errors import SettingsError
    from grove_tui.settings import load_settings

    config = tmp_path / "config.yaml"
    config.write_text("ui:\n  theme: dark\ngeneration:\n&lation:\n  seconds: 60\n")
    monkeypatch.setenv("GROVE_CONFIG_FILE", str(config))
    with pytest.raises(SettingsError, match="key None is not a setting name"):
        load_settings()


class _DraftLLM:
    """Answers every call with one fixed draft (the checks under test run before any model call)."""

    path = None

    def __init__(self, text: str) -> None:
        self.text = text

    def generate(self, messages, grammar=None, **_):
        from grove_tui.llm.local import Generation

        return Generation(self.text, "stop", 100, 40, 0.01, 0.001)


def _pipeline(clinic, draft: str = "2 nurses from restroom: GoTo(lobby)"):
    from grove_tui.generation.pipeline import GenerationPipeline
    from grove_tui.generation.retrieval import NodeRetriever

    class NoRetrieval(NodeRetriever):
        def retrieve(self, prompt, preset=None, k=8):
            return []

    return GenerationPipeline(clinic, load_preset("normal"), None, _DraftLLM(draft), NoRetrieval())


def test_full_width_letters_are_words_to_the_generation_checks(clinic):
    """Issue 35: a prompt typed in full-width letters was refused as "only symbols or emoji" (the reader
    reads it; the check before it did not), and a full-width minus sign or number word slipped past the
    negative and zero checks."""
    result = _pipeline(clinic).run("ｔｗｏ ｎｕｒｓｅｓ ｗａｌｋ ｆｒｏｍ ｔｈｅ ｒｅｓｔｒｏｏｍ ｔｏ ｔｈｅ ｌｏｂｂｙ", seed=0)
    assert sum(1 for agent in result.scenario.agents) == 2
    for prompt, message in (("－５ nurses walk from the restroom to the lobby", "is a negative number of people"),
                            ("ｍｉｎｕｓ ３ nurses walk to the lobby", "is a negative number of people"),
                            ("ｚｅｒｏ nurses walk to the lobby", "asks for nobody"),
                            ("🔥 🚶 ⚕️", "no words to read")):
        with pytest.raises(PromptError, match=message):
            _pipeline(clinic).run(prompt, seed=0)
