"""Pass 3, a part: what a clause says of leaving and following, and cues read over the whole sentence.

Split from `clauses.py` (the clause reader) so neither module grows past its size: people sent away ("are asked
to leave", "is sent out") and evacuation cues in a clause, whom a follower follows, and the sentence-wide cues
the clause reader and the group reader both ask (a hazard named, urgency, an evacuation anywhere, clauses about
nobody, a fronted phrase that opens a group's words). `Clauses` inherits these as `ClauseCues`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.escaped_people import escapes_a_person
from grove_tui.language.events import evacuating
from grove_tui.language.hazards import calm_alarm, cue as hazard_cue, in_a_place_name
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.a_smoke import a_smoke_had
from grove_tui.language.smoking_people import smoked_by_someone
from grove_tui.language.tokens import lemma, verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.clauses import Clause


class ClauseCues:
    """Leaving, following and sentence-wide cues of one sentence (module doc)."""

    s: Sentence
    people: People

    def _sent_away(self, i: int) -> int | None:
        """The word after "to leave", "out", "away" or "home" when the word at i is a passive verb
        by which others make people leave ("is sent out", "are asked to leave", "are ushered away")."""
        s = self.s
        if i < 1 or s.w[i].tag != "VBN" or s.verb(i) not in lx.SENDING_VERBS:
            return None
        aux = i - 1
        while aux > 0 and s.w[aux].pos == "ADV":
            aux -= 1
        if verb_lemma(s.low[aux]) not in ("be", "get") and s.low[aux] not in ("being", "been"):
            return None
        k = s.skip(i + 1, {"quickly", "calmly", "immediately", "swiftly", "gently", "all"})
        if k + 1 < s.n and s.verb(i) in ("call", "summon") and s.low[k] == "out" and s.low[k + 1] in ("to", "into", "onto"):
            return None  # "is called out to the test car park": summoned there by name, no evacuation
        if k < s.n and s.low[k] in ("out", "away", "home", "outside"):
            return k + 1
        if k + 1 < s.n and s.low[k] == "to" and s.verb(k + 1) in lx.DEPARTURE_VERBS:
            return k + 2
        if k + 2 < s.n and s.low[k] == "to" and s.verb(k + 1) in ("get", "go", "head", "move") and \
                s.low[k + 2] in ("out", "away", "home", "outside"):
            return k + 3  # "are told to get out", not "are told to go to the boardroom"
        return None

    def _evacuation(self, c: Clause, own: Sequence[int]) -> None:
        s = self.s
        sent = next((i for i in own if self._sent_away(i) is not None), None)
        if sent is not None:  # "everyone in there is sent out", "the guests are asked to leave"
            c.evacuate = True
            if c.intent is None or c.intent in lx.STATIONARY_INTENTS or c.intent == "walk":
                c.intent, c.verb, c.verb_index, c.moves, c.has_action = "evacuate", s.verb(sent), sent, True, True
        if any(verb_lemma(s.low[i]) in ("evacuate", "flee", "escape") and not escapes_a_person(s, i)
               or s.low[i] in ("evacuation",) for i in own):
            c.evacuate = True
        for i in own:
            pair = (s.verb(i), s.low[i + 1] if i + 1 < s.n else "")
            if pair in lx.EVACUATION_PHRASES + lx.URGENT_EXIT_PHRASES and evacuating(s, i, pair, self.urgent(own)):
                c.evacuate = True  # "empty out through the back door", "must get out via the east exit"
                if c.intent is None or c.intent in lx.STATIONARY_INTENTS:
                    c.intent, c.verb, c.verb_index, c.moves, c.has_action = "evacuate", pair[0], i, True, True
                break
        if any(s.verb(i) in lx.DEPARTURE_VERBS for i in own) and any(s.low[i] in lx.IMMEDIACY_WORDS for i in own):
            c.evacuate = True  # "everyone must leave immediately through the customs exit"
        for i in own:
            if s.verb(i) in lx.PERCEPTION_VERBS and any(
                    s.low[k] in lx.EVACUATION_CUES or self.hazard(k) for k in range(i + 1, min(i + 5, s.n))
                    if not s.is_punct(k)):
                # "hear the alarm", "smell smoke": people who notice a hazard and do nothing else leave
                c.evacuate = True
                if c.intent is None or c.intent in lx.STATIONARY_INTENTS and c.verb_index == i:
                    c.intent, c.verb, c.verb_index, c.moves, c.has_action = "evacuate", s.verb(i), i, True, True
                break

    def _followed(self, c: Clause) -> None:
        """Whom a follower follows: the person after the verb ("follow the charge nurse"), the group
        before ("a porter follows close behind"), or nobody ("follow the signs": walking)."""
        s = self.s
        assert c.verb_index is not None
        k0 = s.skip(c.verb_index + 1, {"close", "closely", "right", "just", "along"})
        k1 = s.skip(k0, {"behind", "after"})
        her = k1 < s.n and s.low[k1] == "her" and (k1 + 1 >= s.n or s.w[k1 + 1].pos not in ("NOUN", "ADJ", "PROPN"))
        k = k1 if her else s.skip(k1, lx.DETERMINERS)  # "follows her", not "follows her mother"
        if k + 1 < s.n and s.w[k].pos in ("NOUN", "ADJ", "PROPN") and self.people.is_person_noun(k + 1):
            k += 1  # "follow the charge nurse"
        if k < s.n and (self.people.is_person_noun(k) or s.low[k] in ("them", "him", "her", "others", "leader",
                                                                      "guide", "us", "everyone")):
            c.follows = s.span(c.verb_index + 1, k)
        elif k1 > k0 or k0 >= s.n or s.is_punct(k0) or s.low[k0] in lx.CLAUSE_STARTERS:
            c.follows = "the group before"
        else:
            c.intent = "walk"

    # ---- sentence-wide cues ----------------------------------------------------------------------

    def hazard(self, i: int) -> bool:
        """A hazard named on its own ("Fire!", "smoke in the kitchen"), not a thing's name ("the fire exit")."""
        s = self.s
        if hazard_cue(s, i):  # "a smell of burning", "the alarm goes off" (hazards.py)
            return True
        if s.lemma(i) not in lx.HAZARD_NOUNS or s.w[i].pos not in ("NOUN", "PROPN") or smoked_by_someone(s, i) \
                or a_smoke_had(s, i):
            return False
        return s.w[i].dep != "compound" and not (i + 1 < s.n and s.w[i + 1].pos == "NOUN")

    def urgent(self, own: Sequence[int]) -> bool:
        """Whether the clause says leaving cannot wait ("must get out", "get out now") or the prompt
        names a hazard ("Fire! ... get out")."""
        return any(self.s.low[i] in lx.URGENCY_WORDS for i in own) or any(self.hazard(i) for i in range(self.s.n))

    def evacuation(self) -> bool:
        """Whether the prompt speaks of an evacuation anywhere (a cue word or a hazard)."""
        s = self.s
        return any((s.low[i] in lx.EVACUATION_CUES or verb_lemma(s.low[i]) in lx.EVACUATION_CUES) and not
                   calm_alarm(s, i) and not in_a_place_name(s, i) and not escapes_a_person(s, i) or self.hazard(i)
                   for i in range(s.n))  # "the drill yard"; "escapes from his mum"

    def negated_tokens(self) -> set[int]:
        """The words of a clause about nobody ("No one uses the main corridor; ...", "No passengers
        are waiting on platform 1, but ..."): its places are where nobody is, so they set no scene.
        Not when the clause names an exception ("nobody is in the kitchen except the cleaner")."""
        s = self.s
        out: set[int] = set()
        for i in range(s.n):
            nobody = s.low[i] in lx.NOBODY_WORDS or (s.low[i] == "no" and i + 1 < s.n and (
                s.low[i + 1] in ("one", "body") or self.people.is_person_noun(i + 1)))
            if not nobody:
                continue
            end = i + 1
            while end < s.n and s.w[end].sentence == s.w[i].sentence and s.low[end] not in (";", ":") \
                    and not (s.low[end] in lx.CLAUSE_STARTERS | {"instead"} and end > i + 2):
                end += 1
            clause = range(i, end)
            if any(s.low[k] in lx.EXCEPT_WORDS or s.low[k] in ("apart", "only", "than") for k in clause) or \
                    (end < s.n and s.low[end] in lx.EXCEPT_WORDS - {"but"}):  # "..., but a cleaner"
                continue
            out.update(clause)
        return out

    def fronted_start(self, previous_last: int, first: int) -> int:
        """Where the group mentioned at `first` starts owning words: before it, a fronted phrase with
        no verb, opened by a preposition and closed by a comma; else the mention itself."""
        s = self.s
        b = first - 1
        if b <= previous_last or s.low[b] != ",":
            return first
        j = b - 1
        while j > previous_last and (not s.is_punct(j) or s.hyphen_inside(j)) and s.low[j] not in lx.CLAUSE_STARTERS:
            j -= 1
        fronted = range(j + 1, b)
        if not fronted or s.low[j + 1] not in lx.PLACE_PREPOSITIONS | {"for", "during", "from"}:
            return first
        if j == previous_last:
            return first  # "8 people in line at the desk, 2 more at ...": the phrase is the group's before
        if any(s.w[x].pos == "VERB" and verb_lemma(s.low[x]) in lx.INTENT_VERBS
               and not s.index.knows(lemma(s.low[x])) for x in fronted):
            return first  # a clause of its own, not a fronted phrase ("sitting" in "the sitting room" is a name)
        return j + 1
