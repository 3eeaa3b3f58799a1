"""Imperatives that place people, said with a verb the parser takes for a noun (round 18): "Post a
trio of doormen at the steps and one more by the staff door", "Station two guards at reception",
"Stick four pickers in the canteen", "Drop 2 guards at reception". At the start of a sentence and before a count or a determiner
they are "Put", so both groups are read as any "Put ... and ..." is. Round 44: "Position a panel of 5
interviewers along one side of the table" is one too, and "along" in a sentence that puts people
somewhere is where they are put ("at"), not a way they go along. Round 45: before a name, a kin word
or "the", "both" or an owner ("Stick Mum by the cooker", "Pop Grandad in his chair", "Plonk the twins
on the rug") too: the parser took "Stick Mum" for one name, and "Stick the kids" was not "Put".
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True))
_PLACING = re.compile(r"(^|[.!?;:]\s+)(?:post|station|stick|plonk|plant|stand|stage|park|seat|sit|drop|pop|chuck|bung|position)\s+"
                      r"(?=(?:a|an|some|the|both|all|my|our|your|his|her|their|\d+|" + _NUMBER + "|"
                      + "|".join(sorted(lx.KIN_NAMES, key=len, reverse=True)) + r")\b|(?-i:[A-Z][a-z]+\b))",
                      re.IGNORECASE)


# "along" in a sentence that opens with "Put": where they are put ("Put two guards along the corridor").
_PUT_ALONG = re.compile(r"((?:^|[.!?;:]\s+)Put\s[^.!?;:]*?)\balong\b")


def placing_verbs(text: str) -> str:
    """The text with a placing imperative at a sentence's start written "Put" (see the module doc)."""
    put = _PLACING.sub(lambda m: f"{m.group(1)}Put ", text)
    return _PUT_ALONG.sub(lambda m: f"{m.group(1)}at", put)
