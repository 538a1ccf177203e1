#!/usr/bin/env bash
# Calendering's quasi-static knobs against the seed spread, through the unloaded state (issue 31,
# docs/calendering.md "Plate speed and density scaling after unloading"): the quick film
# (examples/quick.toml) dried with 3 seeds, each pressed in pressure mode to P, held, unloaded and
# relaxed to rest, at plate speed V and CB density scaling S for every V:S in CASES: the
# settings of the long runs (0.4 m/s, S 16), the plate speed halved, the scaling quartered, and
# the defaults (0.05 m/s, no scaling) as the reference. A finished folder is kept and skipped,
# so a stopped queue resumes. Then
# scripts/calender_quasi_static_report.py prints per case the mean and s.d. over the seeds and
# each case's paired difference from the reference.
#
# usage: bench/calender_quasi_static.sh
# environment: DRYDEM (build/drydem), THREADS (1), OUT (results/calender_quasi_static),
#   SEEDS ("12345 12346 12347"), CASES ("0.4:16 0.2:16 0.4:4 0.05:1"), P (10 MPa),
#   CALENDER_SET (space-separated KEY=VALUE for every calendering run; default the compaction
#   settings calibrated on the Sangros film: docs/calendering.md "Extruding agglomerates"),
#   DRIED (the folder holding dried_s<SEED>, default OUT: another OUT can reuse the films),
#   DRY_SET (space-separated KEY=VALUE for the drying runs, e.g. "film.box_x=80um
#   film.box_y=80um": the quick film has one NCM layer of ~33 spheres in its 40 um box, so its
#   seed spread is ~0.02 in porosity; four times the area halves it)
# Needs: build/drydem (README). Cost on 2 threads (measured 2026-12-06): a 40 um film dries in
# ~1 min, an 80 um one in ~3 min; a calendering run takes 10-20 s (40 um) or 1 min (80 um) at
# 0.4-0.2 m/s with S 16, 3 min or 14 min at the reference 0.05 m/s unscaled.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-1}
out=${OUT:-$here/results/calender_quasi_static}
seeds=${SEEDS:-12345 12346 12347}
cases=${CASES:-0.4:16 0.2:16 0.4:4 0.05:1}
pressure=${P:-10}
calender_set=${CALENDER_SET:-calendering.cb_compaction_pressure=110MPa calendering.cb_yield_pressure=110MPa calendering.yield_pressure=1GPa calendering.cb_dense_yield_pressure=300MPa calendering.cb_extrusion=true numerics.overlap_limit=2}
dried=${DRIED:-$out}
mkdir -p "$out" "$dried"

completed() { [[ -f $1/summary.json ]] && grep -q '"status": "completed"' "$1/summary.json"; }

for seed in $seeds; do
  dir=$dried/dried_s$seed
  completed "$dir" && continue
  rm -rf "$dir"
  dry_extra=()
  for kv in ${DRY_SET:-}; do dry_extra+=(--set "$kv"); done
  "$drydem" run "$here/examples/quick.toml" --seed "$seed" --threads "$threads" --quiet --no-plots \
    "${dry_extra[@]}" -o "$dir" > "$dir.log" 2>&1
done

for seed in $seeds; do
  for c in $cases; do
    v=${c%%:*} s=${c##*:}
    dir=$out/p${pressure}_v${v}_S${s}_s$seed
    completed "$dir" && continue
    rm -rf "$dir"
    extra=()
    for kv in $calender_set; do extra+=(--set "$kv"); done
    echo "== $(basename "$dir") ($(date -u +%H:%M))" >&2
    "$drydem" calender "$dried/dried_s$seed" -o "$dir" --threads "$threads" --quiet --no-plots \
      --set calendering.mode='"pressure"' --set calendering.target_pressure="$pressure MPa" \
      --set calendering.plate_speed="$v m/s" --set calendering.cb_density_scaling="$s" \
      --set analysis.at_end=false "${extra[@]}" > "$dir.log" 2>&1 ||
      echo "== $(basename "$dir") stopped (see $dir.log)" >&2
  done
done
/usr/bin/python3 "$here/scripts/calender_quasi_static_report.py" "$out"
