"""How many cores are free right now: the thread count for llama.cpp and torch.

Both spin-wait at barriers, so a thread placed on a core that something else is using costs far
more than it brings (measured on 2 shared cores under load ~5: SmolLM2 decoded 64 tok/s with 1
thread and 7 with 2). The load average is the wrong gauge for this: it trails by a minute, counts
this process's own work of a moment ago, and on some virtual machines counts kernel threads that
sleep uninterruptibly (seen here: a steady 1.0 on an idle 2-core machine, which kept llama.cpp on
one thread at half its speed). What the kernel reports as idle over a short window is the right one.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable

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
