"""A checkpoint cleared on the way (round 40): "a backpacker clears border control and makes for the
waiting lounge", "having cleared security, a couple walks to gate B1", "after clearing customs they head
to arrivals". Clearing a checkpoint is passing through it, not emptying it; said so when the checkpoint is
one by its head word and the sentence goes on past it (or the clearing is fronted), so "the guards clear
the security checkpoint" alone stays the emptying of a place."""

from __future__ import annotations

import re

# Head words of a checkpoint people pass through: "border control", "security", "the ticket barriers".
_HEADS = (r"security|control|customs|immigration|barriers?|gateline|turnstiles?|screening|checks?|checkpoint|"
          r"scanners?|detectors?")
_FORMS = {"clear": "pass through", "clears": "passes through", "cleared": "passed through",
          "clearing": "passing through"}
_OBJECT = r"((?:the\s+)?(?:[\w'-]+\s+){0,3}?(?:" + _HEADS + r"))\b"
# Going on past it: "and", "then", a comma or "before" after the checkpoint.
_ON = re.compile(r"\b(clear|clears|cleared|clearing)\s+" + _OBJECT + r"(?=\s*(?:,|;|\band\b|\bthen\b|\bbefore\b))", re.I)
# Fronted: "Having cleared security,", "After clearing customs", "Once they've cleared immigration".
_FRONTED = re.compile(r"\b(having|after|once|just)\s+(?:(?:they|he|she|we|you)(?:'ve|'s|\s+have|\s+has)?\s+)?"
                      r"(clear|clears|cleared|clearing)\s+" + _OBJECT, re.I)


def as_passed_checkpoints(text: str) -> str:
    """The text with a checkpoint's clearing said as passing through it."""
    text = _FRONTED.sub(lambda m: m.group(0).replace(m.group(2), _FORMS[m.group(2).lower()], 1), text)
    return _ON.sub(lambda m: _FORMS[m.group(1).lower()] + " " + m.group(2), text)
