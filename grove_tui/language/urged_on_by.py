"""People inside an aside of who urges, cheers or watches the subject (round 34): "a couple of Year 10
lads, egged on by their mates, square up to our robot", "three nurses, cheered on by the patients, walk
to the pharmacy", "a boy, watched by his parents, walks to the exit". The aside's people were read as a
group of their own, given the subject's verb, and the subject left waiting. Those who egg on, cheer or
watch stay where they are and are not said to be anywhere: the aside between its commas is left out,
and the subject keeps its verb. An aside of people who go along ("followed by two porters", "led by a
guide") is no such aside and reads as before."""

from __future__ import annotations

import re

_URGED = ("egged cheered urged spurred goaded dared encouraged jeered heckled teased taunted filmed "
          "photographed watched observed applauded ignored scolded warned nagged egged-on cheered-on "
          "prompted pushed-on")
_PARTICLES = "on|along|ahead"
_ASIDE = re.compile(rf",\s+(?:(?:closely|anxiously|nervously|proudly|loudly|noisily|gleefully|eagerly)\s+)?"
                    rf"(?:{'|'.join(_URGED.split())})(?:\s+(?:{_PARTICLES}))?\s+by\s+[^,;:.!?()]{{2,60}},\s+",
                    re.IGNORECASE)


def without_urging_asides(text: str) -> str:
    """The text without an aside of people who urge or watch the subject (module doc)."""
    return _ASIDE.sub(" ", text)
