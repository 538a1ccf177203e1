#!/usr/bin/python3
"""Plots of a drydem calendering folder (Debian's python3-matplotlib), into DIR/plots:
compaction.png  porosity against the plate's pressure (loading, hold, unloading) with the fitted
                compaction curve of summary.json (docs/calendering.md "Compaction curve");
plate.png       the plate's height, the film top and the pressure over time, by phase.
usage: /usr/bin/python3 scripts/plot_calender.py CALENDER_DIR"""
import csv
import json
import math
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

d = sys.argv[1]
s = json.load(open(os.path.join(d, 'summary.json')))
rows = list(csv.DictReader(open(os.path.join(d, 'compaction.csv'))))
col = {k: [float(r[k]) for r in rows] for k in rows[0]}
plots = os.path.join(d, 'plots')
os.makedirs(plots, exist_ok=True)
names = ['settle', 'load', 'hold', 'unload', 'relax']
colors = ['#999999', 'tab:red', 'tab:orange', 'tab:blue', 'tab:green']

fig, ax = plt.subplots(figsize=(6.0, 4.4))
for k in (1, 2, 3):
    idx = [i for i, ph in enumerate(col['phase']) if int(ph) == k]
    ax.plot([col['pressure_MPa'][i] for i in idx], [col['porosity'][i] for i in idx], '.',
            ms=2, color=colors[k], label=names[k])
fit = s.get('compaction_fit', {})
if fit.get('ok'):
    p_max = max(col['pressure_MPa'])
    ps = [p_max * i / 200 for i in range(201)]
    eps = [fit['porosity_min'] + (fit['porosity_0'] - fit['porosity_min']) *
           math.exp(-p / fit['resistance_MPa']) for p in ps]
    ax.plot(ps, eps, 'k-', lw=1,
            label='fit: min {:.3f}, resistance {:.3g} MPa'.format(fit['porosity_min'],
                                                                  fit['resistance_MPa']))
ax.axhline(s['unloaded']['porosity'], color='tab:green', ls=':', lw=1,
           label='unloaded {:.3f}'.format(s['unloaded']['porosity']))
ax.set_xlabel('plate pressure [MPa]')
ax.set_ylabel('porosity (areal mass / thickness)')
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(plots, 'compaction.png'), dpi=150)

fig, ax = plt.subplots(figsize=(6.4, 4.4))
t = [x * 1e6 for x in col['time_s']]
ax.plot(t, col['film_top_um'], color='k', lw=1, label='film top')
ax.plot(t, [h if math.isfinite(h) else float('nan') for h in col['plate_height_um']],
        color='tab:purple', lw=1, label='plate')
ax.set_xlabel('time [us]')
ax.set_ylabel('height [um]')
ax2 = ax.twinx()
ax2.plot(t, col['pressure_MPa'], color='tab:red', lw=0.8, label='pressure')
ax2.set_ylabel('plate pressure [MPa]', color='tab:red')
ax.legend(loc='lower left', fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(plots, 'plate.png'), dpi=150)
