#!/usr/bin/env bash
# Blender's importers on our exports, one Blender for all the cases (its start-up is most of the
# cost): each OUTDIR (export_for_check.sh) gives its export.glb and export.gltf, and the cases
# marked FBX also the FBX that `motiongp export` makes of export.glb through Blender. Each file
# must import as one armature with one action of the clip's frame count, every bone head within
# 0.1 cm of our FK on five frames (check_gltf_import.py).
# Usage: check_gltf_blender.sh MOTIONGP [--fbx] OUTDIR [[--fbx] OUTDIR ...].  Exits 77 (skipped)
# without Blender.
set -euo pipefail
motiongp=$1
shift
command -v blender >/dev/null || { echo "blender not installed: skipped"; exit 77; }
dirs=()
fbx=0
for arg in "$@"; do
  if [ "$arg" = --fbx ]; then fbx=1; continue; fi
  rm -f "$arg/export.fbx"
  [ "$fbx" = 1 ] && "$motiongp" export "$arg/export.glb" --out "$arg/export.fbx" --json > /dev/null
  dirs+=("$arg")
  fbx=0
done
log=$(blender -b --factory-startup --python-exit-code 1 -P "$(dirname "$0")/check_gltf_import.py" -- "${dirs[@]}" 2>&1) ||
  status=$?
grep -E "BLENDER_GLTF_CHECK|Error|Traceback" <<< "$log" || true
exit "${status:-0}"
