"""Coming up to the robot in anger (round 53): "Red-faced, a dealer storms up to the robot and bangs on
its casing", "Furious, a visitor marches over to the robot", "a commuter storms over to it and thumps
its screen". The clause reads an approach (Curious); but storming at it, striking it, or a word of anger
set before the subject or on it ("a furious floor manager"), shouting at it or telling it to clear off
(round 63) says the approach is a threat: the reaction is Threatening, the interaction
stays an approach (it comes up to the robot; it does not stand in its way)."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

# A word of anger set before the subject at a sentence's start: "Red-faced, ...", "Furious, ...".
_FRONTED_ANGER = re.compile(
    r"(?:^|[.!?;]\s+)(?:(?:visibly|clearly|utterly|absolutely|quite|rather|very)\s+)?"
    r"(?:red[\s-]faced|purple[\s-]faced|furious|fuming|livid|irate|enraged|incensed|seething|angry|outraged|"
    r"apoplectic|infuriated|raging|irritated|annoyed|exasperated|indignant|cross)\s*,", re.I)
# Storming at the robot or striking it: "storms up to", "bangs on its casing", "thumps it", "kicks it".
_HOSTILE = re.compile(
    r"\b(?:storm(?:s|ed|ing)?\s+(?:up|over|across|back)|(?:bang|pound|hammer|beat|thump)(?:s|ed|ing)?\s+on|"
    r"thump(?:s|ed|ing)?|kick(?:s|ed|ing)?|punch(?:es|ed|ing)?|slap(?:s|ped|ping)?|whack(?:s|ed|ing)?|"
    r"smack(?:s|ed|ing)?|shov(?:e|es|ed|ing))\b", re.I)
# A word of anger set on the subject itself (round 63): "a furious floor manager", "an irate diner".
_ATTRIBUTIVE_ANGER = re.compile(
    r"\b(?:a|an|the|one|this|that)\s+(?:(?:visibly|clearly|very|quite|rather|utterly)\s+)?"
    r"(?:red[\s-]faced|purple[\s-]faced|furious|fuming|livid|irate|enraged|incensed|seething|angry|outraged|"
    r"apoplectic|infuriated|irritated|annoyed|exasperated|indignant|raging|hostile|aggressive|belligerent)\s+[a-z]",
    re.I)
# Shouting at the robot or telling it to be gone (round 63): "yells at it", "shouts at the robot", "swears
# at it", "tells it to clear off", "orders the robot to get lost".
_SHOUTED_AT = re.compile(
    r"\b(?:yell|shout|scream|bellow|roar|swear|curse|holler|rant|rage|bark|snarl)(?:s|ed|ing)?\s+"
    r"(?:(?:angrily|furiously|loudly|abuse)\s+)?at\s+(?:the\s+|our\s+|this\s+|that\s+)?(?:robot|bot|it)\b"
    r"|\bto\s+(?:clear\s+off|clear\s+out|get\s+lost|go\s+away|buzz\s+off|push\s+off|shove\s+off|"
    r"sod\s+off|bugger\s+off|naff\s+off|piss\s+off|get\s+out\s+of\s+(?:the|my|our|his|her)\s+way|"
    r"scram|beat\s+it|back\s+off)\b", re.I)
_ROBOT = re.compile(r"\b(?:robot|bot|it|its)\b", re.I)


def _sentences(prompt: str) -> list[str]:
    return [s for s in re.split(r"(?<=[.!?;])\s+", prompt) if s.strip()]


def angry_approach(prompt: str, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups approaching the robot in anger, Threatening (module doc)."""
    out = list(groups)
    for sentence in _sentences(prompt):
        if not _ROBOT.search(sentence) or not (
                _FRONTED_ANGER.search(sentence) or _HOSTILE.search(sentence)
                or _ATTRIBUTIVE_ANGER.search(sentence) or _SHOUTED_AT.search(sentence)):
            continue
        reacting = [k for k, g in enumerate(out) if g.robot_interaction is not None]
        said = [k for k in reacting if out[k].text and out[k].text.lower() in sentence.lower()]
        chosen = said if said else reacting  # one group reacting in the sentence, or in the prompt
        if len(chosen) == 1 and out[chosen[0]].robot_interaction == "approach":
            out[chosen[0]] = replace(out[chosen[0]], robot_reaction="Threatening")
    return tuple(out)
