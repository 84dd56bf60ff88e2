#!/usr/bin/env bash
# Bounded fuzzing of every loader: bash tests/fuzz/run_fuzz.sh [SECONDS_PER_TARGET=60]
#
# Needs clang and libFuzzer (Debian 12: apt-get install clang libclang-rt-14-dev) plus the
# project's build dependencies (.ci/install-deps). Configures build-fuzz with clang and
# -DMOTIONGP_FUZZ=ON, builds the fuzz targets, makes the seed corpora in build-fuzz/seeds (from
# $MOTIONGP_DATA, else ../shared/mocap, else the shipped clips in assets/mocap; the files are only
# read), runs each target for SECONDS_PER_TARGET and prints its executions and coverage.
# Crash/timeout/OOM inputs land in <build>/artifacts/<target>/ (<build>: build-fuzz, or
# MOTIONGP_FUZZ_BUILD); the exit status is 1 if any target found one (reproduce:
# <build>/fuzz_<target> FILE). Environment: MOTIONGP_FUZZ_JOBS
# (targets run in parallel, default 1), MOTIONGP_FUZZ_TARGETS (default "asf amc bvh model session"),
# MOTIONGP_FUZZ_BUILD (a build folder configured with clang, -DMOTIONGP_SANITIZE=ON and
# -DMOTIONGP_FUZZ=ON, e.g. CI's build-asan: its fuzzers are used instead of configuring build-fuzz,
# so the sanitizer build's core library serves both; tests/fuzz/CMakeLists.txt).
set -euo pipefail

SECONDS_PER_TARGET=${1:-60}
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
BUILD=${MOTIONGP_FUZZ_BUILD:-$ROOT/build-fuzz}
MOCAP=${MOTIONGP_DATA:-$ROOT/../shared/mocap}
[ -d "$MOCAP/asf_amc" ] || MOCAP="$ROOT/assets/mocap"
TARGETS=${MOTIONGP_FUZZ_TARGETS:-asf amc bvh model session}
JOBS=${MOTIONGP_FUZZ_JOBS:-1}
FUZZ="$ROOT/tests/fuzz"
start=$(date +%s)

command -v clang++ >/dev/null || { echo "run_fuzz.sh: expected clang++ (apt-get install clang libclang-rt-14-dev), found none" >&2; exit 2; }

# 1. Build (-O1 without NDEBUG: asserts stay on; line tables only, for readable stack traces
#    and a faster build), or take the fuzzers of a build that has them.
if [ -n "${MOTIONGP_FUZZ_BUILD:-}" ]; then
  grep -q '^MOTIONGP_FUZZ:BOOL=ON$' "$BUILD/CMakeCache.txt" 2>/dev/null ||
    { echo "run_fuzz.sh: expected MOTIONGP_FUZZ_BUILD=$BUILD to be a build folder configured with -DMOTIONGP_FUZZ=ON, found none" >&2; exit 2; }
else
  mkdir -p "$BUILD"
  CC=clang CXX=clang++ cmake -S "$ROOT" -B "$BUILD" -G Ninja -DMOTIONGP_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1" >"$BUILD/configure.log" 2>&1 \
    || { cat "$BUILD/configure.log" >&2; exit 2; }
fi
cmake --build "$BUILD" -j2 --target motiongp_fuzzers

# 2. Seed corpora (regenerated every run; the evolving corpus lives in build-fuzz/corpus).
SEEDS="$BUILD/seeds"
rm -rf "$SEEDS"
for t in $TARGETS; do mkdir -p "$SEEDS/$t" "$BUILD/corpus/$t" "$BUILD/artifacts/$t"; done
mkdir -p "$SEEDS/model" "$SEEDS/session"

# AMC: the header plus the first N frames (frame-number lines are a lone integer).
trim_amc() {  # FILE N OUT
  awk -v n="$2" '/^[ \t]*[0-9]+[ \t\r]*$/ { if (++f > n) exit } { print }' "$1" >"$3"
}
# BVH: the hierarchy, "Frames: N" (line ending kept) and the first N data rows.
trim_bvh() {  # FILE N OUT
  awk -v n="$2" '
    state == 0 && /^[ \t]*Frames:/ { cr = ($0 ~ /\r$/) ? "\r" : ""; print "Frames: " n cr; state = 1; next }
    state == 1 && /^[ \t]*Frame Time:/ { print; state = 2; next }
    state == 2 { if (++rows > n) exit }
    { print }' "$1" >"$3"
}

if [ -d "$MOCAP/asf_amc" ]; then
  for f in "$MOCAP"/asf_amc/*.asf; do cp "$f" "$SEEDS/asf/"; done
  for f in "$MOCAP"/asf_amc/*.amc; do
    b=$(basename "$f" .amc)
    trim_amc "$f" 60 "$SEEDS/amc/${b}_60.amc"
    trim_amc "$f" 2 "$SEEDS/amc/${b}_2.amc"
  done
else
  echo "run_fuzz.sh: no mocap folder at $MOCAP; ASF/AMC/BVH seeds come from tests/fuzz/regressions only" >&2
fi
if [ -d "$MOCAP/bvh" ]; then
  for f in "$MOCAP"/bvh/*.bvh; do
    b=$(basename "$f" .bvh)
    trim_bvh "$f" 60 "$SEEDS/bvh/${b}_60.bvh"
    trim_bvh "$f" 2 "$SEEDS/bvh/${b}_2.bvh"
  done
fi
export MOTIONGP_FUZZ_ASF=${MOTIONGP_FUZZ_ASF:-$MOCAP/asf_amc/35.asf}
if [ -f "$MOCAP/asf_amc/35_01.amc" ]; then
  "$BUILD/motiongp_fuzz_seeds" "$SEEDS" "$MOCAP/asf_amc/35.asf" "$MOCAP/asf_amc/35_01.amc"
else
  "$BUILD/motiongp_fuzz_seeds" "$SEEDS"
fi
# A model from the project's own CLI when the default build is there (else the helper's only).
if [ -x "$ROOT/build/motiongp" ] && [ -f "$MOCAP/asf_amc/35_01.amc" ]; then
  "$ROOT/build/motiongp" train "$MOCAP/asf_amc/35_01.amc" --frames 1:40 --active 20 --iters 1 \
    --scg-iters 5 --threads 1 --out "$SEEDS/model/cli_35_01.json" >/dev/null 2>&1 || true
fi
for t in $TARGETS; do
  [ -d "$FUZZ/seeds/$t" ] && cp "$FUZZ/seeds/$t"/* "$SEEDS/$t/" 2>/dev/null || true
  [ -d "$FUZZ/regressions/$t" ] && cp "$FUZZ/regressions/$t"/* "$SEEDS/$t/" 2>/dev/null || true
done

# 3. Run. -max_len fits the trimmed seeds of each format.
declare -A MAXLEN=([asf]=16384 [amc]=65536 [bvh]=131072 [model]=131072 [session]=262144)
declare -A DICT=([asf]=asf.dict [amc]=amc.dict [bvh]=bvh.dict [model]=json.dict [session]=json.dict)
run_one() {
  local t=$1 log="$BUILD/fuzz_$1.log"
  rm -f "$BUILD/artifacts/$t"/*
  set +e
  "$BUILD/fuzz_$t" "$BUILD/corpus/$t" "$SEEDS/$t" -dict="$FUZZ/dict/${DICT[$t]}" \
    -max_len="${MAXLEN[$t]}" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10 \
    -max_total_time="$SECONDS_PER_TARGET" -print_final_stats=1 \
    -artifact_prefix="$BUILD/artifacts/$t/" >"$log" 2>&1
  echo $? >"$BUILD/fuzz_$t.rc"
  set -e
}
running=0
for t in $TARGETS; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then wait -n || true; running=$((running - 1)); fi
done
wait

# 4. Report.
status=0
printf '%-8s %-10s %s\n' target result 'libFuzzer final line (executions, coverage)'
for t in $TARGETS; do
  rc=$(cat "$BUILD/fuzz_$t.rc")
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$BUILD/fuzz_$t.log" | tail -1 || true)
  execs=$(grep -E 'stat::number_of_executed_units' "$BUILD/fuzz_$t.log" | awk '{print $2}' || true)
  artifacts=$(ls "$BUILD/artifacts/$t" 2>/dev/null || true)
  if [ "$rc" = 0 ] && [ -z "$artifacts" ]; then
    printf '%-8s %-10s %s (executions: %s)\n' "$t" ok "$done_line" "${execs:-?}"
  else
    status=1
    printf '%-8s %-10s exit %s after %s executions; artifacts in %s: %s\n' "$t" FOUND "$rc" \
      "${execs:-?}" "$BUILD/artifacts/$t" "$(echo $artifacts)"
    grep -E 'ERROR: |SUMMARY: |fuzz: unexpected|runtime error' "$BUILD/fuzz_$t.log" | head -5 | sed 's/^/         /'
  fi
done
echo "run_fuzz.sh: $(( $(date +%s) - start )) s in total; logs in $BUILD/fuzz_<target>.log"
exit $status
