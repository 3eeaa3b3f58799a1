"""The grounding report in the app: for each group (and the robot), what the sentence asked, what the
scenario plans, and after a run whether the people did it.

Before a run every claim is *planned* (·): the scenario's own reading is no evidence. After a run
(and while it plays) each claim shows ✓ with the measured figure, ✗ with the figure, or ? when the
run is still too short to tell. What the scenario adds beyond the sentence is listed with +, never
counted as ✓; readings the reader was unsure of with ?; a user's count edit with !.

It reads a report as plain data (`GroundingReport.to_dict()`: generation.json's `grounding` entry
for the planned report, grounding.json or the live check for the checked one); bundles made before
reports existed have none, and the panel says so.
"""

from __future__ import annotations

import io
from collections.abc import Mapping
from typing import TYPE_CHECKING

from rich.console import Console, Group, RenderableType
from rich.table import Table
from rich.text import Text
from textual.containers import VerticalScroll
from textual.widgets import Static

from grove_tui.scenario.report import FAILS, HOLDS, MARKS, PLANNED, UNCHECKED, Claim, GroundingReport

if TYPE_CHECKING:
    from textual.app import ComposeResult

    from grove_tui.jsontypes import Parsed

STYLES = {HOLDS: "green", FAILS: "red", UNCHECKED: "yellow", PLANNED: "dim"}


def read_grounding(report: Parsed | None) -> GroundingReport | None:
    """The report of a generation.json (its `grounding` entry) or of a grounding.json (the report
    itself); None when there is none."""
    if not isinstance(report, Mapping):
        return None
    data = report.get("grounding") if "grounding" in report else (report if "groups" in report else None)
    if not isinstance(data, Mapping):
        return None
    try:
        return GroundingReport.from_dict(dict(data))
    except (KeyError, TypeError, ValueError):
        return None


def _claim_row(claim: Claim) -> tuple[Text, Text, Text]:
    style = STYLES.get(claim.status, "")
    mark = Text(f" {claim.mark}", style=style)
    name = Text(claim.kind.replace("robot_", "robot ").replace("_", " "), style="bold" if claim.status == FAILS else "")
    value = Text(claim.asked)
    if claim.status == PLANNED:
        value.append(f"  planned: {claim.plan}" if claim.plan else "  planned", style="dim")
    elif claim.evidence:
        value.append(f"\n{claim.evidence}", style="" if claim.status == HOLDS else "italic")
    return mark, name, value


def render_grounding(report: GroundingReport | None) -> Group:
    """One block per group: its verdict and label, then a grid of claims (mark, claim, asked and the
    evidence), the text wrapping inside its own column so a narrow panel (80x24) stays readable."""
    if report is None:
        return Group(Text("No grounding report in this bundle: it was generated before the sentence was read "
                          "into groups. Regenerate (g) to get one.", style="dim"))
    parts: list[RenderableType] = [Text(report.summary(), style="bold")]
    if not report.checked:
        parts.append(Text("Nothing is ✓ before a run: play it (p) to check what the people do.", style="dim"))
    if not report.groups:
        parts.append(Text("The sentence was read as no group of people.", style="dim"))
    for number, sentence in enumerate(report.sentences, start=1):  # a refined scenario: every sentence
        parts.append(Text(f"{number}. {sentence}", style="dim"))
    for group in report.groups:
        header = Text()
        header.append(f"{MARKS[group.status]} ", style=f"bold {STYLES.get(group.status, '')}")
        label = group.who if group.label.lower() in group.who.lower() else f"{group.who} → {group.label}"
        header.append(label, style="bold")
        header.append(f" ×{len(group.members)}", style="dim")
        if report.sentences:
            header.append(f"  {group.asked()}", style="dim")
        parts.append(header)
        grid = _grid()
        for claim in group.claims:
            grid.add_row(*_claim_row(claim))
        for added in group.added:
            grid.add_row(Text(" +", style="cyan"), Text("added", style="cyan"), Text(added, style="cyan"))
        for question in group.unsure:
            grid.add_row(Text(" ?", style="yellow"), Text("unsure", style="yellow"), Text(question))
        if group.edit:
            grid.add_row(Text(" !", style="yellow"), Text("edited", style="yellow"), Text(group.edit))
        parts.append(grid)
    robot = report.robot
    if robot is not None:
        header = Text()
        if robot.claims:
            header.append(f"{MARKS[robot.status]} ", style=f"bold {STYLES.get(robot.status, '')}")
            header.append(f"robot: {robot.task}", style="bold")
            header.append(f"  '{robot.text}'", style="dim")
        else:
            header.append("- robot", style="bold")
            header.append(f"  {robot.plan}", style="dim")
        parts.append(header)
        grid = _grid()
        for claim in robot.claims:
            grid.add_row(*_claim_row(claim))
        for question in robot.unsure:
            grid.add_row(Text(" ?", style="yellow"), Text("unsure", style="yellow"), Text(question))
        parts.append(grid)
    for correction in report.corrections:
        parts.append(Text(f"~ correction: {correction}", style="dim"))
    for note in report.unhonoured:
        parts.append(Text(f"! {note}", style="yellow"))
    return Group(*parts)


def _grid() -> Table:
    grid = Table.grid(padding=(0, 1, 0, 0))
    grid.add_column(no_wrap=True)
    grid.add_column(no_wrap=True)
    grid.add_column(overflow="fold", ratio=1)
    return grid


def grounding_text(report: GroundingReport | None, width: int = 60) -> str:
    """The report as plain text at a given width (what the panel shows, without colours)."""
    console = Console(width=width, record=True, color_system=None, file=io.StringIO())
    console.print(render_grounding(report))
    return console.export_text()


def summary(report: GroundingReport | None) -> str:
    """'planned: 3 groups' or '2/3 groups ✓, 1 ✗ (run of 60 s)' for a title, or '' without a report."""
    if report is None or not report.groups:
        return ""
    return report.summary()


class GroundingPanel(VerticalScroll, can_focus=True):
    """The report, scrollable with the arrow keys (groups can outnumber the rows at 80x24)."""

    HELP = """\
## Grounding

For each group of people the sentence describes (and the robot): what it asked, what the scenario
plans, and after a run whether the people did it. Before a run everything is *planned* (·); after,
✓ comes with the measured figure, ✗ with the figure, ? when the run was too short to tell (with
how long it needs). `+` lines are what the scenario adds beyond the sentence (never ✓), `?` unsure
readings, `!` count edits and parts of the sentence that could not be honoured.
"""

    def __init__(self, report: Parsed | None, *, name: str | None = None, id: str | None = None,
                 classes: str | None = None, disabled: bool = False) -> None:
        super().__init__(name=name, id=id, classes=classes, disabled=disabled)
        self._parsed = read_grounding(report)

    def compose(self) -> ComposeResult:
        yield Static(render_grounding(self._parsed), id="grounding-text")

    def show(self, report: Parsed | GroundingReport | None) -> None:
        self._parsed = report if isinstance(report, GroundingReport) else read_grounding(report)
        self.query_one("#grounding-text", Static).update(render_grounding(self._parsed))
        self.border_title = self.title()

    def title(self) -> str:
        counted = summary(self._parsed)
        return f"Grounding · {counted}" if counted else "Grounding"

    def on_mount(self) -> None:
        self.border_title = self.title()
