#!/usr/bin/python3
"""Plots of a drydem run folder (Debian's python3-matplotlib): liquid level and film thickness vs
process time (the paper's Fig. 5) with the final-thickness point, and the run's stability/contacts.
usage: /usr/bin/python3 scripts/plot_run.py RUN_DIR"""
import csv
import json
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

run = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(run, 'timeseries.csv'))))
col = lambda k: [float(r[k]) for r in rows]  # noqa: E731
summary = json.load(open(os.path.join(run, 'summary.json')))
os.makedirs(os.path.join(run, 'plots'), exist_ok=True)

t = col('process_time_s')
fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.plot(t, col('liquid_level_um'), label='liquid level')
ax.plot(t, col('film_thickness_um'), label='film thickness (highest particle top)')
ax.plot(t, col('film_top_p99_um'), ':', label='film top, 99th percentile')
if summary.get('final_thickness_um') is not None:
    ax.plot([summary['process_time_final_s']], [summary['final_thickness_um']], 'ko',
            label=f"final thickness {summary['final_thickness_um']:.1f} µm")
ax.set_xlabel('process time / s')
ax.set_ylabel('height above substrate / µm')
ax.set_title(f"{summary.get('name', '')}: {summary.get('areal_loading_mg_cm2', 0):.2f} mg/cm²")
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(run, 'plots', 'film_thickness.png'), dpi=120)

fig, ax = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True)
ax[0].plot(t, col('contacts'), label='particle contacts')
ax[0].plot(t, col('particles_at_level'), label='particles cutting the level')
ax[0].set_ylabel('number / -')
ax[0].legend()
ax[1].plot(t, col('max_overlap_rel'), label='max overlap / smaller radius')
ax[1].plot(t, col('dt_lambda'), label='dt * lambda_max (stable < 2)')
ax[1].set_xlabel('process time / s')
ax[1].set_ylabel('ratio / -')
ax[1].legend()
fig.tight_layout()
fig.savefig(os.path.join(run, 'plots', 'diagnostics.png'), dpi=120)

# Cross-sections of the wet (initial) and the dried (final) structure, the paper's Fig. 4 as a
# section: spheres cut by the plane y = ly/2 at their true cut radius, same scale in both panels.
def section(ax, csv_file, title, lines):
    parts = list(csv.DictReader(open(csv_file)))
    cb_type = max(p['type'] for p in parts) if parts else ''  # CB is the last species
    ly = summary['box_um'][1]
    y0 = 0.5 * ly
    for p in parts:
        r = float(p['radius_m']) * 1e6
        dy = float(p['y_m']) * 1e6 - y0
        if abs(dy) < r:
            rc = (r * r - dy * dy) ** 0.5
            color = '#555555' if p['type'] == cb_type else '#c0392b'
            ax.add_patch(plt.Circle((float(p['x_m']) * 1e6, float(p['z_m']) * 1e6), rc, color=color, lw=0))
    for z, style, label in lines:
        ax.axhline(z, color=style[0], ls=style[1], lw=1.0)
        title += f'\n{label}'
    ax.set_xlim(0, summary['box_um'][0])
    ax.set_aspect('equal')
    ax.set_xlabel('x / µm')
    ax.set_title(f'{title} (section y = {y0:.1f} µm)', fontsize=10)


initial = os.path.join(run, 'initial.csv')
final = os.path.join(run, 'final.csv')
top = summary['wet_film_height_um'] * 1.05
panels = []
if os.path.exists(initial):
    panels.append((initial, 'wet film (start)', [(summary['wet_film_height_um'], ('tab:blue', '-'), f"liquid level {summary['wet_film_height_um']:.1f} µm (blue)")]))
if os.path.exists(final):
    lines = []
    if summary.get('final_thickness_um') is not None:
        lines.append((summary['final_thickness_um'], ('k', '--'), f"final thickness {summary['final_thickness_um']:.1f} µm (dashed)"))
    panels.append((final, 'dried film (end)', lines))
if panels:
    height = min(9.0, max(2.6, 4.2 * top / summary['box_um'][0] + 1.4))
    fig, axes = plt.subplots(1, len(panels), figsize=(4.2 * len(panels) + 0.8, height), squeeze=False)
    for ax, (f, title, lines) in zip(axes[0], panels):
        section(ax, f, title, lines)
        ax.set_ylim(0, top)
    axes[0][0].set_ylabel('z / µm')
    fig.suptitle('structure (red NCM, grey CB)')
    fig.tight_layout()
    fig.savefig(os.path.join(run, 'plots', 'structure_wet_dry.png'), dpi=120)
print('plots written to', os.path.join(run, 'plots'))
