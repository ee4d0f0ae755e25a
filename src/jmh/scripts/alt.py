#!/usr/bin/env python3
"""alt.py RUNS NAME=CMD ...: runs the commands interleaved RUNS times after one warm-up round, in the given order on
even rounds and reversed on odd ones; prints per command the mean, median and min wall time, the median CPU time
(user + system of the command and its children: less disturbed by other load than wall time) and, per round, the
ratio of the first command's wall time to this one's (median of ratios); then the 1-minute load average."""
import os, sys, subprocess, time, statistics, shlex
runs = int(sys.argv[1]); cmds = [a.split('=', 1) for a in sys.argv[2:]]
times = {n: [] for n, _ in cmds}; cpu = {n: [] for n, _ in cmds}; loads = []
for r in range(runs + 1):
    loads.append(os.getloadavg()[0])
    for n, c in (cmds if r % 2 == 0 else cmds[::-1]):
        t0 = time.perf_counter()
        p = subprocess.Popen(shlex.split(c), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, ru = os.wait4(p.pid, 0)
        if status != 0:
            sys.exit(f"{n}: exit status {os.waitstatus_to_exitcode(status)}: {c}")
        if r > 0:
            times[n].append(time.perf_counter() - t0); cpu[n].append(ru.ru_utime + ru.ru_stime)
base = cmds[0][0]
for n, _ in cmds:
    t = times[n]; ratios = [b / x for b, x in zip(times[base], t)]
    print(f"{n:40s} mean {statistics.mean(t):.3f} s  median {statistics.median(t):.3f}  min {min(t):.3f}"
          f"  cpu median {statistics.median(cpu[n]):.3f}  {base}/this median {statistics.median(ratios):.2f}")
print(f"load average (1 min) median {statistics.median(loads):.1f}, {min(loads):.1f}-{max(loads):.1f}")
