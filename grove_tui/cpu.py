"""How many cores are free right now, and how many threads llama.cpp gets: the thread counts for llama.cpp and torch.

Both spin-wait at barriers, so a thread placed on a core that something else is using costs far
more than it brings (measured on 2 shared cores under load ~5: SmolLM2 decoded 64 tok/s with 1
thread and 7 with 2). The load average is the wrong gauge for this: it trails by a minute, counts
this process's own work of a moment ago, and on some virtual machines counts kernel threads that
sleep uninterruptibly (seen here: a steady 1.0 on an idle 2-core machine, which kept llama.cpp on
one thread at half its speed). What the kernel reports as idle over a short window is the right one.
"""

from __future__ import annotations

import math
import os
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

SAMPLE_SECONDS = 0.2
# A core counts as free when at least this share of it was idle in the window.
FREE_SHARE = 0.7

CpuTimes = tuple[int, int]  # (idle ticks, all ticks) summed over the machine's CPUs


def read_cpu_times(path: str = "/proc/stat") -> CpuTimes | None:
    """Idle and total ticks of the aggregate `cpu` line of /proc/stat; None where there is none."""
    try:
        with open(path, encoding="ascii") as stat:
            fields = stat.readline().split()
    except OSError:
        return None
    if len(fields) < 5 or fields[0] != "cpu":
        return None
    try:
        # user nice system idle iowait irq softirq steal; guest time is already inside user.
        ticks = [int(value) for value in fields[1:9]]
    except ValueError:
        return None
    return ticks[3] + ticks[4], sum(ticks)


def usable_cores() -> int:
    """Cores this process may run on (its affinity mask, where the platform has one)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def free_cores(window: float = SAMPLE_SECONDS, read: Callable[[], CpuTimes | None] = read_cpu_times,
               sleep: Callable[[float], None] = time.sleep, own_cpu: Callable[[], float] = time.process_time) -> int:
    """Cores idle over the next `window` seconds, at least 1 and at most `usable_cores()`.

    This process's own CPU time in the window counts as free: the caller is about to hand the
    work to the threads it is sizing. Without /proc/stat the load average stands in.
    """
    cores = usable_cores()
    online = max(cores, os.cpu_count() or cores)
    before, own_before = read(), own_cpu()
    if before is None:
        return _free_by_load_average(cores)
    sleep(window)
    after, own = read(), own_cpu() - own_before
    if after is None or after[1] <= before[1]:
        return cores
    idle_share = (after[0] - before[0]) / (after[1] - before[1])
    idle = idle_share * online + (own / window if window > 0 else 0.0)
    return max(1, min(cores, int(idle + (1.0 - FREE_SHARE))))


def _free_by_load_average(cores: int) -> int:
    try:
        busy = os.getloadavg()[0]
    except OSError:
        return cores
    return max(1, min(cores, cores - round(busy)))


# ---- llama.cpp's thread count: the machine's budget, then the policy ----------------------------

# Up to this many cores a machine is "small": the UI, the SFM and llama.cpp share every core.
SMALL_MACHINE_CORES = 4


@dataclass(frozen=True)
class CoreBudget:
    """What this process may use: affinity CPUs, the physical cores among them, the cgroup quota."""

    cpus: int  # logical CPUs in the affinity mask
    physical: int  # distinct physical cores among them (hyper-threads count once)
    quota: float | None  # cgroup CPU limit in cores (cpu.max / cfs_quota), None when unlimited

    @property
    def cores(self) -> int:
        """Cores llama.cpp can use at full speed: a hyper-thread sibling adds no matmul throughput,
        and threads beyond a CPU quota are throttled (every barrier then waits for the slowest)."""
        limit = min(self.cpus, self.physical)
        if self.quota is not None:
            limit = min(limit, math.floor(self.quota + 1e-9))
        return max(1, limit)


def llm_thread_count(budget: int, idle: int, ui_core: bool = False) -> int:
    """llama.cpp threads for a machine with `budget` usable cores of which `idle` are idle now.

    Small machine (up to SMALL_MACHINE_CORES): the idle cores only, because a spin-waiting llama.cpp
    thread on a busy core costs far more than it brings (cpu.py's docstring); and while the app
    plays a run (`ui_core`), one core stays with the UI and the SFM. A headless command, or the app
    while it only waits for the model, gives the model every idle core. A workstation: a sampled
    busy core or two (the app itself, a compile) must not cut it to two threads, so it takes the
    idle cores but at least half its budget; with that many cores the UI and the SFM find one anyway.
    """
    budget, idle = max(1, budget), max(1, min(idle, budget))
    if budget <= SMALL_MACHINE_CORES:
        return max(1, min(idle, budget - 1 if ui_core else budget))
    return max(budget // 2, idle)


# Who holds a core for the UI now (the app's simulation controllers while they play).
_UI_CORE_HOLDERS: set[int] = set()
_UI_CORE_LOCK = threading.Lock()


def hold_ui_core(holder: object, held: bool) -> None:
    """`holder` (a playing run) keeps one core for the UI and the simulation, or lets it go."""
    with _UI_CORE_LOCK:
        if held:
            _UI_CORE_HOLDERS.add(id(holder))
        else:
            _UI_CORE_HOLDERS.discard(id(holder))


def ui_core_held() -> bool:
    """Whether a run plays in the app now: llama.cpp then leaves it one core (llm_thread_count)."""
    with _UI_CORE_LOCK:
        return bool(_UI_CORE_HOLDERS)


def physical_cores(cpus: Iterable[int], topology: Path = Path("/sys/devices/system/cpu")) -> int:
    """Distinct (package, core) pairs among `cpus`; the CPU count where sysfs has no topology."""
    cpus = list(cpus)
    cores = set()
    for cpu in cpus:
        folder = topology / f"cpu{cpu}" / "topology"
        try:
            cores.add((folder.joinpath("physical_package_id").read_text().strip(),
                       folder.joinpath("core_id").read_text().strip()))
        except OSError:
            return max(1, len(cpus))
    return max(1, len(cores))


def _quota_v2(text: str) -> float | None:
    fields = text.split()
    if len(fields) != 2 or fields[0] == "max":
        return None
    try:
        quota, period = int(fields[0]), int(fields[1])
    except ValueError:
        return None
    return quota / period if quota > 0 and period > 0 else None


def cgroup_cpu_quota(root: Path = Path("/sys/fs/cgroup"), self_cgroup: Path = Path("/proc/self/cgroup")) -> float | None:
    """The tightest CPU quota (in cores) over this process's cgroup and its parents; None when unlimited.

    cgroup v2: `cpu.max` ("max 100000" or "150000 100000") in the unified hierarchy; v1:
    `cpu.cfs_quota_us` / `cpu.cfs_period_us` (-1 is unlimited) in the cpu controller's folder.
    """
    try:
        lines = self_cgroup.read_text().splitlines()
    except OSError:
        lines = []
    quotas: list[float] = []
    for line in lines:
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        hierarchy_id, controllers, relative = parts
        found: Path | None
        if hierarchy_id == "0" and controllers == "":
            found, v2 = root, True
        elif "cpu" in controllers.split(","):
            found = next((root / name for name in (controllers, "cpu", "cpu,cpuacct") if (root / name).is_dir()), None)
            v2 = False
        else:
            continue
        if found is None:
            continue
        base = found
        folder = base / relative.lstrip("/")
        while True:
            quota = _read_quota(folder, v2)
            if quota is not None:
                quotas.append(quota)
            if folder == base or base not in folder.parents:
                break
            folder = folder.parent
    return min(quotas) if quotas else None


def _read_quota(folder: Path, v2: bool) -> float | None:
    try:
        if v2:
            return _quota_v2(folder.joinpath("cpu.max").read_text())
        quota = int(folder.joinpath("cpu.cfs_quota_us").read_text())
        period = int(folder.joinpath("cpu.cfs_period_us").read_text())
    except (OSError, ValueError):
        return None
    return quota / period if quota > 0 and period > 0 else None


def core_budget() -> CoreBudget:
    """This process's CoreBudget, read from the affinity mask, sysfs and the cgroup files."""
    if hasattr(os, "sched_getaffinity"):
        cpus = sorted(os.sched_getaffinity(0))
    else:
        cpus = list(range(os.cpu_count() or 1))
    return CoreBudget(cpus=max(1, len(cpus)), physical=physical_cores(cpus), quota=cgroup_cpu_quota())


def default_llm_threads() -> int:
    """llama.cpp's threads on this machine now: llm_thread_count over the budget, the idle cores and
    whether a run plays in the app. Asked per request (llm/local.py), so the count follows the machine."""
    budget = core_budget().cores
    return llm_thread_count(budget, free_cores(), ui_core_held())
