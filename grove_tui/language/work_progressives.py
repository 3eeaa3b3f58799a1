"""Work at a post said with a progressive or with "run" (round 32): "Janet is manning the front desk",
"Sam's covering the till while ...", "Have Maria run the issue desk" (which `work_imperatives.py` says
as "Maria runs the issue desk"). The small parser takes "Janet is manning" for a name it cannot place
and "runs the issue desk" for a run: the worker is lost, or walks. Said in the simple present ("Janet
mans the front desk"), the worker is one group at the post like any other. "Run" is read as work only
before a post it can be run ("the issue desk", "the tills", "the stall"), so "runs to the desk" and
"is running late" are left alone."""

from __future__ import annotations

import re

from grove_tui.language.tokens import third_person

_WORKING = {"manning": "man", "staffing": "staff", "minding": "mind", "covering": "cover", "working": "work",
            "tending": "tend", "running": "man", "supervising": "supervise", "overseeing": "oversee",
            "guarding": "guard", "watching": "watch"}
_POSTS = ("desk", "desks", "counter", "counters", "till", "tills", "checkout", "checkouts", "stall", "stalls",
          "booth", "booths", "kiosk", "kiosks", "bar", "reception", "door", "doors", "gate", "gates", "stand",
          "post", "station", "hatch", "window", "entrance", "barrier", "barriers", "till-point", "register",
          "shop", "cloakroom", "tannoy", "switchboard", "front", "lectern", "pharmacy", "cart", "carts", "trolley",
          "trolleys", "van", "truck", "cafe", "café", "canteen", "kitchen", "buffet", "grill", "griddle", "fryer")
_DET = r"(?:the|a|an|our|their|his|her|its|that|this)"
_TO_POST = rf"(?=\s+{_DET}\s+(?:[\w'-]+\s+){{0,3}}?(?:{'|'.join(_POSTS)})\b)"
_PROGRESSIVE = re.compile(rf"(\s+is|'s|\s+are|'re)\s+({'|'.join(_WORKING)}){_TO_POST}", re.IGNORECASE)
_RUN = re.compile(rf"\b(runs|run)\b{_TO_POST}", re.IGNORECASE)


def as_simple_work(text: str) -> str:
    """The text with work at a post said in the simple present (module doc)."""
    def simple(m: re.Match[str]) -> str:
        verb = _WORKING[m.group(2).lower()]
        return verb if m.group(1).strip().lower() in ("are", "'re") else third_person(verb)

    def manned(m: re.Match[str]) -> str:
        return "mans" if m.group(1).lower() == "runs" else "man"

    text = _PROGRESSIVE.sub(lambda m: " " + simple(m), text)
    return _RUN.sub(manned, text)
