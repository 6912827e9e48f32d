#!/usr/bin/env bash
# Makes the README's pictures of contract version 2's assets:
#   docs/images/spot-textured.png  spot (../shared/assets) with an MTL whose map_Kd is its texture
#   docs/images/objects.png        a scene of objects: two placed spots and the generated knot
# Usage: [PHONGRAST_SHARED_ASSETS=../shared/assets] docs/images/make_asset_images.sh [build/release/apps/phongrast]
# The meshes stay in ../shared/assets (never copied into the repository): this
# script writes the MTL and the scene files into a temporary folder.
set -euo pipefail
cd "$(dirname "$0")/../.."
phongrast="$(realpath "${1:-build/release/apps/phongrast}")"
shared="$(realpath "${PHONGRAST_SHARED_ASSETS:-../shared/assets}")"
knot="$(realpath assets/default.obj)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# spot.obj has `vt` but no material: give it one whose map_Kd is spot_texture.png.
{ echo 'mtllib spot.mtl'; echo 'usemtl spot'; cat "$shared/spot.obj"; } > "$work/spot.obj"
cp "$shared/spot_texture.png" "$work/"
printf 'newmtl spot\nKa 0.15 0.15 0.15\nKd 0.8 0.8 0.8\nKs 0.25 0.25 0.25\nNs 40\nmap_Kd spot_texture.png\n' > "$work/spot.mtl"

# The cow faces -z: the camera looks at it from there; the objects turn it towards theirs.
cat > "$work/spot.json" <<JSON
{
  "mesh": "spot.obj",
  "camera": { "eye": [2.0, 1.0, -3.0], "lookat": [0, 0.2, 0], "up": [0, 1, 0], "focal": 3, "sensor": [2.0, 2.0] },
  "image": { "height": 384, "width": 384, "background": [1, 1, 1] },
  "ambient": [1, 1, 1],
  "lights": [ { "position": [3, 4, -5], "intensity": [0.8, 0.8, 0.8] }, { "position": [-4, 1, -3], "intensity": [0.3, 0.3, 0.3] } ],
  "shader": "phong",
  "normals": "computed"
}
JSON
cat > "$work/objects.json" <<JSON
{
  "objects": [
    { "mesh": "spot.obj", "translation": [-0.8, 0, 0], "rotation": [0, 0.9238795, 0, 0.3826834] },
    { "mesh": "spot.obj", "translation": [0.8, 0, 0], "rotation": [0, 0.9238795, 0, -0.3826834], "scale": 0.8 },
    { "mesh": "$knot", "translation": [0, 1.3, -1], "scale": 0.25, "material": { "ks": 0.8, "n": 40 } }
  ],
  "camera": { "eye": [0, 1.2, 5], "lookat": [0, 0.4, 0], "up": [0, 1, 0], "focal": 3, "sensor": [2.2, 2.8] },
  "image": { "height": 330, "width": 420, "background": [1, 1, 1] },
  "material": { "ka": 0.15, "kd": 0.8 },
  "ambient": [1, 1, 1],
  "lights": [ { "position": [3, 4, 5], "intensity": [0.8, 0.8, 0.8] }, { "position": [-4, 1, 3], "intensity": [0.3, 0.3, 0.3] } ],
  "shader": "phong"
}
JSON
"$phongrast" render "$work/spot.json" --samples 2 -o docs/images/spot-textured.png --quiet
"$phongrast" render "$work/objects.json" --samples 2 -o docs/images/objects.png --quiet
echo "wrote docs/images/spot-textured.png and docs/images/objects.png"
