#!/usr/bin/env bash
# Makes the README's picture of a dataset layout:
#   docs/images/sphere-layout.png  24 views of the generated knot spread over the sphere
#                                  (a batch "layout": "sphere" job), each with its mask below it
# Usage: docs/images/make_dataset_images.sh [build/release/apps/phongrast]
# Needs oiiotool (Debian package openimageio-tools, in cmake/debian-packages.txt) for the contact sheet.
set -euo pipefail
cd "$(dirname "$0")/../.."
phongrast="$(realpath "${1:-build/release/apps/phongrast}")"
knot="$(realpath assets/default.obj)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "{\"mesh\": \"$knot\", \"layout\": \"sphere\", \"views\": 24, \"size\": \"96x96\", \"samples\": 2, \"aov_files\": \"mask\", \"output\": \"v{view}.png\"}" > "$work/views.jsonl"
"$phongrast" batch "$work/views.jsonl" -o "$work/out" -q
colours=()
for view in $(seq -w 0 23); do colours+=("$work/out/v$view.png"); done
# Two rows of colour (views 0-11, 12-23), each followed by the row of its masks.
oiiotool "${colours[@]:0:12}" --mosaic:pad=4 12x1 -o "$work/c0.png"
oiiotool "${colours[@]:12:12}" --mosaic:pad=4 12x1 -o "$work/c1.png"
m0=() m1=()
for view in $(seq -w 0 11); do m0+=("$work/out/v$view.mask.png" --ch "Y,Y,Y"); done
for view in $(seq -w 12 23); do m1+=("$work/out/v$view.mask.png" --ch "Y,Y,Y"); done
oiiotool "${m0[@]}" --mosaic:pad=4 12x1 -o "$work/m0.png"
oiiotool "${m1[@]}" --mosaic:pad=4 12x1 -o "$work/m1.png"
oiiotool "$work/c0.png" "$work/m0.png" "$work/c1.png" "$work/m1.png" --mosaic:pad=4 1x4 -o docs/images/sphere-layout.png
echo "wrote docs/images/sphere-layout.png"
