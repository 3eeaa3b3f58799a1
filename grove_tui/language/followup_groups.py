"""Group edits of a follow-up: groups removed, replaced, added, or changed.

1. Removals ("remove", "delete", "get rid of", "without", "no more", "X should not be there"); a
   count in the phrase takes that many people away ("remove two of the nurses").
2. Replacements: "replace the cleaner with a guard" / "a guard instead of the cleaner" removes and adds.
3. Additions: "add ...", "also ...", "plus ...", "... too", "another", "N more X". A new group that
   states no action does what the group it adds to does ("plus two more nurses": what the nurses do).
4. Everything else is a change when its subject names a group of the scenario ("the family walks
   slowly", "make the patients wait for five minutes", "no, the cleaner should block the robot"):
   the fields its predicate states are the fields changed; "instead" replaces what they did.
   A subject that names no group adds one.

What people do, where and how many is read by the reader: on the clause, or on its predicate with a
neutral subject ("the visitors walk to the cafeteria instead" is read as "the people walk to the
cafeteria instead": what the visitors now do).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.edits import CountChange, GroupEdit, GroupRef
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.followup_phrases import (ROBOT_PATTERN, count_in, has_people, is_definite, is_indefinite,
                                                 leading_number, listed_phrases, says_together, split_subject,
                                                 states_action)
from grove_tui.language.followup_references import resolve
from grove_tui.language.model import GroupReading
from grove_tui.language.tokens import words

REMOVE_VERBS = ("remove", "delete", "drop", "lose", "ditch", "cut", "eliminate", "scrap", "omit", "exclude",
                "dismiss", "get rid of", "take out", "take away", "send away", "send home", "kick out",
                "forget about", "forget", "no more", "no longer include", "without", "take off")
ADD_VERBS = ("add", "also add", "include", "introduce", "insert", "spawn", "bring in", "put in", "throw in",
             "there is also", "there are also", "there should also be", "also", "plus", "with", "and")

# words that add to a group already there ("two more nurses", "another guard")
MORE_WORDS = frozenset({"more", "another", "extra", "additional", "further"})

# the subject a change's predicate is read with: what the named group now does
NEUTRAL_SUBJECT = "the people"

PACE_NORMAL = re.compile(r"\b(?:at (?:a |their )?(?:normal|usual|regular|walking) (?:speed|pace)|normally)\b")
TOGETHER_OFF = re.compile(r"\b(?:separately|alone|apart|on (?:their|his|her) own|individually|one by one)\b")
IGNORE_ROBOT = re.compile(rf"\b(?:ignores?|ignoring|(?:no longer|stops?|stop|don't|do not|doesn't|does not) "
                          rf"(?:\w+ )?(?:the )?{ROBOT_PATTERN})")

_REMOVE = re.compile(r"^(?:" + "|".join(re.escape(v) for v in REMOVE_VERBS) + r")\s+(.+)$")
_NO_GROUP = re.compile(r"^no\s+(?!one\b|body\b)(.+)$")
_NOT_THERE = re.compile(
    r"^(.+?)\s+(?:should not|shouldn't|must not|mustn't|do not|don't|does not|doesn't|need not|needn't|"
    r"cannot|can't|won't|will not)\s+(?:be (?:there|here|in it|in the scenario)|exist|come|appear|show up)$"
    r"|^(.+?)\s+(?:is|are)\s+(?:not needed|gone|no longer (?:there|needed)|not there|out)$")
_REPLACE = re.compile(r"^(?:replace|swap|substitute|exchange)\s+(.+?)\s+(?:with|for|by)\s+(.+)$")
_INSTEAD_OF = re.compile(r"^(.+?)\s+instead of\s+(.+)$")

_CAUSATIVE = re.compile(r"^(?:make|let|have|get|tell|ask)\s+(.+)$")


# ---- removals and replacements -----------------------------------------------------------------------

def read_removal(text: str, cues: set[str], ctx: FollowupContext) -> list[GroupEdit] | None:
    """The groups a clause removes (or thins: "remove two of the nurses"), else None (it removes nobody)."""
    m = _REMOVE.match(text)
    phrase = m.group(1) if m is not None else None
    if phrase is None:
        m = _NOT_THERE.match(text)
        if m is not None:
            phrase = m.group(1) or m.group(2)
    if phrase is None:
        m = _NO_GROUP.match(text)
        if m is None or not resolve(m.group(1), ctx).found:
            return None  # "no one waits at the desk" is no removal
        phrase = m.group(1)
    edits: list[GroupEdit] = []
    for part in listed_phrases(phrase):
        taken, rest = leading_number(part)
        ref = resolve(rest if taken is not None else part, ctx)
        if not ref.found:
            ctx.notes.append(f"'{part}' names no group of the scenario"
                             f"{ctx.known_groups()}: nothing removed")
            continue
        if taken is not None and ("of" in words(part) or not is_definite(part)):
            edits.append(GroupEdit("change", text, ref, None, ("count",), CountChange("delta", -float(taken))))
        else:
            edits.append(GroupEdit("remove", text, ref))
    return edits


def read_replacement(text: str, cues: set[str], ctx: FollowupContext) -> list[GroupEdit] | None:
    """A group removed and the people that replace it added, else None (the clause replaces nobody)."""
    m = _REPLACE.match(text)
    if m is not None:
        old, new = m.group(1), m.group(2)
    else:
        m = _INSTEAD_OF.match(text)
        if m is None or not resolve(m.group(2), ctx).found:
            return None  # "walk to the cafeteria instead of the pharmacy": a place, read by the reader
        new, old = m.group(1), m.group(2)
    ref = resolve(old, ctx)
    if not ref.found:
        ctx.notes.append(f"'{old}' names no group of the scenario{ctx.known_groups()}: nothing replaced")
        return []
    added = _additions(new, ctx, copy=ref, text=text)
    return [GroupEdit("remove", text, ref)] + added


# ---- additions ------------------------------------------------------------------------------------------

def read_addition(text: str, cues: set[str], ctx: FollowupContext) -> list[GroupEdit] | None:
    """The groups a clause adds, else None (it says no addition)."""
    for verb in sorted(ADD_VERBS, key=len, reverse=True):
        if text.startswith(verb + " "):
            rest = text[len(verb) + 1:].strip()
            if verb in ("and", "with") and not has_people(rest, ctx):
                return None
            return _additions(rest, ctx, text=text)
    if "add" in cues and has_people(text, ctx) and not _subject_names_group(text, ctx):
        return _additions(text, ctx, text=text)
    subject, _ = split_subject(text)
    if set(words(subject)) & MORE_WORDS and has_people(text, ctx):
        return _additions(text, ctx, text=text)  # "a few more visitors", "another nurse waits at reception"
    return None


def _additions(phrase: str, ctx: FollowupContext, *, copy: GroupRef | None = None,
               text: str = "") -> list[GroupEdit]:
    """New groups read from `phrase`; one that says nothing of what it does copies `copy`, or the
    group it is more of ("two more nurses")."""
    reading = ctx.read(phrase)
    ctx.note_unknown(reading.unknown_places)
    if not reading.groups:
        ctx.notes.append(f"'{phrase}': no people to add were read (say who and how many: \"two guards at the "
                         f"entrance\")")
        return []
    edits: list[GroupEdit] = []
    for g in reading.groups:
        own = g.text or phrase
        source = copy
        if source is None and (set(words(g.who)) & MORE_WORDS or is_definite(g.who)):
            ref = resolve(g.who, ctx, label=g.label)
            source = ref if ref.found else None
        g = replace(g, relation=None)
        if source is not None and not states_action(own[len(g.who):] if own.startswith(g.who) else own):
            if source.ambiguous:
                edits.append(GroupEdit("add", text or phrase, source, g))
                continue
            model = ctx.group(source.targets[0])
            g = replace(model, who=g.who, label=g.label, count=g.count, text=own, relation=None, confidence=(),
                        **{k: getattr(g, k) for k in ("start", "location", "destination") if getattr(g, k)})
            edits.append(GroupEdit("add", text or phrase, source, g))
            continue
        edits.append(GroupEdit("add", text or phrase, None, g))
    return edits


# ---- changes --------------------------------------------------------------------------------------------

def read_change_or_addition(text: str, cues: set[str], ctx: FollowupContext) -> list[GroupEdit]:
    """A change of the group the subject names, or new people when it names none (module doc, 4)."""
    m = _CAUSATIVE.match(text)
    body = m.group(1) if m is not None and resolve(split_subject(m.group(1))[0], ctx).found else text
    subject, predicate = split_subject(body)
    ref = resolve(subject, ctx) if subject else GroupRef("", ())
    if not ref.found:
        reading = ctx.read(body)
        if reading.groups and not is_definite(reading.groups[0].who):
            return _additions(body, ctx, text=text)
        if reading.groups:
            # "the janitor mops the hall" with no janitor: a new group, said so
            ctx.notes.append(f"'{subject or reading.groups[0].who}' names no group of the scenario"
                             f"{ctx.known_groups()}: added as a new group")
            return _additions(body, ctx, text=text)
        ctx.notes.append(f"'{text}' names no group of the scenario and no new people{ctx.known_groups()}")
        return []
    stated = ctx.read(f"{NEUTRAL_SUBJECT} {predicate}") if predicate else None
    if stated is not None:
        ctx.note_unknown(stated.unknown_places)
    group = stated.groups[0] if stated is not None and stated.groups else None
    fields = _stated_fields(group, predicate, ctx) if group is not None else []
    count = None
    counted = count_in(subject, ctx)
    if counted is not None:
        count = CountChange("set", float(counted))
        fields.insert(0, "count")
    if not fields:
        ctx.notes.append(f"'{text}': nothing to change was read for {subject}")
        return []
    if is_indefinite(subject) and "instead" not in cues and not ref.ambiguous and \
            not (counted is not None and _restates(group, fields, ref, ctx)):
        return _additions(body, ctx, text=text)  # "two nurses chat in the lobby": more people, not a change
    return [GroupEdit("change", text, ref, group, tuple(fields), count)]


def _stated_fields(group: GroupReading, predicate: str, ctx: FollowupContext) -> list[str]:
    """The fields of a group's reading that its predicate states, not the reader's defaults."""
    fields: list[str] = []
    acts = states_action(predicate)
    plain_walk = group.intent == "walk" and not (group.destination or group.via or group.start)
    # "walks slowly": how they walk, not that they now walk; "should block the robot": how they react to
    # it, while they go on doing what they did
    if acts and group.intent != "robot" and not (plain_walk and (group.pace != "normal" or group.together)):
        fields.append("intent")
    for name in ("start", "destination", "location"):
        if getattr(group, name):
            fields.append(name)
    if group.via:
        fields.append("via")
    if group.pace != "normal" or PACE_NORMAL.search(predicate):
        fields.append("pace")
    if (group.together and says_together(predicate)) or TOGETHER_OFF.search(predicate):
        fields.append("together")
    if group.wait_seconds is not None:
        fields.append("wait_seconds")
    if group.robot_interaction is not None or IGNORE_ROBOT.search(predicate):
        fields.append("robot_interaction")
    return fields


def _restates(group: GroupReading | None, fields: Sequence[str], ref: GroupRef, ctx: FollowupContext) -> bool:
    """Whether a counted clause says again what a group already does ("twelve patients queue at the
    pharmacy" of patients who queue there): then it corrects the count, it adds nobody."""
    if group is None:
        return True
    old = ctx.group(ref.targets[0])
    return all(getattr(group, name) == getattr(old, name) for name in fields if name not in ("count",))


def _subject_names_group(text: str, ctx: FollowupContext) -> bool:
    """Whether the clause's subject is a definite phrase naming a group of the scenario."""
    subject, _ = split_subject(text)
    return is_definite(subject) and resolve(subject, ctx).found
