#!/usr/bin/env bash
# Issue 31: the calendering runs behind docs/calendering.md "Validation" and "The 20.1 mg/cm2
# film". One queue of named steps; a step whose folder holds a completed summary.json is skipped,
# so the queue resumes where it stopped (a stopped calendering run is rerun from its dried film).
# One run at a time (never two timings at once on 2 cores).
#
#   sg_dry          the film of Sangros Gimenez et al. 2019 (examples/sangros2019.toml), dried
#                   by DryDEM with the paper's scheme, seed SEED (12345)
#   sg_p<P>         that film pressed to P MPa (pressure mode) and unloaded, P one of the
#                   article's 19.8 42.7 79.1 159.4; sg_p<P>_v<V> at plate speed V m/s,
#                   sg_p<P>_s<S> with calendering.cb_density_scaling S, _v<V>_s<S> both
#   ng_dry          a film after Ngandjong et al. 2021 (examples/ngandjong2021.toml), dried by
#                   DryDEM; ng_p<P> that film pressed to P MPa (pressure mode) and unloaded,
#                   with the same _c/_y/_n/_d/_x/_v/_s tags as sg_p<P>
#   m20_dry         the README main job's film (20.1 mg/cm2, 75 um box, embedded default)
#   m20_e<E>        that film pressed to the porosity 0.<E> at peak (displacement mode)
#                   and unloaded; m20_e<E>_v<V>_s<S> as above
#   m20_u<E>        that film pressed in passes until its porosity after unloading is 0.<E>
#                   (calendering.mode = "unloaded_porosity", docs/calendering.md); e.g. the
#                   industrial targets m20_u35_c110_y110_n1.5_d300_x_v0.4_s16 and m20_u30_...
#   ..._c<C>        (before _v/_s) with compacting agglomerates: calendering.cb_compaction_pressure
#                   C MPa; ..._c<C>_m<M> also calendering.cb_minimal_porosity M (docs/model.md
#                   M-2.11); e.g. sg_p42.7_c120_v0.4_s16
#   ..._y<Y>        (before _v/_s) calendering.cb_yield_pressure Y MPa (the CB contacts'
#                   limiting pressure); ..._n<N> calendering.yield_pressure N GPa (the NCM
#                   contacts'); e.g. sg_p159.4_c60_y60_n1.5_v0.4_s16
#   ..._d<D>        (before _v/_s) calendering.cb_dense_yield_pressure D MPa (the CB contacts
#                   harden to it as their lens compacts the agglomerate, docs/model.md M-2.12)
#   ..._x           (before _v/_s) calendering.cb_extrusion: agglomerates pressed past their
#                   densest state flow out of the gap (docs/model.md M-2.13)
# Defaults of the calendering runs: plate speed V (0.2 m/s), density scaling S (16), the
# calendering defaults otherwise (docs/configuration.md). Extra --set for every calendering run:
# CALENDER_SET (space-separated KEY=VALUE).
#
# usage: bench/calender_validation.sh STEP...   (then /usr/bin/python3
#        scripts/calender_validation_report.py OUT)
# environment: DRYDEM (build/drydem), THREADS (2), OUT (results/calender_validation), SEED
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
drydem=${DRYDEM:-$here/build/drydem}
threads=${THREADS:-2}
out=${OUT:-$here/results/calender_validation}
seed=${SEED:-12345}
mkdir -p "$out"

completed() { [[ -f $1/summary.json ]] && grep -q '"status": "completed"' "$1/summary.json"; }

dry() {  # $1 folder, rest: drydem run arguments
  local dir=$1
  shift
  completed "$dir" && return # a stopped run also leaves final.csv
  local resume=()
  [[ -d $dir/checkpoint ]] && resume=(--resume)
  if ((${#resume[@]})); then
    "$drydem" run --resume "$dir" --threads "$threads" --quiet --no-plots > "$dir.log" 2>&1
  else
    rm -rf "$dir"
    "$drydem" run "$@" --seed "$seed" --threads "$threads" --quiet --no-plots -o "$dir" > "$dir.log" 2>&1
  fi
}

press() {  # $1 dried folder, $2 step name (carries _v<V> and _s<S>), rest: --set arguments
  local dried=$1 step=$2 dir=$out/$2_s$seed
  shift 2
  completed "$dir" && return
  local speed=0.2 scaling=16
  [[ $step =~ _v([0-9.]+) ]] && speed=${BASH_REMATCH[1]}
  [[ $step =~ _s([0-9.]+)$ ]] && scaling=${BASH_REMATCH[1]}
  local extra=()
  [[ $step =~ _c([0-9.]+) ]] && extra+=(--set calendering.cb_compaction_pressure="${BASH_REMATCH[1]} MPa")
  [[ $step =~ _m([0-9.]+) ]] && extra+=(--set calendering.cb_minimal_porosity="${BASH_REMATCH[1]}")
  [[ $step =~ _y([0-9.]+) ]] && extra+=(--set calendering.cb_yield_pressure="${BASH_REMATCH[1]} MPa")
  [[ $step =~ _n([0-9.]+) ]] && extra+=(--set calendering.yield_pressure="${BASH_REMATCH[1]} GPa")
  [[ $step =~ _d([0-9.]+) ]] && extra+=(--set calendering.cb_dense_yield_pressure="${BASH_REMATCH[1]} MPa")
  [[ $step =~ _x(_|$) ]] && extra+=(--set calendering.cb_extrusion=true)
  for kv in ${CALENDER_SET:-}; do extra+=(--set "$kv"); done
  rm -rf "$dir"
  "$drydem" calender "$dried" -o "$dir" --threads "$threads" --quiet --no-plots \
    --set calendering.plate_speed="$speed m/s" --set calendering.cb_density_scaling="$scaling" \
    "$@" "${extra[@]}" > "$dir.log" 2>&1 || echo "== $step: stopped (see $dir.log)" >&2
}

for step in "$@"; do
  echo "== $step ($(date -u +%H:%M))" >&2
  case $step in
    sg_dry) dry "$out/sg_dry_s$seed" "$here/examples/sangros2019.toml" ;;
    sg_p*) p=${step#sg_p}; p=${p%%_*}
      press "$out/sg_dry_s$seed" "$step" --set calendering.mode='"pressure"' \
        --set calendering.target_pressure="$p MPa" ;;
    ng_dry) dry "$out/ng_dry_s$seed" "$here/examples/ngandjong2021.toml" ;;
    ng_p*) p=${step#ng_p}; p=${p%%_*}
      press "$out/ng_dry_s$seed" "$step" --set calendering.mode='"pressure"' \
        --set calendering.target_pressure="$p MPa" ;;
    m20_dry) dry "$out/m20_dry_s$seed" ;;
    m20_e*) e=${step#m20_e}; e=${e%%_*}
      press "$out/m20_dry_s$seed" "$step" --set calendering.mode='"displacement"' \
        --set calendering.target_porosity="0.$e" ;;
    m20_u*) e=${step#m20_u}; e=${e%%_*}
      press "$out/m20_dry_s$seed" "$step" --set calendering.mode='"unloaded_porosity"' \
        --set calendering.target_porosity="0.$e" ;;
    *) echo "unknown step $step (see the header of $0)" >&2; exit 2 ;;
  esac
done
