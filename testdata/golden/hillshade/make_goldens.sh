#!/usr/bin/env bash
# Regenerates the gdaldem hillshade goldens of this folder (Debian 12 gdal-bin, GDAL 3.6.2).
# Run from this folder: bash make_goldens.sh
set -euo pipefail
D=../../dem
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

# Inputs: crops of the repository's GeoTIFFs (Int16), made with gdal_translate -srcwin XOFF YOFF XSIZE YSIZE.
gdal_translate -q -srcwin 420 120 300 200 $D/bigtujunga_srtm30m_utm11n.tif "$T/bt.tif"
gdal_translate -q -srcwin 100 80 200 160  $D/jacksboro_srtm3s_wgs84.tif    "$T/jb.tif"
cp $D/luxembourg_srtm30s_wgs84.tif "$T/lux.tif"
cp $D/maungawhau-volcano_10m_nztm-approx.tif "$T/vo.tif"
cp $D/vancouver-island_topobathy_2min_mercator.tif "$T/va.tif"

hs() { # name input args...
  local name=$1 in=$2; shift 2
  gdaldem hillshade -q -compute_edges -of PNG "$@" "$T/$in.tif" "$name.png"
  rm -f "$name.png.aux.xml"
}

hs bt_horn_az315_alt45             bt
hs bt_horn_az100.5_alt12.3_z2      bt -az 100.5 -alt 12.3 -z 2
hs bt_horn_az200_alt70             bt -az 200 -alt 70
hs bt_horn_az33.3_alt0.01          bt -az 33.3 -alt 0.01
hs bt_multidir_alt45               bt -multidirectional
hs bt_multidir_alt30_z3            bt -multidirectional -alt 30 -z 3
hs jb_horn_s111120_az315_alt45     jb -s 111120
hs jb_horn_s111120_az250_alt25_z2  jb -s 111120 -az 250 -alt 25 -z 2
hs jb_multidir_s111120_alt60       jb -s 111120 -multidirectional -alt 60
hs lux_horn_s111120_az315_alt45    lux -s 111120
hs lux_horn_s111120_az57_alt5_z5   lux -s 111120 -az 57 -alt 5 -z 5
hs lux_multidir_s111120_alt45_z5   lux -s 111120 -multidirectional -z 5
hs vo_horn_az135_altm5             vo -az 135 -alt -5
hs vo_horn_az1e6_alt89.99          vo -az 1000000 -alt 89.99
hs vo_horn_azm720_alt90            vo -az -720 -alt 90
hs va_horn_az300_alt35_z10         va -az 300 -alt 35 -z 10
hs va_multidir_alt45_z10           va -multidirectional -z 10
hs bt_igor_az315                   bt -igor
hs bt_igor_az100_z3                bt -igor -az 100 -z 3
hs bt_combined_az315_alt45         bt -combined
hs bt_combined_az100_alt20_z3      bt -combined -az 100 -alt 20 -z 3
hs lux_igor_s111120_az315          lux -s 111120 -igor
hs lux_combined_s111120_az57_alt5_z5 lux -s 111120 -combined -az 57 -alt 5 -z 5
