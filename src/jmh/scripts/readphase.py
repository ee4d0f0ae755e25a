#!/usr/bin/env python3
"""readphase.py RUNS INPUT NAME=JAR ...: `java -jar JAR hillshade --method horn INPUT -o OUT --verbose` for each jar,
interleaved RUNS times after one warm-up round (in the given order on even rounds, reversed on odd ones); prints per
jar the median and all values of the `read` phase that --verbose reports, the median wall time and the median CPU
time (user + system) of the whole command, then the 1-minute load average."""
import os, sys, subprocess, time, statistics, re, tempfile
runs = int(sys.argv[1]); dem = sys.argv[2]; jars = [a.split('=', 1) for a in sys.argv[3:]]
res = {n: {'read': [], 'wall': [], 'cpu': []} for n, _ in jars}; loads = []
out = tempfile.mkdtemp()
for r in range(runs + 1):
    loads.append(os.getloadavg()[0])
    for n, jar in (jars if r % 2 == 0 else jars[::-1]):
        cmd = ["java", "-jar", jar, "hillshade", "--method", "horn", dem, "-o", os.path.join(out, n + ".png"),
               "--verbose"]
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        err = p.stderr.read()
        _, status, ru = os.wait4(p.pid, 0)
        if status != 0:
            sys.exit(f"{n}: exit status {os.waitstatus_to_exitcode(status)}: {err}")
        m = re.search(r'read (\d+) ms', err)
        if r > 0:
            res[n]['read'].append(int(m[1])); res[n]['wall'].append(time.perf_counter() - t0)
            res[n]['cpu'].append(ru.ru_utime + ru.ru_stime)
for n, _ in jars:
    d = res[n]
    print(f"{os.path.basename(dem)} {n:10s} read median {statistics.median(d['read']):.0f} ms {sorted(d['read'])}"
          f"  wall {statistics.median(d['wall']):.3f} s  cpu {statistics.median(d['cpu']):.2f} s")
print(f"load average (1 min) median {statistics.median(loads):.1f}, {min(loads):.1f}-{max(loads):.1f}")
