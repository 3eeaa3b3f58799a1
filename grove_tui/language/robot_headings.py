"""The robot's task given as a heading (round 40): "Robot job: take tea and toast from the midwives'
room over to the postnatal ward.", "Task for the robot - fetch blankets from the pharmacy ...", "The
robot's job is to carry the post to ...", "Bot's errand for today: deliver ...". The small parser reads
the heading as a noun and the bare verb after it as no one's, so the robot gets no task. Said as an
order to the robot ("Have the robot take tea ..."), which the reader already reads, the robot does it.
Only a verb the lexicon knows opens the order, so a heading over a noun ("Robot job: tea run") is left
alone."""

from __future__ import annotations

import re

from grove_tui.language.tokens import _KNOWN_VERBS, verb_lemma

_ROBOT = r"(?:(?:the|our|a|this)\s+)?(?:delivery\s+|service\s+)?(?:robot|bot|droid)(?:'s|s'|’s)?"
_JOB = (r"(?:job|task|errand|mission|duty|duties|chore|assignment|brief|instructions?|orders?|to-?do|"
        r"first\s+job|next\s+job|first\s+task|next\s+task)")
_WHEN = r"(?:\s+(?:for\s+)?(?:today|now|tonight|this\s+(?:morning|afternoon|evening|shift)|meanwhile))?"
_HEAD = re.compile(
    r"(^|[.!?;]\s+)"
    rf"(?:{_ROBOT}\s+{_JOB}{_WHEN}\s*(?::|[-–—]|,?\s+is\s+to|,?\s+is\s*:)"  # "Robot job:", "The robot's task is to"
    rf"|{_JOB}\s+for\s+{_ROBOT}{_WHEN}\s*(?::|[-–—]|,?\s+is\s+to)"  # "Task for the robot:"
    rf"|{_ROBOT}\s*:)"  # "Robot: take ..."
    r"\s*(?:to\s+)?([A-Za-z]+)\b", re.IGNORECASE)
_EXTRA_VERBS = frozenset({"shuttle", "hand", "ferry", "tidy", "restock", "vacuum", "hoover", "mop", "scout"})


def _base(word: str) -> str | None:
    """The base form of a known verb that opens the order ("take", "takes", "taking"), else None."""
    w = word.lower()
    for form in (w, verb_lemma(w)):
        if form in _KNOWN_VERBS or form in _EXTRA_VERBS:
            return form
    if w.endswith("s") and w[:-1] in _EXTRA_VERBS:
        return w[:-1]
    return None


def as_robot_order(text: str) -> str:
    """`text` with each heading of the robot's job said as an order to the robot."""
    def order(m: re.Match[str]) -> str:
        verb = _base(m.group(2))
        if verb is None:
            return m.group(0)
        lead = m.group(1)
        have = "have" if lead.strip() == ";" else "Have"
        return f"{lead}{have} the robot {verb}"
    return _HEAD.sub(order, text)
