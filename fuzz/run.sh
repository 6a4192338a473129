#!/usr/bin/env bash
# Runs every fuzz target for SECONDS (default 30) with cargo-fuzz (nightly).
#   fuzz/run.sh 600      # the long run: 10 minutes per target
# The IES target starts from ../shared/data/ies/ as its corpus, and every
# target first replays its past crashes in fuzz/regressions/<target>/. New
# crashes land in fuzz/artifacts/<target>/ and make this script exit non-zero,
# after printing the input (cargo fuzz fmt) so a CI log is enough to reproduce.
# FUZZ_SEED fixes libFuzzer's seed (CI does, so its gate is reproducible);
# without it each run explores from a fresh random seed. FUZZ_SANITIZER picks
# cargo-fuzz's sanitizer (default address): CI's seconds-long smoke pass uses
# none, which finds the same panics and builds in two thirds of the time
# (161 s against about 245 s on CI's 2 cores); AddressSanitizer matters for
# the long runs, where the unsafe code of the SIMD loops and dependencies
# gets the hours it needs.
set -euo pipefail
cd "$(dirname "$0")"
secs="${1:-30}"
seed=()
[ -n "${FUZZ_SEED:-}" ] && seed=("-seed=$FUZZ_SEED")
san=(-s "${FUZZ_SANITIZER:-address}")
targets=(ies_parse scene_loaders bsh_vs_brute range_math kernel_features)
cargo +nightly fuzz build "${san[@]}" "${targets[@]}" >/dev/null 2>&1 || cargo +nightly fuzz build "${san[@]}"
for t in "${targets[@]}"; do
    mkdir -p "corpus/$t"
    if [ "$t" = ies_parse ] && [ -d ../../shared/data/ies ]; then
        cp ../../shared/data/ies/*.ies "corpus/$t/"
    fi
    regress=()
    [ -d "regressions/$t" ] && regress=("regressions/$t")
    echo "== fuzz $t for ${secs}s${FUZZ_SEED:+ (seed $FUZZ_SEED)}"
    cargo +nightly fuzz run "${san[@]}" "$t" "corpus/$t" "${regress[@]}" -- -max_total_time="$secs" -rss_limit_mb=2048 -timeout=10 "${seed[@]}" 2>&1 \
        | grep -E "^(#[0-9]+ +DONE|==[0-9]+== ERROR|SUMMARY|Done [0-9]+ runs)" || true
    if compgen -G "artifacts/$t/*" >/dev/null; then
        echo "fuzz $t found a crash: $(ls artifacts/$t)" >&2
        for a in artifacts/"$t"/*; do cargo +nightly fuzz fmt "${san[@]}" "$t" "$a" 2>&1 | tail -40 >&2 || true; done
        exit 1
    fi
done
