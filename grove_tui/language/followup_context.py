"""What the clause readers of one follow-up share: the scenario's groups, the groups the sentence adds
as it goes, the groups the last edit touched (what "they" means), and the notes said back to the user.

`FollowupContext.read` is the one reader (`read_prompt`) as a follow-up uses it: on a clause or a
predicate, without the unsure group a sentence that names nobody is read as.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from grove_tui.language.model import GroupReading, PromptReading
from grove_tui.language.reading import read_prompt
from grove_tui.world.model import World


@dataclass
class FollowupContext:
    world: World
    groups: Sequence[GroupReading]
    seed: int
    last: tuple[int, ...]
    has_robot: bool
    notes: list[str]
    # groups that exist only once this sentence is applied ("add a cleaner, then make it mop the hall"):
    # a pronoun may name them, by their index after the scenario's groups
    added: list[GroupReading]

    def read(self, text: str) -> PromptReading:
        """The reader's reading of a clause, without the unsure group a sentence that names nobody is read
        as ("the lights are off"): a follow-up that names nobody adds nobody."""
        reading = read_prompt(text, self.world, seed=self.seed)
        named = tuple(g for g in reading.groups if not ((c := g.confidence_of("group")) is not None and c.unsure))
        return reading if len(named) == len(reading.groups) else replace(reading, groups=named)

    @property
    def group_count(self) -> int:
        """The scenario's groups and those this sentence has added so far."""
        return len(self.groups) + len(self.added)

    def group(self, index: int) -> GroupReading:
        """A group by its index: the scenario's, then the ones this sentence added."""
        return self.groups[index] if index < len(self.groups) else self.added[index - len(self.groups)]

    def note_unknown(self, places: Sequence[str]) -> None:
        for place in places:
            self.notes.append(f"'{place}' is not a place of world '{self.world.name}'")

    def known_groups(self) -> str:
        """The scenario's groups, said after a phrase that names none of them."""
        labels = [g.label for g in self.groups]
        return f" (it has: {', '.join(labels)})" if labels else " (it has no groups)"
