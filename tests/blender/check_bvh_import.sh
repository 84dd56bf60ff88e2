#!/usr/bin/env bash
# Exports CLIP to BVH with motiongp, imports it with Blender's BVH importer (headless) and checks
# that Blender places root and effectors where MotionGP's FK does (< 0.01 cm).
# Usage: check_bvh_import.sh MOTIONGP CLIP OUTDIR.  Exits 77 (skipped) when Blender is absent.
set -euo pipefail
motiongp=$1 clip=$2 out=$3
command -v blender >/dev/null || { echo "blender not installed: skipped"; exit 77; }
mkdir -p "$out"
"$motiongp" export "$clip" --out "$out/export.bvh" --json > /dev/null
files=()
for f in 1 60 120 170; do
  "$motiongp" fk "$clip" --frame $f --json > "$out/fk_$f.json"
  files+=("$out/fk_$f.json")
done
status=0
log=$(blender -b --factory-startup --python-exit-code 1 -P "$(dirname "$0")/check_bvh_import.py" -- \
      "$out/export.bvh" "${files[@]}" 2>&1) || status=$?
grep -E "BLENDER_BVH_CHECK|Error|Traceback" <<< "$log" || true
exit $status
