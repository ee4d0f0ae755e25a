#!/bin/sh
# Whole-command timings of `jdem846 shadows` (sweep; the article's march) against SAGA's shadows
# (saga_cmd ta_lighting 0, method 3 "Shadows Only", ray tracing, "slim") on a 4000² DEM and its 2000² and 1000²
# crops, and the fraction of cells where SAGA's mask and ours disagree. Results for docs/performance.md, "Ray tracing".
# DEM: fractal (FractalDem 4000 846, the default) or mirrored (MirroredDem 4000: Big Tujunga SRTM 30 m mirror-tiled,
# real mountains); use one WORKDIR per DEM and sun (the output names do not say which).
#
# From the worktree root, after `./mvnw -B -o -q -Pjmh package -DskipTests`:
#   sh src/jmh/scripts/shadows-vs-saga.sh [WORKDIR] [AZIMUTH] [ELEVATION] [fractal|mirrored]
# Needs gdal_translate, saga_cmd, hyperfine, python3. Every timing holds the exclusive CPU lock
# (flock -x /tmp/cpu.lock), one hyperfine call at a time.
set -eu
WORK=${1:-/tmp/shadows-vs-saga}
AZ=${2:-300}
EL=${3:-5}
DEM=${4:-fractal}
ROOT=$(pwd)
CLI="java -jar $ROOT/target/jdem846-cli.jar"
mkdir -p "$WORK"
cd "$WORK"

# 1. The DEMs: the 4000² fractal (seed 846, 30 m, UTM 11N) or mirror-tiled Big Tujunga (30 m, UTM 11N), and their
#    north-west 2000² and 1000² crops.
case $DEM in
    fractal) [ -f fractal4000.flt ] || java -cp "$ROOT/target/benchmarks.jar" io.github.jdem846.bench.FractalDem \
        4000 846 fractal4000 ;;
    mirrored) [ -f mirrored4000.flt ] || (cd "$ROOT" && java -cp target/benchmarks.jar \
        io.github.jdem846.bench.MirroredDem 4000 "$WORK/mirrored4000") ;;
    *) echo "DEM must be fractal or mirrored, not '$DEM'" >&2; exit 2 ;;
esac
[ -f ${DEM}4000.tif ] || gdal_translate -q ${DEM}4000.flt ${DEM}4000.tif
[ -f ${DEM}2000.tif ] || gdal_translate -q -srcwin 0 0 2000 2000 ${DEM}4000.tif ${DEM}2000.tif
[ -f ${DEM}1000.tif ] || gdal_translate -q -srcwin 0 0 1000 1000 ${DEM}4000.tif ${DEM}1000.tif

ours() { # DEM ALGORITHM OUT
    echo "$CLI shadows $1 -o $3 --algorithm $2 --sun-azimuth $AZ --sun-elevation $EL -q"
}
saga() { # DEM OUT
    echo "saga_cmd ta_lighting 0 -ELEVATION $1 -SHADE $2 -METHOD 3 -POSITION 0 -AZIMUTH $AZ -DECLINATION $EL -UNIT 1 -SHADOW 0"
}

# 2. Whole commands, 4000²: sweep vs SAGA.
flock -x /tmp/cpu.lock hyperfine -N --warmup 1 --runs 5 --export-markdown t4000.md --export-json t4000.json \
    -n "jdem846 shadows sweep 4000² $DEM" "$(ours ${DEM}4000.tif sweep ours4000.tif)" \
    -n "saga_cmd ta_lighting 0 (shadows only) 4000² $DEM" "$(saga ${DEM}4000.tif saga4000.tif)"

# 3. The article's march is slow: 1000² and 2000² crops, against the sweep and SAGA on the same crops.
for n in 1000 2000; do
    runs=5; [ "$n" = 2000 ] && runs=3
    flock -x /tmp/cpu.lock hyperfine -N --warmup 1 --runs $runs --export-markdown t$n.md --export-json t$n.json \
        -n "jdem846 shadows sweep ${n}² $DEM" "$(ours $DEM$n.tif sweep ours$n.tif)" \
        -n "jdem846 shadows march (article) ${n}² $DEM" "$(ours $DEM$n.tif march march$n.tif)" \
        -n "saga_cmd ta_lighting 0 (shadows only) ${n}² $DEM" "$(saga $DEM$n.tif saga$n.tif)"
done

# 3b. The article's march on the whole 4000² (10–25 s per run): two runs, no warm-up.
flock -x /tmp/cpu.lock hyperfine -N --warmup 0 --runs 2 --export-markdown t4000march.md --export-json t4000march.json \
    -n "jdem846 shadows march (article) 4000² $DEM" "$(ours ${DEM}4000.tif march march4000.tif)"

# 4. Masks: ours 0/255, SAGA's π/2 where shadowed and no-data (-99999) where lit; both to raw bytes.
for n in 1000 2000 4000; do
    gdal_translate -q -of ENVI -ot Byte ours$n.tif ours$n.raw
    gdal_translate -q -of ENVI -ot Byte saga$n.tif saga$n.raw
    [ -f march$n.tif ] && gdal_translate -q -of ENVI -ot Byte march$n.tif march$n.raw
done
python3 - <<'PY'
import os
def mask(path):
    b = open(path, 'rb').read()
    return int.from_bytes(b.translate(bytes([0] + [1] * 255)), 'little'), len(b)
for n in (1000, 2000, 4000):
    ours, cells = mask('ours%d.raw' % n)
    saga, _ = mask('saga%d.raw' % n)
    line = '%d²: shadowed ours %.3f %%, SAGA %.3f %%, sweep vs SAGA differ %.3f %%' % (
        n, 100 * ours.bit_count() / cells, 100 * saga.bit_count() / cells, 100 * (ours ^ saga).bit_count() / cells)
    if os.path.exists('march%d.raw' % n):
        march, _ = mask('march%d.raw' % n)
        line += ', march vs SAGA %.3f %%, sweep vs march %.3f %%' % (
            100 * (march ^ saga).bit_count() / cells, 100 * (ours ^ march).bit_count() / cells)
    print(line)
PY
