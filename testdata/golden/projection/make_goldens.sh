#!/bin/sh
# Remakes the gdalwarp references of testdata/golden/projection from the committed jb_relief.png and
# jb_hillshade.png (+ .pgw, .prj).
# Run from the repository root with gdal-bin (Debian 12: GDAL 3.6.2, PROJ 9.1.1). See README.md.
set -e
cd testdata/golden/projection
tmp=$(mktemp -d)
gdalwarp -q -overwrite -s_srs EPSG:4326 \
    -t_srs "+proj=wintri +lon_0=0 +lat_1=50.4597762521898 +datum=WGS84 +units=m +no_defs" \
    -r bilinear -et 0 -dstalpha \
    -te -6993232.9226428615 4226888.211636712 -6954630.739160735 4261164.783718582 -ts 400 355 \
    jb_relief.png "$tmp/wintri.tif"
gdal_translate -q -of PNG "$tmp/wintri.tif" jb_relief_wintri_gdalwarp.png
gdalwarp -q -overwrite -s_srs EPSG:4326 \
    -t_srs "+proj=moll +lon_0=0 +datum=WGS84 +units=m +no_defs" \
    -r bilinear -et 0 -dstalpha \
    -te -7391397.474211908 4388437.364616936 -7344942.705416369 4421049.826613518 -ts 400 281 \
    jb_relief.png "$tmp/moll.tif"
gdal_translate -q -of PNG "$tmp/moll.tif" jb_relief_moll_gdalwarp.png
# the hillshade (gray, 0 = no-data): bilinear with no-data left out
gdalwarp -q -overwrite -s_srs EPSG:4326 \
    -t_srs "+proj=wintri +lon_0=0 +lat_1=50.4597762521898 +datum=WGS84 +units=m +no_defs" \
    -r bilinear -et 0 -srcnodata 0 -dstnodata 0 \
    -te -6993232.9226428615 4226888.211636712 -6954630.739160735 4261164.783718582 -ts 400 355 \
    jb_hillshade.png "$tmp/h_wintri.tif"
gdal_translate -q -of PNG "$tmp/h_wintri.tif" jb_hillshade_wintri_gdalwarp.png
gdalwarp -q -overwrite -s_srs EPSG:4326 \
    -t_srs "+proj=moll +lon_0=0 +datum=WGS84 +units=m +no_defs" \
    -r bilinear -et 0 -srcnodata 0 -dstnodata 0 \
    -te -7391397.474211908 4388437.364616936 -7344942.705416369 4421049.826613518 -ts 400 281 \
    jb_hillshade.png "$tmp/h_moll.tif"
gdal_translate -q -of PNG "$tmp/h_moll.tif" jb_hillshade_moll_gdalwarp.png
rm -f jb_relief_wintri_gdalwarp.png.aux.xml jb_relief_moll_gdalwarp.png.aux.xml
rm -f jb_hillshade_wintri_gdalwarp.png.aux.xml jb_hillshade_moll_gdalwarp.png.aux.xml
rm -r "$tmp"
