#!/usr/bin/python3
"""The plate-speed check of the calendering run (bench/calender_speed.sh) as a Markdown table:
per folder s<seed>_v<speed>, the porosity and thickness at the peak (10 MPa), the fitted
compaction curve, the unloaded thickness (99th percentile of the particle tops, from final.csv),
the springback, the largest inertial number while loading, steps and wall time; then the seed
spread at 0.05 m/s and the spread over the speeds.
usage: /usr/bin/python3 scripts/calender_report.py DIR"""
import csv
import json
import os
import re
import statistics
import sys

d = sys.argv[1]
rows = []
for name in sorted(os.listdir(d)):
    m = re.fullmatch(r's(\d+)_v([0-9.]+)', name)
    path = os.path.join(d, name, 'summary.json')
    if not m or not os.path.exists(path):
        continue
    s = json.load(open(path))
    if s.get('status') != 'completed':
        continue
    tops = sorted(float(r['z_m']) + float(r['radius_m'])
                  for r in csv.DictReader(open(os.path.join(d, name, 'final.csv'))))
    p99 = tops[min(len(tops) - 1, int(0.99 * len(tops)))] * 1e6
    peak = s['peak']
    rows.append(dict(seed=int(m.group(1)), speed=float(m.group(2)), porosity=peak['porosity'],
                     thickness=peak['thickness_um'], pressure=peak['pressure_MPa'],
                     unloaded=p99, springback=100 * (p99 - peak['thickness_um']) /
                     peak['thickness_um'], settled=s['settled_film']['thickness_um'],
                     fit_min=s['compaction_fit']['porosity_min'],
                     fit_pc=s['compaction_fit']['resistance_MPa'],
                     inertial=s['max_inertial_number'], steps=s['steps'],
                     wall=s['wall_time_s']))
rows.sort(key=lambda r: (r['seed'], -r['speed']))
print('| seed | plate speed [m/s] | settled [um] | peak [MPa] | thickness at peak [um] | '
      'porosity at peak | unloaded p99 [um] | springback [%] | fit porosity_min | fit p_c [MPa] '
      '| max inertial number | steps | wall [s] |')
print('|' + '---|' * 13)
for r in rows:
    print('| {seed} | {speed:g} | {settled:.3f} | {pressure:.2f} | {thickness:.3f} | '
          '{porosity:.4f} | {unloaded:.3f} | {springback:.1f} | {fit_min:.3f} | {fit_pc:.3g} | '
          '{inertial:.3g} | {steps} | {wall:.0f} |'.format(**r))


def spread(label, sel):
    if len(sel) < 2:
        return
    for key in ('porosity', 'thickness', 'springback'):
        v = [r[key] for r in sel]
        print('{}: {} mean {:.4g}, s.d. {:.3g} (n = {})'.format(label, key, statistics.mean(v),
                                                                statistics.stdev(v), len(v)))


print()
spread('seeds at 0.05 m/s', [r for r in rows if r['speed'] == 0.05])
spread('speeds, seed 12345', [r for r in rows if r['seed'] == 12345])
