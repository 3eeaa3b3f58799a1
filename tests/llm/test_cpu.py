"""Sizing llama.cpp and torch thread pools by the cores that are idle now, not by the load average."""

from __future__ import annotations

import os

import pytest

from grove_tui import cpu
from grove_tui.cpu import free_cores, read_cpu_times, usable_cores


def readings(*values):
    """A fake /proc/stat reader returning (idle, total) pairs in order."""
    it = iter(values)
    return lambda: next(it)


@pytest.fixture
def two_cores(monkeypatch):
    monkeypatch.setattr(cpu, "usable_cores", lambda: 2)
    monkeypatch.setattr(os, "cpu_count", lambda: 2)


def test_idle_machine_gets_every_core(two_cores):
    # 0.2 s on 2 CPUs at 100 Hz: 40 ticks, all idle.
    assert free_cores(0.2, readings((1000, 5000), (1040, 5040)), sleep=lambda s: None, own_cpu=lambda: 0.0) == 2


def test_a_core_busy_elsewhere_is_not_counted(two_cores):
    assert free_cores(0.2, readings((1000, 5000), (1020, 5040)), sleep=lambda s: None, own_cpu=lambda: 0.0) == 1


def test_a_mostly_busy_core_is_not_counted_but_a_mostly_idle_one_is(two_cores):
    # 1.6 idle cores: the second core is 60 % idle, below the 70 % a free core needs.
    assert free_cores(0.2, readings((0, 0), (32, 40)), sleep=lambda s: None, own_cpu=lambda: 0.0) == 1
    # 1.8 idle cores: 80 % idle counts.
    assert free_cores(0.2, readings((0, 0), (36, 40)), sleep=lambda s: None, own_cpu=lambda: 0.0) == 2


def test_this_process_own_work_counts_as_free(two_cores):
    # One core busy, but with this process (it is about to hand its work to the threads being sized).
    clock = iter([10.0, 10.2])
    assert free_cores(0.2, readings((1000, 5000), (1020, 5040)), sleep=lambda s: None,
                      own_cpu=lambda: next(clock)) == 2


def test_fully_busy_machine_still_gets_one_thread(two_cores):
    assert free_cores(0.2, readings((1000, 5000), (1000, 5040)), sleep=lambda s: None, own_cpu=lambda: 0.0) == 1


def test_without_proc_stat_the_load_average_stands_in(two_cores, monkeypatch):
    monkeypatch.setattr(os, "getloadavg", lambda: (1.2, 1.0, 1.0))
    assert free_cores(0.2, lambda: None, sleep=lambda s: None) == 1
    monkeypatch.setattr(os, "getloadavg", lambda: (0.1, 0.1, 0.1))
    assert free_cores(0.2, lambda: None, sleep=lambda s: None) == 2


def test_reads_the_real_proc_stat_and_answers_within_the_usable_cores(tmp_path):
    if not os.path.exists("/proc/stat"):
        pytest.skip("no /proc/stat on this platform")
    idle, total = read_cpu_times()
    assert 0 <= idle <= total
    assert 1 <= free_cores(0.05) <= usable_cores()
    broken = tmp_path / "stat"
    broken.write_text("intr 1 2 3\n")
    assert read_cpu_times(str(broken)) is None
    broken.write_text("cpu  a b c d e\n")
    assert read_cpu_times(str(broken)) is None
