#!/usr/bin/env bash
# The real-GPU measurements issues 46-48 still wait for, packed for one device call.
#
#   ../shared/tools/gpu-bench.sh prepare && tools/gpu-session.sh
#   then the device's run: command `bash .gpu/gpu-bench.sh run`, carry [".gpu"], timeout_s 600
#
# Adds slc-bevy's many_lights example to .gpu/ (stripped and xz-compressed: the release binary is 90 MB,
# over the 64 MiB a call carries; Python's lzma unpacks it there) and writes .gpu/commands.sh:
# - issue 46: the default VPL frame at 1080p, 65,536 and 1,048,576 VPLs, twice each (two runs must agree
#   within 5% per stage; since 887c3c6 the near field loops over quarter tiles: its stage against the
#   H200's 3.46 ms at a million VPLs in docs/results/gpu-frame-times.md, d001e5f, measures them);
# - issue 47: many_lights at 1080p with 4,000 lights (every configuration, the default's 3 picks with
#   visibility reuse against the old default's 8 with plain reuse among them; then slc's alone with the walk
#   per pixel instead of per tile, with hardware ray queries for the shadow rays, and at eps 0.03),
#   500 and 20,000 (Bevy at unbounded ranges left out
#   there: minutes);
# - issue 48: the path-tracing suite at 512x512, noise from seed pairs (since 97f020f with the BSH's range tail,
#   since f8d059e and 72832ff with the path tracers' tree split by the sphere-area heuristic and 4 wide: against
#   docs/results/gpu-h200/pt-suite-512.json, d001e5f, it measures the three on the GPU); then the losing
#   scenes again with the light connections' shadow rays as hardware ray queries (--ray-query), and five 49,152-light
#   scenes with the BSH grids on (--grid on: off by default on the GPU until this measures them; against the same
#   scenes in pt-suite-512.json, the grids' time per sample).
#   One seed pair per method (the call's budget): where rare bright paths decide the error, one pair's σ moves
#   up to 5x between seeds (docs/results/pt-suite-pairs.md measures the CPU suite with --pairs 8), so read the
#   GPU median with that uncertainty.
# About 570 s on an NVIDIA H200 (the last call's steps: docs/results/gpu-h200-b/log.txt, 490 s, before the
# ray-query and grid suites; the bench's plain-reuse row adds a few seconds to each many_lights step): if the
# call passes 600 s, drop the eps 0.03 step, or split the call in two; give the run timeout_s 600. Results land
# in the call's $OUT; copy them to docs/results/ with the adapter's name and the date.
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"
[ -x .gpu/slc ] || { echo "run ../shared/tools/gpu-bench.sh prepare first" >&2; exit 1; }
cargo build --release -q --manifest-path slc-bevy/Cargo.toml --ignore-rust-version --example many_lights
strip -o .gpu/many_lights.tmp slc-bevy/target/release/examples/many_lights
xz -6 -c .gpu/many_lights.tmp > .gpu/many_lights.xz
rm .gpu/many_lights.tmp
cat > .gpu/commands.sh <<'CMDS'
# Sourced by `gpu-bench.sh run` inside .gpu/ (S is the slc binary); written by tools/gpu-session.sh.
VPL="--backend gpu --width 1920 --height 1080 --error-bounds 0.004 --ranges 0.05"
step 60 $S bench $VPL --json $OUT/vpl-1080-a.json
step 60 $S bench $VPL --json $OUT/vpl-1080-b.json
step 90 $S bench $VPL --vpls 1048576 --json $OUT/vpl-1080-1m-a.json
step 90 $S bench $VPL --vpls 1048576 --json $OUT/vpl-1080-1m-b.json
python3 -c "import lzma, shutil; shutil.copyfileobj(lzma.open('many_lights.xz'), open('many_lights', 'wb'))"
chmod +x many_lights
export RUST_LOG=warn
step 100 env SLC_BEVY_BENCH=$OUT/bevy-4000.json ./many_lights 4000
step 60 env SLC_BEVY_WALK=pixel SLC_BEVY_BENCH_MODES=slc SLC_BEVY_BENCH=$OUT/bevy-4000-pixel-walk.json ./many_lights 4000
step 60 env SLC_BEVY_RAY_QUERY=1 SLC_BEVY_BENCH_MODES=slc SLC_BEVY_BENCH=$OUT/bevy-4000-ray-query.json ./many_lights 4000
step 60 env SLC_BEVY_EPSILON=0.03 SLC_BEVY_BENCH_MODES=slc SLC_BEVY_BENCH=$OUT/bevy-4000-eps003.json ./many_lights 4000
step 60 env SLC_BEVY_BENCH=$OUT/bevy-500.json ./many_lights 500
step 120 env SLC_BEVY_BENCH_FRAMES=32 SLC_BEVY_BENCH_MODES=slc,default SLC_BEVY_BENCH=$OUT/bevy-20000.json ./many_lights 20000
step 150 $S bench --app pt --backend gpu --suite scenes/suite --width 512 --height 512 --seconds 0.3 --noise seeds --json $OUT/pt-suite-512.json
mkdir -p rq-suite && cp scenes/suite/tri-*-49152.toml scenes/suite/tri-away-2048.toml scenes/suite/points-clusters-49152.toml rq-suite/
step 60 $S bench --app pt --backend gpu --ray-query --suite rq-suite --width 512 --height 512 --seconds 0.3 --noise seeds --json $OUT/pt-suite-512-ray-query.json
mkdir -p grid-suite && cp scenes/suite/{points-clusters,points-volume,tri-away,tri-facing,glossy-facing}-49152.toml grid-suite/
step 60 $S bench --app pt --backend gpu --grid on --suite grid-suite --width 512 --height 512 --seconds 0.3 --noise seeds --json $OUT/pt-suite-512-grid.json
CMDS
du -sh .gpu
echo "prepared: run 'bash .gpu/gpu-bench.sh run' on the device, carry [\".gpu\"], timeout_s 600"
