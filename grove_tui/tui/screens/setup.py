"""Setup: pick a world (live map preview) and a preset, see the models, type a prompt, Generate."""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING

from textual import on, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import Screen
from textual.widgets import Button, Input, Label, OptionList, Static
from textual.widgets.option_list import Option

from grove_tui.errors import describe_error
from grove_tui.services.session import ScenarioRequest
from grove_tui.tui import messages as msg
from grove_tui.tui.widgets.map_view import MapView
from grove_tui.tui.widgets.choice_list import ChoiceList
from grove_tui.tui.widgets.clipped import ClippedText
from grove_tui.tui.widgets.map_legend import WORLD_SYMBOLS, MapLegend
from grove_tui.tui.widgets.prompt_input import PromptInput, ReadlineInput
from grove_tui.tui.heap import freeze_heap
from grove_tui.tui.widgets.footer import Footer

if TYPE_CHECKING:
    from grove_tui.services.session import WarmUpStatus
    from grove_tui.tui.app import GroveApp
    from grove_tui.tui.screens.generation import GenerationRequest
    from grove_tui.tui.commands import CommandEntry

SEED_DIGITS = 9  # any seed a user types fits numpy's 32-bit seeds


class SetupScreen(Screen[None]):
    HELP = """\
## Setup

Choose a **world** (**F2**; the map on the right previews it) and a **preset** (**ctrl+r**: what
kind of scenario the model writes); **Enter** picks one and takes you back to the prompt, as you
left it (typing in a list goes on at the prompt's end). Type a prompt and press **Enter** or **ctrl+g** to generate: pressed before the lists have
loaded, it generates as soon as they have. The **seed** beside the prompt makes a run reproducible
(same world, preset, prompt, seed and model give the same scenario); **ctrl+s** jumps to it.
**ctrl+o** lists the recent runs saved under the runs folder and reopens one in the inspect screen.
The models panel shows which GGUF file serves each role and whether it is loaded yet. The app
opens on the world, preset and seed of your last generation; coming back from a scenario, setup
shows its world, preset, prompt and seed.
"""

    # priority: the prompt has focus by default; the screen's keys must work there too, and stay in the
    # footer while it is focused. None of them is a readline editing key (the text fields keep those:
    # ctrl+w deletes a word, so the worlds list is on F2).
    BINDINGS = [
        Binding("ctrl+g", "generate", "Generate", id="setup.generate", tooltip="Generate a scenario from the prompt",
                priority=True),
        Binding("f2", "focus('worlds')", "Worlds", id="setup.worlds", tooltip="Choose the world", priority=True),
        Binding("ctrl+r", "focus('presets')", "Presets", id="setup.presets", tooltip="Choose the preset",
                priority=True),
        Binding("ctrl+o", "recent_runs", "Recent", id="setup.recent", tooltip="Reopen a saved run", priority=True),
        Binding("ctrl+s", "focus('seed')", "Seed", id="setup.seed", tooltip="Change the seed", show=False,
                priority=True),
        Binding("ctrl+l", "focus('prompt')", "Prompt", id="setup.prompt", tooltip="Type the prompt", show=False,
                priority=True),
    ]

    @property
    def grove(self) -> GroveApp:
        return self.app  # type: ignore[return-value]

    def compose(self) -> ComposeResult:
        with Horizontal(id="setup-body"):
            with Vertical(id="setup-side"):
                worlds = ChoiceList(id="worlds", typing_target="prompt")
                worlds.border_title = "World"
                yield worlds
                presets = ChoiceList(id="presets", typing_target="prompt")
                presets.border_title = "Preset"
                yield presets
                yield ClippedText("", id="preset-description", max_lines=4)
                models = Static("models: looking…", id="models", markup=False)
                models.border_title = "Models"
                yield models
                problems = Static("", id="model-problems", markup=False)
                problems.display = False
                yield problems
            with Vertical(id="preview-column"):
                preview = MapView(id="preview")
                preview.border_title = "Map"
                legend = MapLegend("", id="preview-legend")
                preview.legend = legend
                yield preview
                yield legend
        with Horizontal(id="prompt-row"):
            yield PromptInput(self.grove.history, placeholder="Describe the crowd… (Enter to generate)", id="prompt")
            yield Label("seed", id="seed-label")
            yield ReadlineInput(str(self.grove.initial_seed), id="seed", restrict=r"[0-9]*", max_length=SEED_DIGITS,
                                tooltip="Seed of the generation and the simulation (ctrl+s)")
            yield Button("Generate", id="generate", variant="primary")
        yield Footer(compact=True, show_command_palette=False)

    def on_mount(self) -> None:
        self._worlds_listed = False
        self._presets_listed = False
        self._queued = False  # Enter came before the lists: generate once they are in
        self._adopted: object = None  # the scenario whose choices the screen shows (on_screen_resume)
        self._warm_step: tuple[str, float, float] | None = None  # (text, started, expected seconds)
        self.query_one("#prompt", PromptInput).focus()
        self.set_interval(1.0, self._tick_warm_up, name="warm-up-eta")
        # Paint the screen first; the catalogue worker's imports would otherwise delay the first frame.
        self.call_after_refresh(self.load_catalogue)

    def on_screen_resume(self) -> None:
        """Back from a scenario (generated, regenerated or reopened): show its world, preset, prompt and seed."""
        generated = self.grove.generated
        if generated is None or generated is self._adopted:
            return
        self._adopted = generated
        self.select_world(generated.world_name)
        self.select_preset(generated.preset)
        prompt = self.query_one("#prompt", PromptInput)
        if prompt.value != generated.prompt:
            prompt.value = generated.prompt
        self.query_one("#seed", Input).value = str(generated.seed)

    def select_world(self, name: str) -> None:
        worlds = self.query_one("#worlds", OptionList)
        ids = [worlds.get_option_at_index(i).id for i in range(worlds.option_count)]
        if name not in ids:
            if not self._worlds_listed:
                self.grove.initial_world = name  # the list is still on its way: it selects this one
                return
            worlds.add_option(Option(name, id=name))  # a world file given by path
            ids.append(name)
        if worlds.highlighted != ids.index(name):
            worlds.highlighted = ids.index(name)

    def select_preset(self, name: str) -> None:
        presets = self.query_one("#presets", OptionList)
        ids = [presets.get_option_at_index(i).id for i in range(presets.option_count)]
        if name in ids:
            if presets.highlighted != ids.index(name):
                presets.highlighted = ids.index(name)
        elif not self._presets_listed:
            self.grove.initial_preset = name

    def command_entries(self) -> list[CommandEntry]:
        return [
            ("Generate scenario", "Run the pipeline on the prompt", self.action_generate),
            ("Choose world", "Focus the world list", lambda: self.action_focus("worlds")),
            ("Choose preset", "Focus the preset list", lambda: self.action_focus("presets")),
            ("Recent runs", "Reopen a scenario saved under the runs folder", self.action_recent_runs),
            ("Change seed", "Focus the seed field", lambda: self.action_focus("seed")),
        ]

    def action_recent_runs(self) -> None:
        from grove_tui.tui.screens.recent import RecentRunsScreen

        def chosen(bundle_dir: Path | None) -> None:
            if bundle_dir is not None:
                self.grove.open_bundle(bundle_dir)

        self.app.push_screen(RecentRunsScreen(), chosen)

    @property
    def seed(self) -> int | None:
        text = self.query_one("#seed", Input).value.strip()
        return int(text) if text else None

    # Screen.action_focus (async, a selector) replaced: the bindings' focus('worlds') name a widget id.
    def action_focus(self, widget_id: str) -> None:  # type: ignore[override]
        self.query_one(f"#{widget_id}").focus()

    # workers -----------------------------------------------------------------------------------------
    @work(thread=True, exclusive=True, group="catalogue", exit_on_error=False, description="listing worlds")
    def load_catalogue(self) -> None:
        session = self.grove.session
        preload = self.grove.settings.ui.preload_models
        initial = self.grove.initial_world
        if preload and initial:
            # The world is known: warm up at once, beside the listing (progress from the first second).
            self.preload_models(initial, self.grove.initial_preset)
        # Presets before worlds: the map preview's title is what a user (and the tmux test) waits
        # for before typing.
        self.post_message(msg.PresetsListed(session.presets()))
        names: list[str] = []
        try:
            names = session.list_worlds()
        except Exception as exc:  # an engine bug must show, not kill the app
            self.post_message(msg.WorldsListed([], describe_error(exc).text))
        else:
            self.post_message(msg.WorldsListed(names))
        if preload and not initial:
            self.post_message(msg.ModelsChanged(session.model_status(), loading=True))
            self.preload_models(names[0] if names else None, self.grove.initial_preset)
        elif not preload:
            self.post_message(msg.ModelsChanged(session.model_status()))

    @work(thread=True, exclusive=True, group="models", exit_on_error=False, description="loading models")
    def preload_models(self, world: str | None, preset: str | None) -> None:
        """Warm everything the first generation needs (session.warm_up); the panel shows each step."""
        session = self.grove.session
        embedder = ""

        def report(status: WarmUpStatus) -> None:
            nonlocal embedder
            if status.step == "retrieval":
                embedder = {"running": "loading", "done": "ready"}.get(status.state, status.error or "failed")
            loading = status.step == "models" and status.state == "running"
            if status.step == "ready" and status.state == "done" and self.grove.freeze_heap_when_warm:
                # Everything long-lived is loaded now: freeze it before the user starts typing, so
                # no later collection pauses the UI thread to walk it (tui/heap.py).
                self.grove.frozen_heap = freeze_heap()
            self.post_message(msg.ModelsChanged(
                session.model_status(), loading=loading, embedder=embedder,
                warm_up="" if status.step == "ready" and status.state == "done" else status.text,
                expected_seconds=status.expected_seconds if status.state == "running" else 0.0))

        try:
            session.warm_up(world, preset, on_status=report)
        except Exception as exc:  # an engine bug must show on the panel, not kill the app
            self.post_message(msg.ModelsChanged(session.model_status(), embedder=embedder,
                                                warm_up=f"warm-up failed: {describe_error(exc).text}"))

    @work(thread=True, exclusive=True, group="world", exit_on_error=False, description="loading world")
    def load_world(self, name: str) -> None:
        try:
            world = self.grove.session.load_world(name)
        except Exception as exc:
            self.post_message(msg.WorldFailed(name, describe_error(exc).text))
            return
        self.post_message(msg.WorldLoaded(name, world))

    # messages ----------------------------------------------------------------------------------------
    def on_worlds_listed(self, message: msg.WorldsListed) -> None:
        worlds = self.query_one("#worlds", OptionList)
        worlds.clear_options()
        if message.error:
            self.query_one("#preview", MapView).border_subtitle = "cannot list worlds"
            self.notify(message.error, title="Worlds", severity="error", timeout=10)
            self._queued = False
            return
        initial = self.grove.initial_world
        names = list(message.names)
        if initial and initial not in names:
            names.insert(0, initial)  # a path given with --world
        worlds.add_options([Option(name, id=name) for name in names])
        if names:
            worlds.highlighted = names.index(initial) if initial in names else 0
        self._worlds_listed = True
        self._generate_if_queued()

    def on_presets_listed(self, message: msg.PresetsListed) -> None:
        presets = self.query_one("#presets", OptionList)
        presets.clear_options()
        presets.add_options([Option(p.name, id=p.name) for p in message.presets])
        self._preset_descriptions = {p.name: p.description for p in message.presets}
        names = [p.name for p in message.presets]
        if names:
            initial = self.grove.initial_preset
            presets.highlighted = names.index(initial) if initial in names else 0
        self._presets_listed = True
        self._generate_if_queued()

    def _generate_if_queued(self) -> None:
        if self._queued and self._worlds_listed and self._presets_listed:
            self._queued = False
            self.action_generate()

    def on_models_changed(self, message: msg.ModelsChanged) -> None:
        self.model_statuses = list(message.statuses)
        lines = []
        for status in message.statuses:
            state = "loaded" if status.loaded else ("error" if status.error else ("loading…" if message.loading else "on demand"))
            lines.append(f"{status.role:<3} {state}: {status.file}")
        if message.embedder:
            state = {"loading": "loading…", "ready": "ready"}.get(message.embedder, "error")
            lines.append(f"emb {state}")
        problems = self.model_problems()
        if message.embedder not in ("", "loading", "ready"):
            problems.append(f"embedder: {message.embedder}")
        # A running warm-up step counts down from what it took last time: progress from the first second.
        self._warm_step = ((message.warm_up, time.monotonic(), message.expected_seconds)
                           if message.warm_up and message.expected_seconds else None)
        if message.warm_up:
            lines.append(message.warm_up)  # a warm-up step still running (or failed)
        elif not problems and all(status.loaded for status in message.statuses) and message.embedder == "ready":
            lines.append("ready to generate")
        self._model_lines = lines
        panel = self.query_one("#models", Static)
        panel.update(self._models_text())
        panel.set_class(bool(problems), "-broken")
        panel.tooltip = "\n".join([f"{s.role}: {s.file}" for s in message.statuses] + problems)
        # The whole message, wrapped, under the status lines: "error: ?" alone does not say what to fix.
        shown = self.query_one("#model-problems", Static)
        shown.update("\n".join(problems))
        shown.display = bool(problems)

    def _models_text(self) -> str:
        lines = list(getattr(self, "_model_lines", []))
        step = getattr(self, "_warm_step", None)
        if step is not None and lines:
            text, started, expected = step
            lines[-1] = f"~{max(expected - (time.monotonic() - started), 0):.0f}s {text}"
        return "\n".join(lines) or "no models found"

    def _tick_warm_up(self) -> None:
        if getattr(self, "_warm_step", None) is not None:
            self.query_one("#models", Static).update(self._models_text(), layout=False)

    def model_problems(self) -> list[str]:
        """One line per role whose model is known to be broken, with the error's own message."""
        roles_by_error: dict[str, list[str]] = {}
        for status in getattr(self, "model_statuses", []):
            if status.error:
                roles_by_error.setdefault(status.error, []).append(status.role)
        # Both roles fail alike when the registry cannot resolve any model: say it once.
        return [f"{', '.join(roles)}: {error}" for error, roles in roles_by_error.items()]

    @on(OptionList.OptionHighlighted, "#worlds")
    def world_highlighted(self, event: OptionList.OptionHighlighted) -> None:
        name = event.option.id
        if name:
            self.query_one("#preview", MapView).border_title = f"Map: {name} (loading)"
            self.load_world(name)

    @on(OptionList.OptionHighlighted, "#presets")
    def preset_highlighted(self, event: OptionList.OptionHighlighted) -> None:
        descriptions = getattr(self, "_preset_descriptions", {})
        self.query_one("#preset-description", ClippedText).update(descriptions.get(event.option.id or "", ""))

    @on(OptionList.OptionSelected)
    def option_selected(self) -> None:
        """Back to the prompt as the user left it, the cursor at its end (nothing selected, nothing lost)."""
        prompt = self.query_one("#prompt", PromptInput)
        prompt.focus()
        prompt.action_text_end()

    def on_world_loaded(self, message: msg.WorldLoaded) -> None:
        if message.name != self.selected_world:
            return
        preview = self.query_one("#preview", MapView)
        self.query_one("#preview-legend", MapLegend).show_symbols(preview, WORLD_SYMBOLS)
        preview.set_world(message.world)
        preview.border_title = f"Map: {message.world.name}"
        preview.border_subtitle = message.world.description or ""  # cut with "…" by the border when long

    def on_world_failed(self, message: msg.WorldFailed) -> None:
        preview = self.query_one("#preview", MapView)
        preview.set_world(None)
        preview.border_title = f"Map: {message.name} (not loaded)"
        self.notify(message.error, title=f"World {message.name}", severity="error", timeout=10)

    # generate ----------------------------------------------------------------------------------------
    @property
    def selected_world(self) -> str | None:
        worlds = self.query_one("#worlds", OptionList)
        if worlds.highlighted is None:
            return None
        return worlds.get_option_at_index(worlds.highlighted).id

    @property
    def selected_preset(self) -> str | None:
        presets = self.query_one("#presets", OptionList)
        if presets.highlighted is None:
            return None
        return presets.get_option_at_index(presets.highlighted).id

    @on(PromptInput.Submitted, "#prompt")
    @on(Input.Submitted, "#seed")
    @on(Button.Pressed, "#generate")
    def action_generate(self) -> None:
        from grove_tui.tui.screens.generation import GenerationRequest, GenerationScreen

        prompt_box = self.query_one("#prompt", PromptInput)
        prompt = prompt_box.value.strip()
        world, preset = self.selected_world, self.selected_preset
        if not prompt:
            self.notify("Type a prompt first, e.g. 'ten people queue at the counter'.", title="Prompt", severity="warning")
            prompt_box.focus()
            return
        if world is None or preset is None:
            if not (self._worlds_listed and self._presets_listed):
                # Too early: the lists are on their way. Generate as soon as they are in.
                self._queued = True
                self.notify("Generating as soon as the worlds and presets are listed…", title="Setup", timeout=3)
                return
            self.notify("Choose a world and a preset first.", title="Setup", severity="warning")
            return
        problems = self.model_problems()
        if problems:
            # Generating would only fail at the first model call with the error already known here.
            self.notify("\n".join(problems) + "\nFix the model file (grove models list) or start grove with --model PATH.",
                        title="Cannot generate: model broken", severity="error", timeout=15)
            return
        self.grove.remember_prompt(prompt)
        prompt_box.reset_history_position()
        seed = self.seed
        if seed is None:
            self.notify("Type a seed (a whole number, e.g. 0).", title="Seed", severity="warning")
            self.query_one("#seed", Input).focus()
            return
        request = GenerationRequest(prompt=prompt, world=world, preset=preset, seed=seed)
        if not self.grove.settings.ui.ask_when_unsure or getattr(self.grove.session, "unsure", None) is None:
            self.app.push_screen(GenerationScreen(request))
            return
        self.check_reading(request)  # unsure readings are asked about first (on_reading_checked)

    @work(thread=True, exclusive=True, group="reading", exit_on_error=False, description="reading the sentence")
    def check_reading(self, request: GenerationRequest) -> None:
        try:
            questions = list(self.grove.session.unsure(ScenarioRequest(request.world, request.preset, request.prompt,
                                                                        request.seed)))
        except Exception:  # a sentence that cannot be read fails in the generation, with its reason shown there
            questions = []
        self.post_message(msg.ReadingChecked(request, questions))

    def on_reading_checked(self, message: msg.ReadingChecked) -> None:
        from grove_tui.tui.screens.choice import Choice, ChoiceScreen
        from grove_tui.tui.screens.generation import GenerationScreen

        if not message.questions:
            self.app.push_screen(GenerationScreen(message.request))
            return

        def answered(value: str | None) -> None:
            if value == "generate":
                self.app.push_screen(GenerationScreen(message.request))
            else:
                self.query_one("#prompt", PromptInput).focus()

        text = "\n".join(f"• {q}" for q in message.questions)
        self.app.push_screen(ChoiceScreen("The reader is unsure", text + "\n\nGenerate as read, or edit the sentence?",
                                          [Choice("enter", "Generate as read", "generate"),
                                           Choice("e", "Edit the sentence", "edit")]), answered)
