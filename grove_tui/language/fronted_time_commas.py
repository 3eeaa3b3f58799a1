"""A time said first, with no comma before the subject (round 44). The parser runs the subject into the
time phrase: "After dinner a newlywed couple stroll down to the spa" takes "couple stroll" for a noun, and
"During the Saturday changeover a bellboy wheels ..." runs "changeover a bellboy" together, so the first
group is lost or a vague crowd made up. A comma after the fronted time keeps the subject its own, as the
writer would have put one; it is written so before the sentence is parsed. Two shapes: a time word after
"after", "before", "during", ... ("after dinner", "before the match"), and "During/After/Before ... the
X" of up to four words closed by a determiner, a count or a name ("After the lecture theatre empties, ..."
is a clause, and keeps its own words)."""

from __future__ import annotations

import re

# Words that end a phrase of time after "after", "before", "during", ... ("after dinner", "before the
# match", "during the interval").
_TIMES = ("breakfast|brunch|lunch|lunchtime|tea|teatime|dinner|dinnertime|supper|bedtime|noon|midday|midnight|"
          "dusk|dawn|sunset|sunrise|nightfall|closing|opening|interval|half-time|halftime|break|recess|assembly|"
          "school|work|church|mass|service|show|match|film|movie|game|session|meal|shift|hours|class|lessons|"
          "registration|kick-off|kickoff|practice|training|rehearsal|surgery|visiting")
_FRONT = re.compile(r"(^|[.;!?]\s+)((?:after|before|during|following|over|until|till|at)\s+(?:the\s+|their\s+|his\s+|her\s+|"
                    r"our\s+|a\s+)?(?:[a-z-]+\s+)?(?:" + _TIMES + r"))\s+(?=(?:a|an|the|some|two|three|four|five|"
                    r"six|seven|eight|nine|ten|several|both|our|my|his|her|their)\s)", re.IGNORECASE)


def with_fronted_time_commas(text: str) -> str:
    """The text with a comma after a fronted phrase of time before a subject (module doc)."""
    return _FRONT.sub(lambda m: f"{m.group(1)}{m.group(2)}, ", text)


_OPENS = r"(?:During|After|Before|Following|Throughout|Until|Till)"
_DETERMINERS = r"(?:the|a|an|this|that|his|her|their|our|its|my|your)"
_CLOSERS = ("a an the two three four five six seven eight nine ten eleven twelve twenty thirty forty fifty some "
            "several both all every each most many few our their his her my your").split()
_NOT_IN_TIME = set(_CLOSERS) | {"is", "are", "was", "were", "and", "or", "but", "to", "in", "at", "on", "of", "with"}
_WORD = r"[A-Za-z][A-Za-z'-]*"
_FRONTED = re.compile(
    rf"(^|[.!?;]\s+)({_OPENS}\s+{_DETERMINERS}\s+(?P<words>{_WORD}(?:\s+{_WORD}){{0,3}}?))"
    rf"(?=\s+(?:(?:{'|'.join(_CLOSERS)})\b|\d|(?:Mr|Mrs|Ms|Dr|Miss)\b))")


def with_fronted_phrase_commas(text: str) -> str:
    """The text with a comma after a fronted "During the X" that runs into the people after it (module doc)."""
    def comma(m: re.Match[str]) -> str:
        said = m.group("words").split()
        if any(w.lower() in _NOT_IN_TIME for w in said):
            return m.group(0)
        name = next((k for k in range(1, len(said)) if said[k][0].isupper() and said[k - 1][0].islower()), None)
        if name is not None:  # "After the argument Grandad stomps out the ...": the time ends before the name
            opening = m.group(2)[:m.start("words") - m.start(2)]
            return f"{m.group(1)}{opening}{' '.join(said[:name])}, {' '.join(said[name:])}"
        return f"{m.group(1)}{m.group(2)},"
    return _FRONTED.sub(comma, text)
