#!/usr/bin/env bash
# Structure analysis benchmark (issue 5): `drydem analyze` of the peers' settled 75 x 75 um bed
# (47,044 particles, the 20.1 mg/cm2 recipe) at 0.1 um voxels (~4.6e8 voxels), with wall time and
# peak memory from /usr/bin/time. Run it alone (it uses every core).
# usage: bench/analysis_bench.sh [VOXEL (default 0.1um)] [THREADS (default all)]
set -euo pipefail
cd "$(dirname "$0")/.."
voxel=${1:-0.1um}
threads=${2:-$(nproc)}
out=results/analysis_bench
mkdir -p "$out"
data="$out/settled_75um.data"
[[ -f "$data" ]] || gunzip -c ../shared/peers/data/settled_75um.data.gz > "$data"
/usr/bin/time -v ./build/drydem analyze "$data" -o "$out/run" --overwrite --voxel "$voxel" --threads "$threads" --no-plots \
    2> "$out/time.txt" | tee "$out/analyze.txt"
grep -E "Elapsed|Maximum resident" "$out/time.txt"
