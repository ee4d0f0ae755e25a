#!/usr/bin/env python3
"""alt.py RUNS NAME=CMD ...: runs the commands interleaved (round robin) RUNS times after one warm-up round;
prints mean, median, min per command and, per round, the ratio of each command to the first (median of ratios)."""
import sys, subprocess, time, statistics, shlex
runs = int(sys.argv[1]); cmds = [a.split('=', 1) for a in sys.argv[2:]]
times = {n: [] for n, _ in cmds}
for r in range(runs + 1):
    for n, c in cmds:
        t0 = time.perf_counter(); subprocess.run(shlex.split(c), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        if r > 0: times[n].append(time.perf_counter() - t0)
base = cmds[0][0]
for n, _ in cmds:
    t = times[n]; ratios = [b / x for b, x in zip(times[base], t)]
    print(f"{n:40s} mean {statistics.mean(t):.3f} s  median {statistics.median(t):.3f}  min {min(t):.3f}  sd {statistics.stdev(t):.3f}  {base}/this median {statistics.median(ratios):.2f}")
