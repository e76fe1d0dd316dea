#!/usr/bin/env bash
# run_fuzzers.sh BUILD_DIR SECONDS [HARNESS...]: runs each libFuzzer harness of BUILD_DIR
# (configured with -DMESHSTEP_FUZZ=ON) for SECONDS, two at a time, each from its seeds
# (made by the build's make_seeds) and the corpus it grew before (BUILD_DIR/fuzz-corpus/),
# and fails on the first finding. A finding leaves its input in
# BUILD_DIR/fuzz-findings/HARNESS/ (crash-*, timeout-*, oom-*) and the report in
# BUILD_DIR/fuzz-findings/HARNESS.log. See docs/fuzzing.md.
set -euo pipefail
(($# >= 2)) || { echo "usage: $0 BUILD_DIR SECONDS [HARNESS...]" >&2; exit 2; }
build="$(cd "$1" && pwd)"
seconds="$2"
shift 2
harnesses=("$@")
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
if ((${#harnesses[@]} == 0)); then
  # Every harness tests/fuzz/CMakeLists.txt lists (MESHSTEP_FUZZERS), read from there so that
  # a new harness is run without being named twice; each must have been built.
  read -r -a harnesses < <(sed -n 's/^set(MESHSTEP_FUZZERS \(.*\))$/\1/p' "$root/tests/fuzz/CMakeLists.txt") || true
  ((${#harnesses[@]})) || { echo "$0: no MESHSTEP_FUZZERS list in tests/fuzz/CMakeLists.txt" >&2; exit 2; }
fi
for h in "${harnesses[@]}"; do
  [[ -x "$build/tests/fuzz/fuzz_$h" ]] || { echo "$0: $build/tests/fuzz/fuzz_$h is not built (-DMESHSTEP_FUZZ=ON)" >&2; exit 2; }
done

"$build/tests/fuzz/make_seeds" "$root/assets/examples" "$build/tests/fuzz/seeds" >/dev/null
mkdir -p "$build/fuzz-findings"

run_one() {
  local h="$1" build="$2" seconds="$3"
  local corpus="$build/fuzz-corpus/$h" findings="$build/fuzz-findings/$h"
  mkdir -p "$corpus" "$findings"
  # Inputs kept small (each pipeline run triangulates and refines), one input at most 10 s,
  # at most 2 GB: a hang or a runaway allocation is a finding too.
  if "$build/tests/fuzz/fuzz_$h" "$corpus" "$build/tests/fuzz/seeds/$h" \
       -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
       -artifact_prefix="$findings/" -print_final_stats=1 >"$build/fuzz-findings/$h.log" 2>&1; then
    printf 'fuzz_%s: %s s, no finding (%s)\n' "$h" "$seconds" \
      "$(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz-findings/$h.log" | grep -o '[0-9]*$') executions"
  else
    printf 'fuzz_%s: FINDING, see %s.log and %s/\n' "$h" "$findings" "$findings" >&2
    tail -n 40 "$build/fuzz-findings/$h.log" >&2
    return 1
  fi
}
export -f run_one
printf '%s\n' "${harnesses[@]}" | xargs -P 2 -I{} bash -c 'run_one "$@"' _ {} "$build" "$seconds"
