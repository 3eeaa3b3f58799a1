"""Shared test set-up: the network is blocked for every test, models load by local path only."""

from __future__ import annotations

import os
import socket
import tempfile

import pytest

os.environ.setdefault("HF_HUB_OFFLINE", "1")
# Tests never read or write the user's own cache, config or models: a user's config.yaml naming a
# model, or a stale index, must not change what the suite checks. Subprocesses inherit these.
_sandbox = tempfile.mkdtemp(prefix="grove-tests-")
for _name in ("CACHE", "CONFIG", "DATA"):
    os.environ.setdefault(f"GROVE_{_name}_DIR", os.path.join(_sandbox, _name.lower()))
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
