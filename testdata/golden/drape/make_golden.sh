#!/bin/sh
# Regenerates the drape test images of this folder with GDAL (Debian 12 gdal-bin 3.6.2).
# Run from the repository root: sh testdata/golden/drape/make_golden.sh
set -eu
G=testdata/golden/drape
D=testdata/dem
T=$(mktemp -d)

# The article's table 2 (the default tint on a DEM without sea) as absolute stops for the whole Big Tujunga
# file's range, min=315 max=2295 m: level = 315 + percent / 100 * 1980.
awk -v min=315 -v max=2295 'BEGIN {
  print "# table 2 as absolute stops for Big Tujunga, min=315 max=2295 (made by make_golden.sh)"
  split("0 3 5 18 39 52 68 100", p, " ")
  split("0,98,70 36,130,52 228,207,126 154,70,0 124,33,35 121,121,121 178,178,178 229,229,229", c, " ")
  for (i = 1; i <= 8; i++) { split(c[i], rgb, ","); printf "%.17g %d %d %d\n", min + p[i] / 100 * (max - min), rgb[1], rgb[2], rgb[3] }
  print "nv 0 0 0 0"
}' > $G/colors/table2_bigtujunga_m.txt

gdal_translate -q -srcwin 420 120 320 240 $D/bigtujunga_srtm30m_utm11n.tif $T/crop.tif
# 8-bit RGB GeoTIFF on the DEM's own grid (UTM 11N)
GDAL_PAM_ENABLED=NO gdaldem color-relief -q -co COMPRESS=DEFLATE -co PREDICTOR=2 $T/crop.tif \
  $G/colors/table2_bigtujunga_m.txt $G/bigtujunga_crop_table2_utm.tif
# the same picture warped to latitude/longitude (EPSG:4326), bilinear, with an alpha band outside it
GDAL_PAM_ENABLED=NO gdalwarp -q -t_srs EPSG:4326 -r bilinear -dstalpha -co COMPRESS=DEFLATE -co PREDICTOR=2 \
  $G/bigtujunga_crop_table2_utm.tif $G/bigtujunga_crop_table2_wgs84.tif
# the UTM picture as a PNG with a world file (.wld) and GDAL's .aux.xml holding the CRS
gdal_translate -q -of PNG -co WORLDFILE=YES $G/bigtujunga_crop_table2_utm.tif $G/bigtujunga_crop_table2_utm.png
rm -rf "$T"
