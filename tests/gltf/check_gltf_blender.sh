#!/usr/bin/env bash
# Imports OUTDIR's export.glb and export.gltf (export_for_check.sh), and the FBX that
# `motiongp export` makes of export.glb through Blender, with Blender's importers (headless), and
# checks one armature, one action with the clip's frame count, and every bone head within 0.1 cm
# of our FK on five frames (check_gltf_import.py).
# Usage: check_gltf_blender.sh MOTIONGP OUTDIR.  Exits 77 (skipped) without Blender.
set -euo pipefail
motiongp=$1 out=$2
command -v blender >/dev/null || { echo "blender not installed: skipped"; exit 77; }
# shellcheck disable=SC1091
source "$out/check.env"
"$motiongp" export "$out/export.glb" --out "$out/export.fbx" --json > /dev/null
log=$(blender -b --factory-startup --python-exit-code 1 -P "$(dirname "$0")/check_gltf_import.py" -- \
      "$frames" "$fps" "$out/export.glb" "$out/export.gltf" "$out/export.fbx" -- "${fk_files[@]}" 2>&1) || status=$?
grep -E "BLENDER_GLTF_CHECK|Error|Traceback" <<< "$log" || true
exit "${status:-0}"
