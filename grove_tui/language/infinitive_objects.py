"""A verb after "to" with an object of its own is what someone goes to do, not where they go: "a nurse
comes over to check it", "a steward hurries across to help them", "goes to inspect the robot". The
word's letters may share a place's ("check" of the check-in kiosk, "help" of the help desk), so the
phrase matched that place by words. The parser says an infinitive: "to" tagged TO, the word a base
verb, and right after it a pronoun or a noun phrase it governs as its object ("on" one: "to check
on the robot"). "go to check in" (no object) is left to the place matcher: the check-in desk may be
meant."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_OBJECT_PRONOUNS = frozenset("it them him her me us everyone everybody something".split())


def infinitive_with_object(s: Sentence, k: int) -> bool:
    """Whether word k, after "to", is a verb in the infinitive with an object (module doc)."""
    if k < 1 or k + 1 >= s.n or s.w[k - 1].tag != "TO" or s.w[k].tag != "VB":
        return False
    if s.low[k + 1] in _OBJECT_PRONOUNS or s.low[k + 1] == "on" and k + 2 < s.n and (
            s.low[k + 2] in _OBJECT_PRONOUNS or s.w[k + 2].pos == "DET"):
        return True  # "to check it", "to check on the robot"
    return any(s.w[x].dep == "dobj" and s.w[x].head == k for x in range(k + 1, min(k + 5, s.n)))
