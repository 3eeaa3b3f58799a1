"""A party said as the outing it is on, with "of" and a count, round 41: "a stag do of twelve", "a works
outing of twenty", "a birthday bash of ten", "a school trip of thirty". The reader knows "party" as a
collective of people and not these nouns, so the outing is said as a party ("a stag party of twelve"):
twelve people together, not one person called "people" nor twelve "troops"."""

from __future__ import annotations

import re

_OUTINGS = r"do|dos|bash|outing|trip|knees-up|jolly|shindig|excursion|get-together|reunion|beano|night\s+out|away\s+day"
_NUMBER_WORDS = (r"two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|"
                 r"seventeen|eighteen|nineteen|twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred")
_NUMBER = rf"(?:\d+|(?:{_NUMBER_WORDS})(?:[- ](?:one|two|three|four|five|six|seven|eight|nine))?|a\s+dozen|a\s+score)"
# What a count of an outing may measure instead of its people ("a trip of two hours").
_UNITS = (r"hours?|minutes?|mins?|seconds?|days?|nights?|weeks?|months?|years?|miles?|km|kilometres?|metres?|"
          r"meters?|stops?|floors?|pounds?|quid|laps?|legs?|stages?")
_OUTING = re.compile(
    rf"\b((?:a|an|the|our|their|his|her|this|one)\s+(?:[a-z][a-z'-]*\s+)?)(?:{_OUTINGS})(\s+of\s+(?:about\s+|around\s+|some\s+)?{_NUMBER}\b)(?!-|\s+(?:{_UNITS})\b)",
    re.IGNORECASE)


def as_outing_parties(text: str) -> str:
    """The text with an outing counted with "of" said as a party (see the module doc)."""
    return _OUTING.sub(lambda m: f"{m.group(1)}party{m.group(2)}", text)
