#!/usr/bin/env bash
# Drying benchmark (issue 11): the same drying run with the explicit reference and the
# semi-implicit default, one after the other (never two timings at once on 2 cores), and the
# ratio of their wall times to the same end. Prints process seconds per wall second,
# particle-steps/s, the mean time step and the final thickness of each.
#
# usage: bench/drying_bench.sh [CASES...]
#   CASES  quick (examples/quick.toml, 3 mg/cm2, 40 x 40 um, ~2,000 particles; default)
#          paper40 (the paper's 20.1 mg/cm2 recipe in a 40 x 40 um box, 13,382 particles; the
#          explicit run takes about an hour on 2 cores)
#          converged (examples/quick_converged.toml: the quick case at the converged setting of
#          docs/validation.md, force-ratio scheme, e = 24, S = 4; both integrators with the step
#          cap at 1e-10 s, so that the stability guard alone sets each one's step; ~1.5e6 steps,
#          ~15 min each on 2 cores)
# environment: DRYDEM (build/drydem), THREADS (2), SEED (config's), OUT (results/drying_bench), INTEGRATORS
#   ("explicit semi_implicit")
# Needs: build/drydem (README). Run on an otherwise idle machine.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-2}
out=${OUT:-$here/results/drying_bench}
integrators=${INTEGRATORS:-explicit semi_implicit}
cases=${*:-quick}
mkdir -p "$out"
seed_args=()
if [[ -n ${SEED:-} ]]; then seed_args=(--seed "$SEED"); fi
for case in $cases; do
  case $case in
    quick) args=("$here/examples/quick.toml") ;;
    paper40) args=(--set film.box_x=40um --set film.box_y=40um) ;;
    converged) args=("$here/examples/quick_converged.toml" --set run.time_step=1e-10) ;;
    *) echo "unknown case $case (quick, paper40, converged)" >&2; exit 2 ;;
  esac
  for integ in $integrators; do
    dir=$out/${case}_$integ
    echo "== $case, $integ ($threads threads) -> $dir" >&2
    "$drydem" run "${args[@]}" "${seed_args[@]}" --threads "$threads" --quiet --no-plots --overwrite \
      --set numerics.integrator="$integ" --set analysis.at_end=false -o "$dir" >&2 || true
  done
done
INTEGRATORS="$integrators" /usr/bin/python3 - "$out" $cases <<'PY'
import json, sys, os
out, cases = sys.argv[1], sys.argv[2:]
integrators = os.environ["INTEGRATORS"].split()
print(f"{'case':<9} {'integrator':<14} {'wall s':>8} {'proc s/wall s':>13} {'p-steps/s':>10} "
      f"{'mean dt s':>10} {'steps':>9} {'thickness um':>12}  status")
for case in cases:
    walls = {}
    for integ in integrators:
        f = os.path.join(out, f"{case}_{integ}", "summary.json")
        if not os.path.exists(f):
            continue
        s = json.load(open(f))
        wall = s["wall_time_s"]; walls[integ] = wall
        thick = s.get("final_thickness_um")
        print(f"{case:<9} {integ:<14} {wall:8.1f} {s['process_time_end_s'] / wall:13.4f} "
              f"{s['particle_steps_per_s']:10.3g} {s.get('time_step_mean_s', 0):10.3g} {s['steps']:9d} "
              f"{(thick if thick is not None else float('nan')):12.3f}  {s['status']}")
    for integ, wall in walls.items():
        if integ != "explicit" and "explicit" in walls:
            print(f"{case:<9} ratio explicit/{integ} wall time: {walls['explicit'] / wall:.2f}")
PY
