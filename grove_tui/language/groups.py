"""Pass 5: the groups of a prompt (language/model.py `GroupReading`), from its mentions and clauses.

Each group owns its words up to the next mention; a sentence's words before its first mention are
its scene, read for every group of that sentence, and a sentence with no people ("Evacuate the
pharmacy.") sets the scene of the sentences after it. A group whose own words state no action
shares the next group's ("ten patients and two nurses walk out"); everybody "except" someone takes
the verb between them; a led group follows its leader. Then per group: the intent, the places by
role (roles.py), the count settled (group_counts.py) and how sure the reader is of each field.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from grove_tui.language import lexicon as lx
from grove_tui.language.called_in import called_in_to
from grove_tui.language.carried_moves import moves_at
from grove_tui.language.robot_journey import journey_words
from grove_tui.language.clauses import Clause, Clauses
from grove_tui.language.exception_places import split_at_the_verb
from grove_tui.language.escorted import attribute_end, company_between, share_with_joined_movers
from grove_tui.language.fronted_stays import sentence_stay, stayed_spots
from grove_tui.language.later_stops import later_words
from grove_tui.language.group_counts import count_confidence, settle_count
from grove_tui.language.joiners import joined_intent
from grove_tui.language.leading_out import goes_out_by, leads_out
from grove_tui.language.list_items import own_participle
from grove_tui.language.mention import Mention
from grove_tui.language.mentions import Mentions
from grove_tui.language.model import Count, FieldConfidence, GroupReading
from grove_tui.language.place_phrases import Place, PlacePhrases, place_confidences
from grove_tui.language.place_served import served_fixture
from grove_tui.language.places import PlaceMatch
from grove_tui.language.robot import RobotClause, RobotClauses
from grove_tui.language.robot_crowds import met_people_words
from grove_tui.language.roles import Roles, assign_roles
from grove_tui.language.possessor_starts import kept_zone_place
from grove_tui.language.routine_reactions import routine_beside_reaction
from grove_tui.language.sentence import Sentence
from grove_tui.language.sequences import pronoun_sentences_end
from grove_tui.language.there_stays import stayed_there
from grove_tui.language.thing_modifiers import modifies_a_thing
from grove_tui.language.tokens import phrase_lemmas, verb_lemma
from grove_tui.language.wait_first import wait_before_queuing
from grove_tui.language.waits_until import waited_until
from grove_tui.language.possessive_owners import clause_owner
from grove_tui.language.zone_pairs import everyone_in_the_second_zone

_FOLLOWED_BY = ("followed", "trailed", "accompanied", "joined")
# Words after an existential "there" ("there are ten people"), which points at no place.
_EXISTENTIAL = frozenset("is are was were 's be will must may might seems seem has have".split())
_SENDING = (lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS) - {"inside"}  # sent with no verb of motion ("to the exit")


@dataclass
class _GroupWords:
    """One group's mention, its clause, its sentence's scene and its words."""

    mention: Mention
    clause: Clause
    scene: Clause | None
    span: tuple[int, int]


class Groups:
    def __init__(self, s: Sentence, places: PlacePhrases, mentions: Mentions, clauses: Clauses,
                 robot: RobotClauses) -> None:
        self.s = s
        self.places = places
        self.mentions = mentions
        self.clauses = clauses
        self.robot = robot
        self.notes: list[str] = []

    def read(self, mentions: list[Mention], robot_clauses: Sequence[RobotClause]) -> list[GroupReading]:
        s = self.s
        robot_tokens = {i for rc in robot_clauses for i in rc.tokens}
        spans = self._spans(mentions)
        # The robot's own clauses belong to no group: a group's places never come from them.
        excluded = {i for m in mentions for i in range(m.first, m.last + 1)} | robot_tokens | \
            {i for m in mentions if m.apposition for i in range(m.apposition[0], m.apposition[1] + 1)}
        people = self.mentions.people  # "their patient files are ...": the files are no verb of "file"
        excluded |= {k + 1 for k in range(s.n) if people.is_person_noun(k) and
                     modifies_a_thing(s, k, person_next=k + 1 < s.n and people.is_person_noun(k + 1))}
        scenes = self._scenes(mentions, spans, excluded, robot_tokens)
        clauses = [self.clauses.read(range(a, b), excluded, robot_after=self.robot.leads_into(a, b, robot_clauses),
                                     owner=clause_owner(s, mentions, k, (a, b))) for k, (a, b) in enumerate(spans)]
        for k, m in enumerate(mentions):
            if (zone_place := kept_zone_place(m, clauses[k].places)) is not None:  # "half the open office goes ...": where they are
                clauses[k].places.insert(0, zone_place)
            if m.robot_object is not None:
                clauses[k] = self._with_robot(m, robot_clauses, excluded)
        self._share(mentions, clauses)
        evacuation = self.clauses.evacuation()
        groups: list[GroupReading] = []
        for k, (m, clause) in enumerate(zip(mentions, clauses)):
            words = _GroupWords(m, clause, scenes.get(s.w[m.first].sentence), self._own_span(spans[k], m, robot_tokens))
            groups.append(self.group(words, evacuation, groups))
        # "everyone in the bar and the restaurant": everyone in each (after the others, whose relations count groups)
        groups += [g for k, m in enumerate(mentions) if (g := everyone_in_the_second_zone(
            s, m, clauses[k], groups[k], self._own_span(spans[k], m, robot_tokens), self.notes)) is not None]
        for k in range(len(mentions) - 1):
            if self._led_with_next(mentions, k) and groups[k].intent == "follow" and groups[k + 1].intent == "walk":
                groups[k + 1] = replace(groups[k + 1], intent="follow", follows=groups[k].follows)  # led as well
        for k, m in enumerate(mentions):
            g = groups[k]
            parent = int((g.relation or "").partition(":")[2]) if (g.relation or "").startswith("others_of:") else None
            if m.rest_of_parent and parent is not None and g.intent == "wait" and groups[parent].location and \
                    not (g.location or g.start or g.destination or g.via):
                # "two of them go to the kitchen and the others stay": where their group is
                groups[k] = replace(g, location=groups[parent].location)
        # "everyone has gone home (except ...)", "after everyone has left": people no longer there
        gone = [k for k, m in enumerate(mentions) if m.whole_zone and m.relation is None
                and self._already_gone(spans[k]) and len(mentions) > 1]
        if gone and not any(g.relation for g in groups):
            for k in gone:
                self.notes = [n for n in self.notes if not n.startswith(f"'{groups[k].who}': ")]
                self.notes.append(f"'{groups[k].who}' have already left: they are not in the scenario")
            groups = [g for k, g in enumerate(groups) if k not in gone]
        return groups

    # ---- words to groups -------------------------------------------------------------------------

    def _spans(self, mentions: list[Mention]) -> list[tuple[int, int]]:
        """Each group's words: from its mention (or a fronted phrase before it: "..., and from the
        office, eight people walk ...") to the next group's, within its sentence. A group named
        inside a part of it ("two of the six developers at their desks follow ...") owns its own
        phrase and the places after it, up to the verb the part does."""
        s = self.s
        regular = [k for k, m in enumerate(mentions) if not m.partitive]
        spans: list[tuple[int, int]] = [(m.first, self._partitive_end(m)) for m in mentions]
        for n, k in enumerate(regular):
            m = mentions[k]
            start = m.first if n == 0 else self.clauses.fronted_start(mentions[regular[n - 1]].last, m.first)
            end = self.clauses.fronted_start(m.last, mentions[regular[n + 1]].first) if n + 1 < len(regular) else s.n
            end = min(end, mentions[regular[n + 1]].first) if n + 1 < len(regular) else end
            sentence_end = next((i for i in range(m.last + 1, end) if s.w[i].sentence != s.w[m.first].sentence), end)
            spans[k] = (start, pronoun_sentences_end(s, sentence_end, end, {x.first for x in mentions}))
        return spans

    def _partitive_end(self, m: Mention) -> int:
        """The end of the words of a group named inside a part of it: its phrase and the place
        phrases after it, up to a verb, a punctuation mark or a clause word."""
        s = self.s
        j = m.last + 1
        if m.fronted:  # "Of the thirty people watching the fountain, five ...": up to the comma
            return next((x for x in range(j, s.n) if s.is_punct(x)), s.n)
        while j < s.n and not s.is_punct(j) and s.low[j] not in lx.CLAUSE_STARTERS and not (
                s.is_verb(j) or self.mentions.people.third_person_verb(j) or s.w[j].dep == "ROOT"
                or (verb_lemma(s.low[j]) in lx.INTENT_VERBS and not s.index.knows(s.lemma(j)))):
            j += 1
        return j

    def _scenes(self, mentions: list[Mention], spans: list[tuple[int, int]], excluded: set[int],
                robot_tokens: set[int]) -> dict[int, Clause]:
        """Sentence -> the clause of its words before its first group (and of a people-less one before it)."""
        s = self.s
        claimed = {i for a, b in spans for i in range(a, b)}
        negated = self.clauses.negated_tokens()
        preamble_of: dict[int, list[int]] = {}
        for i in range(s.n):
            if i not in claimed and i not in negated and i not in robot_tokens:
                preamble_of.setdefault(s.w[i].sentence, []).append(i)
        scenes: dict[int, Clause] = {}
        for sentence, toks in preamble_of.items():
            # a clause about animals or things ("two goldfish swim in a tank") names no place to refuse
            first = next((i for i in toks if s.w[i].pos not in ("DET", "NUM") and s.low[i] not in lx.NP_MODIFIERS),
                         None)
            self.places.quiet = first is not None and s.lemma(first) in lx.NON_PEOPLE
            scenes[sentence] = self.clauses.read(toks, excluded, scene=True)
            self.places.quiet = False
        with_people = {s.w[m.first].sentence for m in mentions}
        carried: Clause | None = None
        for sentence in range(s.w[-1].sentence + 1):
            own = scenes.get(sentence)
            if carried is not None:
                scenes[sentence] = carried if own is None else replace(
                    own, places=carried.places + own.places, evacuate=own.evacuate or carried.evacuate,
                    intent=own.intent or carried.intent)
            if sentence not in with_people and own is not None:
                carried = scenes[sentence]
        return scenes

    def _share(self, mentions: list[Mention], clauses: list[Clause]) -> None:
        """Clauses that take another group's verb: "ten patients and two nurses walk out", "everybody
        except the receptionist leaves", "a guide leads twelve tourists to the gate"."""
        s = self.s
        for k in range(len(clauses) - 2, -1, -1):
            between = range(mentions[k].last + 1, mentions[k + 1].first)
            in_places = {x for p in clauses[k].places for x in range(p.index, p.end)}
            described = attribute_end(s, self.mentions.people, mentions[k].last)  # "a boy with a broken arm and ..."
            described = max(described, (mentions[k].apposition or (0, 0))[1])  # "Year 2, 25 children, and their teacher"
            leftover = [x for x in between if x not in in_places and not s.is_punct(x) and x > described
                        and s.low[x] not in ("and", "as", "well", "plus", "with", "his", "her", "their", "our", "my", "each")]
            if clauses[k + 1].has_action and (company_between(s, mentions[k].last, mentions[k + 1].first) or (
                    described > mentions[k].last and not leftover and not clauses[k].places)):
                # "a defendant flanked by two guards walks to ...", "a girl with a sprained ankle and her
                # dad wait ...": the verb after both is the first's too, not the participle's
                clauses[k] = replace(clauses[k + 1], places=clauses[k + 1].places)
                continue
            # "Ten patients, three of them on crutches, wait ...": a part set off by commas says nothing of the verb
            aside = mentions[k + 1].relation == f"subset_of:{k}" and s.low[mentions[k + 1].first - 1] == ","
            if mentions[k].partitive or self._an_object(mentions[k]) or \
                    self.mentions.objects.led_by(mentions[k].first):
                continue  # "two of the six developers follow it": the six do not; "follow their guide": an object
            # the next clause's verb, or (a verb no list names, "and their nan bake in the kitchen") its places
            shared = clauses[k + 1].has_action or (bool(clauses[k + 1].places) and not clauses[k].places
                                                   and [s.low[x] for x in between][:1] == ["and"])
            if not clauses[k].has_action and shared and (mentions[k + 1].relation is None or aside) and \
                    not leftover and s.w[mentions[k].first].sentence == s.w[mentions[k + 1].first].sentence and \
                    not any(s.low[x] in (";", ".", ":") for x in between) and \
                    not (clauses[k].places and own_participle(s, mentions[k + 1])):  # "..., and a driver walking to"
                clauses[k] = replace(clauses[k + 1], places=clauses[k].places + clauses[k + 1].places)
        for k, m in enumerate(mentions):
            if k == 0 or m.exception_of != k - 1:
                continue
            in_places = {x for p in clauses[k - 1].places for x in range(p.index, p.end)}
            words_between = [x for x in range(mentions[k - 1].last + 1, m.first) if x not in in_places]
            if all(s.low[x] in lx.EXCEPT_WORDS | {"apart", "from", "for", "other", "than", ","} for x in words_between) \
                    and not clauses[k - 1].has_action and clauses[k].has_action:
                # "Everybody except the receptionist leaves": the verb is the everybody's; the
                # exception does not do it, so stays where it is
                clauses[k - 1], clauses[k] = split_at_the_verb(clauses[k - 1], clauses[k])
        for k, m in enumerate(mentions):
            if k > 0 and self.mentions.objects.followed(m.first) and not m.partitive and mentions[k - 1].last < m.first and \
                    clauses[k - 1].intent == "follow":
                # "the pupils follow their teacher to the hall": the route is the teacher's and theirs
                places = clauses[k - 1].places + clauses[k].places
                routed = any(p.prep in lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS | {"from", "obj:dest", "out"}
                             for p in places)
                clauses[k - 1] = replace(clauses[k - 1], places=places)
                clauses[k] = replace(clauses[k], places=places, has_action=True,
                                     intent=clauses[k].intent or ("walk" if routed else "wander"))
        for k, m in enumerate(mentions):
            if k > 0 and self.mentions.objects.sent_by(m.first) and mentions[k - 1].last == m.first - 2:
                # the sender stays where the people it sends were ("a guard sends the visitors out of the
                # café": the guard is in the café), or where they all are ("asks a nurse ... at reception")
                out, sent_to = self._sent_where(m, clauses[k])
                kept = [replace(p, prep="at") for p in clauses[k].places if p.match is not None and (
                    not (out or sent_to) or p.prep in ("from", "out", "obj:start", "at", "in", "on"))]
                clauses[k - 1] = replace(clauses[k - 1], places=clauses[k - 1].places + kept)
        for k in range(len(mentions) - 2, -1, -1):
            if self._led_with_next(mentions, k) and not clauses[k].has_action:
                # "leads two tourists and a child to the cafe", "walks Mrs Baxter and Mr Reid to ...":
                # both are taken along, by the way said after the last
                clauses[k] = replace(clauses[k + 1], places=clauses[k].places + clauses[k + 1].places)
        for k, m in enumerate(mentions):
            if k > 0 and self.mentions.objects.led_by(m.first) and mentions[k - 1].last >= m.first - 4:
                # the leader takes the route the led group is said to take; with no route ("a nurse
                # helps two kids in the kitchen") both stay where they are
                places = clauses[k - 1].places + clauses[k].places
                routed = any(p.prep in lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS | {"from", "obj:dest", "out"}
                             for p in places)
                around = any(p.prep in ("around", "about", "round") for p in places)  # "shows them around the hall"
                clauses[k - 1] = replace(clauses[k], places=places, has_action=True, intent=clauses[k].intent or (
                    "walk" if routed else "wander" if around else "wait"))
        share_with_joined_movers(s, mentions, clauses, self.mentions.objects.led_by)  # "a doctor and two nurses wheel ..."

    def _led_with_next(self, mentions: list[Mention], k: int) -> bool:
        """Whether mention k is taken along by a leader and the next is joined to it by "and" ("leads
        two tourists and a child"): the next is taken along too."""
        s = self.s
        return k + 1 < len(mentions) and self.mentions.objects.led_by(mentions[k].first) and \
            mentions[k + 1].relation is None and \
            [s.low[x] for x in range(mentions[k].last + 1, mentions[k + 1].first)] in (["and"], [",", "and"])

    def _an_object(self, m: Mention) -> bool:
        """Whether the people are someone's object ("follow their guide"), not the scene's own people
        an imperative sets ("Spawn 8 passengers at gate B1 and 8 at gate B2, all walking ...")."""
        s = self.s
        w = s.w[m.last]
        return w.dep in ("dobj", "dative") and verb_lemma(s.low[w.head]) not in lx.SCENE_VERBS

    def _sent_where(self, m: Mention, c: Clause) -> tuple[bool, bool]:
        """(sent out, sent somewhere) for people someone sends: "out of the café", "to the lobby"."""
        s = self.s
        out = any(s.low[i] in ("out", "away", "home") for i in range(m.last + 1, min(m.last + 3, s.n))) or \
            any(p.prep in ("out", "from", "obj:start") for p in c.places)
        sent_to = any(p.match is not None and (p.prep in lx.DESTINATION_PREPOSITIONS | lx.VIA_PREPOSITIONS
                                               or p.prep == "obj:dest") for p in c.places)
        return out, sent_to

    def _with_robot(self, m: Mention, robot_clauses: Sequence[RobotClause], excluded: set[int]) -> Clause:
        """The clause of people the robot escorts or follows: the robot's route after them is theirs
        too ("the robot escorts a lost child from baggage reclaim to the info desk"); the escorted
        follow the robot, the followed walk it."""
        rc = next((rc for rc in robot_clauses if m.first in rc.tokens), None)
        if rc is None:
            return Clause()
        after = [i for i in rc.tokens if i > m.last]
        after = met_people_words(self.s, after) if m.robot_object == "met" else after  # not the robot's way on
        clause = self.clauses.read(after, excluded - set(after) | journey_words(self.s))  # not "on its way to X"
        if m.robot_object == "led":
            return replace(clause, robot="follow", intent=clause.intent or "walk", has_action=True)
        if m.robot_object == "met":  # people the robot passes, serves or squeezes by stay where they are
            return replace(clause, intent=clause.intent or "wait", has_action=True)
        sends = any(p.prep in lx.DESTINATION_PREPOSITIONS or p.prep == "from" for p in clause.places)
        return replace(clause, intent=clause.intent or ("walk" if sends or not clause.places else "wander"), has_action=True)

    def _own_span(self, span: tuple[int, int], m: Mention, robot_tokens: set[int]) -> tuple[int, int]:
        """A group's span without a robot clause that ends it ("..., while a robot crosses the hall")."""
        s = self.s
        end = next((i for i in range(m.last + 1, span[1]) if i in robot_tokens), span[1])
        while end > m.last + 1 and (s.is_punct(end - 1) or s.low[end - 1] in lx.CLAUSE_STARTERS):
            end -= 1
        return span[0], end

    def _already_gone(self, span: tuple[int, int]) -> bool:
        """Whether a clause says its people have left already: a verb of leaving in the perfect
        ("has gone home", "have left")."""
        s = self.s
        return any(verb_lemma(s.low[i]) in lx.DEPARTURE_VERBS | {"go"} and s.w[i].tag == "VBN"
                   and s.low[i - 1] in ("has", "have", "had", "'s", "'ve", "already")
                   for i in range(max(span[0], 1), span[1]))

    # ---- one group -------------------------------------------------------------------------------

    def group(self, g: _GroupWords, evacuation: bool, earlier: list[GroupReading]) -> GroupReading:
        s = self.s
        m, c, scene, span = g.mention, g.clause, g.scene, g.span
        text = s.span(span[0], span[1] - 1) if span[1] > span[0] else m.who
        intent = self._default_intent(c, scene)
        if intent == "wait" and c.intent in (None, "wait") and not c.places and leads_out(s, m.last + 1):
            intent = "walk"  # "staff guide passengers out": the leaders go (out, in an evacuation)
        followed_by = m.first >= 2 and s.low[m.first - 1] == "by" and s.low[m.first - 2] in _FOLLOWED_BY and earlier
        if followed_by:
            # "..., followed by two assistants": they go where the group before goes, behind it
            leader = earlier[-1]
            intent = "follow" if s.low[m.first - 2] in ("followed", "trailed") else intent
            c = replace(c, follows=leader.who)
            if not c.places:
                return replace(leader, who=m.who, label=m.label, count=m.count or leader.count,
                               intent=intent if intent == "follow" else leader.intent, relation=None,
                               follows=leader.who if intent == "follow" else None, robot_interaction=None,
                               robot_reaction=None, together=m.together, text=text, confidence=())
        kind, _, parent = (m.relation or "").partition(":")
        if kind in ("subset_of", "more_of") and parent.isdigit() and int(parent) < len(earlier) and c.intent is None and \
                c.robot is None and not c.has_action and (kind == "more_of" or not c.places):
            # "..., two of them students": part of the group, doing as it does; "..., 4 more at lane 1":
            # more of it somewhere else, with no verb of their own, doing the same there
            intent = earlier[int(parent)].intent
        if kind == "more_of" and parent.isdigit() and int(parent) < len(earlier):  # "another 3 join them"
            intent = joined_intent(s, m, earlier[int(parent)].intent) or intent
        if self.mentions.objects.led_by(m.first) and earlier and c.robot is None and \
                earlier[-1].intent not in ("wait", "queue", "converse"):
            intent = "follow"  # "leads twelve tourists": they follow the one who leads
            c = replace(c, follows=earlier[-1].who)
        if self.mentions.objects.sent_by(m.first) and c.intent is None:
            # "a guard sends the visitors out of the café": they leave; "to the lobby": they go there
            out, sent_to = self._sent_where(m, c)
            intent = "evacuate" if out else "walk" if sent_to else intent
            c = replace(c, evacuate=c.evacuate or out)
        robot = c.robot if c.robot is not None else (scene.robot if scene is not None else None)
        robot = robot or c.unaimed  # "... and their grandparents shrink back": from the robot named before
        if m.collective in lx.QUEUE_COLLECTIVES and c.intent in (None, "wait") and intent in ("wait", "walk"):
            intent = "queue"  # "a queue of eight people forms at the ticket office", "a line of five waiting"
        if robot is not None:
            intent = "robot"  # also "Startled by the robot, a woman ...", "The robot is followed by ..."
        if (evacuation or c.evacuate or (scene is not None and scene.evacuate)) and intent in ("walk", "evacuate"):
            intent = "evacuate"
        # Someone who looks at the robot or blocks it, with no verb of motion, stays where they are.
        stationary = intent in lx.STATIONARY_INTENTS or (intent == "robot" and (
            c.intent in lx.STATIONARY_INTENTS or (c.intent is None and robot in ("look", "block", "avoid"))))
        roles = assign_roles(s.index, c.places, scene.places if scene is not None else [], verb=c.verb or "",
                             verb_index=c.verb_index, stationary=stationary, intent=intent,
                             then_at=later_words(s, *span), stayed_at=stayed_spots(s),
                             verbs_at=[(i, verb_lemma(s.low[i])) for i in range(*span) if not s.after_determiner(i)
                                       and verb_lemma(s.low[i]) in lx.DEPARTURE_VERBS | lx.ARRIVAL_VERBS | lx.BOARDING_VERBS],
                             moves_at=moves_at(s, span))
        self._settle_places(roles, intent, stationary, c.moves)
        self._inherit_places(m, roles, earlier, stationary)
        if not stayed_there(self.places, span, roles, stationary):
            self._there(span, roles, stationary)
        self._where_before(m, roles, stationary)
        if c.purpose and intent not in ("evacuate", "follow", "robot") and not (roles.destination or roles.location):
            self._purpose_place(c.purpose, span, roles, stationary)
        if stationary and (served := served_fixture(s.index, c.purpose, roles.location)) is not None:
            roles.location = served  # "a woman queuing to pay in the café": at its counter
        self._fixture_where_the_rest_were(m, roles, earlier, stationary)
        if stationary and roles.destination is None and (called := called_in_to(s, span)) is not None:
            roles.start, roles.destination = roles.start or roles.location, called  # "until the hygienist calls her in"
        start, destination, location, via = roles.start, roles.destination, roles.location, roles.via
        count = settle_count(s, m, span, start or location or destination, earlier, self.notes)
        wait = c.wait_seconds
        if wait is None and scene is not None and (intent in lx.STATIONARY_INTENTS or sentence_stay(s, m.first)):
            wait = scene.wait_seconds
        if intent == "wait" and (wait or waited_until(s, span)) and location and destination and start is None:
            start = location  # "waits at the kiosk for 10 minutes, then heads to the shop": it sets off from there
        first_wait = wait_before_queuing(s, span, c.verb_index) if wait and intent == "queue" else None
        if first_wait is not None and start is None:  # "queue after waiting in the food court for a minute": there first
            start = next((p.match.name for p in c.places if p.match and first_wait[0] < p.index < first_wait[1]), None)
        confidence = count_confidence(s, m, count) + place_confidences(
            {"start": start, "destination": destination, "location": location}, via, roles.read_from)
        routine, routine_confidence = routine_beside_reaction(
            s, c, scene, span, robot, {"destination": destination, "location": location}, via, wait)
        confidence += routine_confidence
        if robot is not None and c.robot is None:
            confidence.append(FieldConfidence("robot_interaction", 0.7, "read from the sentence's words about the "
                                                                      "robot, not from this group's own"))
        return GroupReading(
            who=m.who, label=m.label, count=count, intent=intent,
            robot_interaction=robot, robot_reaction=lx.ROBOT_REACTIONS.get(robot) if robot else None,
            start=start, destination=destination, location=location, via=tuple(via),
            purpose=c.purpose or (scene.purpose if scene is not None else None), wait_seconds=wait,
            waits_first=first_wait is not None,
            together=m.together or c.together or count.kind == "structured",
            pace=c.pace if c.pace != "normal" or scene is None else scene.pace, relation=m.relation,
            follows=c.follows, text=text, confidence=tuple(confidence),
            avoid=tuple(dict.fromkeys(c.avoid + (scene.avoid if scene is not None else []))), routine=routine)

    @staticmethod
    def _default_intent(c: Clause, scene: Clause | None) -> str:
        intent = c.intent or (scene.intent if scene is not None and scene.intent else None)
        if c.intent is None and c.has_action and c.robot is None and any(p.prep == "at" for p in c.places):
            return "wait"  # "..., and two crew check boarding cards at the gate desk": a job there, whatever the scene
        if intent is not None:
            return intent
        # No verb of action ("a cleaner is in the cafeteria"): people who are somewhere stay there;
        # only a place they are sent to ("... to the exit") makes them walk. A way taken ("push a bed
        # along the corridor") is walking too. So is being the doer of a passive whose subject is a
        # destination ("the desk is approached by").
        sends = any(p.prep in _SENDING or p.prep == "obj:dest"
                    for p in c.places) or (scene is not None and any(p.prep == "obj:dest" for p in scene.places))
        return "walk" if sends or c.robot or goes_out_by(c) else "wait"  # "stumble out of X", "storms out the door"

    @staticmethod
    def _settle_places(roles: Roles, intent: str, stationary: bool, moves: bool) -> None:
        if intent == "evacuate" and roles.start is None and roles.location is not None:
            roles.start, roles.location = roles.location, None
        if intent == "queue" and roles.location is None and roles.start is not None and roles.destination is None:
            # "a queue snakes back from the check-in counter": a queue stands where its head is
            roles.start, roles.location = None, roles.start
        if stationary and roles.location is None and roles.destination is not None and intent != "robot":
            # "walk to the cafeteria and wait there": they go there, then stay; without a verb of
            # motion ("queue to the desk") the place is only where they are.
            roles.location = roles.destination
            if not moves and not (intent == "wander" and roles.start is not None):  # "from the paint aisle over to lighting"
                roles.destination = None

    @staticmethod
    def _inherit_places(m: Mention, roles: Roles, earlier: list[GroupReading], stationary: bool) -> None:
        """A member of a group keeps its route unless told otherwise ("one of them stares at the
        robot"); an exception stays where the rest were ("... except three patients")."""
        unplaced = roles.start is None and roles.destination is None and roles.location is None
        kind, _, parent_index = (m.relation or "").partition(":")
        if kind == "subset_of" and parent_index.isdigit() and int(parent_index) < len(earlier):
            parent = earlier[int(parent_index)]
            if unplaced:
                roles.start, roles.destination = parent.start, parent.destination
                roles.location = parent.location if stationary else None
                roles.via = list(parent.via)
            elif roles.start is None and not stationary:
                roles.start = parent.start or parent.location  # "a few of them leave": from where the group is
        if m.exception_of is not None and m.exception_of < len(earlier) and unplaced:
            parent = earlier[m.exception_of]
            roles.location = parent.start or parent.location  # "... except three patients, who stay seated"

    def _there(self, span: tuple[int, int], roles: Roles, stationary: bool) -> None:
        """"there" for the place said last before it: "... and three more wait there" (where they are, or go, when
        the group names no place), "everyone in there is sent out", "they come back from there" (where they start)."""
        s = self.s
        at = next((x for x in range(span[0] + 1, span[1]) if s.low[x] == "there" and (
            x + 1 >= s.n or s.low[x + 1] not in _EXISTENTIAL or s.low[x - 1] in lx.PLACE_PREPOSITIONS)), None)
        if at is None:
            return
        before = [p for p in self.places.history if p.index < at and p.match is not None]
        if not before:
            # a place named in no place role before ("a pipe bursts above the dinosaur gallery and everyone in there")
            named = next((x for x in range(at - 1, 0, -1)
                          if s.low[x - 1] in lx.DETERMINERS and self.places.names_place(x)), None)
            place = self.places.phrase(named, "named", named, record_unknown=False) if named is not None else None
            before = [place] if place is not None and place.match is not None else []
        if not before:
            return
        prep = s.low[at - 1]
        if prep in ("from", "of") or (prep in ("in", "inside") and not stationary):
            role = "start"
        elif prep in ("in", "inside") or stationary:
            role = "location"
        else:
            role = "destination"
        if getattr(roles, role) is not None or (prep not in ("from", "of", "in", "inside") and
                                                (roles.start or roles.destination or roles.location)):
            return
        said = before[-1]
        name = said.match.name if said.match is not None else ""
        roles.read_from.setdefault(name, replace(said, score=0.8, alternatives=(),
                                                 reason=f"'there': {name}, said before"))
        setattr(roles, role, name)

    def _where_before(self, m: Mention, roles: Roles, stationary: bool) -> None:
        """"... to the boardroom, where five managers are in a meeting": people named after ", where"
        are at the place said just before it (or leave from it), when they name no place of their own."""
        s = self.s
        if m.first < 2 or s.low[m.first - 1] != "where" or s.low[m.first - 2] != "," or \
                roles.start or roles.destination or roles.location:
            return
        before = [p for p in self.places.history if p.index < m.first - 2 and p.match is not None]
        if not before:
            return
        said = before[-1]
        name = said.match.name if said.match is not None else ""
        roles.read_from.setdefault(name, replace(said, score=0.8, alternatives=(),
                                                 reason=f"', where': {name}, said before"))
        if stationary:
            roles.location = name
        else:
            roles.start = name

    def _purpose_place(self, purpose: str, span: tuple[int, int], roles: Roles, stationary: bool) -> None:
        """"walk from exam room 2 to get a cup of water": with no place to go to, the place the purpose
        is done at, by meaning, less sure than a place said."""
        meant = self.places.purpose_place(purpose)
        if meant is None:
            return
        match, score, reason, alternatives = meant
        roles.read_from[match.name] = Place("purpose", span[0], tuple(purpose.split()), match, span[0], score, reason,
                                            alternatives)
        self.places.named.append(match.name)  # a place of the scenario, as if said
        if stationary:
            roles.location = match.name
        else:
            roles.destination = match.name

    def _fixture_where_the_rest_were(self, m: Mention, roles: Roles, earlier: list[GroupReading],
                                     stationary: bool) -> None:
        """"Ten passengers go from the waiting room to platform 1, five others remain on the benches":
        the others stay where the group was, so a fixture named only by its kind is the one there."""
        kind, _, parent = (m.relation or "").partition(":")
        if kind != "others_of" or not stationary or roles.location is None or not parent.isdigit() or \
                int(parent) >= len(earlier):
            return
        index = self.s.index
        home = earlier[int(parent)].start or earlier[int(parent)].location
        here, there = index.entry(roles.location), index.entry(home) if home else None
        said = roles.read_from.get(roles.location)
        if here is None or there is None or said is None or here.kind != "entity" or here.zone == there.zone:
            return
        content = {t for t in phrase_lemmas(list(said.words)) if t not in lx.PLACE_MODIFIERS}
        same = [e for e in index.entries if e.kind == "entity" and e.zone == there.zone and content <= e.tokens]
        if same:  # the first of several alike ("the chairs": a row of them)
            e = same[0]
            roles.read_from[e.name] = replace(
                said, match=PlaceMatch(e.name, e.kind, e.zone, said.match.score if said.match else 1.0, False),
                score=0.7, alternatives=(roles.location,),
                reason=f"'{' '.join(said.words)}' of the others: {e.name}, in {e.zone} where the rest were")
            roles.location = e.name

    # ---- nobody named ----------------------------------------------------------------------------

    def evacuees_of_an_emptied_zone(self) -> GroupReading | None:
        """"The entire concourse is evacuated through the side entrance", "Evacuate the pharmacy.":
        a zone is emptied and nobody is named, so everyone in it leaves (a whole-zone group), marked
        as assumed."""
        s = self.s
        clause = self.clauses.read(range(s.n), set(), scene=True)
        for i in range(2, s.n):  # the subject of a passive evacuation: "<the X> is evacuated"
            aux = i - 2 if s.low[i - 1] in ("being", "been") else i - 1
            if verb_lemma(s.low[i]) == "evacuate" and s.w[i].tag == "VBN" and aux >= 1 and \
                    verb_lemma(s.low[aux]) in ("be", "get"):
                first = aux - 1
                while first > 0 and s.w[first - 1].pos in ("NOUN", "PROPN", "ADJ", "DET", "NUM") and \
                        not s.is_punct(first - 1):
                    first -= 1
                place = self.places.phrase(first, "obj:start", first, record_unknown=False)
                if place is not None:
                    clause.places.append(place)
        for place in self.places.emptied_zones(range(s.n)):
            clause.places.insert(0, place)
            clause.evacuate = True
            clause.intent = clause.intent or "evacuate"
        emptied = [p for p in clause.places if p.prep in ("obj:start", "from") and p.match is not None]
        if not emptied or not (clause.evacuate or clause.intent == "evacuate"):
            return None
        match = emptied[0].match
        assert match is not None
        mention = Mention(emptied[0].index, emptied[0].end - 1, f"everyone in {match.name}", "person", None,
                          whole_zone=True)
        group = self.group(_GroupWords(mention, clause, None, (0, s.n)), True, [])
        self.notes.append(f"no people are named: everyone in {match.zone} is evacuated")
        return replace(group, who="everyone", text=s.prompt, confidence=group.confidence + (
            FieldConfidence("group", 0.45, f"no people are named: everyone in {match.zone} is assumed"),))

    def unnamed(self, robot_tokens: set[int]) -> GroupReading:
        """The one group of a sentence that names no people ("a busy afternoon in the café", "the robot
        crosses the lobby"): the people the model is asked to fill in, with the places and the verb
        the sentence has for them, marked as assumed."""
        s = self.s
        clause = self.clauses.read(range(s.n), robot_tokens, scene=True)
        low, high = lx.BARE_PLURAL_RANGE
        mention = Mention(0, 0, "people", "person", Count("vague", s.choose(low, high, "unnamed"), low, high))
        if clause.intent is None:
            clause = replace(clause, intent="walk")  # no verb: the model's tree is kept as it writes it
        group = self.group(_GroupWords(mention, clause, None, (0, s.n)), self.clauses.evacuation(), [])
        self.notes.append("no people are named: one group of people is left to the model")
        count = group.count
        return replace(group, text=s.prompt, confidence=tuple(c for c in group.confidence if c.field != "count") + (
            FieldConfidence("group", 0.3, "no people are named: the model is asked to fill in who is there"),
            FieldConfidence("count", 0.5, f"no people are named: {count.value} guessed in {count.low}-{count.high}")))
