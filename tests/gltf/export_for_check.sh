#!/usr/bin/env bash
# Writes what the glTF checks read, into OUTDIR: export.glb and export.gltf of CLIP (or, with
# --edit, of an edit of CLIP: a small model trained on it, the right hand moved over frames
# 40..80), our FK of the exported motion on five frames (fk_<frame>.json), and check.json with
# the frame count, the frame rate and those FK files. A ctest fixture: the validator and Blender
# checks share it.
# Usage: export_for_check.sh MOTIONGP CLIP OUTDIR [--edit]
set -euo pipefail
motiongp=$1 clip=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
if [ "${4:-}" = --edit ]; then
  "$motiongp" train "$clip" --step 4 --active 60 --iters 3 --out "$out/model.json" --json > /dev/null
  "$motiongp" edit "$out/model.json" --effector rhand --keys 40,60,80 --offset 0,15,10 --out "$out/export.glb" \
    --json > /dev/null
  # Our FK of the edited motion, from the same edit written as BVH (independent of the glTF writer).
  "$motiongp" edit "$out/model.json" --effector rhand --keys 40,60,80 --offset 0,15,10 --out "$out/edit.bvh" \
    --json > /dev/null
  fk_source="$out/edit.bvh"
else
  "$motiongp" export "$clip" --out "$out/export.glb" --json > /dev/null
  fk_source="$clip"
fi
"$motiongp" export "$out/export.glb" --out "$out/export.gltf" --json > /dev/null
read -r frames fps < <("$motiongp" info "$fk_source" --json |
  python3 -c 'import json,sys; j = json.load(sys.stdin); print(j["frames"], j["fps"])')
fk_files=()
for f in 1 $((frames / 4)) $((frames / 2)) $((3 * frames / 4)) "$frames"; do
  "$motiongp" fk "$fk_source" --frame "$f" --json > "$out/fk_$f.json"
  fk_files+=("$out/fk_$f.json")
done
python3 -c 'import json, sys; print(json.dumps({"frames": int(sys.argv[1]), "fps": float(sys.argv[2]), "fk_files": sys.argv[3:]}))' \
  "$frames" "$fps" "${fk_files[@]}" > "$out/check.json"
