#!/usr/bin/env bash
# Issue 11 item 5: do the results depend on the time integration? The paper's 20.1 mg/cm2 recipe
# in a 40 x 40 um box (13,382 particles), three seeds each under the explicit reference (its
# guarded step, cap 1e-11 s) and under the semi-implicit default at two step caps (1e-10 s, the
# default, and 5e-11 s). Every run ends with the structure analysis (transport solves off: they
# are not compared here); scripts/compare_integrators.py then writes the table and the plot.
#
# usage: bench/integrator_comparison.sh [RUN...]
#   RUN  names from the matrix below (default: all); runs that already completed are skipped, so
#        the script resumes (a run stopped midway continues from its checkpoint), and two
#        instances with disjoint RUN lists use both cores. A run archived as completed (below) and
#        absent from OUT (a fresh machine) is skipped too.
# environment: THREADS (1), OUT (results/integrator_comparison), DRYDEM (build/drydem; a copy
#   keeps the runs on one binary while the tree is rebuilt)
# Each completed run's small files (config, summary, analysis JSON, profiles, the thickness
# time series thinned to <= 500 rows) are copied to docs/data/integrator_comparison/RUN so the
# table can be rebuilt from a clean clone: the explicit runs take ~1.5-2 h each on one core.
# Needs: build/drydem (README).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-1}
out=${OUT:-$here/results/integrator_comparison}
archive=$here/docs/data/integrator_comparison
# name:integrator:seed:step cap in s (0 = the integrator's default cap)
matrix=(
  expl_s1:explicit:1:0 expl_s2:explicit:2:0 expl_s3:explicit:3:0
  semi_s1:semi_implicit:1:0 semi_s2:semi_implicit:2:0 semi_s3:semi_implicit:3:0
  semi5_s1:semi_implicit:1:5e-11 semi5_s2:semi_implicit:2:5e-11 semi5_s3:semi_implicit:3:5e-11
)
wanted=("$@")
mkdir -p "$out" "$archive"

completed() {  # a run counts when its summary says so and its analysis exists
  [[ -f $1/summary.json && -f $1/analysis/analysis.json ]] &&
    grep -q '"status": *"completed"' "$1/summary.json"
}

keep_small_files() {  # $1 run folder, $2 archive folder
  mkdir -p "$2/analysis"
  cp "$1/config.toml" "$1/summary.json" "$2/"
  cp "$1/analysis/analysis.json" "$1/analysis/profiles.csv" "$2/analysis/"
  /usr/bin/python3 "$here/scripts/thin_timeseries.py" "$1/timeseries.csv" "$2/timeseries.csv"
}

for entry in "${matrix[@]}"; do
  IFS=: read -r name integ seed cap <<< "$entry"
  if ((${#wanted[@]})) && [[ ! " ${wanted[*]} " =~ " $name " ]]; then continue; fi
  dir=$out/$name
  if [[ ! -d $dir ]] && completed "$archive/$name"; then  # a fresh machine: archived already
    echo "== $name: completed (archived), skipped" >&2
    continue
  elif completed "$dir"; then
    echo "== $name: completed, skipped" >&2
  else
    echo "== $name: $integ, seed $seed, cap $cap s, $threads thread(s) -> $dir ($(date -u +%H:%M))" >&2
    cap_args=()
    if [[ $cap != 0 ]]; then cap_args=(--set "run.time_step=$cap"); fi
    if [[ -d $dir/checkpoint ]]; then  # stopped earlier (a session's end): continue it
      echo "== $name: resuming from its checkpoint" >&2
      run=("$drydem" run --resume "$dir")
    else
      run=("$drydem" run --set film.box_x=40um --set film.box_y=40um --seed "$seed"
        --set numerics.integrator="$integ" "${cap_args[@]}"
        --set 'analysis.transport_voxel_sizes=[]' --overwrite -o "$dir")
    fi
    "${run[@]}" --threads "$threads" --quiet --no-plots >> "$out/$name.log" 2>&1 || {
      echo "== $name failed, see $out/$name.log" >&2
      continue
    }
  fi
  keep_small_files "$dir" "$archive/$name"
done

runs=()
for entry in "${matrix[@]}"; do
  name=${entry%%:*}
  if [[ -f $archive/$name/summary.json ]]; then runs+=("$archive/$name"); fi
done
/usr/bin/python3 "$here/scripts/compare_integrators.py" "$archive/comparison" "${runs[@]}"
