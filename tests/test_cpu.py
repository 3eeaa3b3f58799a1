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


# ---- llama.cpp's thread count: a pure policy over the machine's budget and its idle cores ----------

from grove_tui.cpu import CoreBudget, cgroup_cpu_quota, llm_thread_count, physical_cores  # noqa: E402


@pytest.mark.parametrize("idle", [1, 2, 8, 16])
def test_a_workstation_never_runs_two_threads(idle):
    # 16 usable cores: a busy core or two sampled at start (the app itself) must not cut llama.cpp to two.
    assert llm_thread_count(16, idle) >= 8
    assert llm_thread_count(16, 16) == 16


def test_a_workstation_uses_the_idle_cores_it_has():
    assert llm_thread_count(12, 10) == 10
    assert llm_thread_count(8, 3) == 4  # half its budget at least


@pytest.mark.parametrize(("budget", "idle", "ui_core", "threads"), [
    (1, 1, False, 1),  # one core: the one thread
    (1, 1, True, 1),
    (2, 2, False, 2),  # an idle 2-core machine, headless or the app waiting for the model: both cores
    (2, 2, True, 1),  # while a run plays, one core stays with the UI and the SFM
    (2, 1, False, 1),
    (4, 4, False, 4),
    (4, 4, True, 3),
    (4, 2, False, 2),  # busy cores are left alone
    (4, 2, True, 2),
    (4, 1, False, 1),
])
def test_a_small_machine_takes_only_idle_cores_and_leaves_one_while_a_run_plays(budget, idle, ui_core, threads):
    assert llm_thread_count(budget, idle, ui_core) == threads


def test_a_playing_run_holds_a_core_until_it_stops():
    from grove_tui.cpu import hold_ui_core, ui_core_held

    first, second = object(), object()
    assert not ui_core_held()
    hold_ui_core(first, True)
    hold_ui_core(second, True)
    hold_ui_core(first, False)
    assert ui_core_held()
    hold_ui_core(second, False)
    assert not ui_core_held()


def test_the_budget_counts_physical_cores_and_the_cgroup_quota():
    assert CoreBudget(cpus=16, physical=8, quota=None).cores == 8  # hyper-thread siblings add nothing
    assert CoreBudget(cpus=16, physical=16, quota=4.0).cores == 4  # a container limited to 4 CPUs
    assert CoreBudget(cpus=16, physical=16, quota=1.5).cores == 1  # a second thread would be throttled
    assert CoreBudget(cpus=4, physical=4, quota=0.5).cores == 1
    assert CoreBudget(cpus=2, physical=2, quota=None).cores == 2  # an affinity mask of 2 CPUs on a big host


def _topology(root, cores):
    for cpu, (package, core) in enumerate(cores):
        folder = root / f"cpu{cpu}" / "topology"
        folder.mkdir(parents=True)
        (folder / "physical_package_id").write_text(f"{package}\n")
        (folder / "core_id").write_text(f"{core}\n")


def test_physical_cores_count_hyperthread_siblings_once(tmp_path):
    _topology(tmp_path, [(0, 0), (0, 1), (0, 0), (0, 1), (1, 0), (1, 0)])
    assert physical_cores(range(6), tmp_path) == 3
    assert physical_cores([0, 2], tmp_path) == 1  # an affinity mask holding two siblings of one core
    assert physical_cores(range(8), tmp_path) == 8  # no topology for cpu6: every CPU counts


def test_cgroup_v2_quota_is_read_up_the_hierarchy(tmp_path):
    (tmp_path / "proc").write_text("0::/user.slice/app\n")
    leaf = tmp_path / "cg" / "user.slice" / "app"
    leaf.mkdir(parents=True)
    (leaf / "cpu.max").write_text("max 100000\n")
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "proc") is None
    (leaf.parent / "cpu.max").write_text("250000 100000\n")  # the slice above limits it to 2.5 CPUs
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "proc") == 2.5
    (leaf / "cpu.max").write_text("50000 100000\n")
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "proc") == 0.5


def test_cgroup_v1_quota_and_unlimited(tmp_path):
    (tmp_path / "proc").write_text("4:memory:/docker/x\n2:cpu,cpuacct:/docker/x\n")
    folder = tmp_path / "cg" / "cpu,cpuacct" / "docker" / "x"
    folder.mkdir(parents=True)
    (folder / "cpu.cfs_quota_us").write_text("-1\n")
    (folder / "cpu.cfs_period_us").write_text("100000\n")
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "proc") is None
    (folder / "cpu.cfs_quota_us").write_text("300000\n")
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "proc") == 3.0
    assert cgroup_cpu_quota(tmp_path / "cg", tmp_path / "missing") is None


def test_the_real_budget_is_within_the_affinity_mask():
    budget = cpu.core_budget()
    assert 1 <= budget.cores <= budget.cpus <= (os.cpu_count() or 1)
    assert 1 <= cpu.default_llm_threads() <= budget.cores
