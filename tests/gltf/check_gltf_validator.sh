#!/usr/bin/env bash
# Runs the Khronos glTF Validator on OUTDIR's export.glb and export.gltf (export_for_check.sh):
# no error and no warning may be reported.
# Usage: check_gltf_validator.sh OUTDIR.  The validator is the npm package gltf-validator under
# $MOTIONGP_GLTF_VALIDATOR_DIR (default ~/.cache/motiongp/gltf-validator; .ci/run installs it
# there); exits 77 (skipped) when node or the package is absent.
set -euo pipefail
out=$1
validator_dir=${MOTIONGP_GLTF_VALIDATOR_DIR:-$HOME/.cache/motiongp/gltf-validator}
command -v node >/dev/null || { echo "node not installed: skipped"; exit 77; }
[ -d "$validator_dir/node_modules/gltf-validator" ] ||
  { echo "gltf-validator not in $validator_dir (npm install --prefix $validator_dir gltf-validator): skipped"; exit 77; }
exec node "$(dirname "$0")/validate_gltf.js" "$validator_dir" "$out/export.glb" "$out/export.gltf"
