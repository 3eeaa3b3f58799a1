"""GROVE-TUI's Textual app: setup -> generation -> inspect -> simulation -> export.

`App.__init__` does no I/O: the engine facade (`session`) and the settings come in as arguments so
tests inject fakes, and everything slow (world loading, model loading, generation, simulation)
runs in thread workers started after the first screen is on.
"""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path
from typing import TYPE_CHECKING, Literal, TypeVar, overload

from textual.app import App
from textual.binding import Binding
from textual.screen import ModalScreen, Screen

from grove_tui.services.session import GeneratedScenario, GroveSession
from grove_tui.tui.messages import RunOpened, RunOpenFailed
from grove_tui.tui.commands import GroveCommands
from grove_tui.tui.heap import FrozenHeap, drop_dead_widget_caches
from grove_tui.settings import (GroveSettings, load_history, load_last_choices, load_settings, save_history,
                                save_last_choices)

if TYPE_CHECKING:
    from textual.await_complete import AwaitComplete
    from textual.screen import ScreenResultCallbackType
    from textual.widget import AwaitMount

    from grove_tui.settings import LastChoices


_R = TypeVar("_R")  # a screen's result

QUIT_WAIT_SECONDS = 0.05  # a moment for the model processes to stop by themselves when the app closes


class GroveApp(App[int]):
    CSS_PATH = Path(__file__).with_name("app.tcss")  # absolute, so subclasses elsewhere find it too
    TITLE = "GROVE"
    SUB_TITLE = "sentence -> pedestrian scenario"
    HORIZONTAL_BREAKPOINTS = [(0, "-narrow"), (100, "-wide")]
    COMMANDS = App.COMMANDS | {GroveCommands}
    BINDINGS = [
        Binding("f1", "help", "Help", id="app.help", tooltip="Help for the focused widget and the keys of this screen"),
        Binding("ctrl+q", "quit", "Quit", id="app.quit", tooltip="Quit GROVE", priority=True),
    ]

    def __init__(
        self,
        session: GroveSession,
        settings: GroveSettings | None = None,
        *,
        world: str | None = None,
        preset: str | None = None,
        history: list[str] | None = None,
        persist_history: bool = False,
        open_bundle: Path | None = None,
        last_choices: LastChoices | None = None,
        remember_choices: bool = False,
    ) -> None:
        super().__init__()
        self.session = session
        self.settings = settings if settings is not None else GroveSettings()
        # The command line's choice, else the last generation's (data dir), else the config file's.
        last: LastChoices = last_choices or {}
        self.initial_world = world if world is not None else last.get("world", self.settings.generation.world)
        self.initial_preset = preset if preset is not None else last.get("preset", self.settings.generation.preset)
        self.initial_seed = int(last.get("seed", self.settings.generation.seed))
        self.remember_choices = remember_choices
        self.history: list[str] = list(history or [])
        self.persist_history = persist_history
        self.generated: GeneratedScenario | None = None
        self.animation_level = self.settings.ui.animation
        self.open_bundle_at_start = open_bundle
        # Completion tokens of each model stage's last run: the generation screen's ETA expects as many.
        self.stage_tokens: dict[str, int] = {}
        # Seconds each model stage read its prompt before the first token last time: the ETA till then.
        self.stage_first_token: dict[str, float] = {}
        # Freeze the heap once the warm-up has loaded the models, embedder and reader (tui/heap.py);
        # what that freeze did, for the bench and the tests.
        self.freeze_heap_when_warm = True
        self.frozen_heap: FrozenHeap | None = None

    def on_mount(self) -> None:
        from grove_tui.tui.screens.setup import SetupScreen

        if self.settings.ui.theme in self.available_themes:
            self.theme = self.settings.ui.theme
        if self.settings.keymap:
            self.set_keymap(self.settings.keymap)
        self.push_screen(SetupScreen())
        if self.open_bundle_at_start is not None:
            self.open_bundle(self.open_bundle_at_start)

    # saved runs --------------------------------------------------------------------------------------
    def open_bundle(self, bundle_dir: Path) -> None:
        """Load a saved bundle off the UI thread, then show it in the inspect screen over setup."""
        self.notify(f"Opening {bundle_dir.name}…", title="Open run", timeout=3)
        self.run_worker(lambda: self._load_bundle(Path(bundle_dir)), thread=True, exclusive=True, group="open-run",
                        exit_on_error=False, description="opening a run")

    def _load_bundle(self, bundle_dir: Path) -> None:
        try:
            generated = self.session.open_bundle(bundle_dir)
        except Exception as exc:  # a broken bundle must say why, not close the app
            self.post_message(RunOpenFailed(bundle_dir, f"{type(exc).__name__}: {exc}"))
            return
        self.post_message(RunOpened(generated))

    def on_run_opened(self, message: RunOpened) -> None:
        from grove_tui.tui.screens.inspect import InspectScreen
        from grove_tui.tui.screens.setup import SetupScreen

        # The inspect screen sits on setup, so Escape goes back to setup as after a generation.
        while len(self.screen_stack) > 2 and not isinstance(self.screen, SetupScreen):
            self.pop_screen()
        self.generated = message.generated
        self.push_screen(InspectScreen(message.generated, reopened=True))

    def on_run_open_failed(self, message: RunOpenFailed) -> None:
        self.notify(message.error, title=f"Cannot open {message.bundle_dir.name}", severity="error", timeout=15)

    # screens: notifications belong to the screen they were raised on -------------------------------------
    # Cleared before a full screen replaces another (not for dialogs over the same screen), so toasts
    # never carry over and cover the next screen; what the caller notifies after the switch stays.
    if TYPE_CHECKING:  # App.push_screen's own overloads: wait_for_dismiss=True gives a Future of the result

        @overload
        def push_screen(self, screen: Screen[_R] | str, callback: ScreenResultCallbackType[_R] | None = None,
                        wait_for_dismiss: Literal[False] = False, *, mode: str | None = None) -> AwaitMount: ...

        @overload
        def push_screen(self, screen: Screen[_R] | str, callback: ScreenResultCallbackType[_R] | None = None,
                        wait_for_dismiss: Literal[True] = True, *, mode: str | None = None) -> asyncio.Future[_R]: ...

    def push_screen(self, screen: Screen[_R] | str, callback: ScreenResultCallbackType[_R] | None = None,
                    wait_for_dismiss: bool = False, *, mode: str | None = None) -> AwaitMount | asyncio.Future[_R]:
        if not isinstance(screen, ModalScreen):
            self.clear_notifications()
        if wait_for_dismiss:
            return super().push_screen(screen, callback, True, mode=mode)
        return super().push_screen(screen, callback, False, mode=mode)

    def switch_screen(self, screen: Screen | str) -> AwaitComplete:
        if not isinstance(screen, ModalScreen):
            self.clear_notifications()
        result = super().switch_screen(screen)
        drop_dead_widget_caches()
        return result

    def pop_screen(self) -> AwaitComplete:
        if not isinstance(self.screen, ModalScreen):
            self.clear_notifications()
        result = super().pop_screen()
        # The closed screen's widgets would stay reachable from a Textual memo (tui/heap.py).
        drop_dead_widget_caches()
        return result

    # shared state ------------------------------------------------------------------------------------
    def remember_prompt(self, prompt: str) -> None:
        if self.history and self.history[-1] == prompt:
            return
        self.history.append(prompt)
        limit = self.settings.generation.history_size
        del self.history[: max(0, len(self.history) - limit)]
        if self.persist_history:
            save_history(self.history, limit)

    def remember(self, world: str, preset: str, seed: int) -> None:
        """The choices of a generation, for the next start of the app (when this app remembers them)."""
        if not self.remember_choices:
            return
        try:
            save_last_choices(world, preset, seed)
        except OSError as exc:  # an unwritable data dir must not stop a generation
            self.notify(f"Cannot remember the choices: {exc}", title="Settings", severity="warning", timeout=5)

    @property
    def export_root(self) -> Path:
        return Path(self.settings.export.directory)

    # actions ---------------------------------------------------------------------------------------
    def action_help(self) -> None:
        from grove_tui.tui.screens.help import HelpScreen

        if isinstance(self.screen, HelpScreen):
            return
        self.push_screen(HelpScreen(self.focused, self.screen))

    def on_unmount(self) -> None:
        # Closing stops the model processes; it may wait for one that is busy. Quit must take under a
        # second in every state (issue 31), so it waits that long at most: what is still running then
        # is ended by exit_now (run_app), which terminates the app's child processes.
        close = getattr(self.session, "close", None)
        if callable(close):
            closer = threading.Thread(target=close, name="grove-close", daemon=True)
            closer.start()
            closer.join(QUIT_WAIT_SECONDS)


def run_app(model: str | None = None, roi_model: str | None = None, bt_model: str | None = None,
            world: str | None = None, preset: str | None = None, open_bundle: Path | None = None,
            session: GroveSession | None = None) -> int:
    """Entry point of the `grove` command with no subcommand; returns the exit code.

    `session` replaces the one built from the model options (the terminal tests of the UI pass one
    with a scripted model, tests/helpers/fake_grove.py).
    """
    from grove_tui.errors import SettingsError, print_error

    try:
        settings = load_settings()
    except SettingsError as exc:
        return print_error(exc)
    if session is None:
        session = GroveSession.for_app(model=model, roi_model=roi_model, bt_model=bt_model)
    app = GroveApp(session, settings, world=world, preset=preset,
                   history=load_history(settings.generation.history_size), persist_history=True,
                   open_bundle=open_bundle, last_choices=load_last_choices(), remember_choices=True)
    # A loop of our own, never closed: asyncio.run's teardown waits for the default executor, where the
    # app's thread workers run, so a quit while the node index loaded waited 7-13 s for the load to end.
    # exit_now ends the process (those threads with it) once the app has restored the terminal.
    result = app.run(loop=asyncio.new_event_loop())
    code = int(result or 0) if app.return_code in (None, 0) else int(app.return_code or 1)
    exit_now(code)
    return code  # not reached: exit_now ends the process


def exit_now(code: int) -> None:
    """End the process without the interpreter's teardown.

    Everything is saved by now: the app has closed the model processes, history and bundles are
    written, recorder spill files are unlinked temporary files. What is left is freeing torch,
    ChromaDB and numba objects one by one, which took 2.8 s of a 3.4 s quit (issue 21 item 14).
    """
    import multiprocessing
    import os
    import sys

    # A model process still loading or evaluating when the app closed (on_unmount waits QUIT_WAIT_SECONDS
    # for them): end it now rather than leave it to notice its closed pipe when it is done.
    for child in multiprocessing.active_children():
        try:
            child.terminate()
        except OSError:
            pass
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed or broken terminal: nothing left to show there
            pass
    os._exit(code)
