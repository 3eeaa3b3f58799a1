"""A few people said by how they are spread (round 43): "a scattering of OAPs", "a smattering of
tourists", "a sprinkling of regulars". The reader took "a scattering" for one person, or left the
people uncounted; they are a handful, as "a handful of OAPs" reads (a vague few)."""

from __future__ import annotations

import re

# "a scattering of", "a thin smattering of", "a light sprinkling of": a handful of the people after.
_SPREAD = re.compile(r"\b(a|an|the)\s+(?:(?:small|thin|light|little|sparse|few)\s+)?(?:scattering|smattering|"
                     r"sprinkling|scatter|smatter)\s+of\s+(?=[A-Za-z])", re.IGNORECASE)


def with_scattered_counts(text: str) -> str:
    """The text with a spread of people ("a scattering of") written as a handful (module doc)."""
    return _SPREAD.sub(lambda m: ("A" if m.group(1)[0].isupper() else "a") + " handful of ", text)
