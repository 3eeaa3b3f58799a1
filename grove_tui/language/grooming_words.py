"""What is done at a dressing or make-up room, said as the plain words the world's descriptions use:
being powdered, having one's face or hair done, being styled before going on: "the place where guests
get powdered" is where guests are made up (the make-up room). Each is a kind of activity, not a
sentence: the verb phrase and its common forms."""

from __future__ import annotations

import re

GROOMING: tuple[tuple[str, str], ...] = (
    (r"(?:get|gets|got|getting|are|is|be|being) (?:\w+ )?powdered", "have make-up done"),
    (r"powder(?:s|ed|ing)? (?:their|his|her|your) (?:faces?|cheeks|foreheads?)", "have make-up done"),
    (r"(?:have|has|had|having|get|gets|got|getting) (?:their|his|her|your) (?:faces?|hair) (?:done|styled|"
     r"powdered|painted)", "have hair and make-up done"),
    (r"(?:get|gets|got|getting|are|is|be|being) (?:\w+ )?(?:styled|primped|touched up)", "have hair and make-up done"),
)


def plain_grooming(said: str) -> str:
    """`said` (lower case) with its words of grooming as the plain words of make-up."""
    for pattern, plain in GROOMING:
        said = re.sub(r"\b" + pattern + r"\b", plain, said)
    return said
