#!/usr/bin/env bash
# `drydem study` and `drydem calibrate` with `--scheduler slurm` against a real single-node Slurm
# (tests/cli/slurm_cluster.sh: munged, slurmctld, slurmd started here, torn down at the end).
# The study's first case is a run stopped part-way (--stop-after-steps, as a time limit's SIGTERM
# leaves it: a checkpoint and a summary saying so): its array task must resume it. Both results
# are collected into the same files as local runs (study.csv/.json, ledger.json, evaluations.csv).
# usage: slurm_test.sh DRYDEM STUDY_CONFIG CALIBRATION_CONFIG WORKDIR
set -u
drydem=$1 study_cfg=$2 cal_cfg=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/slurm_cluster.sh"
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
trap slurm_down EXIT
fail() { echo "FAIL: $*"; for f in "$work"/cluster/*.log; do echo "== $f"; tail -15 "$f"; done; exit 1; }
slurm_up "$work/cluster" || fail "no Slurm"

# --- the study: 2 loadings x 1 seed, one case stopped beforehand ----------------------------------
stopped="$work/study/runs/L1.50_s12345"
"$drydem" run "$study_cfg" -o "$stopped" --set film.areal_loading=0.015 --set run.seed=12345 \
  --set 'run.name="tiny-L1.50_s12345"' --threads 1 --stop-after-steps 300 --quiet --no-plots
[[ -s $stopped/checkpoint/state.bin ]] || fail "the stopped run has no checkpoint"
grep -q 'stopped after step' "$stopped/summary.json" || fail "the stopped run's summary does not say so"
"$drydem" study "$study_cfg" --loadings 1.5,2 --seeds 1 --scheduler slurm -o "$work/study" --resume --no-plots --quiet
rc=$?
[[ $rc -eq 0 ]] || { cat "$work/study/slurm.txt"; cat "$work"/study/slurm/round_*/task_*.out; fail "study exit $rc"; }
grep -q 'resuming .*L1.50_s12345' "$work"/study/slurm/round_001/task_*.out || fail "the stopped case was not resumed"
grep -q 'starting .*L2.00_s12345 with 1 thread' "$work"/study/slurm/round_001/task_*.out || fail "the new case did not start with SLURM_CPUS_PER_TASK threads"
[[ $(grep -c ',completed,' "$work/study/study.csv") -eq 2 ]] || { cat "$work/study/study.csv"; fail "study.csv: not 2 completed rows"; }
/usr/bin/python3 - "$work/study" <<'PY' || fail "study.json"
import json, sys
s = json.load(open(sys.argv[1] + '/study.json'))
assert s['completed'] == 2 and s['failed'] == 0, s
for c in s['cases']:
    r = json.load(open(f"{sys.argv[1]}/{c['run_dir']}/summary.json"))
    assert r['status'] == 'completed' and r['threads'] == 1, r
    assert abs(c['final_thickness_um'] - r['final_thickness_um']) < 1e-9, (c, r)
print('study via slurm ok:', [(c['areal_loading_mg_cm2'], round(c['final_thickness_um'], 3)) for c in s['cases']])
PY

# --- the calibration: 2 initial points in one array, then 1 by expected improvement -----------
"$drydem" calibrate "$cal_cfg" --scheduler slurm --jobs 2 -o "$work/cal" --no-plots --quiet \
  --set calibration.initial_points=2 --set calibration.evaluations=3
rc=$?
[[ $rc -eq 0 ]] || { tail -30 "$work/cal/log.txt"; fail "calibrate exit $rc"; }
[[ -s $work/cal/slurm/round_001/task_1.out && -s $work/cal/slurm/round_002/task_0.out ]] || fail "not two job arrays (2 + 1 tasks)"
[[ ! -e $work/cal/slurm/round_001/task_2.sh ]] || fail "the first array has more than the 2 initial runs"
/usr/bin/python3 - "$work/cal" <<'PY' || fail "calibration ledger"
import csv, json, sys
d = sys.argv[1]
led = json.load(open(d + '/ledger.json'))
assert [e['status'] for e in led['evaluations']] == ['done'] * 3, led
rows = list(csv.DictReader(open(d + '/evaluations.csv')))
assert len(rows) == 3 and all(r['status'] == 'done' and float(r['misfit_chi2']) >= 0 for r in rows), rows
assert rows[2]['kind'] == 'expected improvement', rows[2]
res = json.load(open(d + '/result.json'))
assert 0.3 <= res['best']['contact.friction']['value'] <= 1.2, res
print('calibration via slurm ok: best', {k: round(v['value'], 4) for k, v in res['best'].items()})
PY
[[ -s $work/cal/calibrated.toml ]] || fail "no calibrated.toml"

# --- a study whose runs use two MPI ranks each (scheduler.ranks_per_run: sbatch --ntasks=2, srun) ---
"$drydem" study "$study_cfg" --loadings 1.5 --seeds 1 --scheduler slurm -o "$work/study2" --no-plots \
  --quiet --set scheduler.ranks_per_run=2
rc=$?
[[ $rc -eq 0 ]] || { cat "$work/study2/slurm.txt"; cat "$work"/study2/slurm/round_*/task_*.out; fail "two-rank study exit $rc"; }
grep -q -- '--ntasks=2' "$work/study2/slurm.txt" || fail "the array was not submitted with --ntasks=2"
/usr/bin/python3 - "$work/study2" <<'PY' || fail "two-rank study results"
import glob, json, sys
runs = glob.glob(sys.argv[1] + '/runs/*/summary.json')
assert len(runs) == 1, runs
r = json.load(open(runs[0]))
assert r['status'] == 'completed' and r['ranks'] == 2, (r['status'], r.get('ranks'))
print('study via slurm with 2 ranks per run ok:', round(r['final_thickness_um'], 3), 'um')
PY
# The local scheduler runs one process per run: several ranks per run are refused (exit 2).
"$drydem" study "$study_cfg" --loadings 1.5 --seeds 1 -o "$work/study3" --quiet --no-plots \
  --set scheduler.ranks_per_run=2 2> "$work/study3.err"
[[ $? -eq 2 ]] && grep -q "scheduler.ranks_per_run" "$work/study3.err" || fail "local study with 2 ranks per run not refused"
squeue -h | grep -q . && fail "jobs left in the queue"
echo "slurm test passed"
