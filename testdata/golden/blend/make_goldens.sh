#!/usr/bin/env bash
# Regenerates the blend goldens of this folder: ImageMagick's composite of this project's own `tint` and
# `hillshade` pictures of a Big Tujunga window (Debian 12 imagemagick 6.9.11-60 Q16).
# Run from this folder, after `./mvnw -B -q package -DskipTests` at the repository root: bash make_goldens.sh
set -euo pipefail
J="java -jar ../../../target/jdem846-cli.jar"
DEM=../../dem/bigtujunga_srtm30m_utm11n.tif
WIN=cells:560,200,160,100
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

golden() { # case-name composite-operator output-name "tint options" "hillshade options"
  local case=$1 op=$2 name=$3
  $J tint "$DEM" -o "$T/$case-tint.png" --window $WIN -q $4
  $J hillshade "$DEM" -o "$T/$case-hill.png" --window $WIN -q $5
  convert "$T/$case-tint.png" -alpha off "$T/$case-hill.png" -compose "$op" -composite \
      -depth 8 -type TrueColor -strip -define png:exclude-chunk=date,time "$name.png"
}

# A: the defaults (table-2 tint, jdem846 hillshade, sun 320°/25°)
golden a Multiply  bt_a_multiply   "" ""
golden a Screen    bt_a_screen     "" ""
golden a Overlay   bt_a_overlay    "" ""
golden a SoftLight bt_a_soft-light "" ""
# B: another ramp, sun, exaggeration and tone
BT="--tint etopo1"
BH="--sun-azimuth 200 --sun-elevation 40 -z 2 --light-intensity 1 --dark-intensity 0.8"
golden b Multiply  bt_b_multiply   "$BT" "$BH"
golden b SoftLight bt_b_soft-light "$BT" "$BH"

# Every golden against the W3C formulas computed with numpy (python3-numpy, python3-gdal)
/usr/bin/python3 check_w3c.py "$T"
