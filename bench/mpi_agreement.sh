#!/usr/bin/env bash
# Issue 32, "Same answers": the same drying case on 1, 2 and 4 MPI ranks, several seeds, compared
# on the validation yardstick with the seed spread (docs/parallel.md "Same answers"). Runs one at
# a time (both cores each), skipping the ones already finished, so the campaign resumes where a
# session stopped.
#   1 rank x 2 threads, 2 ranks x 1 thread, 4 ranks x 1 thread (oversubscribed on 2 cores: its
#   wall time is not a speed figure)
# usage: bench/mpi_agreement.sh [CONFIG]   (default examples/quick.toml; "default": the embedded
#        default config, the paper's 20.1 mg/cm2 film)
# environment: SEEDS ("1 2 3"), RANKS ("1 2 4"), OUT (results/mpi_agreement), NAME (the config's
#   file name), DRYDEM (build/drydem), SET (extra --set KEY=VALUE words for every run)
# then: /usr/bin/python3 scripts/compare_integrators.py --by-ranks OUT/NAME OUT/NAME_r*_s*
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
config=${1:-$here/examples/quick.toml}
drydem=${DRYDEM:-$here/build/drydem}
out=${OUT:-$here/results/mpi_agreement}
name=${NAME:-$(basename "$config" .toml)} # "default" for the embedded config
seeds=${SEEDS:-1 2 3}
ranks_list=${RANKS:-1 2 4}
sets=()
for kv in ${SET:-}; do sets+=(--set "$kv"); done
mkdir -p "$out"
# Open MPI in a container runs as root and needs these; shared memory between the ranks.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=${OMPI_MCA_btl:-self,vader}
for ranks in $ranks_list; do
  for seed in $seeds; do
    dir=$out/${name}_r${ranks}_s${seed}
    if [[ -f $dir/summary.json ]] && grep -q '"status": "completed"' "$dir/summary.json"; then
      continue
    fi
    rm -rf "$dir"
    threads=$((ranks == 1 ? 2 : 1))
    echo "$(date +%T) $name: $ranks rank(s) x $threads thread(s), seed $seed -> $dir"
    cfg=("$config")
    [[ $config == default ]] && cfg=()
    cmd=("$drydem" run "${cfg[@]}" --seed "$seed" --threads "$threads" --quiet --no-plots
         "${sets[@]}" -o "$dir")
    if ((ranks == 1)); then
      "${cmd[@]}" || echo "run failed: $dir"
    else
      mpirun --oversubscribe -np "$ranks" "${cmd[@]}" || echo "run failed: $dir"
    fi
  done
done
