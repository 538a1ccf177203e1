#!/usr/bin/env bash
# `drydem study` with one loading that runs and one that cannot (a film thinner than its largest
# particle: set-up error, exit 2): the study records the failure, finishes the other run, writes
# study.csv / study.json and the Fig. 6 plot, and exits 1 because not every run completed.
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
echo "study smoke test passed"
