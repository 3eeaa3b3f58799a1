"""Working a post said by a verb whose object the post is (round 34): "Janet minds the sign-in desk",
"a clerk looks after the front desk", "two volunteers staff the check-in counter", "Sam keeps an eye
on the till". The object path of the reader loses a post whose name is hyphenated ("sign-in desk")
and does not know "look after" at all, so the worker stands nowhere. Each says where the worker
stays; said as "works at the sign-in desk" the post is read as any other place. Only before a post
word ("desk", "counter", "till", "door", ...) is a verb read so: "covers the bill", "minds the kids"
and "looks after her dad" are left alone."""

from __future__ import annotations

import re

# A verb of working a post, in the forms "works", "work", "worked", "working" are said in.
_VERBS = {
    "man": ("mans", "man", "manned", "manning"), "mind": ("minds", "mind", "minded", "minding"),
    "staff": ("staffs", "staff", "staffed", "staffing"), "cover": ("covers", "cover", "covered", "covering"),
    "tend": ("tends", "tend", "tended", "tending"),
    "look after": ("looks after", "look after", "looked after", "looking after"),
    "keep an eye on": ("keeps an eye on", "keep an eye on", "kept an eye on", "keeping an eye on"),
    "keep watch over": ("keeps watch over", "keep watch over", "kept watch over", "keeping watch over"),
    "keep watch at": ("keeps watch at", "keep watch at", "kept watch at", "keeping watch at"),
}
_WORK = ("works", "work", "worked", "working")
_TO_WORK = {form: work for forms in _VERBS.values() for form, work in zip(forms, _WORK)}
_POSTS = ("desk", "desks", "counter", "counters", "till", "tills", "checkout", "checkouts", "booth", "kiosk",
          "stall", "reception", "door", "doors", "gate", "gates", "hatch", "window", "entrance", "barrier",
          "barriers", "post", "switchboard", "lectern", "podium", "cloakroom", "bar", "register", "station")
_VERB_RE = "|".join(re.escape(f).replace(r"\ ", r"\s+") for f in sorted(_TO_WORK, key=len, reverse=True))
_AT_POST = re.compile(rf"\b({_VERB_RE})\s+(?=(?:the|a|an|our|their|his|her|its|that|this)\s+"
                      rf"(?:(?!(?:by|at|near|in|on|of|with|from|to|and|or|behind|beside)\s)[\w'’-]+\s+){{0,3}}?(?:{'|'.join(_POSTS)})\b(?!\s*[-']))", re.IGNORECASE)


def as_work_at_posts(text: str) -> str:
    """The text with a verb of working a post said as working at it (module doc)."""
    def at(m: re.Match[str]) -> str:
        work = _TO_WORK[" ".join(m.group(1).lower().split())]
        return f"{work.capitalize() if m.group(1)[0].isupper() else work} at "
    return _AT_POST.sub(at, text)
