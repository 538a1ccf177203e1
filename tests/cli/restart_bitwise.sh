#!/usr/bin/env bash
# A run killed with SIGKILL and resumed from its checkpoint ends bit for bit where the
# uninterrupted run ends (interface.md `checkpoint/`, `drydem run --resume DIR`): final particles,
# time series, LAMMPS dump and frame list are byte-identical. Same thread count (1) for both.
# usage: restart_bitwise.sh DRYDEM CONFIG WORKDIR
set -u
drydem=$1 config=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
sets=(--set film.areal_loading=1.5mg/cm^2 --set output.checkpoint_every=0.5s
      --set output.snapshot_every=2s --threads 1 --quiet --no-plots)
"$drydem" run "$config" "${sets[@]}" -o "$work/straight" || { echo "uninterrupted run failed"; exit 1; }

"$drydem" run "$config" "${sets[@]}" -o "$work/killed" &
pid=$!
# Kill it a few checkpoints in, well before its end.
for _ in $(seq 1 600); do
  [[ -f "$work/killed/checkpoint/state.bin" ]] && break
  sleep 0.05
done
sleep 2
kill -9 "$pid"; wait "$pid" 2>/dev/null
[[ -f "$work/killed/summary.json" ]] && { echo "the run ended before it was killed; no restart tested"; exit 1; }
[[ -f "$work/killed/checkpoint/state.bin" ]] || { echo "no checkpoint written"; exit 1; }
"$drydem" run --resume "$work/killed" --quiet --no-plots || { echo "resumed run failed"; exit 1; }
grep -q '"resumed": true' "$work/killed/summary.json" || { echo "summary does not say resumed"; exit 1; }
status=0
for f in final.csv timeseries.csv snapshots/dump.lammpstrj snapshots/particles.pvd \
         snapshots/liquid_level.pvd; do
  if cmp -s "$work/straight/$f" "$work/killed/$f"; then echo "identical: $f"
  else echo "DIFFERENT: $f"; status=1; fi
done
# Resuming needs the checkpoint's own config: extra options are refused (exit 2).
"$drydem" run --resume "$work/killed" --set run.seed=3 >/dev/null 2>&1
[[ $? -eq 2 ]] || { echo "--resume with --set was not refused with exit code 2"; status=1; }
exit $status
