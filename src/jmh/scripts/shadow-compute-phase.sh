#!/bin/sh
# The shadow computation alone, without start-up and file I/O, for docs/performance.md "Ray tracing":
# * SAGA: saga_cmd ta_lighting 0 under strace; the compute phase is the time from closing the input GeoTIFF to
#   opening the output (grid allocation + shadows), read off the system-call timeline.
# * jdem846: ShadowTiming in one JVM (first run = cold, as in one CLI call; then the best of the warm runs): the
#   sweep on 1 and 2 threads (5 warm runs), the article's march on 2 threads (1 warm run).
# DEM: fractal (the default) or mirrored (mirror-tiled Big Tujunga, see shadows-vs-saga.sh).
# From the worktree root, after shadows-vs-saga.sh made WORKDIR/DEM4000.tif (and .flt):
#   sh src/jmh/scripts/shadow-compute-phase.sh [WORKDIR] [AZIMUTH] [ELEVATION] [fractal|mirrored]
set -eu
WORK=${1:-/tmp/shadows-vs-saga}
AZ=${2:-300}
EL=${3:-5}
DEM=${4:-fractal}
ROOT=$(pwd)
cd "$WORK"
case $DEM in
    fractal) TIMING_DEM= ;;                          # ShadowTiming builds the fractal itself
    mirrored) TIMING_DEM="$WORK/mirrored4000.flt" ;;
    *) echo "DEM must be fractal or mirrored, not '$DEM'" >&2; exit 2 ;;
esac
for run in 1 2 3; do
    rm -f saga_phase.tif
    flock -x /tmp/cpu.lock strace -f -tt -e trace=openat,close -o saga.strace \
        saga_cmd ta_lighting 0 -ELEVATION ${DEM}4000.tif -SHADE saga_phase.tif -METHOD 3 -POSITION 0 \
        -AZIMUTH "$AZ" -DECLINATION "$EL" -UNIT 1 -SHADOW 0 >/dev/null 2>&1
    INPUT=${DEM}4000.tif python3 - <<'PY'
import os, re
def t(line):
    h, m, s = line.split()[1].split(':')
    return int(h) * 3600 + int(m) * 60 + float(s)
lines = open('saga.strace').read().splitlines()
fd_in = None
for i, l in enumerate(lines):
    if 'openat' in l and '"%s"' % os.environ['INPUT'] in l:
        fd_in = l.rsplit('=', 1)[1].strip()
        start = t(l)
    elif fd_in and re.search(r'close\(%s\)' % fd_in, l) and 'read_end' not in locals():
        read_end = t(l)
    elif 'openat' in l and '"saga_phase.tif"' in l and 'O_CREAT' in l:
        write_start = t(l)
end = t(lines[-1])
print('SAGA: start-up %.2f s, read %.2f s, shadows %.2f s, write %.2f s, total %.2f s' % (
    start - t(lines[0]), read_end - start, write_start - read_end, end - write_start, end - t(lines[0])))
PY
done
for threads in 1 2; do
    flock -x /tmp/cpu.lock java -cp "$ROOT/target/benchmarks.jar" io.github.jdem846.bench.ShadowTiming 4000 sweep \
        "$AZ" "$EL" $threads 6 $TIMING_DEM
done
flock -x /tmp/cpu.lock java -cp "$ROOT/target/benchmarks.jar" io.github.jdem846.bench.ShadowTiming 4000 march \
    "$AZ" "$EL" 2 2 $TIMING_DEM
[ "$DEM" = fractal ] || exit 0

# Masks on real terrain (the fractal has almost no shadow at 5°): Big Tujunga 30 m, sweep vs SAGA vs the march.
BT="$ROOT/testdata/dem/bigtujunga_srtm30m_utm11n.tif"
for sun in "300 5" "160 20" "250 5"; do
    set -- $sun
    java -jar "$ROOT/target/jdem846-cli.jar" shadows "$BT" -o bt_sweep.tif --algorithm sweep --sun-azimuth $1 --sun-elevation $2 -q
    java -jar "$ROOT/target/jdem846-cli.jar" shadows "$BT" -o bt_march.tif --algorithm march --sun-azimuth $1 --sun-elevation $2 -q
    saga_cmd ta_lighting 0 -ELEVATION "$BT" -SHADE bt_saga.tif -METHOD 3 -POSITION 0 -AZIMUTH $1 -DECLINATION $2 \
        -UNIT 1 -SHADOW 0 >/dev/null 2>&1
    for m in sweep march saga; do gdal_translate -q -of ENVI -ot Byte bt_$m.tif bt_$m.raw 2>/dev/null; done
    AZ=$1 EL=$2 python3 - <<'PY'
import os
def mask(path):
    b = open(path, 'rb').read()
    return int.from_bytes(b.translate(bytes([0] + [1] * 255)), 'little'), len(b)
s, n = mask('bt_sweep.raw'); m, _ = mask('bt_march.raw'); g, _ = mask('bt_saga.raw')
print('Big Tujunga sun %s/%s: shadowed sweep %.2f %%, march %.2f %%, SAGA %.2f %%; differ sweep-SAGA %.2f %%,'
      ' march-SAGA %.2f %%, sweep-march %.2f %%' % (os.environ['AZ'], os.environ['EL'], 100 * s.bit_count() / n,
      100 * m.bit_count() / n, 100 * g.bit_count() / n, 100 * (s ^ g).bit_count() / n, 100 * (m ^ g).bit_count() / n,
      100 * (s ^ m).bit_count() / n))
PY
done
