#!/usr/bin/env bash
# Interleaved A/B of the drying pair loop between builds (issue 11/12: "measure before and after"):
# each binary continues the same dense film for 500 steps on one thread, round after round, and
# prints the seconds of each phase from its summary.json. The machine's speed drifts, so compare
# the best rounds and the ratio pair / integrate of the same run.
#
# usage: bench/pair_loop_ab.sh FINAL_CSV BINARY... (e.g. out/default/final.csv of the main job and
#        two builds' drydem); environment: ROUNDS (3), OUT (results/pair_loop_ab)
# Particles sunk deeper than 0.55 r into the substrate are lifted to 0.55 r so that builds from
# before the reader accepted them (90 %, issue 15) take the same file.
set -euo pipefail
final=$1; shift
out=${OUT:-results/pair_loop_ab}
mkdir -p "$out"
/usr/bin/python3 - "$final" "$out/dense.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    r["z_m"] = repr(max(float(r["z_m"]), 0.55 * float(r["radius_m"])))
w = csv.DictWriter(open(sys.argv[2], "w"), fieldnames=rows[0].keys())
w.writeheader()
w.writerows(rows)
PY
for round in $(seq "${ROUNDS:-3}"); do
  k=0
  for bin in "$@"; do
    k=$((k + 1))
    "$bin" run --particles "$out/dense.csv" --set run.max_process_time=0.5s --set drying.relaxation=0.1s \
      --set analysis.at_end=false --no-plots --quiet --threads 1 -o "$out/run_$k" --overwrite > /dev/null 2>&1 || true
    /usr/bin/python3 - "$out/run_$k/summary.json" "$bin" "$round" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
p = s["wall_time_phases_s"]
print(f"round {sys.argv[3]} {sys.argv[2]}: {s['steps']} steps, " + ", ".join(f"{k} {v:.2f} s" for k, v in p.items())
      + f", pair/integrate {p['pair'] / p['integrate']:.2f}")
PY
  done
done
