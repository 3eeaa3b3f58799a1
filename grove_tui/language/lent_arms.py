"""Escorting said by the arm (round 34): "a carer gives Alastair her arm from the dining tables back to
his bed", "a nurse lends her arm to an old man as far as the lifts", "a porter offers Mrs Reid a
steadying arm to the exit", "a daughter takes her dad's arm and walks him to the café". The parser
reads the arm as the thing given and the person as a second object, so the person taken along is
lost. Each says the giver walks the person along, so it is written so before the sentence is read
("a carer walks Alastair from the dining tables ..."), and the person is the second group, following.
Only an arm is read so: "gives Alastair a hand with the bags" is left alone."""

from __future__ import annotations

import re

# A verb of giving an arm, and the same tense of "walk".
_WALK = {"gives": "walks", "give": "walk", "gave": "walked", "giving": "walking", "lends": "walks",
         "lend": "walk", "lent": "walked", "lending": "walking", "offers": "walks", "offer": "walk",
         "offered": "walked", "offering": "walking"}
_GIVING = "|".join(_WALK)
_ARM = r"(?:his|her|their|an|a)\s+(?:(?:steadying|guiding|helping|supporting|firm|strong)\s+)?arm\b"
# "gives Alastair her arm", "offers the old man a steadying arm": the person between verb and arm.
_PERSON_ARM = re.compile(rf"\b({_GIVING})\s+((?:(?!(?:his|her|their|an|a)\s)[\w'’-]+\s+|(?:the|a|an|his|her|their)\s+)"
                         rf"(?:[\w'’-]+\s+){{0,3}}?){_ARM}", re.IGNORECASE)
# "lends her arm to an old man": the person after "to".
_ARM_TO = re.compile(rf"\b({_GIVING})\s+{_ARM}\s+to\s+(?=(?:the|a|an|his|her|their|Mr|Mrs|Ms|Miss|[A-Z])\b)",
                     re.IGNORECASE)
# "takes her arm and walks her to", "takes Alastair's arm and leads him to".
_TAKES_ARM = re.compile(r"\b(takes|took|taking|take)\s+(?:((?:(?:his|her|their|the|an|a)\s+)?(?:[\w-]+\s+){0,2}?[\w-]+)['’]s|his|her|their)\s+arm\s+and\s+"
                        r"(walks|walked|leads|led|helps|helped|guides|guided|steers|steered|takes|took)\s+"
                        r"(him|her|them)\b")


def _same_case(word: str, like: str) -> str:
    return word.capitalize() if like[:1].isupper() else word


def as_arm_escort(text: str) -> str:
    """The text with an arm given or taken to walk someone said as walking them (module doc)."""
    text = _PERSON_ARM.sub(lambda m: f"{_same_case(_WALK[m.group(1).lower()], m.group(1))} {m.group(2).rstrip()}",
                           text)
    text = _ARM_TO.sub(lambda m: f"{_same_case(_WALK[m.group(1).lower()], m.group(1))} ", text)
    return _TAKES_ARM.sub(lambda m: f"{m.group(3)} {m.group(2) or m.group(4)}", text)
