#!/usr/bin/env bash
# `drydem calibrate` end to end on a tiny case (2 parameters, 4 evaluations), stopped and resumed:
# the driver is killed (SIGKILL, no warning) once 2 evaluations are done; the run it had started
# gets SIGTERM from the kernel (parent-death signal) and writes a checkpoint; `--resume` then
# finishes the calibration without repeating the 2 finished evaluations (their folders are not
# touched) and writes evaluations.csv, result.json, calibrated.toml (which `drydem check` accepts)
# and the plots. Also: a second calibration into the folder without --resume is refused.
# usage: calibrate_test.sh DRYDEM CONFIG WORKDIR
set -u
drydem=$1 cfg=$2 work=$3
rm -rf "$work"
fail() { echo "FAIL: $*"; tail -30 "$work/cal/log.txt" 2>/dev/null; exit 1; }
cal="$work/cal"
mkdir -p "$work"
"$drydem" calibrate "$cfg" -o "$cal" --jobs 1 --threads 1 --quiet &
pid=$!
done_evals() {
  /usr/bin/python3 -c "import json,sys; print(sum(e['status']=='done' for e in json.load(open(sys.argv[1]))['evaluations']))" \
    "$cal/ledger.json" 2>/dev/null || echo 0
}
for _ in $(seq 600); do
  [[ $(done_evals) -ge 2 ]] && break
  kill -0 $pid 2>/dev/null || fail "the calibration ended before 2 evaluations were done"
  sleep 0.2
done
kill -KILL $pid
wait $pid 2>/dev/null
n_before=$(done_evals)
[[ $n_before -eq 2 ]] || fail "$n_before evaluations done when stopped; expected 2"
stamps() { for d in "$cal"/eval_00[12]_s*; do stat -c '%n %Y %s' "$d/summary.json" "$d/final.csv"; done; }
before=$(stamps)

# the folder holds a calibration: refused without --resume (exit 2, naming --resume)
"$drydem" calibrate "$cfg" -o "$cal" --quiet > "$work/refused.txt" 2>&1
rc=$?
[[ $rc -eq 2 ]] && grep -q -- '--resume' "$work/refused.txt" || fail "a second calibration into the folder: exit $rc: $(cat "$work/refused.txt")"

"$drydem" calibrate "$cfg" -o "$cal" --resume --jobs 1 --threads 1 --quiet
rc=$?
[[ $rc -eq 0 ]] || fail "resumed calibration: exit $rc"
[[ "$(stamps)" == "$before" ]] || fail "a finished evaluation was run again"
grep -q "$n_before done before" "$cal/log.txt" || fail "the resumed driver did not start from the ledger"
# the third run, cut off by the kill, is continued from its checkpoint (or, killed before its
# first checkpoint, started again in its folder)
# (the runs go through `drydem pool`, whose lines are in logs/pool.txt)
grep -Eq 'resumed eval_003_s12345' "$cal/logs/pool.txt" ||
  [[ $(grep -c 'started eval_003_s12345' "$cal/logs/pool.txt") -ge 2 ]] ||
  fail "the interrupted run was not continued: $(cat "$cal/logs/pool.txt")"
grep -E 'start eval_003_s12345' "$cal/log.txt" | tail -1
[[ $(ls -d "$cal"/eval_*_s12345 | wc -l) -eq 4 ]] || fail "not 4 evaluation folders"
/usr/bin/python3 - "$cal" <<'PY' || fail "results"
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + '/evaluations.csv')))
assert [r['evaluation'] for r in rows] == ['1', '2', '3', '4'], rows
assert all(r['status'] == 'done' for r in rows), rows
assert [r['kind'] for r in rows] == ['initial'] * 3 + ['expected improvement'], rows
for r in rows:
    assert 0.3 <= float(r['contact.friction']) <= 1.2 and 0.6 <= float(r['formulation.cb_porosity']) <= 0.8, r
    assert 5 < float(r['final_thickness_um']) < 12 and 0.1 < float(r['cb_binder_porosity_eq2']) < 0.9, r
# the curve point: the run's film thickness at 3 s process time, read here from its own time series
for r in rows:
    ts = list(csv.DictReader(open(f"{d}/{r['runs']}/timeseries.csv")))
    t = [float(x['process_time_s']) for x in ts]
    h = [float(x['film_thickness_um']) for x in ts]
    k = next(i for i in range(1, len(t)) if t[i] >= 3.0)
    expect = h[k - 1] + (h[k] - h[k - 1]) * (3.0 - t[k - 1]) / (t[k] - t[k - 1])
    got = float(r['film_thickness_at_3s_um'])
    assert abs(got - expect) < 1e-6 * expect and t[k - 1] < 3.0, (r['runs'], got, expect)
res = json.load(open(d + '/result.json'))
assert 'film_thickness_at_3s' in res['targets'], res['targets']
best = res['best']
for k, (lo, hi) in {'contact.friction': (0.3, 1.2), 'formulation.cb_porosity': (0.6, 0.8)}.items():
    v = best[k]['value']
    a, b = best[k]['range_delta_chi2_1']
    assert lo <= a <= b <= hi and lo <= v <= hi, (k, best[k])
# the best is the evaluation with the least predicted misfit, and calibrated.toml carries it
ev = [r for r in rows if r['evaluation'] == str(res['best_evaluation'])][0]
cal = open(d + '/calibrated.toml').read()
import tomllib
t = tomllib.loads(cal)
assert abs(t['contact']['friction'] - float(ev['contact.friction'])) < 1e-9, (t['contact'], ev)
assert abs(t['formulation']['cb_porosity'] - float(ev['formulation.cb_porosity'])) < 1e-9, (t['formulation'], ev)
from PIL import Image
for n in ('surrogate', 'targets'):
    im = Image.open(f'{d}/plots/{n}.png')
    assert im.format == 'PNG' and im.size[0] >= 500, (n, im.size)
print('calibration ok: best', {k: round(v['value'], 4) for k, v in best.items()}, 'chi2', res['best_evaluation_misfit_chi2'])
PY
"$drydem" check "$cal/calibrated.toml" > /dev/null || fail "calibrated.toml does not validate"

# A minimum at a bound is flagged (pure function of the surrogate's minimum and its chi2+1 region).
src=$(cd "$(dirname "$0")/../.." && pwd)
/usr/bin/python3 - "$src/scripts" "$cal/result.json" <<'PY' || fail "bounds_reached"
import json, sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from calibrate import bounds_reached
region = np.array([[0.0, 0.4], [0.1, 0.5], [0.05, 0.6]])
assert bounds_reached([0.0, 0.5], region) == ["lower", None]
assert bounds_reached([0.3, 1.0], np.array([[0.2, 0.9], [0.4, 1.0]])) == [None, "upper"]
# a minimum at the edge of the unit cube flagged only where the region reaches that bound
assert bounds_reached([0.01, 0.5], np.array([[0.05, 0.5], [0.3, 0.5]])) == [None, None]
for k, v in json.load(open(sys.argv[2]))["best"].items():
    assert v["surrogate_minimum_at_bound"] in (None, "lower", "upper"), (k, v)
PY

# Resumed with a narrower bound: refused (the ledger's evaluations may lie outside); with a wider
# one and one more evaluation: continued, the finished evaluations kept.
sed 's/^max = 1.2$/max = 1.0/' "$cfg" > "$work/narrow.toml"
"$drydem" calibrate "$work/narrow.toml" -o "$cal" --resume --quiet > "$work/narrow.txt" 2>&1
rc=$?
[[ $rc -eq 2 ]] && grep -q 'min/max widen' "$work/narrow.txt" || fail "a narrowed bound on --resume: exit $rc: $(cat "$work/narrow.txt")"
sed -e 's/^max = 1.2$/max = 1.5/' -e 's/^evaluations = 4$/evaluations = 5/' "$cfg" > "$work/wide.toml"
"$drydem" calibrate "$work/wide.toml" -o "$cal" --resume --jobs 1 --threads 1 --quiet || fail "a widened bound on --resume"
grep -q "4 done before" "$cal/log.txt" || fail "the widened calibration did not keep the 4 evaluations"
[[ $(ls -d "$cal"/eval_*_s12345 | wc -l) -eq 5 ]] || fail "not 5 evaluation folders after widening"
echo "calibrate test passed"
