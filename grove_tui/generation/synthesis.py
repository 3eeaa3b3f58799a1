"""Tactical layer: the bt model writes the draft (a tree per group) under a grammar.

The prompt is built for KV prefix reuse (issue 33): what repeats comes first. The system message is
fixed per world and preset (the preset's template, the draft format, the world's one-line
description, then the preset's pinned node cards in a stable order: its everyday vocabulary); its
KV state is cached live and on disk. What varies comes last in the user message, in compact form:
the selected places, the cards retrieval found beyond the pinned ones (stable order), the sentence
and its groups. A sentence whose cards are all pinned prefills only that tail.

The reading (language/) already fixes each group's label, count, places and intent, so the model
writes only what it leaves open: one line per reading group, the group's tree (the lean draft,
draft.tree_grammar); label, count and spawn are filled in from the reading (draft.GroupHead). A
sentence the reader found no groups in gets the full draft (`COUNT LABEL from SPAWN: TREE`).
The vanilla baseline keeps the whole world and the full node documents. The grammar allows exactly
the offered node types and selected RoI names (generation/draft.py), so the model cannot name a
node that was not offered or a place that does not exist. An answer that still fails the draft
check is retried with the next seed.
"""

from __future__ import annotations

import hashlib
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from grove_tui.bt.format.manifest import NODES
from grove_tui.errors import DraftError, GenerationError
from grove_tui.generation.draft import Draft, GroupHead, draft_grammar, parse_draft, parse_trees, tree_grammar
from grove_tui.generation.presets import Preset
from grove_tui.generation.rois import RoISelection
from grove_tui.language.model import PromptReading, effective_counts
from grove_tui.jsontypes import JSONObject
from grove_tui.world.model import World

if TYPE_CHECKING:
    from grove_tui.generation.retrieval import RetrievedNode
    from grove_tui.llm.local import LocalLLM

MAX_ATTEMPTS = 3
# With pinned cards, a retrieved card outside them is shown (and offered) when it scores at least this
# share of the best retrieved score (prepare_request).
RELEVANT_SHARE = 0.8
# Bump when the prompt's wording or layout changes: persisted KV caches of the fixed prefix are keyed by it.
PROMPT_TEMPLATE_VERSION = 4

# The draft syntax (generation/draft.py): the model learns it from these lines and the node cards,
# which show each node in the same form.
_RULES = """Write one line per group of people: COUNT LABEL from SPAWN: TREE
- COUNT: how many, LABEL: who they are (one word), SPAWN: the place where they start.
- TREE: their behavior, a node written Node(required values, optional port=value, children).
  Only control nodes have children. Use only the node types and place names given below.
Ids, coordinates and paths are filled in later: never write them."""

_EXAMPLE = """Example:
3 visitors from lobby: Sequence(GoTo(cafe), Wait(duration=30))"""

# The lean draft: the reading gives label, count and start, so each line is only a tree.
_LEAN_RULES = """Write one line per group listed under Groups, in that order: the group's behavior tree.
- A node is written Node(required values, optional port=value, children).
  Only control nodes have children. Use only the node types and place names given.
Counts, start places, ids, coordinates and paths are filled in later: never write them."""

_LEAN_EXAMPLE = """Example, for the groups
1. visitor x3: walk, destination cafe
2. guard x1: wait, location lobby
write:
Sequence(GoTo(cafe), Wait(duration=30))
Sequence(GoTo(lobby), Wait(duration=600))"""


@dataclass(frozen=True)
class RetrievedDoc:
    name: str
    kind: str
    score: float
    nodes: tuple[str, ...]
    text: str  # the full document (the vanilla baseline reads it)
    card: str = ""  # its one-line card (guided presets read it)


@dataclass
class SynthesisRequest:
    """Everything the bt model is asked, kept for generation.json and the token benchmark."""

    messages: list[dict[str, str]]
    node_names: list[str]
    roi_names: list[str]
    grammar: str  # the GBNF of every draft this request allows (draft.draft_grammar)
    max_groups: int  # the grammar's bound on groups, which parse_draft holds the answer to as well
    documents: list[RetrievedDoc] = field(default_factory=list)
    prefix_label: str = ""  # names the persisted KV state of messages[0] (world, its file hash, preset, version)
    # The lean draft's groups, from the reading: the model writes one tree per head. Empty: the full draft.
    heads: list[GroupHead] = field(default_factory=list)


@dataclass
class SynthesisResult:
    draft: Draft
    text: str
    prompt_tokens: int
    completion_tokens: int
    attempts: int
    seconds: float
    request: SynthesisRequest
    errors: list[str] = field(default_factory=list)
    first_token_seconds: float | None = None  # prompt evaluation (prefill) of the accepted attempt
    cached_tokens: int = 0  # prompt tokens of the accepted attempt served from a live or persisted KV cache
    cache_source: str = "cold"  # "live", "disk" or "cold"


def offered_nodes(preset: Preset, retrieved_nodes: Sequence[str]) -> list[str]:
    """Node types the model may use: the preset's control nodes plus retrieved leaves it allows."""
    key = preset.name if preset.name in ("emergency", "queuing", "normal", "vanilla") else None

    def usable(name: str) -> bool:
        spec = NODES.get(name)
        if spec is None or not spec.llm or name in preset.forbidden_nodes:
            return False
        if key is not None and key not in spec.presets:
            return False
        return not preset.allowed_nodes or name in preset.allowed_nodes or name in preset.required_nodes

    if preset.retrieval_filter is None:
        # The baseline offers every node the manifest lets a model write.
        leaves = [n for n, s in NODES.items() if s.llm and s.category not in ("control",) and usable(n)]
    else:
        leaves = [n for n in dict.fromkeys(list(preset.required_nodes) + list(retrieved_nodes))
                  if NODES.get(n) is not None and NODES[n].category != "control" and usable(n)]
    controls = [n for n in preset.control_nodes if n in NODES]
    if not leaves:
        raise GenerationError(f"preset '{preset.name}' leaves no behavior node to use for this prompt; "
                              "add required nodes to the preset")
    return controls + leaves


def choose_documents(preset: Preset, retrieved: Sequence[RetrievedNode], offered: Sequence[str],
                     documents_for: Callable[[list[str]], list[str]],
                     cards_for: Callable[[list[str]], list[str]] | None = None) -> list[RetrievedDoc]:
    """Retrieved documents about offered nodes, plus the documents of required nodes not retrieved."""
    offered_set = set(offered)
    docs: list[RetrievedDoc] = []
    covered: set[str] = set()
    for r in retrieved:
        if set(r.nodes) <= offered_set:
            docs.append(RetrievedDoc(r.name, r.kind, float(r.score), tuple(r.nodes), r.document, getattr(r, "card", "")))
            covered |= set(r.nodes)
    missing = [n for n in offered if n not in covered and (n in preset.required_nodes or preset.retrieval_filter is None)]
    if preset.retrieval_filter is None:
        missing = [n for n in offered if n not in covered]
    if missing:
        cards = cards_for(missing) if cards_for is not None else [""] * len(missing)
        for name, text, card in zip(missing, documents_for(missing), cards):
            docs.append(RetrievedDoc(name, "node", 0.0, (name,), text, card))
    return docs


def describe_reading_groups(reading: PromptReading, indices: Sequence[int] | None = None) -> str:
    """The reading's groups as the model's task: who, how many, what, where ("Groups to write: ...")."""
    parts = []
    for index, g in enumerate(reading.groups):
        if indices is not None and index not in indices:
            continue
        text = f"{g.label} x{g.count.value}: {g.intent}"
        if g.robot_interaction:
            text += f" ({g.robot_interaction} the robot)"
        for key in ("start", "location", "destination"):
            value = getattr(g, key)
            if value:
                text += f", {key} {value}"
        if g.via:
            text += ", via " + " ".join(g.via)
        if g.together:
            text += ", together"
        parts.append(text)
    return "; ".join(parts)


def fixed_system_message(preset: Preset, world: World | None = None, cards: Sequence[str] = (),
                         lean: bool = True) -> str:
    """The system message: everything fixed for a world and preset, so its KV state can be cached.

    `cards` are the preset's pinned node cards (pinned_cards), `lean` the draft the model writes:
    one tree per reading group, or the full `COUNT LABEL from SPAWN: TREE` lines."""
    if not preset.guided:
        return preset.template  # the baseline: no scenario-specific guidance
    rules, example = (_LEAN_RULES, _LEAN_EXAMPLE) if lean else (_RULES, _EXAMPLE)
    if lean and "Example" in preset.template:
        example = ""  # the preset shows trees of its own kind (a small model copies the example's shape)
    system = f"{preset.template.rstrip()}\n\n{rules}" + (f"\n{example}" if example else "")
    description = " ".join(str(getattr(world, "description", "") or "").split())
    if world is not None:
        system += f"\n\nWorld {world.name}" + (f": {description}" if description else "")
    if cards:
        system += "\n\nNodes:\n" + "\n".join(cards)
    return system


def pinned_documents(preset: Preset,
                     documents_named: Callable[[list[str]], list[RetrievedNode]] | None) -> list[RetrievedNode]:
    """The preset's pinned documents the model may use (their nodes offered whatever the sentence), in order.

    Fixed per preset, so the system message that shows them is fixed per world and preset."""
    if not preset.guided or documents_named is None or not preset.pinned_documents:
        return []
    docs = list(documents_named(list(preset.pinned_documents)))
    offered = set(offered_nodes(preset, [n for d in docs for n in d.nodes]))
    return [d for d in docs if set(d.nodes) <= offered]


def pinned_cards(preset: Preset, documents_named: Callable[[list[str]], list[RetrievedNode]] | None) -> list[str]:
    return [(getattr(d, "card", "") or d.document).strip() for d in pinned_documents(preset, documents_named)]


def group_heads(reading: PromptReading | None, selection: RoISelection,
                max_groups: int) -> tuple[list[GroupHead], list[int]]:
    """The lean draft's groups: each reading group with people of its own, its label, count and start.

    The start is the reading's (where they start, else where they stay); a group the sentence starts
    nowhere gets the selection's first zone, which reconciliation moves off their destination as it
    does for any spawn (reconcile._spawn). Returns the heads and their reading indices."""
    if reading is None or not reading.groups:
        return [], []
    counts = effective_counts(reading)
    default = selection.zones[0] if selection.zones else selection.roi_names[0]
    heads, indices = [], []
    for index, g in enumerate(reading.groups):
        if counts.get(index, 0) <= 0:
            continue
        heads.append(GroupHead(g.label, counts[index], g.start or g.location or default))
        indices.append(index)
    return heads[:max_groups], indices[:max_groups]


def prefix_label(preset: Preset, world: World | None) -> str:
    """What the fixed system message's cached KV state is for: world (and its file's hash), preset, template version.

    The prefix's tokens are part of the cache key as well, so this only has to name the file and to
    keep caches of different worlds and presets apart when their text happens to agree.
    """
    source = getattr(world, "source", None)
    digest = ""
    if source is not None:
        try:
            stat = Path(source).stat()
            digest = _file_digest(str(source), stat.st_size, stat.st_mtime_ns)
        except OSError:
            digest = "unread"
    name = getattr(world, "name", "none")
    return f"{name}-{digest}-{preset.name}-v{PROMPT_TEMPLATE_VERSION}"


@lru_cache(maxsize=64)
def _file_digest(path: str, size: int, mtime_ns: int) -> str:
    """The file's hash, once per version of it (size and mtime in the key): big worlds are megabytes."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()[:12]


def lean_places(world: World | None, selection: RoISelection, reading: PromptReading,
                indices: Sequence[int]) -> list[str]:
    """The places a lean draft may name: where the groups are, go and pass (location, destination, via),
    the zones those lie in and the selected exits, in the selection's order. The reading has already
    fixed where each group is and goes, so the model is not offered every place the selection holds
    for planning; nor where a group starts, which its head gives (a small model offered it walked
    there first: "GoTo(kitchen)" for people who start in the kitchen). A sentence that names no such
    place keeps the whole selection."""
    selected = list(selection.roi_names)
    wanted: set[str] = set(selection.exits)
    named = {p for i in indices for g in (reading.groups[i],)
             for p in (g.location, g.destination, *g.via) if p}
    if not named & set(selected) or world is None:
        evacuating = any(reading.groups[i].intent == "evacuate" for i in indices)
        exits = [name for name in selected if name in wanted]
        return exits if evacuating and exits else selected  # evacuees need only the way out
    wanted |= named
    for name in named:
        try:
            wanted.add(world.roi(name).zone)
        except Exception:  # a place the world does not know is the reader's note, not this list's
            continue
    return [name for name in selected if name in wanted]


def describe_places(world: World | None, names: Sequence[str]) -> str:
    """One line per place: `- pharmacy_counter (counter in pharmacy)`, `- pharmacy (pharmacy)`."""
    lines = []
    for name in names:
        try:
            roi = world.roi(name) if world is not None else None
        except Exception:
            roi = None
        if roi is None:
            lines.append(f"- {name}")
        elif roi.kind == "zone":
            lines.append(f"- {name} ({roi.type})")
        else:
            kind = "exit" if roi.exit else roi.type
            lines.append(f"- {name} ({kind} in {roi.zone})")
    return "\n".join(lines)


def _stable(documents: Sequence[RetrievedDoc]) -> list[RetrievedDoc]:
    """Cards in an order that does not depend on retrieval scores: nodes, then templates, by name."""
    return sorted(documents, key=lambda d: (d.kind != "node", d.name))


def build_messages(preset: Preset, places: str, documents: Sequence[RetrievedDoc], reading: PromptReading,
                   roi_names: Sequence[str], world: World | None = None, pinned: Sequence[RetrievedDoc] = (),
                   group_indices: Sequence[int] | None = None) -> list[dict[str, str]]:
    """The system message fixed per world and preset first (pinned cards included); the variable parts
    (places, the other cards, the sentence and its groups) last.

    `group_indices`: the reading groups of a lean draft (one tree each, numbered in this order); None
    asks for the full draft."""
    prompt = reading.prompt
    lean = group_indices is not None
    system = fixed_system_message(preset, world, [(d.card or d.text).strip() for d in pinned], lean=lean)
    if not preset.guided:
        parts = ["Places:", places, "", "Behavior nodes:"]
        parts += [d.text.strip() for d in documents]
        parts += ["", f"Scenario: {prompt.strip()}"]
        return [{"role": "system", "content": system}, {"role": "user", "content": "\n".join(parts)}]
    # The places list names exactly what the grammar lets the draft use, so no separate name list.
    parts = ["Places:", places]
    pinned_names = {d.name for d in pinned}
    others = _stable([d for d in documents if d.name not in pinned_names])
    if others:
        parts += ["Nodes:"] + [(d.card or d.text).strip() for d in others]
    parts.append(f"Scenario: {prompt.strip()}")
    if lean:
        parts.append("Groups:")
        parts += [f"{number}. {describe_reading_groups(reading, [index])}"
                  for number, index in enumerate(group_indices or (), 1)]
    elif reading.groups:
        parts.append("Groups to write: " + describe_reading_groups(reading))
    return [{"role": "system", "content": system}, {"role": "user", "content": "\n".join(parts)}]


def prepare_request(preset: Preset, selection: RoISelection, retrieved: Sequence[RetrievedNode], reading: PromptReading,
                    documents_for: Callable[[list[str]], list[str]], world: World | None = None,
                    cards_for: Callable[[list[str]], list[str]] | None = None,
                    documents_named: Callable[[list[str]], list[RetrievedNode]] | None = None) -> SynthesisRequest:
    """The bt model's request: offered nodes, the prompt, and the grammar of every draft it may write.

    `documents_named` looks documents up by name (NodeRetriever.documents_named): the preset's pinned
    cards come from it, ahead of what retrieval found."""
    pinned_found = pinned_documents(preset, documents_named)
    pinned_names = {d.name for d in pinned_found}
    if pinned_found:
        # Beside the pinned vocabulary, a retrieved card earns its prefill only if retrieval ranks it
        # close to its best match ("look at the robot": the robot nodes; not a robot greeting at 0.3
        # for "two visitors walk to the lobby", which retrieval's top-k carries along).
        top = max((float(r.score) for r in retrieved), default=0.0)
        retrieved = [r for r in retrieved if r.name in pinned_names or float(r.score) >= RELEVANT_SHARE * top]
    retrieved = list(pinned_found) + [r for r in retrieved if r.name not in pinned_names]
    retrieved_nodes = [n for r in retrieved for n in r.nodes]
    offered = offered_nodes(preset, retrieved_nodes)
    documents = choose_documents(preset, retrieved, offered, documents_for, cards_for)
    pinned = [d for d in documents if d.name in pinned_names]
    heads, indices = group_heads(reading, selection, preset.limits.max_groups) if preset.guided else ([], [])
    roi_names, places = list(selection.roi_names), selection.summary
    if heads:
        roi_names = lean_places(world, selection, reading, indices)
        places = describe_places(world, roi_names)
        grammar = tree_grammar(offered, roi_names, len(heads), max_depth=preset.limits.max_depth)
        max_groups = len(heads)
    else:
        # Post-processing keeps one group per group of the reading, so asking for more only costs tokens.
        groups = len(effective_counts(reading))
        max_groups = min(preset.limits.max_groups, groups) if preset.guided and groups else preset.limits.max_groups
        grammar = draft_grammar(offered, selection.roi_names, max_groups=max_groups,
                                max_count=preset.limits.max_count, max_depth=preset.limits.max_depth)
    messages = build_messages(preset, places, documents, reading, roi_names, world, pinned,
                              indices if heads else None)
    return SynthesisRequest(messages, list(offered), roi_names, grammar, max_groups, documents,
                            prefix_label(preset, world), heads)


# Cut-off answers: LocalLLM.generate(length_retries=0) raises ModelError with this phrase when the
# answer filled its token budget (tests/llm/test_llm.py holds the llm to it). Synthesis retries a
# cut-off itself, once per attempt with twice the budget and the next seed (what LocalLLM's own
# length retry did), so every model call is an attempt the caller is told about.
CUT_OFF_PHRASE = "did not finish its answer"
CUT_OFF_RETRIES = 1


def is_cut_off(exc: BaseException) -> bool:
    """Whether a model error is an answer that ran out of tokens (worth a retry with a larger budget)."""
    from grove_tui.errors import ContextTooSmallError, ModelError

    return isinstance(exc, ModelError) and not isinstance(exc, ContextTooSmallError) and CUT_OFF_PHRASE in str(exc)


def synthesize(llm: LocalLLM, request: SynthesisRequest, preset: Preset, seed: int,
               on_token: Callable[[str], None] | None = None, cancel: threading.Event | None = None,
               max_tokens: int = 512, on_attempt: Callable[[int, str], None] | None = None) -> SynthesisResult:
    """Generate and parse the draft; retry with the next seed when the answer does not validate.

    Every model call is one attempt: an answer cut off at its token budget is asked again with twice
    the budget, an answer that fails the draft check with the next seed. Before every attempt after
    the first, `on_attempt(attempt, reason)` says why, so a stream of tokens can start afresh there.
    """
    from grove_tui.errors import ModelError

    grammar = request.grammar
    errors: list[str] = []
    prompt_tokens = completion_tokens = 0
    seconds = 0.0
    attempt = 0
    streamed = [0]  # tokens of the running call: what a cut-off call spent (it returns no Generation)

    def relay(text: str) -> None:
        streamed[0] += 1
        if on_token is not None:
            on_token(text)

    def begin(reason: str) -> None:
        nonlocal attempt
        attempt += 1
        streamed[0] = 0
        if attempt > 1 and on_attempt is not None:
            on_attempt(attempt, reason)

    reason = ""
    for draft_try in range(1, MAX_ATTEMPTS + 1):
        draft_seed = int(seed) * 7919 + draft_try - 1
        budget = max_tokens
        for cut_try in range(CUT_OFF_RETRIES + 1):
            begin(reason)
            started = time.monotonic()
            try:
                generation = llm.generate(request.messages, grammar=grammar, max_tokens=budget,
                                          seed=draft_seed + cut_try, on_token=relay, cancel=cancel, length_retries=0,
                                          prefix_label=request.prefix_label)
            except ModelError as exc:
                if not is_cut_off(exc):
                    raise
                completion_tokens += streamed[0]
                seconds += time.monotonic() - started
                if cut_try == CUT_OFF_RETRIES:
                    raise ModelError(
                        f"the bt model did not finish its answer within {budget} tokens (attempt {attempt}); "
                        "the output was cut off, so it was not used",
                        hint="Ask for fewer groups in the prompt, or try another seed.") from None
                reason = f"cut off at {budget} tokens"
                budget *= 2
                continue
            break
        prompt_tokens = generation.prompt_tokens
        completion_tokens += generation.completion_tokens
        seconds += generation.seconds
        try:
            if request.heads:
                draft = parse_trees(generation.text, request.heads, request.node_names, request.roi_names,
                                    max_depth=preset.limits.max_depth)
            else:
                draft = parse_draft(generation.text, request.node_names, request.roi_names,
                                    max_groups=request.max_groups,
                                    max_count=preset.limits.max_count, max_depth=preset.limits.max_depth)
        except DraftError as exc:
            errors.append(f"attempt {attempt}: {exc}")
            reason = f"invalid draft: {exc}"
            continue
        return SynthesisResult(draft, generation.text, prompt_tokens, completion_tokens, attempt, seconds, request, errors,
                               generation.first_token_seconds, int(getattr(generation, "cached_tokens", 0)),
                               str(getattr(generation, "cache_source", "cold")))
    raise GenerationError(f"the bt model wrote no valid draft in {attempt} attempts: " + "; ".join(errors))


def draft_summary(draft: Draft) -> list[JSONObject]:
    from grove_tui.generation.draft import node_to_dict

    return [{"label": g.label, "count": g.count, "spawn": g.spawn, "tree": node_to_dict(g.tree)} for g in draft.groups]


def describe_documents(documents: Sequence[RetrievedDoc]) -> list[JSONObject]:
    return [{"name": d.name, "kind": d.kind, "score": d.score, "nodes": list(d.nodes)} for d in documents]



def warm_prefix(llm: LocalLLM, preset: Preset, world: World | None,
                documents_named: Callable[[list[str]], list[RetrievedNode]] | None = None) -> dict[str, object] | None:
    """Evaluate the fixed system message of this world and preset once, before the first request.

    The worker keeps its KV state live and persists it (keyed as prefix_label says), so the first
    scenario's synthesis evaluates only its own part of the prompt (issue 20: the first scenario
    within 1.5x of a warm one; with Qwen3-4B the prefix alone is over ten seconds of prefill). The
    system message is the lean draft's with the preset's pinned cards (`documents_named` finds them,
    as prepare_request does). The stand-in user message only marks where the prefix ends: the worker
    evaluates and keeps the tokens before it. None when the model cannot evaluate without sampling
    (a test's scripted LLM).
    """
    evaluate = getattr(llm, "evaluate", None)
    if evaluate is None:
        return None
    system = fixed_system_message(preset, world, pinned_cards(preset, documents_named))
    messages = [{"role": "system", "content": system}, {"role": "user", "content": "."}]
    return dict(evaluate(messages, prefix_label(preset, world)))
