"""The one lexicon of English the product reads: data only, no logic beyond lookups.

Every word table the reader needs lives here so that there is one answer to "is this a verb of
walking", "does this word mark a place", "how many is a few". Only language/ reads English; the
stages below it take the reading.

Vague and implied counts have documented ranges; the reader picks a value inside the range from
the seed, so one prompt and one seed always give the same crowd:

    a few / few 2-4      a handful 3-5     several 3-6     some 3-6      a number of 4-8
    many / lots of 8-15  dozens of 24-40   scores of 40-80   hundreds of 100-300
    others / the rest 2-5 (when no total fixes them)
    a bare plural ("visitors walk in") 3-6
    implied: couple 2, pair 2, family 3-4, group 3-5, party 3-5, team 3-6, crowd 15-30

Whole-zone counts ("everyone in the cafeteria") fill the zone at WHOLE_ZONE_DENSITY person/m^2,
never more than WHOLE_ZONE_CAP people.
"""

from __future__ import annotations

from grove_tui.language.robot_feeling_words import DISTANCE_NOUNS, MORE_FEELINGS, WAKE_PHRASES, WATCHING_PHRASES
from grove_tui.language.manner_walks import MANNER_WALKS
from grove_tui.language.role_nouns import ROLE_NOUNS

# ---- numbers --------------------------------------------------------------------------------

UNITS = {
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15,
    "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19,
}
TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
# Millions and billions are read so "a billion people" is refused as too many, not ignored.
SCALES = {"hundred": 100, "thousand": 1000, "million": 10**6, "billion": 10**9, "trillion": 10**12}
BIG_SCALES = frozenset({"thousand", "million", "billion", "trillion"})  # each closes a group of three digits
NUMBER_WORDS = frozenset(UNITS) | frozenset(TENS) | frozenset(SCALES) | {"dozen", "dozens", "couple", "pair", "handful"}

# Words before a number that make it approximate ("about twenty people"): the value stays the
# number, the range is +-APPROXIMATE_SPREAD of it.
APPROXIMATE_WORDS = frozenset("about around approximately roughly nearly almost circa some maybe perhaps".split())
APPROXIMATE_PHRASES = (("close", "to"), ("more", "or", "less"), ("up", "to"), ("at", "least"), ("at", "most"),
                       ("give", "or", "take"), ("in", "the", "region", "of"), ("something", "like"),
                       ("upwards", "of"), ("just", "under"), ("just", "over"), ("a", "little", "over"))
APPROXIMATE_SPREAD = 0.2

# Vague quantity words -> (low, high) head counts.
VAGUE_RANGES: dict[str, tuple[int, int]] = {
    "few": (2, 4), "handful": (3, 5), "several": (3, 6), "some": (3, 6), "number": (4, 8),
    "many": (8, 15), "lots": (8, 15), "lot": (8, 15), "plenty": (8, 15), "numerous": (8, 15),
    "dozens": (24, 40), "various": (3, 6), "multiple": (3, 6), "scores": (40, 80), "hundreds": (100, 300),
    "loads": (8, 15), "heaps": (8, 15), "tons": (8, 15), "few dozen": (24, 48), "several dozen": (36, 72),
}
OTHERS_RANGE = (2, 5)  # "others", "a few others" with nothing that fixes how many
BARE_PLURAL_RANGE = (3, 6)  # "visitors walk to the ward": some visitors, not none

# Collective nouns: a size when the prompt gives none, and whether the members move together.
IMPLIED_RANGES: dict[str, tuple[int, int]] = {
    "couple": (2, 2), "pair": (2, 2), "family": (3, 4), "group": (3, 5), "party": (3, 5), "team": (3, 6),
    "squad": (3, 6), "crowd": (15, 30), "throng": (15, 30), "horde": (15, 30), "army": (20, 50), "legion": (20, 50), "swarm": (15, 30), "stream": (10, 25), "flood": (15, 30), "gaggle": (5, 12), "flock": (8, 20), "herd": (8, 20), "mob": (8, 20), "trickle": (3, 8), "bunch": (3, 5), "circle": (3, 5), "gang": (3, 5), "trio": (3, 3), "jury": (12, 12), "triplet": (3, 3),
    "duo": (2, 2), "class": (10, 20), "tour": (6, 12), "queue": (4, 8), "line": (4, 8), "delegation": (3, 6), "twin": (2, 2), "quartet": (4, 4), "quintet": (5, 5), "twosome": (2, 2), "foursome": (4, 4), "sextet": (6, 6), "threesome": (3, 3), "fivesome": (5, 5), "fourball": (4, 4), "household": (3, 5),
    # what a vehicle holds ("a coachload of pensioners", "a minibus of pupils" is read as a place)
    "coachload": (30, 50), "busload": (30, 50), "vanload": (5, 10), "carload": (3, 5), "boatload": (20, 40),
    "planeload": (100, 180), "minibusload": (10, 16), "trainload": (100, 300), "crew": (3, 8), "shift": (4, 10),
    "club": (6, 15), "choir": (10, 25), "troop": (8, 15), "pack": (12, 24), "squadron": (8, 15), "audience": (20, 60), "congregation": (20, 60),
}
# Collectives that end a person named by two words and still count people ("the cabin crew", "a film
# crew of four"), unlike "the au pair".
MULTIWORD_COLLECTIVES = frozenset({"crew", "shift"})
# What a vehicle holds: "a coachload of pensioners" are pensioners, as many as a coach holds.
VEHICLE_LOADS = frozenset("coachload busload vanload carload boatload planeload minibusload trainload".split())
# Collectives known by their members when the members are named ("a choir of thirty children": children).
MEMBERS_NAME_COLLECTIVES = VEHICLE_LOADS | MULTIWORD_COLLECTIVES | {"club", "choir", "troop", "squadron", "pack"}
# Words that put what follows after what came before ("..., then waits in the waiting room").
SEQUENCE_WORDS = frozenset({"then", "afterwards", "afterward", "later"})
# Words between two places of one route, the second with no preposition ("to the café and then the pharmacy").
PLACE_SEQUELS = frozenset({"and", "then", ",", "afterwards", "finally"})
# Collectives that also name the kind of a collective after them ("a tour group", "a family party").
MODIFYING_COLLECTIVES = frozenset({"tour", "family", "class", "delegation"})
# Family words said as names, with no determiner ("mum cooks", "grandpa naps"): what follows is their verb.
KIN_NAMES = frozenset("mum mom mummy mommy mama dad daddy papa grandma grandpa granny gran nan nana grandad "
                      "granddad".split())
# Plurals that, said of one family ("the parents", "her grandparents"), are a known few people.
FAMILY_PLURALS: dict[str, tuple[int, int]] = {"parent": (2, 2), "grandparent": (2, 4),
                                             "newlywed": (2, 2), "honeymooner": (2, 2)}
COUPLE_PLURALS = frozenset({"newlywed", "honeymooner"})  # "the newlyweds": a couple, together
# Collectives that, with "of" and people, are only a vague quantity ("a crowd of visitors").
QUANTIFYING_COLLECTIVES = frozenset({"crowd", "throng", "horde", "army", "legion", "swarm", "stream", "flood", "gaggle", "flock", "herd", "mob", "trickle"})
TOGETHER_COLLECTIVES = frozenset({"couple", "pair", "family", "group", "party", "team", "bunch", "circle", "gang",
                                  "trio", "duo", "quartet", "quintet", "twosome", "foursome", "sextet", "threesome", "fivesome", "fourball", "household", "class", "tour", "delegation", "twin", "triplet", "coachload", "busload",
                                  "vanload", "carload", "boatload", "planeload", "minibusload", "trainload", "crew",
                                  "shift", "club", "choir", "troop", "pack"})
# What a collective does as it comes about: "a queue of 12 forms at the desk" counts no "forms".
GATHERING_VERBS = frozenset("form build grow snake stretch set gather assemble develop appear".split())
# Collectives whose members stand in line: "a queue of eight people forms at the desk" is a queue.
QUEUE_COLLECTIVES = frozenset({"queue", "line"})

WHOLE_ZONE_WORDS = frozenset({"everyone", "everybody", "all"})
WHOLE_ZONE_DENSITY = (0.3, 0.5)  # person/m^2 of the zone's floor: a busy room, still able to move
WHOLE_ZONE_CAP = 40  # the presets' default per-group limit
NOBODY_WORDS = frozenset({"nobody", "noone", "none"})  # "no one" is read as two words
EXCEPT_WORDS = frozenset({"except", "but", "save", "besides"})  # "other than", "apart from" are read as two words
# A place after these is where people do NOT go: neither a role nor an unknown place.
NEGATED_PLACE_PHRASES = (("instead", "of"), ("rather", "than"))
# A place a group must not use: "..., not the main doors", "but not through the lobby", "avoiding the lifts",
# and the words between that word and the place.
NOT_USING_WORDS = frozenset({"not", "never", "avoiding", "bypassing"})
NOT_USING_LINKS = frozenset({"by", "through", "thru", "via", "using", "use", "past", "into", "out", "of", "towards",
                             "toward", "to", "at", "from", "near", "the", "a", "an", "that", "this", "their", "its"})

DURATION_UNITS = {"second": 1.0, "sec": 1.0, "minute": 60.0, "min": 60.0, "hour": 3600.0, "hr": 3600.0, "moment": 10.0}
# A part of the day as a stay ("spend the afternoon in the bar"), in seconds.
DAY_PERIODS = {"morning": 3 * 3600.0, "afternoon": 3 * 3600.0, "evening": 3 * 3600.0, "day": 8 * 3600.0}

# Abbreviations people type in a hurry, written out before the prompt is parsed (language/text.py).
CHAT_WORDS: dict[str, str] = {
    "ppl": "people", "ppls": "people", "peeps": "people", "pax": "passengers", "thru": "through",
    "w/": "with", "w/o": "without", "abt": "about", "approx": "approximately", "approx.": "approximately",
    "ca.": "about", "nr": "near", "btw": "", "pls": "please", "plz": "please", "mins": "minutes",
    "hrs": "hours", "secs": "seconds", "sec": "second", "min": "minute", "ppl's": "people's",
    # people by their short names ("2 devs grab coffee", "a few execs")
    "dev": "developer", "devs": "developers", "exec": "executive", "execs": "executives", "prof": "professor",
    "profs": "professors", "techs": "technicians", "reps": "representatives", "admins": "administrators",
    "grads": "graduates", "mgr": "manager", "mgrs": "managers", "hubby": "husband", "kiddos": "kids",
    "peds": "pedestrians", "ped": "pedestrian", "npcs": "people", "npc": "person",
}

# ---- people ---------------------------------------------------------------------------------

PERSON_NOUNS = frozenset(
    """person people folk individual pedestrian visitor patient nurse doctor physician surgeon staff employee worker
    colleague coworker manager receptionist clerk cashier pharmacist guard security officer cleaner janitor
    porter student teacher child kid baby toddler teenager teen adult parent mother father mom mum dad grandparent
    grandmother grandfather grandma grandpa family friend couple guest resident neighbour neighbor roommate tenant
    customer client shopper tourist traveller traveler passenger man woman boy girl gentleman lady elderly senior
    volunteer caregiver paramedic intern developer engineer member attendee participant crowd throng horde audience congregation group team party
    occupant user walker runner diner commuter spectator fan player athlete pilgrim inpatient outpatient therapist
    technician radiologist dentist vet chef cook waiter waitress barista boss professor pupil infant housemate sibling
    brother sister son daughter husband wife partner relative cousin uncle aunt courier smoker jogger pair
    stranger newcomer latecomer passerby bystander onlooker stakeholder executive director secretary assistant
    analyst programmer designer consultant contractor electrician plumber technician inspector officer police
    policeman policewoman firefighter medic orderly attendant steward stewardess pilot crew traveller tenant
    homeowner host hostess child everyone everybody someone somebody anyone anybody nobody gang trio duo quartet quintet twosome foursome sextet threesome fivesome fourball
    delegation tour class kids youngster adolescent elder pensioner retiree grandson granddaughter grandchild
    nephew niece baby nanny babysitter mum mom dad papa mama husband wife fiance bride groom
    cashier clerk vendor shopkeeper salesperson pharmacist surgeon midwife janitor custodian
    grandad granddad gran granny nan nana grandpa ceo cto cfo boss backpacker hiker businessman businesswoman
    businessperson twin triplet toddler schoolchild schoolboy schoolgirl inspector conductor driver mechanic builder
    lecturer researcher scientist relative carer holidaymaker newlywed honeymooner
    traveler sightseer photographer journalist reporter auxiliary
 candidate applicant interviewee recruit trainee apprentice graduate newcomer employer staffer official
 crewmember crewman aircrew airman airwoman captain copilot steward purser handler
 porter bellboy concierge doorman usher caretaker housekeeper maid butler gardener handyman repairman
 decorator painter carpenter labourer laborer workman tradesman deliveryman postman postwoman
 mailman dispatcher operator supervisor foreman administrator receptionist registrar clinician
 anaesthetist anesthetist pediatrician paediatrician cardiologist neurologist oncologist psychiatrist
 psychologist counsellor counselor pharmacologist optician physio physiotherapist nutritionist dietitian
 sonographer phlebotomist registrar consultant houseman matron sister carer caretaker
 convalescent evacuee refugee migrant immigrant emigrant expat foreigner villager townsperson
 citizen civilian pedestrian cyclist motorist driver chauffeur cabbie rider commuter hitchhiker
 worshipper pilgrim churchgoer mourner reveller partygoer clubber dancer singer musician performer actor
 actress artist author writer poet blogger influencer vlogger youtuber gamer hacker coder techie geek
 salesman saleswoman salesperson trader dealer broker banker accountant auditor lawyer solicitor barrister counsel
 attorney judge clerk notary agent realtor landlord landlady lodger boarder flatmate housemate
 neighbour schoolteacher headteacher headmaster headmistress principal tutor lecturer instructor 
 mentor pupil schoolkid undergraduate postgraduate fresher scholar fellow academic librarian
 archivist curator guide chaperone minder bodyguard bouncer warden ranger steward marshal
 sheriff detective constable sergeant lieutenant soldier sailor marine veteran cadet
 commissionaire ticketholder shopper buyer seller bargain-hunter punter gambler
 vip councillor councilor alderman dignitary celebrity politician mayor minister diplomat ambassador delegate envoy representative
 spokesperson presenter host moderator panelist panellist attendee exhibitor organiser organizer
 planner coordinator volunteer helper aide assistant intern understudy deputy temp busker
 newborn infant tot kiddo youngster youth lad lass bloke chap fellow fella pal buddy chum dude guy gal granny oldie widow widower
 wheelchair-user amputee patient sufferer sitter dogsitter housesitter
 club choir troop coach referee umpire lifeguard chaplain vicar priest imam rabbi nun monk storyteller footballer golfer
 swimmer bather skater climber boxer rower cricketer borrower reader gymnast sprinter bodybuilder learner supporter""".split()
) | ROLE_NOUNS  # court, port, school, shop, factory, theatre, church and stadium roles
# Last parts of a compound that names a person ("lifeguard", "groundsman", "goalkeeper", "headteacher"),
# with at least three letters before them; not the things so named ("mudguard", "ottoman").
COMPOUND_PERSON_HEADS = ("guard", "man", "woman", "keeper", "boy", "girl", "maid", "master", "mistress", "wife",
                         "worker", "teacher", "fighter", "minder", "person", "goer", "watcher", "seller", "leader", "people")
COMPOUND_THINGS = frozenset("safeguard mudguard fireguard vanguard rearguard ottoman walkman caiman dolman "
                            "human".split())
# Kinds of people a place can belong to, by the kind it counts as: "their room" said of teenagers
# is the kids' room, "his office" said of the boss is the manager's office.
OWNER_KINDS: dict[str, str] = {}
for _kind, _people in {
    "child": "child kid teenager teen son daughter boy girl toddler baby youngster schoolchild pupil infant",
    "parent": "parent mum mom dad mother father husband wife",
    "manager": "manager director boss ceo executive head gaffer guvnor guv",
    "guard": "guard security officer",
    "doctor": "doctor physician surgeon consultant",
    "nurse": "nurse",
    "staff": "staff employee worker colleague clerk",
}.items():
    for _person in _people.split():
        OWNER_KINDS.setdefault(_person, _kind)

# Titles before a name ("Dr Jones", "Mr Li", "Mrs Patel"): one person, known by the title's kind.
TITLES: dict[str, str] = {"mr": "man", "mrs": "woman", "ms": "woman", "miss": "woman", "mx": "person",
                          "dr": "doctor", "doctor": "doctor", "prof": "professor", "professor": "professor",
                          "sir": "man", "dame": "woman", "nurse": "nurse", "sister": "nurse", "father": "priest",
                          "officer": "officer", "captain": "captain", "auntie": "aunt", "uncle": "uncle"}
# Verbs by which people go behind someone ("the pupils follow their teacher to the hall"): the one
# followed is a person of the scene too.
FOLLOWING_VERBS = frozenset("follow trail shadow tail chase pursue".split())
# People named by two words, the second of which means something else alone ("au pair" is one
# person, not a pair; "station master" is no master of anything here).
MULTIWORD_PEOPLE: frozenset[tuple[str, ...]] = frozenset(tuple(p.split()) for p in (
    "au pair", "station master", "tour guide", "ground crew", "cabin crew", "lollipop lady",
    "night porter", "head waiter", "shop assistant", "sales assistant", "flight crew", "crossing guard",
    "best man", "maid of honour", "night shift", "day shift", "early shift", "late shift", "morning shift",
    "evening shift", "cleaning crew", "dinner lady", "tea lady", "new starter", "new hire", "new joiner", "team leader", "group leader", "squad leader", "team captain"))
# Animals and things that can be counted and do something, but are nobody a crowd simulation places
# ("two cats sleep on the sofa", "three trolleys stand by the door").
NON_PEOPLE = frozenset("""cat dog puppy kitten bird pigeon sparrow seagull gull crow horse pony donkey cow sheep goat
    pig duck goose chicken hen rabbit hamster mouse rat fish goldfish parrot squirrel fox deer bee wasp fly ant insect
    animal pet clock lamp light bulb candle train bus car taxi van lorry truck plane aircraft jet trolley cart suitcase
    bag case luggage box parcel machine computer laptop phone monitor heater radiator speaker alarm siren bell
    engine motor drone balloon leaf flower plant tree elevator escalator printer scanner projector shutter conveyor
    generator sprinkler dishwasher boiler fridge freezer kettle timer tram ferry tractor forklift mower shuttle
    scooter trailer container dispenser detector sensor extinguisher ventilator indicator compressor thermostat""".split()) | DISTANCE_NOUNS
# Endings of nouns for someone who does something ("busker", "florist", "violinist", "sommelier"):
# the subject of a verb, such a noun is a person unless the world or a list says otherwise.
AGENT_SUFFIXES = ("er", "or", "ist", "ian", "eur", "ier", "ess")
# Endings only people's nouns have ("radiotherapist", "librarian", "locksmith", "beekeeper",
# "fishmonger"): the subject of any verb of going or staying is a person ("the locksmith waits at
# reception"); the weaker endings above (and "-ant", "-ent") need a pronoun that refers to the noun
# ("the radiographer leaves her department"), since lifts, printers and trains go and wait too.
STRONG_AGENT_SUFFIXES = ("ist", "ian", "eur", "smith", "keeper", "monger", "wright", "man", "woman", "person")
WEAK_AGENT_SUFFIXES = AGENT_SUFFIXES + ("ant", "ent")
# Verbs of going and staying that machines seldom have for subject with a place after them ("an
# interpreter waits at the desk", not "the dryer runs in the basement").
PEOPLE_GOING_VERBS = frozenset("wait leave enter arrive head walk queue linger visit exit proceed hurry wander "
                               "stroll loiter".split())
# Pronouns that refer to a person: "her", "his" said of a noun make it someone.
PERSONAL_PRONOUNS = frozenset("he she him her his hers himself herself".split())
PLURAL_PERSONAL_PRONOUNS = frozenset("they them their theirs themselves".split())
# Verbs only people do: the noun that is their subject is a person even when no list names it
# ("a sommelier chats with ...", "two botanists stroll to ..."). Not "wait", "go", "run" or "move":
# trains, queues and lifts do those too.
HUMAN_SUBJECT_VERBS = frozenset("chat talk converse gossip discuss argue debate socialise socialize greet "
                                "queue stroll wander amble saunter meander browse mill stare gaze glance gawk "
                                "chat giggle laugh smile chatter whisper sip eat drink shop hurry sprint jog "
                                "tiptoe limp hobble shuffle nap doze snooze bicker squabble quarrel".split())
# Verbs of things, not people: a counted noun no list names that does only these is no group
# ("two posters hang in the lobby", "three clocks tick", "four lamps light the hall").
THING_VERBS = frozenset("hang tick light glow shine flash beep buzz hum whir whirr display show cover line decorate "
                        "contain lean".split())
# Person words that name things too ("two fans whir", "the runner lies along the hall"): only these
# are taken for things by any verb above; any other person leans, hangs or lines up as people do
# ("the porter leans against the wall"), and is a thing only by a verb of sound or light.
PERSON_THINGS = frozenset("fan guide host party crew runner walker driver cook monitor sitter speaker "
                          "conductor class tour".split())
# What an event does, said of a word for people that names an event too ("once the class ends, ...",
# "when the tour finishes,"): no group, when nothing follows the verb in its clause.
EVENT_VERBS = frozenset("end finish conclude begin start close break".split())
SOUND_LIGHT_VERBS = frozenset("tick glow shine flash beep buzz hum whir whirr".split())
# Words that stand for people without naming what kind ("three of them", "someone").
PRONOUN_PEOPLE = frozenset({"someone", "somebody", "anyone", "anybody", "everyone", "everybody", "nobody", "one",
                            "them", "they", "others", "other", "rest", "more"})
GENERIC_PEOPLE = frozenset({"person", "people", "individual", "pedestrian", "someone", "somebody", "anyone",
                            "anybody", "one", "human", "occupant", "folk"})

# ---- clause structure -----------------------------------------------------------------------

# Words after which a new group of people may be introduced ("..., while a few others stroll").
# Not "until", "unless" or "if": "... until someone collects them" names nobody who is there.
CLAUSE_STARTERS = frozenset("and while whilst whereas but as meanwhile then when also plus so after before once "
                            "except with".split())
# Imperative verbs that introduce the people of a scenario ("Simulate ten patients ...").
SCENE_VERBS = frozenset("simulate show create generate spawn add have make let put place model imagine picture "
                        "depict want need include populate start send position inject insert deploy instantiate".split())
# Words that can stand between a count and its person noun ("ten tired old patients").
NP_MODIFIERS = frozenset("the other more tired young old elderly busy waiting new local senior junior impatient "
                         "anxious worried excited angry calm happy curious nervous hungry sick injured "
                         "frail elder little small big large different additional extra".split())

# ---- what people do --------------------------------------------------------------------------

# verb lemma -> intent. Multi-word verbs ("line up", "mill around") are in PHRASAL_INTENTS.
INTENT_VERBS: dict[str, str] = {}
for _intent, _verbs in {
    "queue": "queue line queueing",
    "wait": "wait sit stand rest linger stay remain pause idle loiter relax lounge perch sleep read gather doze nap "
            "snooze spend scatter spread dot",
    "converse": "chat talk converse gossip discuss socialise socialize meet greet argue debate natter chatter banter "
                "bicker squabble quarrel wrangle murmur whisper mutter confer",
    "wander": "wander stroll roam browse meander mill amble saunter explore shop patrol drift pace crawl potter "
              "mop sweep vacuum hoover scrub tidy clean tour rummage prowl dawdle float bob paddle wade",
    "follow": "follow accompany escort trail shadow",
    "evacuate": "evacuate flee escape",
    "walk": "walk go head move come leave enter cross arrive proceed return visit pass exit commute travel "
            "hurry rush run jog dash sprint race march step make get reach transfer walk shuffle stride stroll pour "
            "file troop stream flood trickle spill surge toddle deliver drop bring fetch collect slip sneak nip pop board carry "
            "lug haul traverse quit retire totter waddle trot " + MANNER_WALKS,
}.items():
    for _verb in _verbs.split():
        INTENT_VERBS.setdefault(_verb, _intent)
PHRASAL_INTENTS: dict[tuple[str, ...], str] = {
    ("line", "up"): "queue", ("wait", "in", "line"): "queue", ("stand", "in", "line"): "queue",
    ("wait", "in", "a", "line"): "queue", ("wait", "their", "turn"): "queue", ("wait", "for", "their", "turn"): "queue",
    ("form", "a", "line"): "queue", ("form", "a", "queue"): "queue", ("get", "in", "line"): "queue",
    ("take", "turns"): "queue", ("take", "their", "turn"): "queue", ("await", "their", "turn"): "queue",
    ("in", "the", "line"): "queue", ("queue", "up"): "queue", ("on", "the", "waiting", "list"): "queue",
    ("mill", "around"): "wander", ("mill", "about"): "wander", ("walk", "around"): "wander",
    ("walk", "about"): "wander", ("look", "around"): "wander", ("wander", "around"): "wander",
    ("hang", "out"): "wait", ("hang", "around"): "wait", ("hang", "about"): "wait", ("hang", "on"): "wait",
    ("hang", "round"): "wait", ("catch", "up"): "converse", ("have", "a", "chat"): "converse",
    ("have", "a", "conversation"): "converse", ("stand", "around"): "wait", ("sit", "down"): "wait", ("have", "words"): "converse",
    ("join", "the", "queue"): "queue", ("join", "the", "line"): "queue", ("join", "a", "queue"): "queue",
    ("join", "the", "back"): "queue", ("check", "in"): "queue", ("in", "conversation"): "converse",
    ("in", "line"): "queue", ("in", "a", "line"): "queue", ("in", "a", "queue"): "queue", ("in", "the", "queue"): "queue",
    ("in", "discussion"): "converse", ("make", "a", "beeline"): "walk", ("make", "a", "dash"): "walk",
    ("make", "a", "run"): "walk", ("make", "a", "break"): "walk", ("pace", "up", "and", "down"): "wander",
    ("get", "out"): "walk", ("get", "off"): "walk", ("get", "on"): "walk", ("get", "onto"): "walk",
    ("set", "off", "from"): "walk", ("set", "out", "from"): "walk",  # "set off from the beach": they leave it
    **{(verb, *how): "wander" for verb in ("walk", "move", "go", "stroll", "random") for how in (  # no aim
        ("randomly",), ("aimlessly",), ("at", "random"), ("walk",), ("around", "randomly"), ("about", "randomly"))},
}
# Verbs whose counted object is a second group that goes along ("a guide leads twelve tourists to ..."):
# the subject walks the route, the object follows.
# So is the person pushed, wheeled or helped along ("an orderly wheels a patient to radiology").
LEADING_VERBS = frozenset("lead guide escort usher shepherd accompany take bring show push wheel roll carry help assist "
                          "support transport walk drag pull haul hurry rush move evacuate transfer ferry relocate "
                          "piggyback cradle chaperone steer tow steady".split())
# What a person is carried or pushed in: "pushes his father's wheelchair" takes the father along.
CARRYING_THINGS = frozenset("wheelchair pram buggy stroller pushchair bed trolley stretcher gurney chair scooter "
                            "cot crib".split())
# Verbs by which someone sends people elsewhere without going along ("a guard sends the visitors out of
# the café", "the manager tells the interns to go to the boardroom"): the people go, the sender stays.
SENT_VERBS = frozenset("send tell order ask direct call wave shoo summon instruct urge".split())
# "groups of three", "pairs of tourists" with no number of groups: how many groups. Not "the twins",
# which is one pair.
PLURAL_PARTIES_RANGE = (2, 5)
ONE_SET_PLURALS = frozenset({"twin", "triplet"})
# Verbs whose object is where people start ("leave the cafeteria") or where they go ("enter the ward").
START_OBJECT_VERBS = frozenset("leave exit evacuate vacate flee escape quit abandon desert".split())
DESTINATION_OBJECT_VERBS = frozenset("enter reach visit approach cross".split())
LOCATION_OBJECT_VERBS = frozenset("patrol roam explore browse wander occupy fill clean search tour mop sweep vacuum watch "
                                  "hoover scrub tidy crowd throng pack cram pace prowl stalk comb scour".split())
# Verbs of a purpose ("to reach the ICU", "to get to the pharmacy") whose object, or the place after
# their "to", is where people go; PURPOSE_OBJECT_VERBS take it as an object ("to use the toilets").
PURPOSE_OBJECT_VERBS = frozenset("use board".split())
PURPOSE_PLACE_VERBS = DESTINATION_OBJECT_VERBS | PURPOSE_OBJECT_VERBS | frozenset("get go head make return run hurry".split())
# Verbs whose object is a place or a thing in it ("mop the corridor", "clean the windows in the hall").
# What people carry or hold is no place ("an intern carrying coffees", "a man holding a map").
HOLDING_VERBS = frozenset("carry hold clutch lug juggle balance grip tote cradle".split())
THING_OR_PLACE_VERBS = frozenset("clean mop sweep vacuum hoover scrub tidy search fill wipe polish dust swab hose".split())
# Verbs whose object is what people look at ("watch TV"): where they are, unless a place is named too.
SEEN_OBJECT_VERBS = frozenset({"watch"})
# Verbs whose object is a place passed through ("cross the hall", "as it passes the lobby").
VIA_OBJECT_VERBS = frozenset("cross pass traverse".split())
# Verbs whose object, when it is a way through ("take the stairs", "use the side entrance"), is a place
# passed on the way: "Three developers take the stairs to the kitchen".
ROUTE_OBJECT_VERBS = frozenset("use take".split())
PASSAGE_WORDS = frozenset("stair stairs staircase stairway stairwell steps lift elevator escalator travelator door "
                          "doorway entrance exit gate ramp corridor hallway passage passageway walkway path route bridge "
                          "footbridge tunnel underpass shortcut turnstile barrier gateline".split())
OBJECT_VERBS = START_OBJECT_VERBS | DESTINATION_OBJECT_VERBS | LOCATION_OBJECT_VERBS | VIA_OBJECT_VERBS
ARRIVAL_VERBS = frozenset("arrive come enter reach return gather meet end deliver drop bring".split())
# "buy tickets from the machines": after these, `from` says where the thing is got, so where people stand.
TRANSACTION_VERBS = frozenset("buy purchase get collect pick fetch order borrow take grab withdraw".split())
DEPARTURE_VERBS = frozenset("leave exit evacuate flee escape vacate depart".split())
# Getting on a plane or train: a door they board through or by is where they end (no evacuation).
BOARDING_VERBS = frozenset("board embark".split())
# "head for the exit": `for` marks a destination only after these; otherwise it is a purpose.
FOR_DESTINATION_VERBS = frozenset("head make run aim bolt dash rush race beeline bound".split())
STATIONARY_INTENTS = frozenset({"queue", "wait", "converse", "wander"})
# Verbs whose object is a place people do not go to ("skip the ICU", "bypass the lobby").
NEGATING_VERBS = frozenset("skip bypass ignore miss shun".split())

# ---- the robot -------------------------------------------------------------------------------

ROBOT_WORDS = frozenset({"robot", "robots", "bot", "amr", "droid"})
# What the robot itself is asked to do, by the verb of its own clause ("the robot waits by reception":
# wait; "a robot crosses the hall to the lifts": cross). A verb of motion none of these lists names is a
# crossing when the clause gives the robot somewhere to go.
ROBOT_WAIT_VERBS = frozenset("wait stand stay park idle remain sit rest stop pause hover linger charge sleep halt "
                             "dock be recharge plug station position".split())
# Said of the robot in the passive, where it is put to stay ("the robot is parked by the lifts", "is
# left in the hallway"): a wait there.
ROBOT_PLACED_VERBS = frozenset("park dock station position place leave plug charge store keep stop".split())
ROBOT_PATROL_VERBS = frozenset("patrol roam wander circle sweep clean mop vacuum guard scan explore monitor tour "
                               "survey inspect cruise prowl loop".split())
# Words between the robot's verb and people it meets on its way ("drives past two nurses").
ROBOT_PREPOSITIONS = frozenset("past by between among around round behind beside near to with through towards "
                               "toward alongside for".split())
ROBOT_FOLLOW_VERBS = frozenset("follow trail accompany shadow tail chase pursue".split())
ROBOT_CROSS_VERBS = frozenset("cross pass traverse drive roll glide move navigate travel deliver carry bring fetch "
                              "transport head go leave enter return zoom trundle come reach visit proceed rush hurry "
                              "ride run walk lead guide escort take make get exit arrive depart zip whizz whiz "
                              "scoot whoosh sail slide shuffle crawl creep".split())
# Verbs of sending the robot somewhere: "send the robot to ward A", "have the robot wait by the door".
ROBOT_COMMAND_VERBS = frozenset("send have let make get tell ask order direct program command dispatch "
                                "instruct".split())
# verb lemma -> interaction when the robot is its object ("stares at the robot").
ROBOT_VERBS: dict[str, str] = {}
for _interaction, _verbs in {
    "look": "look stare watch glance gaze notice observe eye peer see spot regard study film photograph wave gape gawp",
    "approach": "approach greet inspect investigate touch examine check poke gather tug pat stroke hug prod nudge tap "
                "ask talk chat speak question consult query hail thank crowd surround encircle swarm mob",
    "follow": "follow trail chase shadow tail pursue stalk",
    "avoid": "avoid dodge evade flee escape sidestep shun fear shrink recoil flinch cower hide retreat duck "
             "swerve",
    "block": "block obstruct confront threaten stop corner impede hinder intercept harass refuse barricade kick shove "
             "hit punch push slap smack thump whack bash ram barge heckle taunt abuse grab tip topple vandalise "
             "vandalize headbutt bar fight attack assault damage wreck rock climb ride trip sabotage smash overturn upend shoo hem",
}.items():
    for _verb in _verbs.split():
        ROBOT_VERBS.setdefault(_verb, _interaction)
# Multi-word robot interactions, matched on lemmas with the robot anywhere after them in the clause.
ROBOT_PHRASES: dict[tuple[str, ...], str] = {
    ("keep", "away"): "avoid", ("stay", "away"): "avoid", ("keep", "their", "distance"): "avoid", ("keep", "pace"): "follow",
    ("keep", "a", "distance"): "avoid", ("step", "aside"): "avoid", ("back", "away"): "avoid",
    ("shy", "away"): "avoid", ("steer", "clear"): "avoid", ("move", "away"): "avoid", ("run", "away"): "avoid",
    ("walk", "up", "to"): "approach", ("go", "up", "to"): "approach", ("come", "up", "to"): "approach",
    ("walk", "over", "to"): "approach", ("go", "over", "to"): "approach", ("walk", "towards"): "approach",
    ("walk", "toward"): "approach", ("go", "towards"): "approach", ("move", "towards"): "approach",
    ("stand", "in", "front", "of"): "block", ("get", "in", "the", "way"): "block", ("stand", "in", "the", "way"): "block",
    ("step", "in", "front", "of"): "block", ("walk", "behind"): "follow", ("look", "at"): "look",
    ("tag", "along"): "follow", ("turn", "to", "look"): "look", ("stop", "and", "stare"): "look",
    ("turn", "their", "head"): "look", ("turn", "his", "head"): "look", ("turn", "her", "head"): "look",
    ("crane", "their", "neck"): "look", ("crane", "his", "neck"): "look", ("crane", "her", "neck"): "look",
    ("keep", "clear"): "avoid", ("stay", "clear"): "avoid", ("give", "a", "wide", "berth"): "avoid",
    ("at", "the", "sight", "of"): "look", ("take", "a", "photo"): "look", ("take", "photo"): "look",
    ("take", "picture"): "look", ("take", "a", "picture"): "look", ("take", "a", "selfie"): "look",
    # Any posture in front of the robot is in its way ("plants herself in front of the robot").
    ("in", "front", "of"): "block", ("in", "the", "way", "of"): "block", ("bar", "the", "way"): "block",
    ("shrink", "back"): "avoid", ("draw", "back"): "avoid", ("pull", "back"): "avoid", ("jump", "back"): "avoid",
    ("back", "off"): "avoid", ("get", "out", "of", "the", "way"): "avoid", ("make", "way"): "avoid",
    ("edge", "away"): "avoid", ("scuttle", "away"): "avoid",
    ("square", "up", "to"): "block", ("barge", "into"): "block", ("push", "into"): "block",
    **WATCHING_PHRASES, ("sit", "on"): "block", ("climb", "on"): "block", ("sneak", "up"): "approach", ("creep", "up"): "approach", ("tiptoe", "up"): "approach",
}
# Words that may stand inside a robot phrase without changing it ("keep well clear", "steer
# completely clear", "stand right in front of").
ROBOT_PHRASE_FILLERS = frozenset("well very far right completely quite just deliberately carefully".split())
# Nouns in the robot's clause that name the interaction when no verb does ("a wide berth", "photos of it").
ROBOT_NOUNS: dict[str, str] = {"berth": "avoid", "photo": "look", "picture": "look", "selfie": "look",
                               "video": "look", "glimpse": "look", "sight": "look"}
# Any verb of motion toward or away from the robot: "run up to the robot", "step away from it".
for _verb in "walk go come run rush hurry move step head wander stroll dash race jog".split():
    for _tail in (("up", "to"), ("over", "to"), ("towards",), ("toward",), ("closer", "to"), ("right", "up", "to")):
        ROBOT_PHRASES.setdefault((_verb, *_tail), "approach")
    for _tail in (("away", "from"), ("away",), ("back", "from"), ("off",)):
        ROBOT_PHRASES.setdefault((_verb, *_tail), "avoid")
    ROBOT_PHRASES.setdefault((_verb, "after"), "follow")  # "a boy runs after it"
# Gathering round the robot is coming to see it ("crowd around the robot").
for _verb in "crowd gather cluster swarm huddle flock throng mob".split():
    for _tail in (("around",), ("round",), ("about",)):
        ROBOT_PHRASES.setdefault((_verb, *_tail), "approach")
# Any verb of walking the lexicon knows, not only the few above ("toddle up to the robot").
ROBOT_APPROACH_TAILS = (("up", "to"), ("over", "to"), ("towards",), ("toward",), ("closer", "to"), ("right", "up", "to"))
# Words right after the robot that name an interaction ("stand in the robot's way").
ROBOT_AFTER_PHRASES: dict[tuple[str, ...], str] = {("'s", "way"): "block", ("'s", "path"): "block",
                                                   ("’s", "way"): "block", ("’s", "path"): "block",
                                                   ("'s", "route"): "block", ("’s", "route"): "block", **WAKE_PHRASES}
# Feelings that name a reaction when the robot is in the same clause ("scared of the robot").
ROBOT_FEELINGS: dict[str, str] = {
    "curious": "approach", "curiosity": "approach", "interested": "approach", "fascinated": "approach",
    "scared": "avoid", "afraid": "avoid", "frightened": "avoid", "fearful": "avoid", "nervous": "avoid",
    "wary": "avoid", "surprised": "look", "startled": "look", "amazed": "look", "astonished": "look", **dict.fromkeys(
        "astonishment amazement surprise awe wonder wonderment disbelief".split(), "look"),
    "hostile": "block", "aggressive": "block", "threatening": "block", "angry": "block", **MORE_FEELINGS,
}
# HuNavSim behavior types for each robot interaction.
ROBOT_REACTIONS = {"look": "Surprised", "approach": "Curious", "follow": "Curious", "avoid": "Scared",
                   "block": "Threatening"}

# ---- manner ---------------------------------------------------------------------------------

FAST_WORDS = frozenset("quickly fast rush hurry hurried hurriedly run running dash sprint race briskly hastily "
                       "rapidly swiftly speedily hasty quick urgent urgently stride striding strode scurry scamper "
                       "bolt dart zoom gallop barrel".split())
SLOW_WORDS = frozenset("slowly slow leisurely stroll amble shuffle saunter dawdle unhurried unhurriedly gently "
                       "carefully calmly limp hobble trudge plod tiptoe totter creep mosey".split())
TOGETHER_WORDS = frozenset({"together", "jointly"})
TOGETHER_PHRASES = (("as", "a", "group"), ("in", "a", "group"), ("as", "a", "family"), ("side", "by", "side"),
                    ("in", "pairs"), ("in", "groups"), ("with", "each", "other"), ("as", "a", "team"),
                    ("in", "a", "pack"), ("arm", "in", "arm"), ("hand", "in", "hand"), ("in", "twos"), ("in", "threes"))
EVACUATION_CUES = frozenset("evacuate evacuation evacuating evacuates evacuated alarm flee escape drill alert".split())
# Hazards that, named on their own ("Fire!", "Smoke in the kitchen!", "a gas leak"), make leaving an
# evacuation; as the first word of a compound ("fire exit", "smoke detector") they only name a thing.
# Verbs of noticing: noticing an alarm or a hazard, and nothing else said, is leaving ("hear the alarm").
PERCEPTION_VERBS = frozenset("hear smell see notice spot sense detect".split())
HAZARD_NOUNS = frozenset("fire smoke blaze flames bomb scare leak flood flooding explosion threat "
                         "emergency".split())
# Phrasal verbs of getting everybody out: an evacuation in any building ("get out", "empty out").
# "get out" alone is also leaving a lift or a car, so it needs urgency ("now", "must", a hazard).
EVACUATION_PHRASES: tuple[tuple[str, ...], ...] = (("clear", "out"), ("empty", "out"), ("order", "out"),
                                                   ("pile", "out"), ("bail", "out"))
URGENT_EXIT_PHRASES: tuple[tuple[str, ...], ...] = (("get", "out"), ("head", "out"), ("rush", "out"),
                                                    ("run", "out"), ("hurry", "out"), ("pour", "out"))
# Verbs by which others make people leave, in the passive ("everyone in there is sent out", "the guests
# are asked to leave", "the pupils are ushered out"): the people evacuate.
SENDING_VERBS = frozenset("send order tell ask usher move clear evacuate hurry shepherd direct instruct escort "
                          "lead guide take rush urge force call".split())
# Verbs of telling people what to do: after them in the passive, "to <verb>" is what they do, no
# purpose ("ten visitors are asked to wait in the café").
TELLING_VERBS = frozenset("ask tell order instruct request direct urge advise invite allow force make call "
                          "encourage expect".split())
URGENCY_WORDS = frozenset("now immediately urgently quickly asap must fast instantly".split())
# Words that make plain leaving ("leave", "exit") an evacuation: not "must" or "quickly", which a
# normal departure can have ("the visitors must leave by six").
IMMEDIACY_WORDS = frozenset("immediately urgently asap instantly".split())
# Verbs whose object (or passive subject) is a zone that people leave: "clear the platform",
# "the ward must be emptied" is an evacuation of that zone.
ZONE_EMPTYING_VERBS = frozenset("clear empty vacate evacuate".split())

# ---- places ---------------------------------------------------------------------------------

# Prepositions and the role of the place they introduce.
START_PREPOSITIONS = frozenset({"from", "off"})
DESTINATION_PREPOSITIONS = frozenset({"to", "into", "towards", "toward", "onto", "inside"})
LOCATION_PREPOSITIONS = frozenset({"at", "in", "on", "near", "by", "beside", "within", "around", "outside", "next",
                                   "behind", "about", "opposite", "against", "under", "among", "between", "beyond"})
VIA_PREPOSITIONS = frozenset({"through", "via", "past", "across", "along", "down", "throughout"})
PLACE_PREPOSITIONS = START_PREPOSITIONS | DESTINATION_PREPOSITIONS | LOCATION_PREPOSITIONS | VIA_PREPOSITIONS

# Adverbs of place after a person noun ("the guests inside", "the pupils downstairs"): no place
# phrase, no noun the person word would name.
LOCATION_ADVERBS = frozenset("inside outside indoors outdoors downstairs upstairs nearby here there below above "
                             "outdoor indoor".split())
DETERMINERS = frozenset("the a an their our its his her my your this that these those some each every any".split())
# Parts of a place, said with "of" before it ("the corner of the lobby"): the place itself.
PLACE_PARTS = frozenset("corner end middle centre center side edge floor back front rear far part area half "
                        "top bottom entrance doorway threshold foot perimeter".split())
# Words that qualify a place without naming one ("the nearest exit", "the other corridor").
PLACE_MODIFIERS = frozenset(
    """nearest closest nearby near far farthest furthest other same next first last main back front side rear left
    right north south east west northern southern eastern western big small large little new old busy empty quiet
    crowded open closed whole entire central middle upper lower""".split())
# Nouns that follow a preposition without naming a place of the world ("in a hurry", "at the same time").
NON_PLACES = frozenset(
    """robot robots bot time same moment morning afternoon evening night day hour minute second end start beginning
    middle way direction line queue row circle group pair hurry rush panic order turn silence distance speed pace
    crowd other each everyone someone people person alarm fire emergency evacuation meantime while chance case past
    future background foreground left right top bottom here there curiosity fear surprise interest anger
    conversation chat talk discussion meeting lunch breakfast dinner coffee tea break work shift appointment
    purpose reason fun sake help care each other them themselves him her it rest once all least most front
    side half sight flight train bus plane match delay delays
    window windows windowsill wall walls pillar pillars column columns ceiling radiator skylight""".split())
# Words for the whole building: never an unknown place, never a particular RoI.
BUILDING_WORDS = frozenset("hospital building clinic house home flat apartment premises site facility floor "
                           "place area scene venue property complex centre center interior indoors outdoors "
                           "inside outside".split())
# Outdoors beyond the building's doors: "out to the street" is out through an exit, when the world
# names no such place itself.
OUTDOOR_WORDS = frozenset("street road pavement sidewalk kerb curb kerbside curbside carpark car_park parking forecourt outdoors".split())
# Heads that say "a part of" without naming which: matching rests on the words before them.
GENERIC_PLACE_HEADS = frozenset("area room space zone spot section part region corner bit".split())
DOOR_WORDS = frozenset("door exit gate opening entrance doorway way out".split())
# Groups of words people use for the same kind of place; matching one counts, at a discount, as
# matching the others (the literal word still wins).
PLACE_SYNONYMS: tuple[frozenset[str], ...] = tuple(
    frozenset(group.split())
    for group in (
        "toilet restroom bathroom washroom wc lavatory loo",
        "cafeteria canteen cafe dining restaurant",
        "lobby foyer entrance entry hall atrium",
        "reception front desk check",
        "corridor hallway hall passage aisle",
        "exit door gate",
        "stair stairs staircase stairway",
        "elevator lift",
        "kitchen kitchenette pantry",
        "living lounge sitting",
        "bedroom bed sleeping",
        "office workspace desk cubicle",
        "meeting conference boardroom",
        "ward patient",
        "pharmacy drugstore dispensary chemist medicine",
        "emergency er ae casualty",
        "sofa couch settee",
        "vending machine snack",
        "tv television telly",
        "counter desk booth till",
        "garden yard patio terrace balcony",
        "study library",
        "printer copier print",
        "storage stockroom storeroom",
        "child kid",  # "the kids room" is the children's room
    )
)

# Words that never name anything: skipped when matching places and labels.
STOPWORDS = frozenset(
    """a an the and or of in on at to from into onto by with for as is are was were be been being it its
    this that these those there their they them he she his her we our you your i me my some any each every
    all who whom which what while when where then than so very just also around near next inside outside
    toward towards through across about over under up down out off people person someone everyone
    other others one ones do does did have has had will would should can could may might must let lets make makes
    while during after before until still again more most many much few several""".split()
)
# Where a person is held or led "by": body parts and clothes, never a place of the world ("leads her by the
# hand", "grabs him by the sleeve"); only after "by", so "the hand-wash station" or "an arm chair" still match.
HELD_BY = frozenset(
    """arm arms hand hands elbow elbows wrist wrists shoulder shoulders finger fingers thumb neck nose ear ears
    hair collar sleeve sleeves scruff coat jacket hood lead leash strap belt""".split())
