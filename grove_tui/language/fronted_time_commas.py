"""A time said first, with no comma before the subject (round 44): "After dinner a newlywed couple stroll
down to the spa", "After lunch an elderly couple walk ...", "Before the match a few fans gather". The
small parser runs the subject into the time phrase and takes the verb for a noun ("couple stroll"), so
the couple was lost and a vague crowd made up. A comma after the fronted time ("After dinner, a ...")
keeps the subject its own; it is added before the sentence is parsed, when a determiner or a count
opens the subject."""

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
