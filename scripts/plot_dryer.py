#!/usr/bin/python3
"""Plot of a `drydem dryer` output folder (Debian's python3-matplotlib): film thickness, film and
dryer air temperature, and solvent mass fraction along the dryer (paper Figs. 2-3), with the zone
boundaries, the consolidation point and the point at which the film is dry.
usage: /usr/bin/python3 scripts/plot_dryer.py DRYER_DIR"""
import csv
import json
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

run = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(run, 'dryer.csv'))))
col = lambda k: [float(r[k]) for r in rows]  # noqa: E731
info = json.load(open(os.path.join(run, 'dryer.json')))
os.makedirs(os.path.join(run, 'plots'), exist_ok=True)

x = col('position_m')
fig, ax = plt.subplots(3, 1, figsize=(7.0, 8.4), sharex=True)


def marks(a):
    for z in info['zones'][:-1]:
        a.axvline(z['position_m'][1], color='0.6', lw=0.8, ls=':')
    if info.get('consolidation_position_m') is not None:
        a.axvline(info['consolidation_position_m'], color='tab:red', lw=1.0, ls='--')
    if info.get('dry_position_m') is not None:
        a.axvline(info['dry_position_m'], color='tab:green', lw=1.0, ls='--')
    a.grid(alpha=0.3)


ax[0].plot(x, col('film_thickness_um'), color='tab:blue', label='film thickness')
ax[0].axhline(info['final_thickness_um'], color='0.4', lw=0.8, ls='-.',
              label=f"final thickness {info['final_thickness_um']:.1f} um "
                    f"(porosity {info['final_porosity']:.3f})")
for z in info['zones']:
    if z['shrinkage_rate_um_s'] is not None:
        x0, x1 = z['position_m']
        ax[0].text(0.5 * (x0 + x1), info['wet_film_height_um'] + 0.03 * (info['wet_film_height_um'] - info['final_thickness_um']),
                   f"s{z['zone']} = {z['shrinkage_rate_um_s']:.3f} um/s", ha='center', va='bottom', fontsize=9)
marks(ax[0])
ax[0].set_ylabel('film thickness / um')
span = info['wet_film_height_um'] - info['final_thickness_um']
ax[0].set_ylim(info['final_thickness_um'] - 0.08 * span, info['wet_film_height_um'] + 0.15 * span)
ax[0].legend(loc='center right', fontsize=9)

ax[1].plot(x, col('film_temperature_C'), color='tab:red', label='film temperature')
ax[1].plot(x, col('dryer_temperature_C'), color='k', drawstyle='steps-post', label='dryer air temperature')
marks(ax[1])
ax[1].set_ylabel('temperature / °C')
ax[1].legend(loc='lower right', fontsize=9)

ax[2].plot(x, col('solvent_mass_fraction'), color='tab:purple', label='NMP mass fraction')
marks(ax[2])
ax[2].plot([], [], color='tab:red', ls='--', label='consolidation (end of shrinkage)')
ax[2].plot([], [], color='tab:green', ls='--', label='dry')
ax[2].set_ylabel('solvent mass fraction / -')
ax[2].set_xlabel('dryer position / m')
ax[2].set_ylim(bottom=0)
ax[2].legend(loc='upper right', fontsize=9)

fig.suptitle(f"dryer model, preset '{info['preset']}': {info['areal_loading_mg_cm2']:.1f} mg/cm2")
fig.tight_layout()
out = os.path.join(run, 'plots', 'dryer.png')
fig.savefig(out, dpi=120)
print('plot written to', out)
