#!/usr/bin/python3
"""Plot of a drydem study folder (Debian's python3-matplotlib): dry-film thickness and density vs
areal loading (the paper's Fig. 6), simulation mean +- standard deviation over the seeds, each run
as a small dot, measured values from [study] of the config beside them.
usage: /usr/bin/python3 scripts/plot_study.py STUDY_DIR"""
import json
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

study_dir = sys.argv[1]
study = json.load(open(os.path.join(study_dir, 'study.json')))
os.makedirs(os.path.join(study_dir, 'plots'), exist_ok=True)
stats = [s for s in study.get('loadings', []) if s['completed'] > 0]
cases = [c for c in study.get('cases', []) if c['status'] == 'completed']
measured = study.get('measured', [])

fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for ax, key, std_key, case_key, label, m_key, m_std in (
        (axes[0], 'thickness_mean_um', 'thickness_std_um', 'final_thickness_um',
         'dry film thickness / µm', 'thickness_um', 'thickness_std_um'),
        (axes[1], 'density_mean_g_cm3', 'density_std_g_cm3', 'density_g_cm3',
         'coating density / (g/cm$^3$)', 'density_g_cm3', 'density_std_g_cm3')):
    if stats:
        ax.errorbar([s['areal_loading_mg_cm2'] for s in stats], [s[key] for s in stats],
                    yerr=[s[std_key] for s in stats], fmt='s-', color='tab:blue', capsize=4,
                    label='simulation (mean $\\pm$ s.d.)')
    if cases:
        ax.plot([c['areal_loading_mg_cm2'] for c in cases], [c[case_key] for c in cases], '.',
                color='tab:blue', alpha=0.4, label='single runs')
    pts = [m for m in measured if m.get(m_key) is not None]
    if pts:
        ax.errorbar([m['areal_loading_mg_cm2'] for m in pts], [m[m_key] for m in pts],
                    yerr=[m.get(m_std, 0.0) for m in pts], fmt='o', color='tab:orange',
                    capsize=4, label='experiment')
    ax.set_xlabel('areal loading / (mg/cm$^2$)')
    ax.set_ylabel(label)
    ax.grid(alpha=0.3)
    ax.legend()
failed = study.get('failed', 0)
fig.suptitle(f"{study.get('name', '')}: {study.get('completed', 0)} runs completed"
             + (f", {failed} failed" if failed else ''))
fig.tight_layout()
fig.savefig(os.path.join(study_dir, 'plots', 'thickness_density_vs_loading.png'), dpi=120)

# A drying-rate study (study.shrinkage_rate_factors): thickness, tortuosity and the binder at the
# substrate against the rate factor, one line per loading, each run a dot.
factors = sorted({c.get('shrinkage_rate_factor', 1.0) for c in cases})
if len(factors) > 1:
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.0))
    panels = (('final_thickness_um', 'dry film thickness / µm'),
              ('tortuosity_through_plane', 'tortuosity factor through-plane'),
              ('binder_bottom10_over_mean', 'binder in the bottom 10 % / mean'))
    for ax, (key, label) in zip(axes, panels):
        for load in sorted({c['areal_loading_mg_cm2'] for c in cases}):
            pts = [(c['shrinkage_rate_factor'], c[key]) for c in cases
                   if c['areal_loading_mg_cm2'] == load and c.get(key) is not None]
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], 'o', alpha=0.5)
            means = [(f, sum(p[1] for p in pts if p[0] == f) / sum(1 for p in pts if p[0] == f))
                     for f in factors if any(p[0] == f for p in pts)]
            ax.plot([m[0] for m in means], [m[1] for m in means], '-', label=f'{load:.2f} mg/cm$^2$')
        ax.set_xscale('log')
        ax.set_xlabel('shrinkage-rate factor (drying rate)')
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(study_dir, 'plots', 'drying_rate.png'), dpi=120)
