#!/usr/bin/env bash
# A run stopped and resumed from its checkpoint ends bit for bit where the uninterrupted run ends
# (README "Outputs", `drydem run --resume DIR`): final particles, time series, LAMMPS dump and
# frame lists are byte-identical. Same thread count (1) for all. Deterministic on any machine:
# the stops come at given steps (--stop-after-steps, the stop path of SIGTERM), never after a
# wall-clock delay.
#   1. stopped after step N1 as SIGTERM would stop it (checkpoint, results so far, exit 1);
#   2. resumed and stopped again after step N2, then its checkpoint put back to the one of N1:
#      the folder now holds what SIGKILL after N2 leaves (time-series rows, frames and dump
#      frames written after the last checkpoint), which a resume must cut back and write again;
#   3. resumed to the end;
#   4. the run stopped after N1, packed and unpacked as bench/study_queue.sh carries an unfinished
#      run to a fresh machine, resumed to the end: the same files identical.
# usage: restart_bitwise.sh DRYDEM CONFIG WORKDIR
set -u
drydem=$1 config=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# No wall-clock checkpoints: the only checkpoints are the stops' (and so the same on any machine).
# No structure analysis at the end: it is not compared, and it is half of each run's time.
sets=(--set film.areal_loading=1.5mg/cm^2 --set output.checkpoint_every=0s
      --set output.snapshot_every=2s --set analysis.at_end=false --threads 1 --quiet --no-plots)
"$drydem" run "$config" "${sets[@]}" -o "$work/straight" || { echo "uninterrupted run failed"; exit 1; }
steps=$(grep -o '"steps": [0-9]*' "$work/straight/summary.json" | grep -o '[0-9]*$')
[[ -n "$steps" && "$steps" -gt 30 ]] || { echo "uninterrupted run has too few steps ($steps)"; exit 1; }
n1=$((steps / 3)) n2=$((2 * steps / 3))
echo "uninterrupted: $steps steps; stops after steps $n1 and $n2"

killed="$work/killed"
"$drydem" run "$config" "${sets[@]}" --stop-after-steps "$n1" -o "$killed"
[[ $? -eq 1 ]] || { echo "--stop-after-steps $n1 did not stop the run with exit code 1"; exit 1; }
grep -q "stopped after step $n1 " "$killed/summary.json" || { echo "summary does not say where it stopped"; exit 1; }
cp "$killed/checkpoint/state.bin" "$work/state_n1.bin" || { echo "no checkpoint written"; exit 1; }

# Carried to a fresh machine (bench/study_queue.sh): the run stopped after n1, packed as a run
# queue carries an unfinished run across sessions and unpacked into a new study folder, resumes
# below to the same end as the uninterrupted run.
# shellcheck source=bench/study_queue.sh
source "$(dirname "$0")/../../bench/study_queue.sh"
carry_unfinished "$killed" "$work/archive/run" 2>/dev/null
[[ -f $work/archive/run/carry.tar.gz ]] || { echo "the stopped run was not carried"; exit 1; }
restore_archived_runs "$work/fresh" "$work/archive" completed 2>/dev/null
[[ -f $work/fresh/runs/run/checkpoint/state.bin ]] || { echo "the carried run was not restored"; exit 1; }

"$drydem" run --resume "$killed" --stop-after-steps "$n2" --quiet --no-plots
[[ $? -eq 1 ]] || { echo "resumed run did not stop after step $n2"; exit 1; }
cmp -s "$killed/checkpoint/state.bin" "$work/state_n1.bin" && { echo "no new checkpoint at step $n2"; exit 1; }
cp "$work/state_n1.bin" "$killed/checkpoint/state.bin" # as SIGKILL after step n2 leaves it

"$drydem" run --resume "$killed" --quiet --no-plots || { echo "resumed run failed"; exit 1; }
grep -q '"resumed": true' "$killed/summary.json" || { echo "summary does not say resumed"; exit 1; }
status=0
# compare_outputs LABEL DIR: the uninterrupted run's outputs against DIR's, byte for byte.
compare_outputs() {
  local f
  for f in final.csv timeseries.csv snapshots/dump.lammpstrj snapshots/particles.pvd \
           snapshots/liquid_level.pvd; do
    if cmp -s "$work/straight/$f" "$2/$f"; then echo "$1identical: $f"
    else echo "$1DIFFERENT: $f"; status=1; fi
  done
}
compare_outputs "" "$killed"
"$drydem" run --resume "$work/fresh/runs/run" --quiet --no-plots || { echo "carried run failed"; exit 1; }
compare_outputs "carried, " "$work/fresh/runs/run"
# Resuming needs the checkpoint's own config: extra options are refused (exit 2).
"$drydem" run --resume "$killed" --set run.seed=3 >/dev/null 2>&1
[[ $? -eq 2 ]] || { echo "--resume with --set was not refused with exit code 2"; status=1; }
exit $status
