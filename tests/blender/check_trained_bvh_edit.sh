#!/usr/bin/env bash
# A BVH-trained edit in Blender: trains a small model on a BVH clip, moves its right hand over a
# span with `motiongp edit`, and checks the edited BVH with check_bvh_import.sh (re-exported in
# the source hierarchy, imported by Blender, every joint against our FK of the edit, < 0.01 cm).
# Usage: check_trained_bvh_edit.sh MOTIONGP CLIP.bvh OUTDIR.  Exits 77 (skipped) without Blender.
set -euo pipefail
motiongp=$1 clip=$2 out=$3
command -v blender >/dev/null || { echo "blender not installed: skipped"; exit 77; }
mkdir -p "$out"
"$motiongp" train "$clip" --step 4 --active 60 --iters 3 --out "$out/model.json" --json > /dev/null
"$motiongp" edit "$out/model.json" --effector rhand --keys 40,60,80 --offset 0,15,10 --out "$out/edit.bvh" \
  --json > /dev/null
exec bash "$(dirname "$0")/check_bvh_import.sh" "$motiongp" "$out/edit.bvh" "$out/import"
