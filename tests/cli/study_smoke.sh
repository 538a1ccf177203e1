#!/usr/bin/env bash
# `drydem study` with one loading that runs and one that cannot (a film thinner than its largest
# particle: set-up error, exit 2): the study records the failure, finishes the other run, writes
# study.csv / study.json and the Fig. 6 plot, and exits 1 because not every run completed. Then
# --resume: a completed case is kept, a stopped one continues from its checkpoint.
# usage: study_smoke.sh DRYDEM CONFIG WORKDIR
set -u
drydem=$1 config=$2 work=$3
rm -rf "$work"
"$drydem" study "$config" --loadings 1.5,0.05 --seeds 1 --threads 1 --jobs 2 -o "$work"
rc=$?
[[ $rc -eq 1 ]] || { echo "exit code $rc, expected 1 (one run failed)"; exit 1; }
[[ $(wc -l < "$work/study.csv") -eq 3 ]] || { echo "study.csv should have a header and 2 rows"; exit 1; }
grep -q '^1.5,12345,completed,' "$work/study.csv" || { echo "the 1.5 mg/cm2 run is not completed"; exit 1; }
grep -q '^0.05,12345,failed,' "$work/study.csv" || { echo "the failed run is not recorded"; exit 1; }
/usr/bin/python3 - "$work" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1] + '/study.json'))
assert s['completed'] == 1 and s['failed'] == 1, s
ok = [l for l in s['loadings'] if l['completed'] == 1][0]
assert abs(ok['areal_loading_mg_cm2'] - 1.5) < 1e-9, ok
assert 5.0 < ok['thickness_mean_um'] < 12.0 and 0.3 < ok['porosity_mean'] < 0.7, ok
print('study.json ok:', ok)
PY
[[ -s "$work/plots/thickness_density_vs_loading.png" ]] || { echo "no plot"; exit 1; }
# The completed run's own plots (paper Figs. 4, 5, 7 and the profiles) and its structure analysis,
# each a real PNG image that Pillow opens.
run="$work/runs/L1.50_s12345"
[[ -s "$run/analysis/analysis.json" ]] || { echo "no analysis of the run"; exit 1; }
/usr/bin/python3 - "$run/plots" "$work/plots" <<'PY' || exit 1
import sys
from PIL import Image
names = ['film_thickness', 'diagnostics', 'structure_wet_dry', 'profiles', 'pore_size']
files = [f'{sys.argv[1]}/{n}.png' for n in names] + [f'{sys.argv[2]}/thickness_density_vs_loading.png']
for f in files:
    im = Image.open(f)
    assert im.format == 'PNG' and im.size[0] >= 500 and im.size[1] >= 300, (f, im.format, im.size)
print('plots ok:', len(files))
PY
# --resume (local): a completed case is kept as it is, a stopped one continues from its checkpoint.
before=$(stat -c %Y "$run/summary.json")
"$drydem" study "$config" --loadings 1.5 --seeds 1 --threads 1 -o "$work" --resume --no-plots --quiet
[[ $? -eq 0 && $(stat -c %Y "$run/summary.json") == "$before" ]] || { echo "resume re-ran a completed case"; exit 1; }
grep -q "started L1.50" <(tail -3 "$work/log.txt") && { echo "resume started a completed case again"; exit 1; }
second="$work-resume"
rm -rf "$second"
"$drydem" run "$config" -o "$second/runs/L1.50_s12345" --set film.areal_loading=0.015 --set run.seed=12345 \
  --set 'run.name="tiny-L1.50_s12345"' --threads 1 --stop-after-steps 300 --quiet --no-plots
[[ -s "$second/runs/L1.50_s12345/checkpoint/state.bin" ]] || { echo "the stopped run has no checkpoint"; exit 1; }
"$drydem" study "$config" --loadings 1.5 --seeds 1 --threads 1 -o "$second" --no-plots --quiet 2>/dev/null
[[ $? -eq 2 ]] || { echo "a study into a folder with runs but without --resume should be refused"; exit 1; }
"$drydem" study "$config" --loadings 1.5 --seeds 1 --threads 1 -o "$second" --resume --no-plots --quiet
[[ $? -eq 0 ]] || { echo "the resumed study failed"; exit 1; }
grep -q "resumed L1.50_s12345" "$second/log.txt" || { echo "the stopped case was not resumed"; exit 1; }
grep -q "resumed from the checkpoint" "$second/runs/L1.50_s12345/log.txt" || { echo "the run did not resume"; exit 1; }
grep -q '^1.5,12345,completed,' "$second/study.csv" || { echo "the resumed case is not completed"; exit 1; }
echo "study smoke test passed"
