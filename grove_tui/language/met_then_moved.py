"""A person met first and then taken along by a pronoun (round 43): "Auntie Pat links arms with Gramps
and walks him from the bedroom to the settee", "a nurse finds an old man in the corridor and walks
him to the pharmacy", "a porter greets Mr Shah at the door and takes him up to ward B". The person
is named only as the object of the first verb, and the pronoun after the verb of taking along was
read as nobody, so the person moved was lost. The first verb only says how they met: it is written
as the taking along itself ("walks Gramps from the bedroom ...", "walks an old man from the corridor
to ..."), and the person is the second group, following the mover. A place said with the meeting is
where they set off, unless the route says its own start. Only a verb of taking someone along with
"him/her/them" right after "and" is read so; "finds a seat and walks to the bar" is untouched."""

from __future__ import annotations

import re

_MEETING = (r"(?:links?|linked|linking)\s+arms\s+with|(?:takes?|took|taking)\s+hold\s+of|(?:picks?|picked|picking)\s+up|"
            r"(?:greets?|greeted|greeting|meets?|met|meeting|finds?|found|finding|collects?|collected|collecting|"
            r"fetches|fetch|fetched|fetching|wakes?|woke|waking|spots?|spotted|spotting|hugs?|hugged|hugging|"
            r"calms?|calmed|calming|comforts?|comforted|comforting)")
_TAKING = (r"(?:walks?|walked|walking|leads?|led|leading|takes?|took|taking|guides?|guided|guiding|helps?|helped|"
           r"helping|steers?|steered|steering|brings?|brought|bringing|escorts?|escorted|escorting|ushers?|"
           r"ushered|ushering|accompanies|accompanied|wheels?|wheeled|wheeling|shepherds?|shepherded)")
_PERSON = (r"(?:(?:the|a|an|his|her|their|my|our|your)\s+(?:[\w'’-]+\s+){0,3}?[\w'’-]+|"
           r"(?:(?:Mr|Mrs|Ms|Miss|Dr|Auntie|Aunt|Uncle|Nurse|Sister)\.?\s+)?[A-Z][\w'’-]+(?:\s+[A-Z][\w'’-]+)?)")
_MET = re.compile(rf"\b(?:{_MEETING})\s+({_PERSON})"
                  rf"(?:\s+(?:at|in|on|by|outside|near)\s+((?:the\s+)?[\w'’ -]{{1,40}}?))?"
                  rf"\s*,?\s+and\s+(?:then\s+)?({_TAKING})\s+(?:him|her|them)\b(?=(\s+\w+)?)")


def as_taken_along(text: str) -> str:
    """The text with a person met and then taken along by a pronoun said as taken along (module doc)."""
    def said(m: re.Match[str]) -> str:
        start = "" if m.group(2) is None or (m.group(4) or "").strip().lower() == "from" else f" from {m.group(2)}"
        return f"{m.group(3)} {m.group(1)}{start}"
    return _MET.sub(said, text)
