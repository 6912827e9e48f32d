#!/usr/bin/env bash
# Makes the README's pictures of the extra outputs and of smoothing by position:
#   docs/images/default-aovs.png   colour | depth | normal | id | alpha of the default scene
#   docs/images/teapot-smooth.png  the Utah teapot, normals by vertex index | by position
# Usage: docs/images/make_aov_images.sh [build/release/apps/phongrast]
# Needs oiiotool (Debian: openimageio-tools) and, for the teapot, ../shared/assets/teapot.obj.
set -euo pipefail
cd "$(dirname "$0")/../.."
phongrast="${1:-build/release/apps/phongrast}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
label=(--text:x=8:y=22:size=18:font=DejaVuSans:color=1,1,1)

# One EXR with every plane; supersampled so alpha shows the anti-aliased edges.
"$phongrast" render assets/default.json --samples 2 --aov all -o "$work/aovs.exr" --quiet
# Depth: nearest white, farthest (and the background) black, over the finite range.
oiiotool "$work/aovs.exr" --ch Z -o "$work/z.exr"
read -r z_min z_max < <(oiiotool --stats "$work/z.exr" | awk '/Stats Min/ {min=$3} /Stats Max/ {max=$3} END {print min, max}')
oiiotool "$work/aovs.exr" --ch R,G,B --clamp:min=0:max=1 "${label[@]}" colour -o "$work/0.png"
oiiotool "$work/aovs.exr" --ch Z,Z,Z --clamp:min="$z_min":max="$z_max" --subc "$z_max" \
  --mulc "$(awk -v a="$z_min" -v b="$z_max" 'BEGIN {print -1 / (b - a)}')" "${label[@]}" depth -o "$work/1.png"
# Normal: world x, y, z as red, green, blue in [0, 1]; black where nothing is.
oiiotool "$work/aovs.exr" --ch N.X,N.Y,N.Z --mulc 0.5 --addc 0.5 "$work/aovs.exr" --ch A,A,A --mul \
  "${label[@]}" normal -o "$work/2.png"
# Id: OpenImageIO reads the unsigned channel as id / (2^32 - 1); spread the knot's triangles over a colour map.
triangles=$(grep -c '^f ' assets/default.obj)
oiiotool "$work/aovs.exr" --ch id --mulc "$(awk -v t="$triangles" 'BEGIN {printf "%.6f", 4294967295 / t}')" \
  --clamp:min=0:max=1 --colormap viridis "$work/aovs.exr" --ch A,A,A --mul "${label[@]}" "id" -o "$work/3.png"
oiiotool "$work/aovs.exr" --ch A,A,A "${label[@]}" alpha -o "$work/4.png"
oiiotool "$work"/{0,1,2,3,4}.png --mosaic 5x1 --resize 1280x256 -d uint8 -o docs/images/default-aovs.png

teapot=../shared/assets/teapot.obj
if [[ -f "$teapot" ]]; then
  for smooth in index position; do
    "$phongrast" render "$teapot" --smooth "$smooth" --size 480x320 -o "$work/teapot-$smooth.png" --quiet
    oiiotool "$work/teapot-$smooth.png" --text:x=8:y=22:size=18:font=DejaVuSans:color=0,0,0 "--smooth $smooth" \
      -o "$work/teapot-$smooth.png"
  done
  oiiotool "$work/teapot-index.png" "$work/teapot-position.png" --mosaic 2x1 -d uint8 -o docs/images/teapot-smooth.png
else
  echo "skipped the teapot: $teapot is not there" >&2
fi
