"""Shared test set-up: the network is blocked for every test, models load by local path only."""

from __future__ import annotations

import atexit
import functools
import os
import shutil
import socket
import tempfile
from pathlib import Path

import pytest

os.environ.setdefault("HF_HUB_OFFLINE", "1")
# Tests never read or write the user's own cache, config or models: a user's config.yaml naming a
# model, or a stale index, must not change what the suite checks. Subprocesses inherit these.
_sandbox = tempfile.mkdtemp(prefix="grove-tests-")
# The suite's caches (a node index, KV caches, bundles) are hundreds of MB: gone when the run ends.
atexit.register(shutil.rmtree, _sandbox, ignore_errors=True)
for _name in ("CACHE", "CONFIG", "DATA"):
    os.environ.setdefault(f"GROVE_{_name}_DIR", os.path.join(_sandbox, _name.lower()))
# The cache every test that runs `grove` as a user would shares (the node index, the assembled RoI model,
# the prompts' KV caches): built once per suite, like once per machine (tests/helpers/terminal.py).
os.environ.setdefault("GROVE_TEST_CACHE_DIR", os.environ["GROVE_CACHE_DIR"])
for _name in ("GROVE_MODEL", "GROVE_ROI_MODEL", "GROVE_BT_MODEL"):
    os.environ.pop(_name, None)
os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
os.environ.setdefault("ANONYMIZED_TELEMETRY", "False")

_LOOPBACK = ("127.", "::1", "localhost")


class NetworkBlocked(RuntimeError):
    pass


def _is_loopback(address: object) -> bool:
    if isinstance(address, tuple) and address:
        host = str(address[0])
        return host.startswith(_LOOPBACK)
    if isinstance(address, (str, bytes)):  # AF_UNIX paths
        return True
    return False


_real_connect = socket.socket.connect
_real_connect_ex = socket.socket.connect_ex
_real_getaddrinfo = socket.getaddrinfo


def _guarded_connect(self: socket.socket, address: object) -> None:
    if not _is_loopback(address):
        raise NetworkBlocked(f"test tried to reach the network: {address!r}")
    return _real_connect(self, address)


def _guarded_connect_ex(self: socket.socket, address: object) -> int:
    if not _is_loopback(address):
        raise NetworkBlocked(f"test tried to reach the network: {address!r}")
    return _real_connect_ex(self, address)


def _guarded_getaddrinfo(host, *args, **kwargs):  # type: ignore[no-untyped-def]
    if host is not None and not str(host).startswith(_LOOPBACK) and host not in ("", b""):
        raise NetworkBlocked(f"test tried to resolve a network host: {host!r}")
    return _real_getaddrinfo(host, *args, **kwargs)


@pytest.fixture(autouse=True, scope="session")
def block_network():
    """Socket guard: only loopback (the tests' own servers) is reachable."""
    socket.socket.connect = _guarded_connect  # type: ignore[method-assign]
    socket.socket.connect_ex = _guarded_connect_ex  # type: ignore[method-assign]
    socket.getaddrinfo = _guarded_getaddrinfo  # type: ignore[assignment]
    yield
    socket.socket.connect = _real_connect  # type: ignore[method-assign]
    socket.socket.connect_ex = _real_connect_ex  # type: ignore[method-assign]
    socket.getaddrinfo = _real_getaddrinfo


# ---- `slow` marks every test that runs a real model (and any test that takes more than a second or so) -
# `python -m pytest -m "not slow"` is the fast run for daily work. It stays fast only if no test in it
# starts a llama.cpp worker (the embedded model, a tiny Qwen3, any GGUF), the sentence-transformers
# embedder or the ChromaDB node index; so the ways in are watched here and such a test without the mark
# fails, saying so. (A model loaded by a child process, `grove ...` run as a subprocess or a Ray worker,
# is not seen here: `--durations` shows those tests.)

_MODELS_USED: list[str] = []


def _watch(owner: object, name: str, what: str) -> None:
    original = getattr(owner, name)

    @functools.wraps(original)
    def watched(*args, **kwargs):  # type: ignore[no-untyped-def]
        _MODELS_USED.append(what)
        return original(*args, **kwargs)

    setattr(owner, name, watched)


def pytest_configure(config: pytest.Config) -> None:
    from grove_tui.generation import retrieval
    from grove_tui.llm.local import LocalLLM

    _watch(LocalLLM, "_ensure_worker", "a llama.cpp model (LocalLLM)")
    _watch(retrieval, "embedding_model", "the sentence-transformers embedder")
    _watch(retrieval.NodeRetriever, "ensure_index", "the ChromaDB node index")


@pytest.hookimpl(wrapper=True)
def pytest_runtest_setup(item: pytest.Item):  # type: ignore[no-untyped-def]
    _MODELS_USED.clear()  # a module's model fixture is set up in its first test's setup: that test uses it
    return (yield)


@pytest.hookimpl(wrapper=True)
def pytest_runtest_call(item: pytest.Item):  # type: ignore[no-untyped-def]
    result = yield
    used = sorted(set(_MODELS_USED))
    if used and item.get_closest_marker("slow") is None:
        pytest.fail(f"{item.nodeid} uses {', '.join(used)} but is not marked `slow`: add @pytest.mark.slow "
                    "(or pytestmark = pytest.mark.slow for a module of such tests)", pytrace=False)
    return result


# ---- shared worlds: one fixture each, used across tiers ------------------------------------------


@pytest.fixture(scope="session")
def clinic(tmp_path_factory):
    """The small clinic world of tests/helpers/clinic.py, loaded from a real file (bundles name it)."""
    from helpers.clinic import CLINIC

    from grove_tui.world import parse_world

    path = tmp_path_factory.mktemp("world") / "clinic.yaml"
    path.write_text(CLINIC)
    world, problems = parse_world(CLINIC, str(path))
    assert not problems, problems
    return world


@pytest.fixture(scope="module")
def hall():
    """The hall of tests/helpers/hall.py: (world, grid, Theta* planner)."""
    from helpers.hall import HALL

    from grove_tui.navigation.grid import build_grid
    from grove_tui.navigation.theta_star import ThetaStarPlanner
    from grove_tui.world import parse_world

    world, problems = parse_world(HALL, "hall.yaml")
    assert not problems
    grid = build_grid(world)
    return world, grid, ThetaStarPlanner(grid)


@pytest.fixture(scope="session")
def hospital():
    """The shipped hospital world (load_world caches it: every caller gets the same object)."""
    from grove_tui.world import load_world

    return load_world("hospital")


@pytest.fixture(scope="session")
def library():
    """The library of eval/understanding/worlds, a world no reader rule was written for."""
    from grove_tui.world import load_world

    return load_world(str(Path(__file__).parents[1] / "eval" / "understanding" / "worlds" / "library.yaml"))


# ---- hand-built bundles: the hospital scenario of tests/helpers/handmade.py ----------------------


@pytest.fixture(scope="module")
def bundle(tmp_path_factory):
    """The hand-built hospital bundle (queue, conversation, a Surprised agent, a robot), not simulated."""
    from helpers.handmade import build_hospital_bundle

    return build_hospital_bundle(tmp_path_factory.mktemp("bundle") / "bundle")


@pytest.fixture(scope="session")
def _hospital_runs(tmp_path_factory):
    """Simulated hand-built hospital bundles by duration, each simulated once per session (read-only)."""
    from helpers.handmade import build_hospital_bundle

    from grove_tui.services.session import GroveSession

    runs: dict[float, object] = {}

    def run(seconds: float):
        if seconds not in runs:
            bundle = build_hospital_bundle(tmp_path_factory.mktemp(f"run_{seconds:g}s") / "bundle")
            GroveSession().simulate(bundle, seconds)
            runs[seconds] = bundle
        return runs[seconds]

    return run


@pytest.fixture(scope="module")
def simulated(request, tmp_path_factory, _hospital_runs):
    """The hand-built hospital bundle after a real simulation of the module's SIMULATED_SECONDS (3 s if it
    names none): one run per duration per session, copied so that each module owns what it writes."""
    import shutil

    seconds = float(getattr(request.module, "SIMULATED_SECONDS", 3.0))
    copy = tmp_path_factory.mktemp("simulated") / "bundle"
    shutil.copytree(_hospital_runs(seconds), copy, symlinks=True)
    return copy


@pytest.fixture()
def simulated_copy(simulated, tmp_path):
    """A copy of `simulated` that one test may damage."""
    import shutil

    copy = tmp_path / "bundle"
    shutil.copytree(simulated, copy, symlinks=True)
    return copy


# ---- real models: the embedded SmolLM2, a tiny random Qwen3, the node index ----------------------


@pytest.fixture(scope="module")
def llm():
    """The embedded model (SmolLM2-135M) for behavior trees, one worker per module."""
    from grove_tui.llm.embedded import embedded_model_path
    from grove_tui.llm.local import LocalLLM

    model = LocalLLM(embedded_model_path(), role="bt")
    yield model
    model.close()


@pytest.fixture(scope="module")
def tiny_path(tmp_path_factory):
    """A two-layer Qwen3-architecture GGUF with random weights (tests/helpers/tiny_qwen3.py)."""
    from helpers.tiny_qwen3 import build_tiny_qwen3

    return build_tiny_qwen3(tmp_path_factory.mktemp("qwen3") / "tiny-qwen3.gguf")


@pytest.fixture(scope="module")
def tiny_llm(tiny_path):
    """The tiny Qwen3 served as the behavior-tree model, one thread, 1024 tokens of context."""
    from grove_tui.llm.local import LocalLLM

    model = LocalLLM(tiny_path, role="bt", n_ctx=1024, n_threads=1)
    yield model
    model.close()


@pytest.fixture(scope="module")
def retriever():
    """The node retriever on the suite's index (built once in the sandboxed cache, then reused)."""
    from grove_tui.generation.retrieval import NodeRetriever

    return NodeRetriever()


# ---- services ------------------------------------------------------------------------------------


@pytest.fixture()
def shared_index(monkeypatch):
    """The retrieval index is built once per machine: reuse the suite's (GROVE_TEST_CACHE_DIR) when it has one."""
    if os.environ.get("GROVE_TEST_CACHE_DIR"):
        monkeypatch.setenv("GROVE_CACHE_DIR", os.environ["GROVE_TEST_CACHE_DIR"])


@pytest.fixture(scope="module")
def session():
    """A GroveSession for a module's tests, closed after them."""
    from grove_tui.services.session import GroveSession

    with GroveSession() as s:
        yield s
