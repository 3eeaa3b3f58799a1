"""A state said before someone pushed or wheeled along ("wheels a snoozing baby in a pram", "pushes
his dozing grandson in the buggy", "carries a grizzling toddler") is how they are, not a verb: the
small parser read the "-ing" word as one and lost the person, so no second group followed the pusher.
Written before parsing without the state word ("wheels a baby in a pram"), only right after a
pushing or carrying verb and its determiner, and only before a word for a person."""

from __future__ import annotations

import re

_PUSHING = r"(?:wheel|push|pull|carr(?:y|ie)|tow|trundle|steer|cart)(?:s|es|ed|ing)?"
_DET = r"(?:a|an|the|his|her|their|our|my|its|two|twin)"
_STATE = (r"(?:snoozing|sleeping|dozing|napping|slumbering|snoring|grizzling|crying|wailing|howling|gurgling|"
          r"teething|dribbling|drooling|yawning|whimpering|sniffling|babbling|squirming|wriggling)")
_PERSON = (r"(?:bab(?:y|ies)|infants?|newborns?|toddlers?|tots?|child(?:ren)?|kids?|sons?|daughters?|"
           r"grand(?:son|daughter|child|children|kid)s?|twins|boys?|girls?|nephews?|nieces?|patients?|"
           r"gentlem[ae]n|lad(?:y|ies)|m[ae]n|wom[ae]n|gran|grandad|grandma|grandpa|nan|mum|dad|wife|husband)")
_STATED = re.compile(r"\b(" + _PUSHING + r"\s+" + _DET + r")\s+" + _STATE + r"\s+(?=" + _PERSON + r"\b)",
                     re.IGNORECASE)


def without_wheeled_states(text: str) -> str:
    """The text without a state word before someone pushed or carried (module doc)."""
    return _STATED.sub(lambda m: m.group(1) + " ", text)
