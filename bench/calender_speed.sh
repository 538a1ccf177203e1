#!/usr/bin/env bash
# Calendering plate-speed check (issue 31, docs/calendering.md "What is measured so far"): the
# quick film (examples/quick.toml, paper scheme) dried with 3 seeds, each pressed to 10 MPa
# (pressure mode, 1 us hold, 2 us relaxation) at 0.05 m/s, and seed 12345 also at 0.2, 0.1,
# 0.025 and 0.0125 m/s. One run at a time (never two timings at once on 2 cores); a finished
# folder is kept and skipped. Then scripts/calender_report.py prints the table.
#
# usage: bench/calender_speed.sh
# environment: DRYDEM (build/drydem), THREADS (2), OUT (results/calender_speed), DRIED (a folder
#   holding dried_s12345 ... from an earlier call, default OUT)
# Needs: build/drydem (README). Run on an otherwise idle machine: the drying of the three films
# takes ~3 x 5 min, the calendering runs 0.5-5 min each.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-2}
out=${OUT:-$here/results/calender_speed}
dried=${DRIED:-$out}
mkdir -p "$out"
for seed in 12345 12346 12347; do
  if [[ ! -f $dried/dried_s$seed/final.csv ]]; then
    rm -rf "$dried/dried_s$seed"
    "$drydem" run "$here/examples/quick.toml" --seed "$seed" --threads "$threads" --quiet --no-plots \
      -o "$dried/dried_s$seed"
  fi
done
press() { # $1 seed, $2 plate speed [m/s]
  local dir=$out/s$1_v$2
  if [[ -f $dir/summary.json ]] && grep -q '"completed"' "$dir/summary.json"; then return; fi
  rm -rf "$dir"
  "$drydem" calender "$dried/dried_s$1" -o "$dir" --threads "$threads" --quiet --no-plots \
    --set calendering.mode='"pressure"' --set calendering.target_pressure=10MPa \
    --set calendering.plate_speed="$2 m/s" --set calendering.hold_time=1us \
    --set calendering.relaxation=2us > "$dir.log" 2>&1 || echo "== s$1 v$2 failed: $dir.log" >&2
}
for seed in 12345 12346 12347; do press "$seed" 0.05; done
for v in 0.2 0.1 0.025 0.0125; do press 12345 "$v"; done
/usr/bin/python3 "$here/scripts/calender_report.py" "$out"
