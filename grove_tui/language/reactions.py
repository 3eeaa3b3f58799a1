"""Pass 3, part 1: how a group reacts to the robot, from its own clause ("stares at the robot",
"keep their distance from it", "run after it", "curious about the robot"): look, approach, follow,
avoid or block (HuNavSim's Surprised, Curious, Curious, Scared, Threatening; language/lexicon.py)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.robot_company import goes_with_robot
from grove_tui.language.disregard import disregards
from grove_tui.language.hemmed_in import kept_from_passing_later
from grove_tui.language.hostile_gestures import gesture_threat
from grove_tui.language.modified_nouns import after_modified_determiner
from grove_tui.language.sentence import Sentence
from grove_tui.language.reaction_order import depicts, goes_after, later_reaction, stops_for, verb_in
from grove_tui.language.reaction_words import in_place_name, speaks_elsewhere
from grove_tui.language.robot_journey import robots_own_way
from grove_tui.language.robot_fronts import placed_before
from grove_tui.language.robot_idioms import idiom_reaction, timed_by_robot, timed_reaction
from grove_tui.language.robot_manner import manner_reaction
from grove_tui.language.robot_requests import asks_to_be_led
from grove_tui.language.robot_motion import motion_reaction_before
from grove_tui.language.tokens import verb_lemma

# Hostility to the robot: shouting or throwing something at it ("shouts at the robot", "throws a cup
# at the robot"), not shouting alone ("kids shout with excitement"); refusing or failing to give way
# ("won't let it pass", "refuses to budge for the robot", "doesn't make way for it") is blocking it.
HOSTILE_AT_VERBS = frozenset("throw hurl fling chuck toss lob aim shout yell holler swear curse jeer spit snarl "
                              "growl bark".split())
WAY_GIVING_VERBS = frozenset("let move budge shift give make step get".split())
REFUSALS = frozenset("not n't never refuse refuses refused refusing won't".split())
# Paying the robot no heed ("take no notice of the robot", "pay little attention to it", "never look at
# it"): no reaction, whatever verb of looking or coming over follows.
IGNORING_PHRASES = (("pay", "no", "attention"), ("pay", "little", "attention"), ("take", "no", "notice"),
                    ("take", "little", "notice"), ("pay", "no", "heed"), ("pay", "it", "no"), ("barely", "notice"))
NEGATIONS = frozenset("not n't never".split())
# Verbs of ignoring whose object is the robot ("ignoring the robot", "snubs it").
IGNORING_VERBS = frozenset("ignore disregard snub blank".split())
# Verbs of contact that are hostile only with the robot for object or after "into"/"at": "pushes past
# the robot" is passing it.
PASSING_AFTER = frozenset("past by around round".split())


def robot_positions(s: Sentence, own: Sequence[int], robot_after: int | None) -> list[int]:
    """Where a clause names the robot: its word, or "it"/"its" once the robot was named before; and
    the first word of a robot clause the group's clause leads into ("step aside as it passes")."""
    found = [i for i in own if s.low[i] in lx.ROBOT_WORDS or (
        s.low[i] in ("it", "its") and any(s.low[k] in lx.ROBOT_WORDS for k in range(i)))]
    if robot_after is not None:
        found.append(robot_after)
    return found


def clause_reaction(s: Sentence, own: Sequence[int], robot_after: int | None) -> tuple[str | None, str | None]:
    """A clause's reaction to the robot and, when it has none, its reaction with no object once the
    robot was named (`unaimed_reaction`). An idiom comes first when the clause names the robot or the
    robot's clause times it ("stops dead in her tracks as the robot approaches"); a clause the robot
    times reacts with a verb of shrinking or a start too (robot_idioms.py)."""
    robot_at = robot_positions(s, own, robot_after)
    timed = timed_by_robot(s, own, robot_after)
    idiom = idiom_reaction(s, own) if robot_at or timed else None
    idiom = "follow" if asks_to_be_led(s, own, robot_at) else idiom  # "lets the robot lead her to room 107"
    if idiom == "approach" and any(kept_from_passing_later(s, r) for r in robot_at):
        idiom = "block"  # "crowd round the robot so it can't get by" (hemmed_in.py)
    found = idiom if idiom is not None else robot_interaction(s, own, robot_at)
    if found is None and timed:
        found = timed_reaction(s, own)
    return found, (unaimed_reaction(s, own) if found is None else None)


def robot_interaction(s: Sentence, own: Sequence[int], robot_at: Sequence[int]) -> str | None:
    """The interaction a clause's words give the robot it names: phrases, then verbs, then nouns,
    then feelings ("scared of the robot"), then anything aimed "at" it ("gawk at the robot")."""
    robot_at = [r for r in robot_at if not disregards(s, own, r)]  # "not giving it a second glance"
    if not robot_at:
        return None
    if gesture_threat(s, own, robot_at):
        return "block"  # "shakes his fist at the robot", "jabs a finger at it"
    ownset = set(own)
    chosen: str | None = None
    for n_mention, r in enumerate(robot_at):
        # The verb closest before the robot governs it ("stop and stare at the robot": look); with
        # two mentions, the words since the one before ("curious about the robot and follow it").
        since = robot_at[n_mention - 1] if n_mention else -1
        found = (_after_robot(s, r) or _before_robot(s, own, ownset, since, r)
                 or motion_reaction_before(s, own, since, r) or _noun_after(s, ownset, r) or _passive(s, r)
                 or goes_with_robot(s, own, r) or placed_before(s, own, r))
        if found in (None, "approach") and kept_from_passing_later(s, r):
            found = "block"  # "surround the robot up on the gallery so it can't get past"
        if (found == "avoid" or n_mention) and _refused(s, own, r):
            # "refuses to get out of the robot's way"; and a later mention refused its way after an
            # earlier one ("gather round the robot and won't let it through"): they end by blocking it
            return "block"
        if found in ("look", "approach", "follow") and _ignored(s, own, r):
            return chosen  # "take no notice of the robot", "does not notice it"
        if found is not None and chosen is not None and found != later_reaction(chosen, found):
            return chosen  # "stares at the robot, then backs away from it": the first that is no step on
        chosen = later_reaction(chosen, found)  # "waves at the robot and follows it": follow
    if chosen is not None:
        return chosen
    if (manner := manner_reaction(s, own, robot_at)) is not None:
        return manner  # "edges warily past the robot", "plant themselves where the robot wants to go"
    if any(_refused(s, own, r) for r in robot_at):
        return "block"  # "won't let it pass", "won't budge for the robot"
    if any(_kept_from_passing(s, r) for r in robot_at):
        return "block"  # "stand side by side so the robot can't get through"
    for i in own:
        if s.low[i] in lx.ROBOT_FEELINGS:
            return lx.ROBOT_FEELINGS[s.low[i]]
    if any(s.low[r - 1] == "at" or (s.low[r - 1] == "the" and s.low[r - 2] == "at") for r in robot_at if r >= 2):
        if any(verb_in(s, i, HOSTILE_AT_VERBS) for i in own if i < robot_at[-1]):
            return "block"  # "throws a cup at the robot"
        return "look"  # "gawk at the robot", "smile at the robot": a verb the lexicon lacks, aimed at it
    return None


def _ignored(s: Sentence, own: Sequence[int], r: int) -> bool:
    """Whether the clause pays the robot at r no heed: a phrase of ignoring before it, or a negation
    then, within three words, the verb of looking or coming over ("never look at the robot")."""
    ownset = set(own)
    before = [i for i in own if i < r]
    if any(s.verb(k) in IGNORING_VERBS for k in before[-3:]):
        return True  # "gather round the coffee machine, ignoring the robot": not gathering round it
    for n, i in enumerate(before):
        if any(s.phrase_words(i, len(p), ownset) == p for p in IGNORING_PHRASES):
            return True
        near = before[n + 1:n + 4]
        if s.low[i] in NEGATIONS and any(lx.ROBOT_VERBS.get(s.verb(k)) in ("look", "approach", "follow") for k in near) \
                and not any(s.verb(k) in ("stop", "help", "resist") for k in near):  # not "can't stop staring"
            return True
    return False


def _refused(s: Sentence, own: Sequence[int], r: int) -> bool:
    """Whether the clause refuses the robot its way before the robot at r: a negation or "refuse"
    then, within three words, a verb of giving way ("won't let the robot through", "refuses to budge
    for it", "doesn't move out of its way")."""
    before = [i for i in own if i < r]
    for n, i in enumerate(before):
        if s.low[i] in REFUSALS or s.verb(i) == "refuse":
            if any(s.verb(k) in WAY_GIVING_VERBS or s.verb(k) == "budge" for k in before[n + 1:n + 4]):
                return True
    return False


_PASSING_VERBS = frozenset("get pass go move squeeze fit through past by".split())


def _kept_from_passing(s: Sentence, r: int) -> bool:
    """Whether people act so that the robot at r cannot pass: "so (that) the robot can't get
    through", "so it cannot pass", "so that the robot is unable to get by"."""
    k = r - 1 if r > 0 and s.low[r - 1] == "the" else r
    k = k - 1 if k > 0 and s.low[k - 1] == "that" else k
    if k < 1 or s.low[k - 1] not in ("so", "that"):
        return False
    after = s.low[r + 1:r + 5]
    negated = any(w in NEGATIONS or w in ("cannot", "unable") for w in after)
    return negated and any(s.verb(j) in _PASSING_VERBS for j in range(r + 1, min(s.n, r + 6)))


# Reactions said with no object: "their grandparents shrink back", "a cleaner recoils".
_UNAIMED_TAILS = frozenset({"back", "away", "aside", "off"})
_UNAIMED_VERBS = frozenset({"recoil", "flinch", "cower", "retreat"})
_UNAIMED_PHRASES = (("step", "back"), ("move", "back"), ("stand", "back"), ("hang", "back"))
_APPROACH_TAILS = frozenset({"over", "up", "across"})


def unaimed_reaction(s: Sentence, own: Sequence[int]) -> str | None:
    """A shrinking back (or a coming over) with no object, in a sentence that has named the robot
    before it: a reaction to the robot ("When the robot rolls in, the kids run to it and their
    grandparents shrink back", "..., and now and then a lost visitor wanders over")."""
    if not own or not any(s.low[k] in lx.ROBOT_WORDS for k in range(own[0])):
        return None
    ownset = set(own)
    for i in own:
        end = None
        aimed = [p for p, interaction in lx.ROBOT_PHRASES.items() if interaction == "avoid" and p[-1] in _UNAIMED_TAILS]
        for phrase in (*aimed, *_UNAIMED_PHRASES):
            if s.phrase_words(i, len(phrase), ownset) == phrase:
                end = i + len(phrase)
                break
        if end is None and s.verb(i) in _UNAIMED_VERBS and not s.after_determiner(i):
            end = i + 1
        if end is not None and (end >= s.n or s.is_punct(end) or s.low[end] in lx.CLAUSE_STARTERS):
            return "avoid"
    for i in own:
        # "a lost visitor wanders over (to ask something)": coming over to the robot named before
        end = i + 2
        if lx.INTENT_VERBS.get(s.verb(i)) in ("walk", "wander") and not s.after_determiner(i) and end <= s.n and \
                s.low[i + 1] in _APPROACH_TAILS and i + 1 in ownset and (
                    end >= s.n or s.is_punct(end) or s.low[end] in lx.CLAUSE_STARTERS or (
                        s.low[end] == "to" and s.verb_follows(end + 1))):
            return "approach"
    return None


def _after_robot(s: Sentence, r: int) -> str | None:
    """Words right after the robot: "stands in the robot's way", "blocks its path"; but out of its
    way is making way ("steps out of its way", "out of the robot's path")."""
    for phrase, interaction in lx.ROBOT_AFTER_PHRASES.items():
        if tuple(s.low[r + 1:r + 1 + len(phrase)]) == phrase or (
                s.low[r] == "its" and tuple(s.low[r:r + len(phrase)]) == ("its", *phrase[1:])):
            if interaction == "block" and robots_own_way(s, r):
                return None  # "squeezes past eighty freshers on its way to the lifts": its own journey
            before = r - 1
            while before > 0 and s.low[before] in lx.DETERMINERS:
                before -= 1
            return "avoid" if before >= 1 and tuple(s.low[before - 1:before + 1]) == ("out", "of") else interaction
    return None


def _before_robot(s: Sentence, own: Sequence[int], ownset: set[int], since: int, r: int) -> str | None:
    for i in sorted((x for x in own if since < x < r), reverse=True):
        if in_place_name(s, i) or _sends_robot(s, i, r) or speaks_elsewhere(s, i, r):
            continue  # "queue at both check-in counters while the robot ...", "ask the robot to fetch ..."
        for phrase, interaction in lx.ROBOT_PHRASES.items():
            last = i + len(phrase) - 1
            if s.phrase_words(i, len(phrase), ownset) == phrase and not (
                    s.w[last].pos == "ADP" and _object_elsewhere(s, last, r)):
                return interaction  # not "look at the flight board while the robot ..."
        # any verb of walking or roaming, known or only tagged a verb by the parser ("waddle over to it",
        # "a toddler crawls towards the robot")
        v = s.verb(i)
        if lx.INTENT_VERBS.get(v) in ("walk", "wander") or (s.w[i].pos == "VERB" and v not in lx.INTENT_VERBS
                                                             and lx.ROBOT_VERBS.get(v) != "look"):  # "waves to it"
            for tail in lx.ROBOT_APPROACH_TAILS:
                if s.phrase_words(i + 1, len(tail), ownset) == tail:
                    return "approach"  # "the twins toddle up to the robot"
            if _sent_to_robot(s, ownset, i, r):
                return "approach"  # "hurries to the robot", "runs from the lobby to it"
        if v in lx.ROBOT_VERBS and lx.ROBOT_VERBS[v] == "block" and i + 1 < s.n and s.low[i + 1] in PASSING_AFTER:
            continue  # "pushes past the robot": going by it
        stopping = stops_for(s, i, r)
        if stopping == "skip":
            continue  # "stop whispering when the robot passes": no stopping of the robot
        if stopping is not None:
            return stopping  # "stops to let the robot cross": making way
        if v in lx.ROBOT_VERBS and not s.after_determiner(i) and not after_modified_determiner(s, i) and \
                not _object_elsewhere(s, i, r, through_preposition=lx.ROBOT_VERBS[v] in ("look", "approach")):
            return lx.ROBOT_VERBS[v]
        if s.lemma(i) in lx.ROBOT_NOUNS:
            return lx.ROBOT_NOUNS[s.lemma(i)]  # "stop to take photos of the robot"
        if goes_after(s, i, r):
            return "follow"  # "toddles after it", "trots after the robot"
        if depicts(s, i, r):
            return "look"  # "an artist sketches the robot"
    return None


def _sends_robot(s: Sentence, i: int, r: int) -> bool:
    """Whether the verb at i tells the robot at r what to do ("asks the robot to fetch a wheelchair"):
    a command to it, not talking to it ("asks the robot the way")."""
    return s.verb(i) in lx.ROBOT_COMMAND_VERBS and r + 2 < s.n and s.low[r + 1] == "to" and s.verb_follows(r + 2)


def _sent_to_robot(s: Sentence, ownset: set[int], i: int, r: int) -> bool:
    """Whether the robot at r is where the verb of walking at i goes: "to the robot" in the same
    clause, though a place may come between ("hurries from the boardroom to the robot"); not the
    robot's things ("to the robot's dock")."""
    back = r - 1
    while back > i and s.low[back] in lx.DETERMINERS:
        back -= 1
    if back <= i or s.low[back] not in ("to", "towards", "toward") or s.low[r] in ("its",):
        return False
    if r + 1 < s.n and s.low[r + 1] in ("'s", "’s", "'"):
        return False
    return all(k in ownset and not s.is_punct(k) and s.low[k] not in lx.CLAUSE_STARTERS for k in range(i + 1, back))


def _object_elsewhere(s: Sentence, i: int, r: int, through_preposition: bool = False) -> bool:
    """Whether the words after i name something else before the robot at r: "the kids watch TV while
    the robot vacuums", "check their phones as it passes", "stand in front of the vending machine";
    with `through_preposition`, after a preposition too ("look at the flight board while ...")."""
    k = i + 1
    if through_preposition and k < r and s.w[k].pos == "ADP":
        k += 1
    while k < r and not s.is_punct(k) and s.low[k] not in lx.CLAUSE_STARTERS:
        if s.low[k] in lx.ROBOT_WORDS or s.low[k] in ("it", "its"):
            return False
        if s.w[k].pos in ("NOUN", "PROPN") and s.low[k] not in lx.DETERMINERS:
            return s.lemma(k) not in lx.DURATION_UNITS and s.lemma(k) != "time"  # not "every time the robot ..."
        if s.w[k].pos not in ("DET", "ADJ", "NUM", "VERB", "PRON") and s.low[k] not in lx.NP_MODIFIERS:
            return False
        k += 1
    return False


def _noun_after(s: Sentence, ownset: set[int], r: int) -> str | None:
    """"give the robot a wide berth": a noun just after the robot names it."""
    for i in range(r + 1, min(r + 5, s.n)):
        if i not in ownset or s.is_punct(i):
            break
        if s.lemma(i) in lx.ROBOT_NOUNS:
            return lx.ROBOT_NOUNS[s.lemma(i)]
    return None


def _passive(s: Sentence, r: int) -> str | None:
    """"the robot is followed by ...": the doers react as the verb says."""
    if r + 3 < s.n and verb_lemma(s.low[r + 1]) == "be" and verb_lemma(s.low[r + 2]) in lx.ROBOT_VERBS \
            and s.low[r + 3] == "by":
        return lx.ROBOT_VERBS[verb_lemma(s.low[r + 2])]
    return None
