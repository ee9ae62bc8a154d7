#!/usr/bin/env bash
# Loads a glTF in Blender's and Godot 3's own importers and checks that it stands upright there:
# Blender (background, bpy.ops.import_scene.gltf) must find it tallest along its Z (glTF's +Y
# turned by Blender's importer), Godot (its editor imports the .glb, a script instances the
# scene) tallest along Y. Prints one "blender: ..." and one "godot: ..." line with the bounding
# boxes (scripts/engines/) and exits 1 when either engine sees the asset on its side or cannot
# load it.
#   scripts/check-engines.sh [RAMUS] [FILE.glb]
# Without FILE it builds the demo tree (examples/trees/broadleaf.ramus, --lod 2 --wind) with
# RAMUS (default build/release/ramus). Installs Debian's blender, godot3, xvfb and xauth when
# missing (RAMUS_NO_INSTALL=1 skips that and fails instead).
set -euo pipefail
cd "$(dirname "$0")/.."
ramus="${1:-build/release/ramus}"
glb="${2:-}"

packages=(blender godot3 xvfb xauth)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "${RAMUS_NO_INSTALL:-0}" = 1 ]; then
    echo "check-engines: missing ${missing[*]}" >&2
    exit 2
  fi
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

work="$(mktemp -d)"
editor_group=""
cleanup() {
  # The Godot editor (and its Xvfb) run in a session of their own: end that group only.
  [ -n "$editor_group" ] && kill -- "-$editor_group" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
if [ -z "$glb" ]; then
  glb="$work/broadleaf.glb"
  "$ramus" -q build examples/trees/broadleaf.ramus -o "$glb" --lod 2 --wind
fi
status=0

# Blender: its glTF importer, in the background; the bounds script exits 1 when not upright.
if ! blender -b --factory-startup --python scripts/engines/blender_bounds.py -- "$glb" \
    >"$work/blender.log" 2>&1; then
  status=1
fi
grep '^blender:' "$work/blender.log" || { tail -20 "$work/blender.log" >&2; status=1; }

# Godot 3 imports assets only in its editor: open the project under Xvfb until the .glb's
# imported scene appears, close it, then run the bounds script (LC_ALL: Godot rejects locale C).
project="$work/godot"
mkdir -p "$project"
cp "$glb" "$project/asset.glb"
cp scripts/engines/godot_bounds.gd "$project/"
printf 'config_version=4\n\n[application]\n\nconfig/name="ramus engine check"\n' >"$project/project.godot"
export LC_ALL=C.UTF-8
setsid xvfb-run -a godot3 --editor --path "$project" >"$work/godot-editor.log" 2>&1 &
editor_group=$!
for _ in $(seq 1 180); do
  ls "$project"/.import/asset.glb-*.scn >/dev/null 2>&1 && break
  sleep 1
done
sleep 1
kill -- "-$editor_group" 2>/dev/null || true
wait "$editor_group" 2>/dev/null || true
editor_group=""
if ! ls "$project"/.import/asset.glb-*.scn >/dev/null 2>&1; then
  echo "godot: the editor did not import the glb within 180 s" >&2
  tail -20 "$work/godot-editor.log" >&2
  exit 1
fi
if ! xvfb-run -a godot3 --no-window --path "$project" -s godot_bounds.gd >"$work/godot.log" 2>&1; then
  status=1
fi
grep '^godot:' "$work/godot.log" || { tail -20 "$work/godot.log" >&2; status=1; }
exit $status
