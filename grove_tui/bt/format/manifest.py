"""THE node manifest: every behavior-tree node GROVE-TUI knows, with its ports and meaning.

Everything else derives from this one table: XML validation (bt/format/xml.py), the runtime's port
parsing, the retrieval documents (retrieval.py), the draft grammar (draft.py), the planner's
choice of navigation nodes (`navigates`), and the Groot2 TreeNodesModel (`grove bt manifest`).

Conventions
- Port names follow BehaviorTree.CPP v4 (control nodes, decorators) and HuNavSim 2.0
  (`hunav_agent_manager/behavior_trees/TreeNodesModel.xml`) so generated trees also run there.
- `auto=True` ports are written by post-processing (ids, time steps, resolved points, waypoints)
  and never by the model. Most have a default that points at the agent's blackboard
  (`{id}`, `{dt}`) or are optional because the runtime can resolve them itself from the
  world/scenario when they are absent (x/y from the `target` name, group members from the
  scenario); post-processing writes them so the file is self-contained for HuNavSim.
- Every navigation node (`navigates=True`) has a `target` port (RoI name: zone, door or
  entity) plus auto ports `x`, `y` (the resolved target point) and `waypoints` (point_list
  "x1,y1;x2,y2": intermediate points only, target excluded, injected by the planner).
- Durations of HuNavSim and GROVE nodes are simulation seconds; BT.CPP's `msec` ports are
  simulation milliseconds. (HuNavSim itself counts some of them in wall-clock time:
  bt/hunav_compat.CLOCKS says which; exported trees name those nodes "... (wall clock)".)
- GROVE's `GoTo` replaces HuNavSim's GoTo(agent_id, time_step, goal_id, tolerance): the HuNavSim
  ports are kept (all auto/optional) so a HuNavSim tree using `goal_id` still validates and runs.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from lxml import etree

from grove_tui.limits import MAX_COORDINATE

CATEGORIES = ("control", "decorator", "action", "condition")
PORT_TYPES = ("int", "float", "bool", "string", "target", "agent", "agents", "point_list")
PRESETS = ("emergency", "queuing", "normal", "vanilla")

# BT.CPP type names Groot2 shows for our port types
_BTCPP_TYPE = {
    "int": "int",
    "float": "double",
    "bool": "bool",
    "string": "std::string",
    "target": "std::string",
    "agent": "int",
    "agents": "std::string",
    "point_list": "std::string",
}


@dataclass(frozen=True)
class PortSpec:
    name: str
    type: str
    default: int | float | bool | str | None = None  # None: no default; a "{key}" string: blackboard pointer (BT.CPP v4 semantics)
    min: float | None = None
    max: float | None = None
    choices: tuple[str, ...] | None = None
    description: str = ""
    direction: str = "in"  # "in" | "out"
    auto: bool = False

    @property
    def required(self) -> bool:
        """An input the tree must set: no default and not something post-processing/runtime fills."""
        return self.direction == "in" and self.default is None and not self.auto


@dataclass(frozen=True)
class NodeSpec:
    name: str
    category: str
    ports: tuple[PortSpec, ...]
    description: str
    origin: str  # "btcpp" | "hunavsim" | "grove"
    navigates: bool = False
    presets: frozenset[str] = frozenset()
    llm: bool = False
    synonyms: tuple[str, ...] = ()

    def port(self, name: str) -> PortSpec | None:
        for p in self.ports:
            if p.name == name:
                return p
        return None

    @property
    def port_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.ports)

    @property
    def llm_ports(self) -> tuple[PortSpec, ...]:
        """Ports the model may write in a draft (inputs that are not auto)."""
        return tuple(p for p in self.ports if p.direction == "in" and not p.auto)

    @property
    def max_children(self) -> int | None:
        """None: any number (control); 1 for decorators; 0 for leaves."""
        if self.category == "control":
            return None
        return 1 if self.category == "decorator" else 0


ALL = frozenset(PRESETS)
NOT_EMERGENCY = frozenset({"queuing", "normal", "vanilla"})
SOCIAL = frozenset({"normal", "vanilla"})
EVACUATION = frozenset({"emergency", "vanilla"})
NONE: frozenset[str] = frozenset()


# ---- port helpers (keep the table below readable) -------------------------------------------

def _in(name: str, type_: str, default: int | float | bool | str | None = None, description: str = "", *,
        min: float | None = None, max: float | None = None, choices: tuple[str, ...] | None = None,
        auto: bool = False) -> PortSpec:
    return PortSpec(name, type_, default, min, max, choices, description, "in", auto)


def _out(name: str, type_: str, description: str = "") -> PortSpec:
    return PortSpec(name, type_, None, None, None, None, description, "out", False)


def _agent_id(name: str = "agent_id") -> PortSpec:
    return _in(name, "agent", "{id}", "Id of the agent running this tree (filled by post-processing).", auto=True)


def _time_step(name: str = "time_step") -> PortSpec:
    return _in(name, "float", "{dt}", "Simulation time step in seconds, read from the blackboard key dt.", auto=True,
               min=0.0, max=10.0)


def _other_agent(name: str = "target_agent_id", what: str = "the other agent") -> PortSpec:
    return _in(name, "agent", None,
               f"Id of {what}. Filled by post-processing; when absent the runtime binds the first other member "
               "of the agent's group, else the nearest agent.", auto=True)


def _duration(default: float = 5.0, name: str = "duration", what: str = "the behavior") -> PortSpec:
    return _in(name, "float", default, f"How long {what} lasts, in simulation seconds (0 = until halted).",
               min=0.0, max=3600.0)


def _target(name: str = "target", what: str = "Region of interest to go to") -> PortSpec:
    return _in(name, "target", None, f"{what}: the name of a zone, door or entity of the world.")


def _xy() -> tuple[PortSpec, PortSpec]:
    return (
        _in("x", "float", None, "Resolved x of the target point in metres (post-processing).", auto=True,
            min=-MAX_COORDINATE, max=MAX_COORDINATE),
        _in("y", "float", None, "Resolved y of the target point in metres (post-processing).", auto=True,
            min=-MAX_COORDINATE, max=MAX_COORDINATE),
    )


def _waypoints() -> PortSpec:
    return _in("waypoints", "point_list", "",
               "Intermediate points 'x1,y1;x2,y2' from the global planner, target excluded (post-processing).",
               auto=True)


def _legacy_point(x: str = "target_x", y: str = "target_y", what: str = "the point") -> tuple[PortSpec, PortSpec]:
    """A literal point in the port names earlier HuNavSim 2.0 commits used before global goal ids
    (go_to_node.hpp@ba0c562, conversation_formation_node.hpp center_x/center_y, TestBT_*.xml): read
    when no goal_id is given, so the trees HuNavSim ships still validate and run."""
    return (_in(x, "float", None, f"x of {what} (older HuNavSim 2.0 trees).", auto=True),
            _in(y, "float", None, f"y of {what} (older HuNavSim 2.0 trees).", auto=True))


def _reaction_ports(extra: tuple[PortSpec, ...]) -> tuple[PortSpec, ...]:
    return (
        _agent_id(),
        _time_step(),
        _in("beh_duration", "float", 5.0, "How long the reaction lasts once triggered, in simulation seconds.",
            min=0.0, max=600.0),
        _in("only_once", "bool", True, "React only the first time; later activations fail at once, so a "
            "Fallback falls through to the routine."),
    ) + extra


_specs: list[NodeSpec] = []


def _node(name: str, category: str, ports: Iterable[PortSpec], description: str, origin: str, *, navigates: bool = False,
          presets: Iterable[str] = NONE, llm: bool = False, synonyms: Iterable[str] = ()) -> None:
    _specs.append(NodeSpec(name, category, tuple(ports), " ".join(description.split()), origin, navigates,
                           frozenset(presets), llm, tuple(synonyms)))


# ---- BehaviorTree.CPP v4 control nodes -------------------------------------------------------

_node("Sequence", "control", (), """
    Runs its children in order, one per tick while they are running, and succeeds only when every child
    succeeds; the first child that fails makes the whole sequence fail and it starts again from the first
    child next time. Use it for steps that must all happen in order, like walk to the counter, then queue,
    then leave.""", "btcpp", presets=ALL, llm=True, synonyms=("then", "in order", "steps", "and then", "after that"))

_node("SequenceWithMemory", "control", (), """
    Like Sequence, but a failing child does not restart the steps already done: next tick it resumes at
    the child that failed. Use it for a chore list whose completed steps must not be repeated.""",
      "btcpp", presets=ALL, llm=True, synonyms=("resume", "remember progress", "checklist"))

_node("ReactiveSequence", "control", (), """
    Re-checks every child from the first on every tick: while all earlier children (usually conditions)
    keep succeeding the running child continues; as soon as one fails the running child is halted. Use
    it for 'keep doing X while condition Y holds', such as walking while the robot is not close.""",
      "btcpp", presets=ALL, llm=True, synonyms=("while", "as long as", "keep checking", "guard"))

_node("Fallback", "control", (), """
    Tries its children in order until one succeeds; fails only if all fail. Use it for alternatives and
    priorities: react to the robot if it is near, otherwise carry on with the normal routine.""",
      "btcpp", presets=ALL, llm=True, synonyms=("otherwise", "else", "or", "alternative", "priority", "selector"))

_node("ReactiveFallback", "control", (), """
    A Fallback that re-checks its earlier children on every tick and halts a running later child as soon
    as an earlier one succeeds. Use it so a higher-priority condition interrupts a lower-priority activity,
    for example stop wandering as soon as the robot comes close.""",
      "btcpp", presets=ALL, llm=True, synonyms=("interrupt", "unless", "until", "preempt"))

_node("Parallel", "control", (
    _in("success_count", "int", -1, "Children that must succeed for the node to succeed (-1 = all).",
        min=-1, max=100),
    _in("failure_count", "int", 1, "Children that must fail for the node to fail (-1 = all).", min=-1, max=100),
), """
    Ticks all children concurrently every tick; succeeds once success_count children succeeded and fails
    once failure_count children failed, halting the others. Use it to do two things at once, like talking
    while walking or waiting with a time limit.""",
      "btcpp", presets=ALL, llm=True, synonyms=("at the same time", "meanwhile", "simultaneously", "while also"))

# ---- BehaviorTree.CPP v4 decorators ----------------------------------------------------------

_node("Inverter", "decorator", (), """
    Turns the child's success into failure and failure into success; running passes through. Use it to
    negate a condition: 'not at the goal', 'robot not visible'.""",
      "btcpp", presets=ALL, llm=True, synonyms=("not", "negate", "unless", "invert"))

_node("RunOnce", "decorator", (
    _in("then_skip", "bool", True, "After the first completion return SKIPPED (true) or repeat the first result (false)."),
), """
    Runs its child to completion only the first time; afterwards it is skipped (or returns the same
    result again). Use it for one-time setup such as setting goals or a single greeting.""",
      "btcpp", presets=ALL, llm=True, synonyms=("once", "only once", "first time", "one time"))

_node("Repeat", "decorator", (
    _in("num_cycles", "int", None, "How many times the child must succeed (-1 = forever).", min=-1, max=10000),
), """
    Runs its child again each time it succeeds, num_cycles times in total, then succeeds; a failing child
    makes it fail. Use it for routines repeated a fixed number of times, like three laps of a corridor.""",
      "btcpp", presets=ALL, llm=True, synonyms=("repeat", "times", "again", "loop", "laps", "forever"))

_node("RetryUntilSuccessful", "decorator", (
    _in("num_attempts", "int", None, "How many times the child may be tried (-1 = forever).", min=-1, max=10000),
), """
    Re-runs a failing child up to num_attempts times and succeeds as soon as it succeeds. Use it for
    'keep trying', like trying to reach a busy counter again after giving up.""",
      "btcpp", presets=ALL, llm=True, synonyms=("retry", "try again", "keep trying", "attempts"))

_node("KeepRunningUntilFailure", "decorator", (), """
    Keeps restarting its child as long as it succeeds and returns running; stops with failure when the
    child fails. Use it for endless routines such as patrolling until something breaks the loop.""",
      "btcpp", presets=ALL, llm=True, synonyms=("keep going", "endless", "patrol", "loop until"))

_node("ForceSuccess", "decorator", (), """
    Returns success whatever its child did once the child completes. Use it for optional steps whose
    failure must not stop the routine, like an optional chat on the way.""",
      "btcpp", presets=ALL, llm=True, synonyms=("optional", "maybe", "try", "ignore failure"))

_node("ForceFailure", "decorator", (), """
    Returns failure whatever its child did once the child completes. Use it to fall through to the next
    alternative of a Fallback after doing something.""",
      "btcpp", presets=ALL, llm=True, synonyms=("fail", "fall through"))

_node("Timeout", "decorator", (
    _in("msec", "int", None, "Time limit in simulation milliseconds.", min=0, max=3_600_000),
), """
    Halts its running child and fails when it has not finished within msec simulation milliseconds. Use
    it to bound an activity: wait in the queue at most two minutes.""",
      "btcpp", presets=ALL, llm=True, synonyms=("time limit", "at most", "give up after", "deadline"))

_node("Delay", "decorator", (
    _in("delay_msec", "int", None, "Waiting time before the child starts, in simulation milliseconds.",
        min=0, max=3_600_000),
), """
    Waits delay_msec simulation milliseconds (returning running) before ticking its child for the first
    time. Use it for late arrivals or staggered starts: leave after ten seconds.""",
      "btcpp", presets=ALL, llm=True, synonyms=("later", "after a while", "start after", "stagger", "delay"))

# ---- BehaviorTree.CPP v4 leaves -------------------------------------------------------------

_node("AlwaysSuccess", "action", (), """
    Succeeds immediately. A placeholder leaf for empty branches.""", "btcpp", synonyms=("succeed", "noop"))

_node("AlwaysFailure", "action", (), """
    Fails immediately. A placeholder leaf to end a branch with failure.""", "btcpp", synonyms=("fail",))

_node("SetBlackboard", "action", (
    _in("value", "string", None, "Value to write (a literal or a {key} pointer)."),
    _in("output_key", "string", None, "Name of the blackboard entry to write."),
), """
    Writes a value into the blackboard and succeeds. Used by HuNavSim 1.0 trees to remap subtree ports;
    not for generation.""", "btcpp", synonyms=("assign", "store"))

# ---- HuNavSim 2.0 decorator ------------------------------------------------------------------

_node("TimeDelay", "decorator", (
    _in("delay", "float", 1.0, "Seconds of simulation time to wait before ticking the child.", min=0.0, max=3600.0),
), """
    HuNavSim delay: fails until delay seconds of simulation time have passed, then ticks its child;
    halting it restarts the wait. Kept for HuNavSim compatibility; generated trees use Delay.""",
      "hunavsim", synonyms=("wait before",))

# ---- HuNavSim 2.0 conditions ----------------------------------------------------------------

_node("IsGoalReached", "condition", (_agent_id(),), """
    Succeeds when the agent is within its goal radius plus 0.1 m of its current goal. The low-level
    HuNavSim check behind goal-list navigation; GoTo already handles arrival.""",
      "hunavsim", synonyms=("arrived", "at goal"))

_node("IsRobotVisible", "condition", (
    _agent_id(),
    _in("distance", "float", 5.0, "Range in metres within which the robot counts as seen.", min=0.0, max=50.0),
), """
    Succeeds when the robot is within distance metres and inside the agent's field of view (about 100
    degrees to each side of its heading). The trigger of every reaction to the robot: noticing the robot,
    seeing it approach, spotting it nearby.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True,
      synonyms=("see the robot", "notice the robot", "robot in sight", "spot", "when the robot appears"))

_node("TimeExpiredCondition", "condition", (
    _in("seconds", "float", 1.0, "Time to accumulate before the condition holds, in simulation seconds.",
        min=0.0, max=3600.0),
    _time_step("ts"),
    _in("only_once", "bool", False, "Keep succeeding after expiry (true) or restart the count (false)."),
), """
    Counts simulation time while it is ticked and fails until seconds have accumulated, then succeeds
    (and starts counting again unless only_once). Use it under an Inverter to limit how long a reaction
    or activity lasts.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("for a while", "after some time", "time is up", "limit"))

_node("RandomChanceCondition", "condition", (
    _agent_id(),
    _in("probability", "float", 0.3, "Probability of success on each tick.", min=0.0, max=1.0),
), """
    Succeeds at random with the given probability each time it is ticked (seeded, reproducible). Use it
    for behavior that only some people show or that happens now and then: sometimes, occasionally.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("sometimes", "occasionally", "randomly", "some of them", "maybe"))

_node("IsRobotFacingAgent", "condition", (_agent_id(),), """
    Succeeds when the robot's heading points at the agent (within 0.3 rad). Use it for reactions to being
    approached head-on by the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True, synonyms=("robot looks at me", "robot heading toward"))

_node("IsAgentVisible", "condition", (
    _agent_id("observer_id"),
    _other_agent("agent_id", "the agent to look for"),
    _in("distance", "float", 5.0, "Range in metres.", min=0.0, max=50.0),
    _in("field_of_view", "float", 1.57, "Half-angle of the field of view in radians.", min=0.0, max=3.1416),
), """
    Succeeds when another agent is within distance and inside the observer's field of view. Use it for
    reactions to seeing a companion or another person.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("see someone", "spot a friend"))

_node("IsRobotClose", "condition", (
    _agent_id(),
    _in("threshold", "float", 1.0, "Distance in metres below which the robot counts as close.", min=0.0, max=50.0),
), """
    Succeeds when the robot is within threshold metres, whatever the agent's heading. Use it for
    reactions to the robot being near: making way, stopping, stepping aside.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("robot nearby", "robot close", "too close", "near the robot"))

_node("IsAgentClose", "condition", (
    _agent_id("observer_id"),
    _other_agent("target_agent_id"),
    _in("threshold", "float", 1.0, "Distance in metres.", min=0.0, max=50.0),
), """
    Succeeds when the other agent is within threshold metres. Use it to wait for a companion or react to
    a person close by.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("someone near", "companion close"))

_node("IsAtPosition", "condition", (
    _agent_id(),
    _in("goal_id", "int", None, "Id of a global goal (HuNavSim 2.0) to compare with.", auto=True, min=1, max=100000),
    _in("target_x", "float", None, "x of the position (HuNavSim d5b716b variant).", auto=True,
        min=-MAX_COORDINATE, max=MAX_COORDINATE),
    _in("target_y", "float", None, "y of the position (HuNavSim d5b716b variant).", auto=True,
        min=-MAX_COORDINATE, max=MAX_COORDINATE),
    _in("tolerance", "float", 0.1, "Distance in metres.", min=0.0, max=10.0),
), """
    Succeeds when the agent stands within tolerance of a global goal (goal_id) or of target_x/target_y.
    Low-level HuNavSim check kept for compatibility.""", "hunavsim", synonyms=("at position",))

_STATEFUL_COND = "RUNNING while it watches, SUCCESS when it sees it, FAILURE after duration seconds (simulation time)."

_node("IsAnyoneSpeaking", "condition", (
    _agent_id(), _time_step(),
    _in("distance_threshold", "float", 5.0, "Hearing range in metres.", min=0.0, max=50.0),
    _duration(5.0, what="listening"),
    _out("speaker_id", "agent", "Id of the agent heard speaking."),
), f"""
    Listens for any agent within distance_threshold saying something (SaySomething). {_STATEFUL_COND}
    Use it to react to someone talking nearby.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("hear someone", "someone talks", "listen"))

_node("IsSpeaking", "condition", (
    _agent_id(), _time_step(), _other_agent("target_id", "the agent listened to"),
    _in("distance_threshold", "float", 5.0, "Hearing range in metres.", min=0.0, max=50.0),
    _duration(5.0, what="listening"),
), f"""
    Listens for one particular agent saying something within distance_threshold. {_STATEFUL_COND}""",
      "hunavsim", synonyms=("hear",))

_node("IsAnyoneLookingAtMe", "condition", (
    _agent_id(), _time_step(),
    _in("distance_threshold", "float", 5.0, "Range in metres.", min=0.0, max=50.0),
    _in("angle_threshold", "float", 0.2, "Maximum angle in radians between the other's heading and me.",
        min=0.0, max=3.1416),
    _duration(5.0, what="watching"),
    _out("observer_id", "agent", "Id of the agent looking at me."),
), f"""
    Watches for any agent within distance_threshold whose heading points at this agent. {_STATEFUL_COND}
    Use it to react to being looked at.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("someone looks at me", "being watched", "stared at"))

_node("IsLookingAtMe", "condition", (
    _agent_id(), _time_step(), _other_agent("target_id", "the agent watched"),
    _in("distance_threshold", "float", 5.0, "Range in metres.", min=0.0, max=50.0),
    _in("angle_threshold", "float", 0.2, "Maximum angle in radians.", min=0.0, max=3.1416),
    _duration(5.0, what="watching"),
), f"""
    Watches whether one particular agent's heading points at this agent. {_STATEFUL_COND}""",
      "hunavsim", synonyms=("looked at",))

# ---- HuNavSim 2.0 simple actions ------------------------------------------------------------

_node("UpdateGoal", "action", (_agent_id(),), """
    Drops the agent's current goal (and appends it again at the end when goals are cyclic). Low-level
    goal-list bookkeeping of HuNavSim's regular tree.""", "hunavsim", synonyms=("next goal",))

_node("RegularNav", "action", (_agent_id(), _time_step()), """
    Walks toward the current goal of the goal list with the social force model; succeeds every tick.
    HuNavSim's regular navigation step.""", "hunavsim", synonyms=("walk", "navigate"))

_node("SurprisedNav", "action", _reaction_ports(()), """
    Reaction of a surprised person: stops and turns to look at the robot for beh_duration seconds, then
    resumes. Use it for startled, astonished or surprised people who notice the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True,
      synonyms=("surprised", "startled", "astonished", "stop and stare", "amazed", "freeze"))

_node("CuriousNav", "action", _reaction_ports((
    _in("agent_vel", "float", 1.0, "Walking speed toward the robot in m/s.", min=0.0, max=1.8),
    _in("stop_distance", "float", 0.5, "Distance to the robot in metres where the agent stops and looks.",
        min=0.0, max=10.0),
)), """
    Reaction of a curious person: walks toward the robot, slowing down as it gets close, stops at
    stop_distance and looks at it for beh_duration seconds. Use it for curious, interested people, children
    drawn to the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True,
      synonyms=("curious", "interested", "approach the robot", "inspect", "fascinated", "children"))

_node("ScaredNav", "action", _reaction_ports((
    _in("runaway_vel", "float", 1.5, "Speed when fleeing from the robot in m/s.", min=0.0, max=2.5),
    _in("scary_force_factor", "float", 1.0, "Weight of the extra repulsion away from the robot.",
        min=0.0, max=25.0),
)), """
    Reaction of a frightened person: hurries away from the robot with an extra repulsive force for
    beh_duration seconds, then resumes. Use it for scared, afraid, nervous people who avoid the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True,
      synonyms=("scared", "afraid", "frightened", "nervous", "flee", "run away", "keep away"))

_node("ThreateningNav", "action", _reaction_ports((
    _in("goal_dist", "float", 1.0, "Distance in metres in front of the robot the agent heads for.",
        min=0.5, max=5.0),
)), """
    Reaction of an aggressive person: walks fast to a point goal_dist metres in front of the robot and
    stands there facing it for beh_duration seconds, blocking its way. Use it for threatening, hostile,
    aggressive or obstructive people.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True,
      synonyms=("threatening", "aggressive", "hostile", "confront", "obstruct", "get in the way"))

_node("FindNearestAgent", "action", (
    _agent_id(),
    _out("target_agent_id", "agent", "Id of the nearest other agent."),
), """
    Writes the id of the nearest other agent into its output port. Low-level helper for agent-targeted
    nodes.""", "hunavsim", synonyms=("nearest person",))

_node("SaySomething", "action", (
    _agent_id(),
    _in("message", "string", "Hello, I am here!", "What the agent says (shown in the status line)."),
), """
    The agent says a short message, heard by agents nearby (IsAnyoneSpeaking) and shown in the
    simulation status; succeeds at once. Use it for greetings, calls and remarks.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("say", "talk", "shout", "call", "greet", "announce", "speak"))

_node("SetGroupId", "action", (
    _agent_id(),
    _in("group_id", "int", None, "Group id to join (-1 = none).", auto=True, min=-1, max=100000),
), """
    Sets the agent's social-force group so group cohesion forces act with the other members. Low-level;
    generated trees use JoinGroup.""", "hunavsim", synonyms=("group",))

_node("SetGoal", "action", (
    _agent_id(),
    _in("goal_id", "int", None, "Id of the global goal to append.", auto=True, min=1, max=100000),
    *_legacy_point(what="the goal"),
), """
    Appends a global goal (radius 0.1 m) to the agent's goal list; fails if the id is unknown. Low-level
    goal-list bookkeeping; generated trees use GoTo.""", "hunavsim", synonyms=("add goal",))

_node("StopMovement", "action", (_agent_id(),), """
    Sets the agent's speed to zero so it stands still until ResumeMovement; succeeds at once. Use it to
    make a person stop walking on the spot.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("stop", "halt", "stand still", "freeze"))

_node("ResumeMovement", "action", (_agent_id(),), """
    Restores the agent's normal walking speed after StopMovement; succeeds at once.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("resume", "continue walking", "move on"))

# ---- HuNavSim 2.0 stateful actions ----------------------------------------------------------

_node("StopAndWaitTimerAction", "action", (
    _agent_id(),
    _in("wait_duration", "float", 3.0, "Waiting time in simulation seconds.", min=0.0, max=3600.0),
), """
    Stops the agent where it is for wait_duration seconds (RUNNING), then restores its speed and
    succeeds. HuNavSim's timed stop; equivalent to Wait.""",
      "hunavsim", presets=ALL, llm=True, synonyms=("pause", "stop for", "hold on"))

_node("ConversationFormation", "action", (
    _agent_id("main_agent_id"),
    _in("goal_id", "int", None, "Global goal at the centre of the conversation.", auto=True, min=1, max=100000),
    *_legacy_point("center_x", "center_y", "the conversation centre"),
    _duration(10.0, "conversation_duration", "the conversation"),
    _time_step(),
    _in("non_main_agent_ids", "agents", "", "Comma-separated ids of the other participants.", auto=True),
), """
    HuNavSim conversation: the main agent and the listed agents walk to spots on a circle around a goal,
    face its centre and talk for conversation_duration seconds. Generated trees use Converse, which needs
    no ids.""", "hunavsim", synonyms=("conversation",))

_node("ApproachAgent", "action", (
    _agent_id(), _other_agent(), _time_step(),
    _in("closest_dist", "float", 1.5, "Distance in metres at which the agent stops.", min=0.0, max=10.0),
    _in("max_vel", "float", 1.5, "Walking speed in m/s.", min=0.0, max=2.5),
    _duration(5.0, what="the approach"),
), """
    Walks toward another agent until closest_dist metres away, then stands facing it; RUNNING for duration
    seconds, then succeeds. Use it to go up to a companion or a stranger.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("go up to someone", "approach a person", "join a friend"))

_node("ApproachRobot", "action", (
    _agent_id(), _time_step(),
    _in("closest_dist", "float", 1.5, "Distance in metres at which the agent stops.", min=0.0, max=10.0),
    _in("max_vel", "float", 1.8, "Walking speed in m/s.", min=0.0, max=2.5),
    _duration(5.0, what="the approach"),
    _in("behind", "float", 0.0, "When above 0: walk to a place this many metres behind the robot along its "
        "heading, spread by the agent's place among its followers, not at the robot (people the robot leads).",
        min=0.0, max=10.0),
), """
    Walks toward the robot (slowing as it gets near) until closest_dist metres away, then stands facing it;
    RUNNING for duration seconds, then succeeds. Use it for people who go to the robot on purpose.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True, synonyms=("go to the robot", "walk up to the robot", "greet the robot"))

_node("BlockRobot", "action", (
    _agent_id(), _time_step(),
    _in("front_dist", "float", 1.0, "Distance in metres in front of the robot to stand at.", min=0.3, max=5.0),
    _duration(5.0, what="the blocking"),
), """
    Steps into the robot's way, front_dist metres ahead of it, and stays there facing it for duration
    seconds. Use it for people who block or obstruct the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True, synonyms=("block the robot", "stand in the way", "obstruct"))

_node("BlockAgent", "action", (
    _agent_id(), _other_agent(), _time_step(),
    _in("front_dist", "float", 1.0, "Distance in metres in front of the other agent.", min=0.3, max=5.0),
    _duration(5.0, what="the blocking"),
), """
    Steps into another agent's way, front_dist metres ahead of it, for duration seconds.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("block someone", "stand in front of"))

_node("AvoidRobot", "action", (
    _agent_id(), _time_step(),
    _in("safe_distance", "float", 3.0, "Distance in metres the agent keeps from the robot.", min=0.0, max=20.0),
    _in("runaway_vel", "float", 1.5, "Speed when moving away in m/s.", min=0.0, max=2.5),
    _duration(5.0, what="the avoidance"),
), """
    Moves away from the robot until safe_distance metres separate them, then stands facing it; RUNNING for
    duration seconds. Use it for cautious people who keep their distance from the robot.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True, synonyms=("avoid the robot", "keep distance", "step aside", "make way"))

_node("SetGroupWalk", "action", (
    _agent_id("main_agent_id"), _time_step(),
    _in("non_main_agent_ids", "agents", "", "Comma-separated ids of the followers.", auto=True),
    _duration(5.0, what="the group walk"),
), """
    HuNavSim group walk: the listed agents take the main agent's group and goals for duration seconds,
    then get theirs back. Generated trees use JoinGroup, which needs no ids.""", "hunavsim", synonyms=("group walk",))

_node("FollowAgent", "action", (
    _agent_id(), _time_step(), _other_agent(),
    _in("closest_dist", "float", 1.5, "Distance in metres kept behind the followed agent.", min=0.0, max=10.0),
    _in("max_vel", "float", 1.5, "Maximum speed in m/s.", min=0.0, max=2.5),
    _duration(5.0, what="following"),
), """
    Follows another agent, slowing down inside closest_dist (speed max_vel times (d/closest_dist)^2);
    RUNNING for duration seconds, then succeeds. Use it for a child following a parent or a visitor
    following a guide.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("follow", "tag along", "walk behind", "accompany", "trail"))

_node("LookAtAgent", "action", (
    _agent_id("observer_id"), _other_agent("target_id", "the agent to look at"),
    _in("yaw_tolerance", "float", 0.01, "Heading tolerance in radians.", min=0.0, max=3.1416),
), """
    Stops and turns to face another agent; RUNNING while turning, SUCCESS when facing it.""",
      "hunavsim", presets=SOCIAL, llm=True, synonyms=("look at someone", "turn to", "face a person"))

_node("LookAtRobot", "action", (
    _agent_id(),
    _in("yaw_tolerance", "float", 0.01, "Heading tolerance in radians.", min=0.0, max=3.1416),
), """
    Stops and turns to face the robot; RUNNING while turning, SUCCESS when facing it. Use it for people
    watching the robot go by.""",
      "hunavsim", presets=NOT_EMERGENCY, llm=True, synonyms=("look at the robot", "watch the robot", "stare"))

_node("LookAtPoint", "action", (
    _agent_id(),
    _in("goal_id", "int", None, "Global goal to look at.", auto=True, min=1, max=100000),
    *_legacy_point(what="the point to look at"),
    _in("yaw_tolerance", "float", 0.01, "Heading tolerance in radians.", min=0.0, max=3.1416),
), """
    Turns to face a global goal; RUNNING while turning, SUCCESS when facing it. Low-level (goal ids).""",
      "hunavsim", synonyms=("look at",))

# ---- GROVE nodes ------------------------------------------------------------------------------

_node("GoTo", "action", (
    _target(),
    *_xy(),
    _waypoints(),
    _in("tolerance", "float", 0.3, "Distance in metres at which the target counts as reached.", min=0.05, max=5.0),
    _agent_id(),
    _time_step(),
    *_legacy_point(what="the goal"),
    _in("temporary", "bool", False, "Older HuNavSim 2.0 GoTo: a temporary goal (freezes the agent on arrival).",
        auto=True),
    _in("stop_duration", "float", 5.0, "Older HuNavSim 2.0 GoTo: how long a temporary goal freezes the agent.",
        auto=True),
    _in("goal_id", "int", None, "HuNavSim compatibility: a global goal id used when x/y are absent.", auto=True,
        min=1, max=100000),
), """
    Walks to a place of the world (a zone, a door or an object such as a counter, bed or vending machine)
    along the planned collision-free waypoints; RUNNING while walking, SUCCESS on arrival. The basic way
    to send someone somewhere: go to, walk to, head for, visit, leave through a door.""",
      "grove", navigates=True, presets=NOT_EMERGENCY, llm=True,
      synonyms=("go to", "walk to", "head to", "visit", "move to", "enter", "leave", "reach", "arrive", "navigate"))

_node("Wait", "action", (
    _in("duration", "float", 5.0, "Waiting time in simulation seconds.", min=0.0, max=3600.0),
    _agent_id(),
), """
    Stands still where the agent is for duration seconds (RUNNING), then succeeds. Use it for waiting,
    resting, pausing, sitting or standing around for a while.""",
      "grove", presets=ALL, llm=True,
      synonyms=("wait", "rest", "pause", "stand", "linger", "idle", "stay", "sit", "for a while"))

_node("Queue", "action", (
    _target("service_point", "Where the queue is served (usually a counter or desk entity, or a door)"),
    *_xy(),
    _in("spacing", "float", 0.6, "Distance between consecutive people in the line, in metres.", min=0.3, max=3.0),
    _in("service_time", "float", 10.0, "Time the person at the head is served, in simulation seconds.",
        min=0.0, max=3600.0),
    _agent_id(),
), """
    Joins the line of people waiting at a service point: the agent takes the next free slot behind the
    last person (slots spaced along a line leading away from the service point into free space), moves up
    one slot each time the person at the head is served and leaves, is served itself for service_time
    seconds at the head, then succeeds. Use it for queues, lines and waiting your turn at counters,
    pharmacies, ticket booths, reception desks, checkpoints and vending machines.""",
      "grove", presets=NOT_EMERGENCY, llm=True,
      synonyms=("queue", "line up", "wait in line", "stand in line", "wait your turn", "take a ticket", "be served",
                "counter", "checkout"))

_node("FollowVelocityField", "action", (
    _target("exit", "Exit door the crowd flows to"),
    _in("field", "string", None, "Id of the group's velocity field (a key of Scenario.fields).", auto=True),
    *_xy(),
    _agent_id(),
), """
    Moves with the crowd flow of the agent's group: follows a precomputed velocity field that leads around
    obstacles to the exit door, RUNNING until the agent has passed through the exit, then SUCCESS and the
    agent is counted as evacuated. Use it for evacuations, emergencies, fire alarms, everyone leaving the
    building, rushing to the exits.""",
      "grove", presets=EVACUATION, llm=True,
      synonyms=("evacuate", "escape", "flee the building", "emergency exit", "rush out", "fire alarm", "leave the building",
                "exit", "panic"))

_node("Wander", "action", (
    _target("zone", "Zone to roam in"),
    _duration(30.0, what="the wandering"),
    _agent_id(),
), """
    Roams inside a zone, walking to random reachable spots one after another (seeded, reproducible), for
    duration seconds, then succeeds. Use it for browsing, strolling, roaming, walking around, window
    shopping or patrolling an area.""",
      "grove", presets=SOCIAL, llm=True,
      synonyms=("wander", "roam", "stroll", "walk around", "browse", "explore", "mill about", "meander"))

_node("JoinGroup", "action", (
    _in("members", "agents", None, "Comma-separated ids of the agents of the same draft group.", auto=True),
    _in("group_id", "int", None, "Social-force group id shared by the members.", auto=True, min=0, max=100000),
    _agent_id(),
), """
    Makes the agent walk together with the other people of its group: group cohesion forces keep them side
    by side and the group moves at the pace of its slowest member; succeeds at once, so the following
    nodes are done together. Use it for families, friends, couples, tour groups and colleagues walking
    together.""",
      "grove", presets=ALL, llm=True,
      synonyms=("together", "as a group", "family", "friends", "couple", "walk together", "side by side", "tour group"))

_node("Converse", "action", (
    _target("target", "Place where the group gathers to talk"),
    *_xy(),
    _waypoints(),
    _in("members", "agents", None, "Comma-separated ids of the participants (the agent's draft group).", auto=True),
    _duration(20.0, what="the conversation"),
    _agent_id(),
), """
    Gathers the group's people in a conversation circle at a place: each walks to a spot on a circle
    around it (radius 0.5 + 0.2 per extra person), turns to face the centre and talks for duration seconds
    once everyone has arrived, then succeeds. Use it for chatting, talking, meeting, gossiping, greeting
    each other or discussing in a small group.""",
      "grove", navigates=True, presets=SOCIAL, llm=True,
      synonyms=("talk", "chat", "converse", "conversation", "meet", "gossip", "discuss", "catch up", "gather"))


NODES: dict[str, NodeSpec] = {spec.name: spec for spec in _specs}
del _specs

# names the XML format reserves besides NODES (handled by the parser itself)
SUBTREE = "SubTree"


def nodes_for_preset(preset: str, *, llm_only: bool = True) -> list[NodeSpec]:
    """Nodes the given preset may offer; unknown (user) presets get the vanilla set."""
    key = preset if preset in PRESETS else "vanilla"
    return [s for s in NODES.values() if key in s.presets and (s.llm or not llm_only)]


def navigation_nodes() -> frozenset[str]:
    return frozenset(name for name, spec in NODES.items() if spec.navigates)


def _default_text(port: PortSpec) -> str | None:
    if port.default is None:
        return None
    if isinstance(port.default, bool):
        return "true" if port.default else "false"
    return str(port.default)


def treenodes_model_xml(renamed: dict[str, str] | None = None) -> str:
    """The manifest as a Groot2 TreeNodesModel (BT.CPP v4); built-in control nodes are omitted.

    `renamed` gives some nodes another ID (the HuNavSim export keeps GROVE nodes as Grove<Node>).
    Built as an lxml tree, so every ID, port name, default and description is escaped by the writer."""
    renamed = renamed or {}
    tag = {"control": "Control", "decorator": "Decorator", "action": "Action", "condition": "Condition"}
    root = etree.Element("root", BTCPP_format="4")
    model = etree.SubElement(root, "TreeNodesModel")
    for spec in NODES.values():
        if spec.origin == "btcpp":
            continue
        node = etree.SubElement(model, tag[spec.category], ID=renamed.get(spec.name, spec.name))
        for port in spec.ports:
            kind = "input_port" if port.direction == "in" else "output_port"
            element = etree.SubElement(node, kind, name=port.name, type=_BTCPP_TYPE[port.type])
            default = _default_text(port)
            if default is not None:
                element.set("default", default)
            element.text = port.description
        metadata = etree.SubElement(node, "MetadataFields")
        etree.SubElement(metadata, "Metadata", description=spec.description)
    etree.indent(root, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(root, encoding="unicode", pretty_print=True)
