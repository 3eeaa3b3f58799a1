"""Follow-up sentences read against a scenario that exists: which groups to add, change or remove.

    edit = read_followup("make the queue twice as long", world, groups)      # groups: the scenario's GroupReadings
    edit.edits[0]   # GroupEdit(kind="change", target=GroupRef("the queue", (0,)), count=CountChange("factor", 2.0))

A small pass over the one reader (`read_prompt`): this module finds what kind of edit each clause is
and which groups it names; the people, counts, places, intents, robot interactions, pace and waits
are read by `read_prompt` itself, on the clause or on its predicate with a neutral subject ("the
visitors walk to the cafeteria instead" is read as "the people walk to the cafeteria instead": what
the visitors now do). How:

1. Clauses. The sentence is split at sentence ends and semicolons, and before an edit verb joined by
   "and"/"then" ("remove the cleaner and add two guards"). Words of conversation ("no,", "now",
   "ok") are dropped; "instead", "too", "as well" are kept as cues.
2. The robot. "no robot", "remove the robot" remove it; "add a robot" puts one back; a clause whose
   subject is the robot ("the robot waits at reception", "send the robot to the lifts") gives it a
   task, read by the reader as the same clause about a person (RobotReading: task, places).
3. Removals ("remove", "delete", "get rid of", "without", "no more", "X should not be there"); a
   count in the phrase takes that many people away ("remove two of the nurses").
4. Counts: factors ("twice as long", "double", "halve", "three times as many"), comparatives
   ("make the queue longer": x1.5, "smaller": x2/3, said in a note), a new count ("make it twenty
   patients", "only two nurses", "make the queue 15"), fewer ("two fewer visitors").
5. Additions: "add ...", "also ...", "plus ...", "... too", "another", "N more X". A new group that
   states no action does what the group it adds to does ("plus two more nurses": what the nurses do).
   "Replace the cleaner with a guard" / "a guard instead of the cleaner" removes and adds.
6. Everything else is a change when its subject names a group of the scenario ("the family walks
   slowly", "make the patients wait for five minutes", "no, the cleaner should block the robot"):
   the fields its predicate states are the fields changed; "instead" replaces what they did.
   A subject that names no group adds one.

Which groups a phrase names (`resolve`): "everyone"/"all"/"both" (every group, or every group the
rest of the phrase names), a pronoun (the groups the previous edit touched), "group 2" / "the
second group", a person word against each group's label and phrase ("the elderly patients"), an
intent noun or participle ("the queue", "the people chatting"), and a place inside the phrase ("the
people at the pharmacy") to tell candidates apart. Several candidates for one phrase are ambiguous.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

from grove_tui.language import lexicon as lx
from grove_tui.language.edits import (CountChange, EditReading, GroupEdit, GroupRef, RobotEdit)
from grove_tui.language.model import Count, GroupReading, PromptReading, RobotReading
from grove_tui.language.places import place_index
from grove_tui.language.reading import read_prompt as _read_sentence
from grove_tui.language.tokens import lemma, verb_lemma, words

# ---- word tables of edits (the reader's own tables are in lexicon.py) ------------------------------

_ROBOT = r"(?:robots?|bot|amr|droid)"
_DET = r"(?:the|a|an|our|my|this|that|these|those|its|their)"
_NUMBER = r"(?:\d+|" + "|".join(sorted(set(lx.UNITS) | set(lx.TENS), key=len, reverse=True)) + \
    r")(?:[\s-](?:" + "|".join(sorted(lx.UNITS, key=len, reverse=True)) + r"))?"
REMOVE_VERBS = ("remove", "delete", "drop", "lose", "ditch", "cut", "eliminate", "scrap", "omit", "exclude",
                "dismiss", "get rid of", "take out", "take away", "send away", "send home", "kick out",
                "forget about", "forget", "no more", "no longer include", "without", "take off")
ADD_VERBS = ("add", "also add", "include", "introduce", "insert", "spawn", "bring in", "put in", "throw in",
             "there is also", "there are also", "there should also be", "also", "plus", "with", "and")
FACTOR_WORDS: dict[str, float] = {
    "twice": 2.0, "double": 2.0, "doubled": 2.0, "two times": 2.0, "thrice": 3.0, "three times": 3.0,
    "triple": 3.0, "tripled": 3.0, "four times": 4.0, "quadruple": 4.0, "five times": 5.0, "ten times": 10.0,
    "half": 0.5, "halve": 0.5, "halved": 0.5, "a third": 1 / 3, "one third": 1 / 3, "a quarter": 0.25,
}
FACTOR_VERBS: dict[str, float] = {"double": 2.0, "triple": 3.0, "quadruple": 4.0, "halve": 0.5}
# "make the queue longer": a comparative with no number (the factor is said in a note).
COMPARATIVES: dict[str, float] = {"longer": 1.5, "bigger": 1.5, "larger": 1.5, "busier": 1.5, "fuller": 1.5,
                                  "more crowded": 1.5, "shorter": 2 / 3, "smaller": 2 / 3, "quieter": 2 / 3}
SIZE_WORDS = r"(?:long|many|big|large|numerous|crowded|busy|full|much)"
# Nouns and participles that name a group by what it does ("the queue", "those waiting").
INTENT_NOUNS: dict[str, str] = {
    "queue": "queue", "line": "queue", "queuer": "queue", "conversation": "converse", "chat": "converse",
    "circle": "converse", "talker": "converse", "evacuee": "evacuate", "walker": "walk", "wanderer": "wander",
    "follower": "follow", "stroller": "wander", "waiter": "wait",
}
EVERY_WORDS = frozenset({"everyone", "everybody", "all", "both", "every", "each", "whole", "entire"})
PRONOUNS = frozenset({"they", "them", "it", "he", "she", "him", "her", "those", "these", "that", "this"})
GROUP_WORDS = frozenset({"group", "groups", "ones", "one", "lot"})
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
            "eighth": 8, "ninth": 9, "tenth": 10, "last": -1}
MORE_WORDS = frozenset({"more", "another", "extra", "additional", "further"})
# A change that says this much replaces what the group did rather than adding to it.
INSTEAD_WORDS = ("instead", "rather", "now")
NEUTRAL_SUBJECT = "the people"
MODALS = frozenset("should must will shall would could can may might need needs has have had is are be "
                   "become becomes start starts begin begins keep keeps stay stays".split())
PACE_NORMAL = re.compile(r"\b(?:at (?:a |their )?(?:normal|usual|regular|walking) (?:speed|pace)|normally)\b")
TOGETHER_OFF = re.compile(r"\b(?:separately|alone|apart|on (?:their|his|her) own|individually|one by one)\b")
IGNORE_ROBOT = re.compile(rf"\b(?:ignores?|ignoring|(?:no longer|stops?|stop|don't|do not|doesn't|does not) "
                          rf"(?:\w+ )?(?:the )?{_ROBOT})")

_LEADING = re.compile(
    r"^(?:(?:no|nope|ok|okay|actually|now|then|and|but|so|well|oh|please|right|hmm|wait|sorry|instead|also|next|"
    r"finally|alright|good|great|fine|yes|yeah)\s*[,:;!-]\s*"
    r"|(?:now|then|and|but|so|please|actually|ok|okay|oh|right|well|next|finally|alright|hmm)\s+"
    r"|no\s+(?=(?:the|a|an|they|it|make|let|have|add|remove|instead|only)\b))")
_TRAILING = re.compile(r"(?:\s*,)?\s+(?:instead|too|as well|please|now|this time|again|then|also)\s*$")
_SPLIT_SENTENCES = re.compile(r"(?<=[.!?;])\s+|\s*;\s*")
_EDIT_START = (r"(?:add|also|plus|remove|delete|drop|get rid of|take (?:out|away)|make|let|have|double|halve|"
               r"triple|replace|swap|send|put|place|move|no\s+" + _ROBOT + r"|" + _DET + r"\s+" + _ROBOT + r")\b")
_SPLIT_EDITS = re.compile(r"\s*(?:,\s*(?:and\s+(?:then\s+)?|then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)(?=" + _EDIT_START + ")")

_NO_ROBOT = re.compile(
    rf"^(?:(?:remove|delete|drop|lose|ditch|disable|get rid of|take (?:out|away)|switch off|turn off|forget|"
    rf"skip)\s+(?:{_DET}\s+)?{_ROBOT}|(?:no|without)(?:\s+(?:a|the|any))?\s+{_ROBOT}|there (?:is|should be) no "
    rf"{_ROBOT}|(?:we|i) (?:do not|don't|dont) (?:need|want) (?:a |the |any )?{_ROBOT})\b")
_ADD_ROBOT = re.compile(
    rf"^(?:add|include|bring(?: in| back)?|put|place|also|plus|with|use|there is)\s+(?:(?:a|the|one|our|back)\s+)+"
    rf"{_ROBOT}\b(?:\s+back)?\s*(?:(?:that|which|who)\s+)?(.*)$")
_ROBOT_SUBJECT = re.compile(rf"^(?:(?:make|let|have|get|tell|ask)\s+)?{_DET}\s+{_ROBOT}\s+(.+)$")
# "send the robot to the lifts", "put the robot at the entrance": verb -> how the rest is read.
_MOVE_ROBOT = re.compile(rf"^(send|take|move|drive|steer|bring|put|place|position|start|park|station)\s+"
                         rf"{_DET}\s+{_ROBOT}\s+(.+)$")
_ROBOT_START = re.compile(r"^(?:(?:should|must|will|can)\s+)?(?:starts?|begins?|spawns?|comes? from|starting)\s+"
                          r"(?:off\s+)?(?:at|in|from|by|near|on)?\s*(.+)$")
_ROBOT_END = re.compile(r"^(?:(?:should|must|will|can)\s+)?(?:ends?|finish(?:es)?|stops?|arrives?)\s+"
                        r"(?:up\s+)?(?:at|in|by|near|on)\s+(.+)$")

_REMOVE = re.compile(r"^(?:" + "|".join(re.escape(v) for v in REMOVE_VERBS) + r")\s+(.+)$")
_NO_GROUP = re.compile(r"^no\s+(?!one\b|body\b)(.+)$")
_NOT_THERE = re.compile(
    r"^(.+?)\s+(?:should not|shouldn't|must not|mustn't|do not|don't|does not|doesn't|need not|needn't|"
    r"cannot|can't|won't|will not)\s+(?:be (?:there|here|in it|in the scenario)|exist|come|appear|show up)$"
    r"|^(.+?)\s+(?:is|are)\s+(?:not needed|gone|no longer (?:there|needed)|not there|out)$")
_REPLACE = re.compile(r"^(?:replace|swap|substitute|exchange)\s+(.+?)\s+(?:with|for|by)\s+(.+)$")
_INSTEAD_OF = re.compile(r"^(.+?)\s+instead of\s+(.+)$")
_FACTOR_WORD = "|".join(re.escape(w) for w in sorted(FACTOR_WORDS, key=len, reverse=True))
_MAKE_FACTOR = re.compile(rf"^(?:make|let|have)\s+(.+?)\s+({_FACTOR_WORD})\s+(?:as\s+)?{SIZE_WORDS}"
                          rf"(?:\s+(?:as\s+)?(?:before|now|it is|they are|as it was|as they were))?$")
_IS_FACTOR = re.compile(rf"^(.+?)\s+(?:is|are|should be|must be|becomes?|gets?|grows?|will be)\s+"
                        rf"({_FACTOR_WORD})\s+(?:as\s+)?{SIZE_WORDS}(?:\s+as\s+(?:before|now))?$")
_FACTOR_VERB = re.compile(r"^(" + "|".join(FACTOR_VERBS) + r")\s+(?:the\s+(?:size|number|length)\s+of\s+)?(.+)$")
_FACTOR_MANY = re.compile(rf"^({_FACTOR_WORD})\s+as\s+many\s+(.+?)(?:\s+as\s+(?:before|now))?$")
_COMPARATIVE = re.compile(r"^(?:make|let)\s+(.+?)\s+(" + "|".join(COMPARATIVES) + r")$")
_SET_COUNT = re.compile(rf"^(?:make (?:it|that|them|this)|let (?:it|there) be|use|we need|i want|there should be|"
                        rf"there are|there is|(?:it|that) should be|only|just|(?:i|we) want|have|make)\s+"
                        rf"({_NUMBER}\s+.+)$")
_MAKE_NUMBER = re.compile(rf"^(?:make|set|change)\s+(.+?)\s+(?:to\s+|into\s+)?({_NUMBER})(?:\s+(?:people|persons|"
                          rf"strong|long))?$")
_FEWER = re.compile(rf"^({_NUMBER})\s+(?:fewer|less)\s+(.+)$")
_CAUSATIVE = re.compile(r"^(?:make|let|have|get|tell|ask)\s+(.+)$")


@dataclass
class _Context:
    world: Any
    groups: Sequence[GroupReading]
    seed: int
    last: tuple[int, ...]
    has_robot: bool
    notes: list[str]
    # groups that exist only once this sentence is applied ("add a cleaner, then make it mop the hall"):
    # a pronoun may name them, by their index after the scenario's groups
    added: list[GroupReading]


def _read(text: str, world: Any, *, seed: int) -> PromptReading:
    """The reader's reading of a clause, without the unsure group a sentence that names nobody is read
    as ("the lights are off"): a follow-up that names nobody adds nobody."""
    reading = _read_sentence(text, world, seed=seed)
    named = tuple(g for g in reading.groups if not ((c := g.confidence_of("group")) is not None and c.unsure))
    return reading if len(named) == len(reading.groups) else replace(reading, groups=named)


# ---- entry point ----------------------------------------------------------------------------------------

def read_followup(sentence: str, world: Any, groups: Sequence[GroupReading], *, has_robot: bool = True,
                  seed: int = 0, last: Sequence[int] = ()) -> EditReading:
    """What a follow-up sentence asks to change in a scenario of `groups` (see the module doc).

    `has_robot`: whether the scenario has a robot now. `last`: the groups the previous edit touched, the
    groups "they" or "it" mean. `seed` settles vague counts ("a few more visitors") as the reader does."""
    text = " ".join((sentence or "").split())
    ctx = _Context(world, tuple(groups), int(seed), tuple(last), has_robot, [], [])
    edits: list[GroupEdit] = []
    robot: RobotEdit | None = None
    for clause in _clauses(text):
        found, robot_edit = _read_clause(clause, ctx)
        edits.extend(found)
        if robot_edit is not None:
            robot = robot_edit
        first_new = len(ctx.groups) + len(ctx.added)
        new = [e.group for e in found if e.kind == "add" and e.group is not None]
        ctx.added.extend(new)
        touched = tuple(t for e in found if e.kind != "add" and e.target is not None for t in e.target.targets)
        touched += tuple(range(first_new, first_new + len(new)))  # "add a cleaner, then make it walk slowly"
        if touched:
            ctx.last = touched
    if not edits and robot is None and text and not ctx.notes:
        ctx.notes.append("nothing in it adds, changes or removes a group or the robot")
    return EditReading(text, tuple(edits), robot, tuple(dict.fromkeys(ctx.notes)))


def edited_reading(old: GroupReading, edit: GroupEdit) -> GroupReading:
    """A group's reading after a change: the fields the follow-up states replace the old ones, and
    places that belonged to what the group no longer does go with it ("the visitors walk to the
    cafeteria instead": no longer queueing at the pharmacy)."""
    new = edit.group
    values: dict[str, Any] = {}
    fields = set(edit.fields)
    if edit.count is not None:
        value = edit.count.apply(old.count.value)
        values["count"] = Count("exact", value, value, value)
    if new is not None:
        if "intent" in fields and new.intent == "walk" and old.intent == "evacuate":
            fields.discard("intent")  # "the patients leave through the east exit": they still evacuate, there
        if "intent" in fields and new.intent != old.intent:
            values["intent"] = new.intent
            stationary = new.intent in lx.STATIONARY_INTENTS
            if stationary and "location" not in fields:
                # what they now do, they do where they were (waiting instead of queueing at the desk)
                values["location"] = old.location or (old.destination if old.intent not in lx.STATIONARY_INTENTS
                                                      else None)
            if stationary and "destination" not in fields:
                values["destination"] = None
            if not stationary and new.intent != "robot" and "location" not in fields:
                values["location"] = None
            if not stationary and new.intent != "robot" and "destination" not in fields and \
                    old.intent in lx.STATIONARY_INTENTS:
                values["destination"] = None
        for name in ("start", "destination", "location", "via", "pace", "together", "wait_seconds"):
            if name in fields:
                values[name] = getattr(new, name)
        if "robot_interaction" in fields:
            values["robot_interaction"] = new.robot_interaction
            values["robot_reaction"] = new.robot_reaction
            if new.robot_interaction is None and old.intent == "robot":
                values["intent"] = "walk" if (values.get("destination", old.destination)) else "wait"
        if "destination" in fields and "location" not in fields and old.intent in lx.STATIONARY_INTENTS and \
                values.get("intent", old.intent) not in lx.STATIONARY_INTENTS:
            values["location"] = None
    text = f"{old.text} / {edit.text}" if old.text else edit.text
    return replace(old, **values, text=text, relation=None, confidence=())


# ---- clauses --------------------------------------------------------------------------------------------

def _clauses(text: str) -> list[str]:
    out: list[str] = []
    for sentence in _SPLIT_SENTENCES.split(text):
        sentence = sentence.strip().rstrip(".!?;,").strip()
        if not sentence:
            continue
        for part in _SPLIT_EDITS.split(sentence.lower()):
            part = part.strip(" ,")
            if part:
                out.append(part)
    return out


def _clean(clause: str) -> tuple[str, set[str]]:
    """The clause without words of conversation, and the cues found ("instead", "add")."""
    cues: set[str] = set()
    text = clause.lower().strip(" .!?,")
    while True:
        m = _LEADING.match(text)
        if m is None:
            break
        word = m.group(0).strip(" ,:;!-")
        if word in ("instead", "also", "now"):
            cues.add("instead" if word in ("instead", "now") else "add")
        text = text[m.end():].strip()
    while True:
        m = _TRAILING.search(text)
        if m is None:
            break
        word = m.group(0).strip(" ,")
        cues.add("instead" if word in ("instead", "now", "this time") else "add" if word in ("too", "as well", "also")
                 else "")
        text = text[:m.start()].strip()
    cues.discard("")
    return text, cues


def _read_clause(clause: str, ctx: _Context) -> tuple[list[GroupEdit], RobotEdit | None]:
    text, cues = _clean(clause)
    if not text:
        return [], None
    robot = _robot_edit(text, ctx)
    if robot is not None:
        return [], robot
    for reader in (_removal, _replacement, _count_edit, _addition):
        found = reader(text, cues, ctx)
        if found is not None:
            return found, None
    return _change_or_add(text, cues, ctx), None


# ---- the robot ------------------------------------------------------------------------------------------

def _robot_edit(text: str, ctx: _Context) -> RobotEdit | None:
    if _NO_ROBOT.match(text):
        return RobotEdit("remove", text)
    m = _ADD_ROBOT.match(text)
    if m is not None:
        task = _robot_task(m.group(1), ctx) if m.group(1).strip() else None
        return RobotEdit("add", text, task)
    m = _MOVE_ROBOT.match(text)
    if m is not None:
        verb, rest = m.group(1), m.group(2)
        if verb in ("put", "place", "position", "start", "station"):
            rest = "starts " + rest
        elif verb == "park":
            rest = "waits " + rest
        else:
            rest = "goes " + rest
        return RobotEdit("set", text, _robot_task(rest, ctx))
    m = _ROBOT_SUBJECT.match(text)
    if m is not None and not re.search(rf"\b{_ROBOT}\b", m.group(1)):
        return RobotEdit("set", text, _robot_task(m.group(1), ctx))
    return None


def _robot_task(predicate: str, ctx: _Context) -> RobotReading | None:
    """What a predicate asks of the robot, read as the same words said of one person."""
    predicate = predicate.strip()
    start = _ROBOT_START.match(predicate)
    end = _ROBOT_END.match(predicate)
    if start is not None or end is not None:
        place = _place_of(((start or end).group(1)), ctx)  # type: ignore[union-attr]
        if place is None:
            ctx.notes.append(f"'{predicate}': no place of this world is named for the robot")
            return None
        return RobotReading("cross", start=place if start is not None else None,
                            destination=place if end is not None else None, text=predicate)
    said = _read(f"the robot {predicate}", ctx.world, seed=ctx.seed)
    if said.robot is not None and not said.groups and not any(c.unsure for c in said.robot.confidence):
        _note_unknown(said.unknown_places, ctx)
        return replace(said.robot, text=predicate)
    # the same words said of a person, read as the reader reads people
    reading = _read(f"a person {predicate}", ctx.world, seed=ctx.seed)
    _note_unknown(reading.unknown_places, ctx)
    if not reading.groups:
        ctx.notes.append(f"'{predicate}': nothing the robot can do was read")
        return None
    g = reading.groups[0]
    if g.intent in ("wait", "queue", "converse"):
        where = g.location or g.destination or g.start
        if where is None:
            ctx.notes.append(f"'{predicate}': the robot waits where it starts")
        return RobotReading("wait", start=where, location=where, text=predicate)
    if g.intent == "wander":
        return RobotReading("patrol", location=g.location or g.start, text=predicate)
    if g.intent == "follow":
        return RobotReading("follow", destination=g.destination, text=predicate)
    if not (g.start or g.destination or g.via):
        ctx.notes.append(f"'{predicate}': no place of this world is named for the robot")
        return None
    return RobotReading("cross", start=g.start, destination=g.destination, via=g.via, text=predicate)


def _place_of(phrase: str, ctx: _Context) -> str | None:
    lemmas = [lemma(w) for w in words(phrase) if w not in lx.DETERMINERS]
    found = place_index(ctx.world).match(lemmas)
    return found.name if found is not None else None


# ---- removals and replacements -----------------------------------------------------------------------

def _removal(text: str, cues: set[str], ctx: _Context) -> list[GroupEdit] | None:
    m = _REMOVE.match(text)
    phrase = m.group(1) if m is not None else None
    if phrase is None:
        m = _NOT_THERE.match(text)
        if m is not None:
            phrase = m.group(1) or m.group(2)
    if phrase is None:
        m = _NO_GROUP.match(text)
        if m is None or not _resolve(m.group(1), ctx).found:
            return None  # "no one waits at the desk" is no removal
        phrase = m.group(1)
    edits: list[GroupEdit] = []
    for part in _phrases(phrase):
        taken, rest = _leading_number(part)
        ref = _resolve(rest if taken is not None else part, ctx)
        if not ref.found:
            ctx.notes.append(f"'{part}' names no group of the scenario"
                             f"{_known_groups(ctx)}: nothing removed")
            continue
        if taken is not None and ("of" in words(part) or not _definite(part)):
            edits.append(GroupEdit("change", text, ref, None, ("count",), CountChange("delta", -float(taken))))
        else:
            edits.append(GroupEdit("remove", text, ref))
    return edits


def _replacement(text: str, cues: set[str], ctx: _Context) -> list[GroupEdit] | None:
    m = _REPLACE.match(text)
    if m is not None:
        old, new = m.group(1), m.group(2)
    else:
        m = _INSTEAD_OF.match(text)
        if m is None or not _resolve(m.group(2), ctx).found:
            return None  # "walk to the cafeteria instead of the pharmacy": a place, read by the reader
        new, old = m.group(1), m.group(2)
    ref = _resolve(old, ctx)
    if not ref.found:
        ctx.notes.append(f"'{old}' names no group of the scenario{_known_groups(ctx)}: nothing replaced")
        return []
    added = _additions(new, ctx, copy=ref, text=text)
    return [GroupEdit("remove", text, ref)] + added


# ---- counts ---------------------------------------------------------------------------------------------

def _count_edit(text: str, cues: set[str], ctx: _Context) -> list[GroupEdit] | None:
    for pattern, phrase_group, factor_group in ((_MAKE_FACTOR, 1, 2), (_IS_FACTOR, 1, 2), (_FACTOR_MANY, 2, 1)):
        m = pattern.match(text)
        if m is not None:
            return _count_change(text, m.group(phrase_group), CountChange("factor", FACTOR_WORDS[m.group(factor_group)]),
                                 ctx)
    m = _FACTOR_VERB.match(text)
    if m is not None:
        return _count_change(text, m.group(2), CountChange("factor", FACTOR_VERBS[m.group(1)]), ctx)
    m = _COMPARATIVE.match(text)
    if m is not None:
        factor = COMPARATIVES[m.group(2)]
        ctx.notes.append(f"'{m.group(2)}' with no number: read as x{factor:.2g}; say \"twice as long\" or a number "
                         f"to be exact")
        return _count_change(text, m.group(1), CountChange("factor", factor), ctx)
    m = _FEWER.match(text)
    if m is not None:
        return _count_change(text, m.group(2), CountChange("delta", -float(_number(m.group(1)) or 0)), ctx)
    m = _MAKE_NUMBER.match(text)
    if m is not None and _number(m.group(2)) is not None and _resolve(m.group(1), ctx).found:
        return _count_change(text, m.group(1), CountChange("set", float(_number(m.group(2)) or 1)), ctx)
    m = _SET_COUNT.match(text)
    if m is not None:
        reading = _read(m.group(1), ctx.world, seed=ctx.seed)
        if reading.groups:
            g = reading.groups[0]
            ref = _resolve(g.who, ctx, label=g.label)
            if ref.found and not _states_action(m.group(1)[len(g.who):]):
                return [GroupEdit("change", text, ref, g, ("count",), CountChange("set", float(g.count.value)))]
    return None


def _count_change(text: str, phrase: str, change: CountChange, ctx: _Context) -> list[GroupEdit]:
    ref = _resolve(phrase, ctx)
    if not ref.found:
        ctx.notes.append(f"'{phrase}' names no group of the scenario{_known_groups(ctx)}: no count changed")
        return []
    return [GroupEdit("change", text, ref, None, ("count",), change)]


# ---- additions ------------------------------------------------------------------------------------------

def _addition(text: str, cues: set[str], ctx: _Context) -> list[GroupEdit] | None:
    for verb in sorted(ADD_VERBS, key=len, reverse=True):
        if text.startswith(verb + " "):
            rest = text[len(verb) + 1:].strip()
            if verb in ("and", "with") and not _has_people(rest, ctx):
                return None
            return _additions(rest, ctx, text=text)
    if "add" in cues and _has_people(text, ctx) and not _subject_names_group(text, ctx):
        return _additions(text, ctx, text=text)
    subject, _ = _subject(text)
    if set(words(subject)) & MORE_WORDS and _has_people(text, ctx):
        return _additions(text, ctx, text=text)  # "a few more visitors", "another nurse waits at reception"
    return None


def _additions(phrase: str, ctx: _Context, *, copy: GroupRef | None = None, text: str = "") -> list[GroupEdit]:
    """New groups read from `phrase`; one that says nothing of what it does copies `copy`, or the
    group it is more of ("two more nurses")."""
    reading = _read(phrase, ctx.world, seed=ctx.seed)
    _note_unknown(reading.unknown_places, ctx)
    if not reading.groups:
        ctx.notes.append(f"'{phrase}': no people to add were read (say who and how many: \"two guards at the "
                         f"entrance\")")
        return []
    edits: list[GroupEdit] = []
    for g in reading.groups:
        own = g.text or phrase
        source = copy
        if source is None and (set(words(g.who)) & MORE_WORDS or _definite(g.who)):
            ref = _resolve(g.who, ctx, label=g.label)
            source = ref if ref.found else None
        g = replace(g, relation=None)
        if source is not None and not _states_action(own[len(g.who):] if own.startswith(g.who) else own):
            if source.ambiguous:
                edits.append(GroupEdit("add", text or phrase, source, g))
                continue
            model = _group(source.targets[0], ctx)
            g = replace(model, who=g.who, label=g.label, count=g.count, text=own, relation=None, confidence=(),
                        **{k: getattr(g, k) for k in ("start", "location", "destination") if getattr(g, k)})
            edits.append(GroupEdit("add", text or phrase, source, g))
            continue
        edits.append(GroupEdit("add", text or phrase, None, g))
    return edits


# ---- changes --------------------------------------------------------------------------------------------

def _change_or_add(text: str, cues: set[str], ctx: _Context) -> list[GroupEdit]:
    m = _CAUSATIVE.match(text)
    body = m.group(1) if m is not None and _resolve(_subject(m.group(1))[0], ctx).found else text
    subject, predicate = _subject(body)
    ref = _resolve(subject, ctx) if subject else GroupRef("", ())
    if not ref.found:
        reading = _read(body, ctx.world, seed=ctx.seed)
        if reading.groups and not _definite(reading.groups[0].who):
            return _additions(body, ctx, text=text)
        if reading.groups:
            # "the janitor mops the hall" with no janitor: a new group, said so
            ctx.notes.append(f"'{subject or reading.groups[0].who}' names no group of the scenario"
                             f"{_known_groups(ctx)}: added as a new group")
            return _additions(body, ctx, text=text)
        ctx.notes.append(f"'{text}' names no group of the scenario and no new people{_known_groups(ctx)}")
        return []
    stated = _read(f"{NEUTRAL_SUBJECT} {predicate}", ctx.world, seed=ctx.seed) if predicate else None
    if stated is not None:
        _note_unknown(stated.unknown_places, ctx)
    group = stated.groups[0] if stated is not None and stated.groups else None
    fields = _stated_fields(group, predicate, ctx) if group is not None else []
    count = None
    counted = _count_in(subject, ctx)
    if counted is not None:
        count = CountChange("set", float(counted))
        fields.insert(0, "count")
    if not fields:
        ctx.notes.append(f"'{text}': nothing to change was read for {subject}")
        return []
    if _indefinite(subject) and "instead" not in cues and not ref.ambiguous and \
            not (counted is not None and _restates(group, fields, ref, ctx)):
        return _additions(body, ctx, text=text)  # "two nurses chat in the lobby": more people, not a change
    return [GroupEdit("change", text, ref, group, tuple(fields), count)]


def _stated_fields(group: GroupReading, predicate: str, ctx: _Context) -> list[str]:
    """The fields of a group's reading that its predicate states, not the reader's defaults."""
    fields: list[str] = []
    acts = _states_action(predicate)
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
    if (group.together and _says_together(predicate)) or TOGETHER_OFF.search(predicate):
        fields.append("together")
    if group.wait_seconds is not None:
        fields.append("wait_seconds")
    if group.robot_interaction is not None or IGNORE_ROBOT.search(predicate):
        fields.append("robot_interaction")
    return fields


def _restates(group: GroupReading | None, fields: Sequence[str], ref: GroupRef, ctx: _Context) -> bool:
    """Whether a counted clause says again what a group already does ("twelve patients queue at the
    pharmacy" of patients who queue there): then it corrects the count, it adds nobody."""
    if group is None:
        return True
    old = _group(ref.targets[0], ctx)
    return all(getattr(group, name) == getattr(old, name) for name in fields if name not in ("count",))


# ---- which groups a phrase names ------------------------------------------------------------------------

def _resolve(phrase: str, ctx: _Context, label: str | None = None) -> GroupRef:
    """The groups of the scenario a phrase can mean (module doc)."""
    ws = [w for w in words(phrase)]
    content = [w for w in ws if w not in lx.DETERMINERS and w not in ("of", "and")]
    count = len(ctx.groups) + len(ctx.added)
    everyone = bool(set(ws) & EVERY_WORDS)
    every = everyone or "both" in ws
    # "group 2", "the second group", "the last group"
    for k, w in enumerate(ws):
        if w in ("group", "groups") and k + 1 < len(ws) and ws[k + 1].isdigit():
            n = int(ws[k + 1])
            return GroupRef(phrase, (n - 1,) if 1 <= n <= count else ())
        if w in ORDINALS and k + 1 < len(ws) and ws[k + 1] in ("group", "one"):
            n = ORDINALS[w]
            index = count - 1 if n < 0 else n - 1
            return GroupRef(phrase, (index,) if 0 <= index < count else ())
    if content and all(w in PRONOUNS or w in GROUP_WORDS or w in ("new", "same", "other", "last", "just", "added")
                       for w in content):
        if ctx.last:
            return GroupRef(phrase, ctx.last, every=True)
        return GroupRef(phrase, tuple(range(count)), every=count == 1)
    candidates = list(range(count))
    person_words = [lemma(w) for w in content if lemma(w) in lx.PERSON_NOUNS and lemma(w) not in lx.GENERIC_PEOPLE
                    and w not in EVERY_WORDS and lemma(w) not in ("group", "crowd", "everyone", "everybody")]
    if label and label not in lx.GENERIC_PEOPLE and label not in person_words and label != "group":
        person_words.append(label)
    narrowed = False
    generic = [lemma(w) for w in content if lemma(w) in lx.GENERIC_PEOPLE]
    if not person_words and generic:
        # "the people" of a scenario that has a group the sentence called people is that group
        named = [i for i in candidates if lemma(_group(i, ctx).label) in lx.GENERIC_PEOPLE]
        if named:
            candidates, narrowed = named, True
    if person_words:
        candidates = [i for i in candidates if _names_group(person_words, _group(i, ctx))]
        narrowed = True
        if not candidates:
            return GroupRef(phrase, ())
    intents = {INTENT_NOUNS[lemma(w)] for w in content if lemma(w) in INTENT_NOUNS}
    intents |= {lx.INTENT_VERBS[verb_lemma(w)] for w in content
                if w.endswith("ing") and verb_lemma(w) in lx.INTENT_VERBS}
    if intents:
        by_intent = [i for i in candidates if _group(i, ctx).intent in intents or
                     (_group(i, ctx).intent == "robot" and "wait" in intents)]
        if by_intent or not narrowed:
            candidates = by_intent
            narrowed = True
        if not candidates:
            return GroupRef(phrase, ())
    zones = _zones_in(phrase, ctx)
    if zones:
        here = [i for i in candidates if zones & _group_zones(_group(i, ctx), ctx)]
        if here or not narrowed:
            candidates = here
            narrowed = True
    if not narrowed and not everyone and not (set(content) & {"people", "person", "crowd", "group", "everyone",
                                                              "everybody", "one", "ones", "others", "rest"}):
        return GroupRef(phrase, ())  # no word of it names people: "the corridor", "the lights"
    return GroupRef(phrase, tuple(candidates), every=every or len(candidates) == 1)


def _names_group(person_words: Sequence[str], group: GroupReading) -> bool:
    own = {lemma(group.label)} | {lemma(w) for w in words(group.who)} | {lemma(w) for w in group.label.split("_")}
    return any(w in own for w in person_words)


def _group(index: int, ctx: _Context) -> GroupReading:
    return ctx.groups[index] if index < len(ctx.groups) else ctx.added[index - len(ctx.groups)]


def _zones_in(phrase: str, ctx: _Context) -> set[str]:
    """Zones named after a place preposition inside a phrase ("the people at the pharmacy")."""
    ws = words(phrase)
    index = place_index(ctx.world)
    found: set[str] = set()
    for k, w in enumerate(ws):
        if w in lx.PLACE_PREPOSITIONS and k + 1 < len(ws):
            lemmas = [lemma(x) for x in ws[k + 1:] if x not in lx.DETERMINERS]
            match = index.match(lemmas)
            if match is not None:
                found.add(match.zone)
    return found


def _group_zones(group: GroupReading, ctx: _Context) -> set[str]:
    index = place_index(ctx.world)
    out: set[str] = set()
    for name in (group.start, group.location, group.destination, *group.via):
        entry = index.entry(name) if name else None
        if entry is not None:
            out.add(entry.zone)
    return out


# ---- small readings -------------------------------------------------------------------------------------

def _subject(text: str) -> tuple[str, str]:
    """(subject phrase, predicate): the words before the first verb, and the rest."""
    ws = text.split()
    for k in range(1, len(ws)):
        w = ws[k].strip(",")
        before = ws[k - 1]
        if before in lx.DETERMINERS or before in lx.NP_MODIFIERS or before in ("of",):
            continue
        base = verb_lemma(w)
        if w in MODALS or base in lx.INTENT_VERBS or base in lx.ROBOT_VERBS or w in ("ignore", "ignores") or \
                (w.endswith("s") and base != w and base in lx.INTENT_VERBS):
            if before in lx.PLACE_PREPOSITIONS:
                continue
            return " ".join(ws[:k]), " ".join(ws[k:])
    return text, ""


def _subject_names_group(text: str, ctx: _Context) -> bool:
    subject, _ = _subject(text)
    return _definite(subject) and _resolve(subject, ctx).found


def _states_action(predicate: str) -> bool:
    """Whether words say what people do (a verb, phrase or feeling of the lexicon), not only who they are."""
    ws = words(predicate)
    lemmas = [verb_lemma(w) for w in ws]
    if any(v in lx.INTENT_VERBS or v in lx.ROBOT_VERBS for v in lemmas):
        return True
    if any(w in lx.EVACUATION_CUES or w in lx.ROBOT_FEELINGS for w in ws):
        return True
    joined = " ".join(lemmas)
    return any(" ".join(p) in joined for p in lx.PHRASAL_INTENTS) or any(" ".join(p) in joined for p in lx.ROBOT_PHRASES)


def _says_together(predicate: str) -> bool:
    ws = words(predicate)
    return bool(set(ws) & lx.TOGETHER_WORDS) or any(" ".join(p) in " ".join(ws) for p in lx.TOGETHER_PHRASES)


def _definite(phrase: str) -> bool:
    ws = words(phrase)
    return bool(ws) and (ws[0] in ("the", "this", "that", "these", "those", "our", "my", "their", "his", "her",
                                   "its") or ws[0] in PRONOUNS or ws[0] in EVERY_WORDS)


def _indefinite(phrase: str) -> bool:
    """"a nurse", "two nurses", "some visitors": people introduced, not people already there."""
    ws = words(phrase)
    return bool(ws) and (ws[0] in ("a", "an", "another", "some", "several", "few", "many") or ws[0].isdigit()
                         or ws[0] in lx.NUMBER_WORDS)


def _count_in(phrase: str, ctx: _Context) -> int | None:
    """A head count stated in a subject ("ten visitors", "the two nurses"), else None."""
    ws = words(phrase)
    if not any(w.isdigit() or w in lx.NUMBER_WORDS or w in lx.VAGUE_RANGES for w in ws):
        return None
    reading = _read(phrase + " wait", ctx.world, seed=ctx.seed)
    return reading.groups[0].count.value if reading.groups else None


def _leading_number(phrase: str) -> tuple[int | None, str]:
    """"two of the nurses" -> (2, "the nurses"); "three visitors" -> (3, "visitors")."""
    m = re.match(rf"^({_NUMBER})\s+(?:of\s+)?(.+)$", phrase)
    if m is None:
        return None, phrase
    value = _number(m.group(1))
    return value, m.group(2)


def _number(text: str) -> int | None:
    text = text.strip().replace("-", " ")
    if text.isdigit():
        return int(text)
    total = 0
    for w in text.split():
        if w in lx.UNITS:
            total += lx.UNITS[w]
        elif w in lx.TENS:
            total += lx.TENS[w]
        else:
            return None
    return total or None


def _phrases(text: str) -> list[str]:
    return [p.strip() for p in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", text) if p.strip()]


def _has_people(text: str, ctx: _Context) -> bool:
    return bool(_read(text, ctx.world, seed=ctx.seed).groups)


def _note_unknown(places: Sequence[str], ctx: _Context) -> None:
    for place in places:
        ctx.notes.append(f"'{place}' is not a place of world '{ctx.world.name}'")


def _known_groups(ctx: _Context) -> str:
    labels = [g.label for g in ctx.groups]
    return f" (it has: {', '.join(labels)})" if labels else " (it has no groups)"
