"""The reading of a prompt: which groups of people, how many, doing what, where, and what the robot
itself is asked to do (the contract's types are in language/model.py).

    reading = read_prompt("Two families of three walk together to the cafeteria, while a few others "
                          "stroll around the lobby", world, seed=0)
    reading.groups[0].count   # Count(kind="structured", value=6, low=6, high=6, parties=2, party_size=3)
    reading.groups[1].intent  # "wander", location "entrance_lobby", relation "others_of:0"

Pure and deterministic. The prompt is read once, in small passes, each a module of its own:

0. text (`text.py`, `spelling.py`): Unicode folded, emoji dropped, chat abbreviations written out;
   misspelt place words put right against the world's names (each correction reported).
1. tokens and parse (`sentence.py`): spaCy words, tags and dependencies, corrected by the lexicon.
2. people (`people.py`, `counts.py`, `mentions.py`): who is a person and each group's mention with
   its count (numbers, approximations, ranges, vague words, collectives, "all ... some thirty of them").
3. clauses (`clauses.py`, `reactions.py`, `robot.py`): verbs and intents, the robot interaction of
   each group, the robot's own clauses, purposes and their places, durations, pace.
4. places (`places.py`, `place_phrases.py`): each place phrase matched against the world's one place
   index, by words and, when words do not decide, by meaning, with how sure the match is.
5. groups (`groups.py`, `roles.py`, `group_counts.py`): places by role, counts settled, relations,
   and the confidence of every field.

No model is asked, except the small sentence-embedding model for places words do not decide.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.awaited_people import awaited_at_the_place
from grove_tui.language.activity_times import without_activity_times
from grove_tui.language.asides import without_asides
from grove_tui.language.awaited_events import with_until, without_awaited_things
from grove_tui.language.awaited_comers import without_awaited_comers
from grove_tui.language.second_names import without_second_names
from grove_tui.language.chat_spelling import chat_to
from grove_tui.language.scale_and_figures import with_scale_and_figures
from grove_tui.language.fronted_lead_times import without_fronted_lead_times
from grove_tui.language.homophone_slips import with_homophone_slips
from grove_tui.language.chat_waits import as_chat_wait
from grove_tui.language.chat_requests import as_chat_request
from grove_tui.language.clock_fronts import with_clock_commas
from grove_tui.language.crammed_into import with_crammed_in
from grove_tui.language.hyphened_waits import with_stays_as_lengths
from grove_tui.language.fronted_time_commas import with_fronted_phrase_commas, with_fronted_time_commas
from grove_tui.language.function_word_people import with_function_word_people
from grove_tui.language.fronted_place_commas import with_fronted_place_commas
from grove_tui.language.urged_on_by import without_urging_asides
from grove_tui.language.worn_clothes import without_worn_clothes
from grove_tui.language.worn_place_words import without_worn_place_words
from grove_tui.language.ordinal_others import with_ordinal_others
from grove_tui.language.watched_people import without_watched
from grove_tui.language.vehicle_loads import with_vehicle_loads
from grove_tui.language.chat_articles import with_chat_articles
from grove_tui.language.chat_ing_items import with_chat_ing_items
from grove_tui.language.chat_place_tallies import with_chat_place_tallies
from grove_tui.language.described_things import without_described_things
from grove_tui.language.named_events import without_named_events
from grove_tui.language.work_imperatives import as_workers
from grove_tui.language.got_out import as_got_out
from grove_tui.language.into_waits import with_stays_into
from grove_tui.language.left_with import as_dropped_off
from grove_tui.language.causative_orders import as_ordered_clauses
from grove_tui.language.chat_pairs import with_chat_pairs
from grove_tui.language.scale_counts import with_scale_figures
from grove_tui.language.counted_collectives import with_counted_collectives
from grove_tui.language.queue_lengths import with_queue_lengths
from grove_tui.language.has_a_queue import with_queues_had
from grove_tui.language.places_having_people import with_places_having_people
from grove_tui.language.work_progressives import as_simple_work
from grove_tui.language.fronted_movers import with_fronted_movers
from grove_tui.language.fronted_ing_times import with_fronted_ing_times
from grove_tui.language.mid_events import with_mid_events
from grove_tui.language.owned_partitives import without_partitive_owners
from grove_tui.language.past_drills import without_past_drills
from grove_tui.language.post_verbs import as_work_at_posts
from grove_tui.language.fronted_feeling_waits import without_feelings_before_stays
from grove_tui.language.fronted_feelings import with_small_fronted_feelings
from grove_tui.language.waiting_then_sent import without_staying_before_passive_moves
from grove_tui.language.fronted_held import with_small_held_fronts
from grove_tui.language.clauses import Clauses
from grove_tui.language.cleared_checkpoints import as_passed_checkpoints
from grove_tui.language.place_part_counts import with_plain_parts
from grove_tui.language.robot_aliases import with_robot_aliases
from grove_tui.language.robot_place_names import without_robot_words_in_place_names
from grove_tui.language.robot_headings import as_robot_order
from grove_tui.language.converging import as_heading
from grove_tui.language.shut_in import as_going_in
from grove_tui.language.gone_and_done import as_gone_to
from grove_tui.language.each_person import taken_by_each
from grove_tui.language.each_place import spread_over_each
from grove_tui.language.event_causes import without_causers
from grove_tui.language.event_appositions import with_people_after_an_event
from grove_tui.language.groups import Groups
from grove_tui.language.scene_closers import without_closers
from grove_tui.language.couples import joined_couples
from grove_tui.language.kin_lists import kin_families
from grove_tui.language.leaving import as_verbs
from grove_tui.language.singular_verbs import as_singular_verbs
from grove_tui.language.age_nouns import with_age_heads
from grove_tui.language.age_bands import with_age_bands
from grove_tui.language.hyphened_people import with_whole_person_words
from grove_tui.language.mention import Mention
from grove_tui.language.mentions import Mentions
from grove_tui.language.named_roles import without_apposed_roles
from grove_tui.language.apposed_members import without_apposed_members
from grove_tui.language.apposed_parts import with_apposed_parts
from grove_tui.language.collective_roles import with_collective_roles
from grove_tui.language.counted_loads import without_counted_loads
from grove_tui.language.fronted_size_parts import with_fronted_size_parts
from grove_tui.language.bare_fronted_wholes import with_fronted_whole_articles
from grove_tui.language.little_ones import with_little_ones
from grove_tui.language.described_youngest import with_described_youngest
from grove_tui.language.fronted_subsets import with_fronted_subsets
from grove_tui.language.setup_orders import as_setup_orders
from grove_tui.language.included_members import with_included_members
from grove_tui.language.joined_kinds import with_joined_kinds
from grove_tui.language.counted_lists import with_counted_lists
from grove_tui.language.named_lists import with_named_lists
from grove_tui.language.role_lists import with_role_lists
from grove_tui.language.treated_everyone import without_treated_everyone
from grove_tui.language.wheeled_states import without_wheeled_states
from grove_tui.language.setup_doings import with_setup_doings_after
from grove_tui.language.rough_scales import with_rough_scales
from grove_tui.language.comma_names import without_name_commas
from grove_tui.language.counted_outings import with_counted_outings
from grove_tui.language.awaited_arrivals import without_awaited_arrivals
from grove_tui.language.finished_acts import without_finished_acts
from grove_tui.language.relative_pasts import without_relative_pasts
from grove_tui.language.signal_fronts import without_signal_fronts
from grove_tui.language.side_places import with_side_places
from grove_tui.language.stopping_by import as_stopped_by
from grove_tui.language.left_for_events import with_events_left_for
from grove_tui.language.closed_behind import as_left_behind_door
from grove_tui.language.seen_to_by import without_seen_to_by
from grove_tui.language.glued_to import as_kept_at
from grove_tui.language.lent_arms import as_arm_escort
from grove_tui.language.linked_arms import without_held_hands
from grove_tui.language.met_then_moved import as_taken_along
from grove_tui.language.carried_babies import without_carried_babies
from grove_tui.language.people_named_things import without_people_named_things
from grove_tui.language.named_workplaces import without_named_workplaces
from grove_tui.language.placed_with import as_placing_clause
from grove_tui.language.model import (COUNT_KINDS, INTENTS, ROBOT_INTERACTIONS, Count, FieldConfidence,
                                      GroupReading, PromptReading, RobotReading, effective_counts)
from grove_tui.language.parser import parse
from grove_tui.language.role_leads import with_role_leads
from grove_tui.language.chat_headings import without_vehicle_headings
from grove_tui.language.passive_escort import to_active
from grove_tui.language.passive_order import in_said_order
from grove_tui.language.passive_late_agents import late_agents_to_active
from grove_tui.language.gone_and_done import going_to_get
from grove_tui.language.followed_as import followed_route_first
from grove_tui.language.swamped_places import crowded_places_to_active
from grove_tui.language.perceivers import without_perceivers
from grove_tui.language.people import People
from grove_tui.language.place_phrases import PlacePhrases
from grove_tui.language.places import place_index
from grove_tui.language.robot import RobotClause, RobotClauses
from grove_tui.language.robot_deliveries import as_delivery
from grove_tui.language.robot_crowds import via_the_people_passed
from grove_tui.language.robot_led import led_by_robot
from grove_tui.language.guided_route import route_from_the_guided, said_last_before
from grove_tui.language.robot_bound import people_passed_stay
from grove_tui.language.robot_followers import with_robot_followers
from grove_tui.language.robot_in_tow import with_robot_in_tow
from grove_tui.language.passing_moment import with_passing_moments
from grove_tui.language.owners_stay import owners_stay_put
from grove_tui.language.whole_of_zone import whole_of_zone
from grove_tui.language.poured_through import poured_through
from grove_tui.language.room_numbers import without_number_words
from grove_tui.language.sentence import Sentence
from grove_tui.language.spelling import correct_places
from grove_tui.language.refused_corrections import refused_real_words
from grove_tui.language.outing_parties import as_outing_parties
from grove_tui.language.split_wholes import parts_of_a_split_whole
from grove_tui.language.text import normalise
from grove_tui.language.listed_adjectives import without_adjective_commas
from grove_tui.language.prefixed_verbs import with_joined_prefixes
from grove_tui.language.contracted_is import with_full_is
from grove_tui.language.they_all import all_go_on
from grove_tui.language.talk_idioms import with_talk_idioms
from grove_tui.language.got_up import got_up_and_went
from grove_tui.language.clause_passes import with_clause_passes
from grove_tui.language.reduced_passives import reduced_to_active
from grove_tui.language.counted_chat_waits import as_counted_chat_wait
from grove_tui.language.listed_chat_waits import as_listed_chat_wait
from grove_tui.language.chat_meetings import with_chat_meetings
from grove_tui.language.chat_fragments import chat_fragments, with_counted_from
from grove_tui.language.chat_school_years import with_school_year_pupils
from grove_tui.language.chat_joined_ing import with_joined_ing_items
from grove_tui.language.fronted_passives import with_fronted_passives_after
from grove_tui.language.scattered_counts import with_scattered_counts
from grove_tui.language.unnamed_counts import counted_unnamed
from grove_tui.language.tailed_counts import with_counts_before
from grove_tui.language.robot_guided_people import following_the_robot
from grove_tui.language.waited_escorts import with_escorts_after_a_wait
from grove_tui.language.misspelt_verbs import with_misspelt_verbs
from grove_tui.world.model import World

NO_WORDS = ("the prompt has no words to read (only symbols or emoji): describe in English who is there and what "
            "they do, e.g. 'ten patients queue at the pharmacy'")
NOBODY = "the sentence says nobody is there: a scenario needs at least one person; say who is there and what they do"

__all__ = ["COUNT_KINDS", "INTENTS", "ROBOT_INTERACTIONS", "Count", "FieldConfidence", "GroupReading",
           "PromptReading", "RobotReading", "effective_counts", "read_prompt"]


def read_prompt(prompt: str, world: World, *, seed: int = 0) -> PromptReading:
    """The groups of people a prompt describes and what it asks of the robot, in the world's own
    place names (see the module doc)."""
    typed = " ".join((prompt or "").split())
    text = without_fronted_lead_times(normalise(with_chat_place_tallies(without_vehicle_headings(typed), place_index(world))))  # "conference rm x3": 3 people in it  # "Ten minutes ahead of the late shift, ...": when, no ten of a shift
    if not text:
        return PromptReading(typed, (), problems=(NO_WORDS,) if typed else ())
    index = place_index(world)
    text = going_to_get(with_joined_prefixes(without_adjective_commas(without_name_commas(as_chat_request(text), index))))  # "noodle bar q is like 8 deep rn, can u add that + a busker": the order asked for; "a pale, woozy student": one person; "to births, deaths and marriages": one name; "re-cable": one verb
    text = with_fronted_passives_after(with_full_is(text))  # "Dad's snoozing on the couch": Dad is snoozing, one person; "While X is restocked by a porter, ...": "X is restocked by a porter while ..."
    text = as_robot_order(with_robot_aliases(without_robot_words_in_place_names(text, index)))  # "to the robot lab": the robotics lab, no robot; "... sidesteps the machine": the robot; "Robot job: take X to Y": "Have the robot take X to Y"
    text = with_robot_followers(with_robot_in_tow(text))  # "With a nurse in tow, the robot ...", "Followed by a nurse, the robot ...": the nurse follows the robot
    text = as_chat_wait(with_school_year_pupils(text))  # "12 yr7s in X": "12 year 7 pupils in X"; "guard @ cashpoint 2 mins then off to X": a wait, then the walk
    text = with_scattered_counts(with_joined_ing_items(with_counted_from(chat_fragments(as_listed_chat_wait(with_chat_meetings(text))))))  # "boardroom mtg 9 ppl": 9 people meeting in it; "the two from the chess club": two people; "3 from sales gossiping", "... @ desk, 10 mins then out"
    text = as_counted_chat_wait(text)  # "3 ppl lookin at cacti 2 mins then off to tills": the same, counted
    text = with_misspelt_verbs(text, index)  # "infants from the school trapse across": "traipse", no "school trapse"
    text = with_homophone_slips(chat_to(text, index), index)  # "form there desks too the kitchen": from their desks to it; "from the staff office 2 bay 4": chat's "to" before a place
    text = without_number_words(text, index)  # "to number 107": to the room 107
    text = with_chat_ing_items(with_chat_articles(with_chat_pairs(text)))  # "couple at the suv, sales guy nr the stand": a couple, a sales guy
    text = as_dropped_off(as_ordered_clauses(as_got_out(as_workers(text))), index)  # "Have Janet man the front desk": Janet mans it; "get the parents in X out by Y"; "leaves a box with the desk": drops it off there
    text = with_setup_doings_after(as_setup_orders(text))  # "Have one porter folding sheets in X and ...": "one porter in X folding sheets"; "Set up a class of fifteen in X and two helpers in Y": "Have ..."
    text = with_counted_outings(as_outing_parties(text))  # "a stag do of twelve": a stag party of twelve; "twenty on the tour": twenty people on it
    text = with_counted_collectives(with_scale_figures(with_joined_kinds(with_counted_lists(with_role_lists(with_named_lists(with_rough_scales(with_scale_and_figures(text))))))))  # "the cast of 14", "Six of Blue Watch"; "the hundred-odd travellers": about 100; "ten men and women": ten people
    text = with_places_having_people(with_queues_had(with_queue_lengths(text)), index)  # "the line at X is forty strong", "X has a line of 3": they queue at X; "the academy has six trainees in induction": six are in it
    text = as_work_at_posts(as_simple_work(text))  # "Janet is manning the desk", "Maria runs the issue desk": she mans it
    text = with_fronted_movers(text)  # "Pushing her dad's wheelchair, a woman brings him ...": her dad goes too
    text = without_staying_before_passive_moves(text)  # "the travellers waiting there are sent up X": "the travellers there are sent up X"
    text = without_wheeled_states(without_treated_everyone(text))  # "wheels a snoozing baby": a baby; "to make everyone a brew": a brew, no crowd of everyone
    text = with_crammed_in(text)  # "nine porters are crammed into the lounge": they are in it
    text = with_talk_idioms(text)  # "orderlies chinwag by the lifts": they chat there
    text = with_small_held_fronts(text)  # "Mug in hand, a keeper walks ...": no one called Mug
    text = without_feelings_before_stays(text)  # "Fed up after an hour in X, a man ...": "After an hour in X, ..."
    text = with_small_fronted_feelings(text)  # "Fascinated, a little lad ...": no one called Fascinated
    text = without_partitive_owners(text)  # "a trio of the accused's brothers": a trio of brothers
    text = with_ordinal_others(text)  # "two guards at X and a third at Y": another guard
    text = with_until(text)  # "waits till the coach comes": a time, not the shop's till
    text = with_fronted_phrase_commas(with_fronted_time_commas(with_clock_commas(with_stays_as_lengths(with_stays_into(text)))))  # "At nine Tom Hale walks": a time, not nine of him; "After dinner a couple stroll", "During the changeover a bellboy ...": a comma after the time; "after a 15-minute wait"
    text = with_fronted_place_commas(without_urging_asides(without_worn_place_words(without_worn_clothes(text, index), index)))  # "By the kiosks a toddler gapes": one toddler
    text = with_age_heads(with_age_bands(with_function_word_people(with_whole_person_words(text))))  # "his 4-year-old walks": "his 4-year-old child walks"; "eighteen over-fifties": "eighteen older people"
    text = with_side_places(text, index)  # "2 physios poolside": by the pool
    text = without_named_workplaces(text, index)  # "Sam from security walks": "Sam walks"
    text = without_people_named_things(without_carried_babies(text), index)  # "mums with babies in slings wait": "mums wait"; "the parent-and-baby session": "the session"
    text = as_taken_along(without_held_hands(text))  # "links arms with Gramps and walks him": walks Gramps; "takes Edith arm in arm out of X": "takes Edith out of X"
    text = without_past_drills(with_fronted_ing_times(as_arm_escort(with_mid_events(text))))  # "gives Al her arm to X": walks Al; "after a drill": over
    text = with_plain_parts(as_passed_checkpoints(text))  # "clears customs and heads": passes through; "one end of the bar": the end of it
    text = with_role_leads(with_collective_roles(text))  # "the night shift boss": "the night-shift boss", one person
    text = without_counted_loads(text)  # "a driver with two crates of milk waits": "a driver waits"
    text = with_little_ones(with_described_youngest(text))  # "leads the little one": "the little child"
    text = with_fronted_size_parts(with_fronted_whole_articles(text))  # "Of nine potters ..., a trio": "Of the nine ..."; "Of the twelve in X, a trio are called": "three of them"
    text = with_fronted_subsets(without_signal_fronts(without_finished_acts(without_awaited_arrivals(text))))  # "Before the boss gets in, ...", "When the teacher claps, ...": left out; "Of the nine sat in X, a pair get up": "Of the nine people ..., a pair of them"
    text = with_apposed_parts(without_apposed_members(with_included_members(text)))  # "Kayleigh, one of the lifeguards, leaves": "Kayleigh leaves"; "a family of seven, grandparents included,": "including grandparents"
    text = without_apposed_roles(text)  # "Pete the butcher nips across": "Pete nips across"
    text = without_relative_pasts(text)  # "kids who've sat through the film pile out of X": "kids pile out of X"
    text = as_left_behind_door(text)  # "pulls her office door to and ...": leaves her office
    text = as_kept_at(without_seen_to_by(with_events_left_for(as_stopped_by(text, index), index)), index)  # "abandon their desks for the briefing at the whiteboard": they go there; "to be seen by the medics at X": to X; "glued to the wallboard": at it  # "stops by the toy store to buy a gift", "pops by the pharmacy": goes to it
    text = as_gone_to(as_going_in(as_heading(with_vehicle_loads(text))))  # "go and flop in X": "go to X"; "locks himself in the gents": "heads into the gents"  # "a minibus of pensioners": a minibusload; "a coachload descends on the café": "heads to the café"
    text = as_placing_clause(text)
    text = as_delivery(text)  # "the robot carries soup out to Gran, who is knitting on the terrace": to the terrace, Gran there # "the robot brings Nan's pills to the settee where she's sitting": Nan waits there  # "With Nan at the stove, the twins ...": "Nan is at the stove, and ..."
    words = as_singular_verbs(as_verbs(parse(text)))  # "the carers in the lounge leg it": a verb, not "lounge leg"
    active = to_active(text, words)
    if active is None:
        active = crowded_places_to_active(text, words) or followed_route_first(text, words) or \
            reduced_to_active(text, words)  # "X is swamped by people drifting over from Y"; "a baby carried by her dad to X"
    late = active is None and (active := late_agents_to_active(text, words)) is not None  # "is wheeled up to ward B by a porter": the taker first
    # "a pupil is taken to ... by the nurse": "the nurse takes a pupil to ..."
    if active is not None:
        text, words = active, as_singular_verbs(as_verbs(parse(active)))
    corrected, corrections = correct_places(text, words, index)
    reading = None
    if corrections:
        # The corrected sentence is parsed again: a misspelt word is often mis-tagged too ("the kitchn").
        as_written, written_words = text, words
        text, words = corrected, as_singular_verbs(as_verbs(parse(corrected)))
        reading = _read(Sentence(text, words, index, int(seed)))
        if kept := refused_real_words(written_words, index, reading.unknown_places):  # "car park" is no "cart park"
            corrected, corrections = correct_places(as_written, written_words, index, skip=kept)
            text, words = corrected, as_singular_verbs(as_verbs(parse(corrected))) if corrections else written_words
            reading = _read(Sentence(text, words, index, int(seed)))
    reading = reading or _read(Sentence(text, words, index, int(seed)))
    if active is not None and not late:  # the taken before their taker, as the sentence says them
        reading = replace(reading, groups=in_said_order(reading.groups, typed))
    reading = with_clause_passes(typed, index, reading)  # "swerves her buggy wide of the robot", "late for boarding at B2"
    reading = owners_stay_put(typed, reading)  # "from Mr Shah's office to X; he stays put in his": in his office
    reading = poured_through(typed, index, whole_of_zone(typed, index, reading))  # "all of the circle, roughly 300 punters, escapes": from the circle; "pour through the lobby and ...": from the lobby
    reading = with_passing_moments(typed, reading)  # "look at the robot as it passes the desk"
    reading = awaited_at_the_place(reading)  # "the robot waits for ten commuters to board at platform 1": there too
    return replace(reading, prompt=typed, corrections=tuple(corrections))


def _read(s: Sentence) -> PromptReading:
    people = People(s)
    places = PlacePhrases(s, people)
    finder = Mentions(s, people, places)
    clauses = Clauses(s, people, places)
    robot_clauses = RobotClauses(s, people, clauses)
    groups = Groups(s, places, finder, clauses, robot_clauses)
    mentions = joined_couples(s, people, kin_families(s, without_described_things(s, without_named_events(s, without_activity_times(s, without_awaited_things(s, without_awaited_comers(s, without_closers(s, without_causers(s, without_second_names(s, without_asides(s, with_people_after_an_event(s, with_counts_before(s, finder.mention_at, finder.find())))))))))))))  # "Mum and Dad", "a man and his wife": one group of two
    taken_by_each(s, people, mentions)
    found = robot_clauses.find(mentions)
    robot = robot_clauses.reading(found)
    robot_tokens = {i for rc in found for i in rc.tokens}
    problems = list(finder.problems)
    read: tuple[GroupReading, ...] = ()
    if mentions:
        read = without_watched(s, mentions, without_perceivers(s, mentions, with_escorts_after_a_wait(
            s, people, mentions, groups.read(mentions, found))))  # "a guard notices smoke and ..."; "waits, then wheels a patient to X"
    elif (assumed := groups.evacuees_of_an_emptied_zone()) is not None:
        read = (assumed,)
    elif clauses.negated_tokens():
        # "Nobody is in the ward": a sentence about nobody sets no scene; nobody to simulate
        places.scan_unknown([i for i in range(s.n) if i not in robot_tokens])
        groups.notes.append("no group of people found in the prompt")
        problems.append(NOBODY)
    else:
        read = (counted_unnamed(s, groups.unnamed(robot_tokens), robot_tokens),)  # "a first-time donor lies ..."
    places.scan_names({i for m in mentions for i in range(m.first, m.last + 1)})
    first_robot_word = min((i for rc in found for i in rc.tokens), default=s.n)
    robot = route_from_the_guided(robot, first_robot_word, mentions, read)  # "walk to the exit while the robot guides them"
    robot = led_by_robot(_robot_follows_someone_said(robot, found, mentions, read), read)  # "follow the robot into X"
    robot = via_the_people_passed(s, robot, [rc.tokens for rc in found], mentions, read)  # "weaves through them"
    read = people_passed_stay(s, robot, found, read)  # "threads through teens by the fountain, bound for the cinema"
    robot, read = following_the_robot(s, robot, first_robot_word, read)  # "has wandered into X, so the robot guides him back"
    read = spread_over_each(s, parts_of_a_split_whole(all_go_on(s, _followers_of_someone_said(read))))
    read = got_up_and_went(read)  # "a pair get up and pay at reception": they walk there
    return PromptReading(s.prompt, read, tuple(dict.fromkeys(places.unknown)), tuple(groups.notes), robot=robot,
                         places=tuple(dict.fromkeys(places.named)), problems=tuple(dict.fromkeys(problems)))


_FOLLOWED_PRONOUNS = {"them", "him", "her", "us", "the group before"}


def _robot_follows_someone_said(robot: RobotReading | None, found: Sequence[RobotClause],
                                mentions: Sequence[Mention], read: Sequence[GroupReading]) -> RobotReading | None:
    """Whom "the robot follows them" follows: the group said last before the robot's clause (the one
    the pronoun points back to), by its own words, so the plan and the report find the group it names."""
    if robot is None or robot.task != "follow" or not read:
        return robot
    if robot.follows is not None and robot.follows.lower() not in _FOLLOWED_PRONOUNS:
        return robot  # "the robot follows the nurse": named in its own words
    said_in_clause = set(robot.text.lower().split())
    if robot.follows is None and any((set(g.who.lower().split()) - {"a", "an", "the"}) & said_in_clause for g in read):
        return robot  # "the robot follows the climbers": its words name the group
    first = min((i for rc in found for i in rc.tokens), default=0)
    group = said_last_before(first, bool(said_in_clause & {"him", "her"}), mentions, read)
    return replace(robot, follows=(group or read[0]).who)


def _followers_of_someone_said(read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """People who follow "them", "her", "the group before": the group said last before them (one
    person for "him"/"her"), by its words; with no way of their own they go where it goes."""
    out: list[GroupReading] = []
    for g in read:
        pronoun = (g.follows or "").lower()
        if g.intent == "follow" and pronoun in _FOLLOWED_PRONOUNS and out:
            singular = pronoun in ("him", "her")
            leader = next((e for e in reversed(out) if not singular or e.count.value == 1), out[-1])
            g = replace(g, follows=leader.who)
            if not (g.start or g.destination or g.location or g.via):
                g = replace(g, start=leader.start, destination=leader.destination, via=leader.via,
                            location=leader.location)
        out.append(g)
    return tuple(out)

