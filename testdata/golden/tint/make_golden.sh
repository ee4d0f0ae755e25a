#!/bin/sh
# Regenerates the golden colour-relief PNGs of this folder with gdaldem (Debian 12 gdal-bin 3.6.2).
# Run from the repository root: sh testdata/golden/tint/make_golden.sh
set -eu
G=testdata/golden/tint
D=testdata/dem
T=$(mktemp -d)
export GDAL_PAM_ENABLED=NO          # never write .aux.xml statistics next to the inputs

# Derived colour files (written here, committed; see README.md).
# exact_every5m.txt: a stop every 5 m from 145 to 545 m; the first line is a sentinel no cell has
# (GDAL 3.6.2's VRT lookup table drops the first entry in exact mode).
{
  echo "# -exact_color_entry classes for Luxembourg: a stop every 5 m, colour r=(3v mod 256), g=(7v mod 256), b=(v-140)/2"
  echo "# first line: a sentinel elevation no cell has (see README.md)"
  echo "-99999 0 0 0 255"
  awk 'BEGIN { for (v = 145; v <= 545; v += 5) printf "%d %d %d %d\n", v, (3*v)%256, (7*v)%256, int((v-140)/2) }'
} > $G/colors/exact_every5m.txt

# standard_vancouver.txt: the 'standard' ramp (hypsometric-global above 0 m over [0, max], bathymetric at and
# below 0 m over [min, 0]) written out as absolute stops for Vancouver's range min=-1437, max=2205.
awk -v min=-1437 -v max=2205 'BEGIN {
  print "# the standard ramp as absolute stops for min=-1437 max=2205 (made by make_golden.sh)"
  split("2.5 6.25 12.5 25 37.5 50 62.5 75 87.5 100", sp, " ")
  split("24,23,54 21,46,103 21,87,135 21,138,171 27,155,184 11,176,203 55,186,216 95,194,217 134,205,211 175,218,209", sc, " ")
  for (i = 1; i <= 10; i++) printf "%.17g %s\n", min + sp[i] / 100 * (0 - min), sc[i]
  split("0 3.2967 5.3407 18.0769 39.3626 51.6484 68.1319 100", lp, " ")
  split("0,99,70 37,131,53 228,207,126 154,70,0 124,34,36 121,121,121 179,179,179 230,230,230", lc, " ")
  for (i = 1; i <= 8; i++) { z = lp[i] / 100 * max; if (i == 1) z = 0.0001; printf "%.17g %s\n", z, lc[i] }
}' > $G/colors/standard_vancouver.txt

gdal_translate -q -srcwin 420 120 320 240 $D/bigtujunga_srtm30m_utm11n.tif $T/bigtujunga_crop.tif
cp $D/luxembourg_srtm30s_wgs84.tif $D/vancouver-island_topobathy_2min_mercator.tif $T/

relief() { gdaldem color-relief -q -alpha -of PNG "$@"; }
relief $T/vancouver-island_topobathy_2min_mercator.tif $G/colors/vancouver_absolute.txt $G/vancouver_absolute.png
relief $T/vancouver-island_topobathy_2min_mercator.tif $G/colors/etopo1.txt             $G/vancouver_etopo1.png
relief $T/vancouver-island_topobathy_2min_mercator.tif $G/colors/standard_vancouver.txt $G/vancouver_standard.png
relief $T/luxembourg_srtm30s_wgs84.tif                 $G/colors/table2_percent.txt     $G/luxembourg_table2.png
relief $T/luxembourg_srtm30s_wgs84.tif                 $G/colors/names_mixed.txt        $G/luxembourg_names.png
relief $T/bigtujunga_crop.tif                          $G/colors/table2_percent.txt     $G/bigtujunga_crop_table2.png
relief $T/bigtujunga_crop.tif $G/colors/nearest_classes.txt $G/bigtujunga_crop_nearest.png -nearest_color_entry
# Exact mode: GDAL 3.6.2's direct path matches only the first entry (fixed in GDAL 3.9.2, PR #10596), so the
# golden file comes from gdaldem's VRT lookup-table path, which is right except for its first entry.
gdaldem color-relief -q -alpha -exact_color_entry -of VRT $T/luxembourg_srtm30s_wgs84.tif \
  $G/colors/exact_every5m.txt $T/exact.vrt
gdal_translate -q -of PNG $T/exact.vrt $G/luxembourg_exact.png
rm -f $G/*.png.aux.xml
rm -rf "$T"
