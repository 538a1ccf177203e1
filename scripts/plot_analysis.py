#!/usr/bin/python3
"""Plots of a drydem analysis folder (Debian's python3-matplotlib):
profiles.png  volume fractions of NCM, CB (envelope and carbon + binder) and pores over the height;
pore_size.png the pore size distributions: chord lengths (as GeoDict PoroDict, the paper's Fig. 7),
              local thickness (continuous PSD) and the simulated mercury intrusion (dV/dlog d, as
              porosimetry reports it).
transport.png tortuosity factors and electronic conductivity against the voxel size of the solve
              (convergence), and the binder profile after drying (paper Eq. 1 model) at the run's
              drying rate and faster / slower.
usage: /usr/bin/python3 scripts/plot_analysis.py ANALYSIS_DIR [PLOTS_DIR (default ANALYSIS_DIR/plots)]"""
import csv
import json
import math
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

d = sys.argv[1]
a = json.load(open(os.path.join(d, 'analysis.json')))
plots = sys.argv[2] if len(sys.argv) > 2 else os.path.join(d, 'plots')
os.makedirs(plots, exist_ok=True)


def table(name):
    path = os.path.join(d, name)
    if not os.path.exists(path):
        return None
    rows = list(csv.DictReader(open(path)))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else None


p = table('profiles.csv')
fig, ax = plt.subplots(figsize=(5.6, 6.4))
ax.plot(p['ncm'], p['z_um'], color='#c0392b', label='NCM')
ax.plot(p['cb_envelope'], p['z_um'], color='#555555', label='CB agglomerates (envelope)')
ax.plot(p['cb_carbon_binder'], p['z_um'], color='#555555', ls=':', label='carbon + binder')
ax.plot(p['pore'], p['z_um'], color='tab:blue', label='pores between spheres')
ax.plot(p['pore_total'], p['z_um'], color='tab:blue', ls='--', label='pores incl. inside CB')
ax.axhline(a['thickness_um'], color='k', ls='--', lw=1)
ax.axhline(a['thickness_half_solid_um'], color='k', ls=':', lw=1)
ax.text(0.99, a['thickness_um'], f"highest top {a['thickness_um']:.1f} µm", ha='right', va='bottom', fontsize=8)
ax.text(0.99, a['thickness_half_solid_um'], f"half-solid top {a['thickness_half_solid_um']:.1f} µm",
        ha='right', va='top', fontsize=8)
ax.set_xlim(0, 1)
ax.set_ylim(0, a['thickness_um'] * 1.04)
ax.set_xlabel('volume fraction / -')
ax.set_ylabel('height above substrate z / µm')
ax.set_title(f"composition over the height (slabs of {a['profile_dz_um']:.2g} µm)\n"
             f"{a['areal_loading_mg_cm2']:.2f} mg/cm², {a['density_g_cm3']:.3f} g/cm³, porosity {a['porosity']:.3f}",
             fontsize=10)
ax.legend(fontsize=8, loc='upper center', bbox_to_anchor=(0.5, -0.11), ncol=2)
fig.tight_layout()
fig.savefig(os.path.join(plots, 'profiles.png'), dpi=120)

ch = table('psd_chord.csv')
lt = table('psd_local_thickness.csv')
if ch and lt:
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.4))
    for axis, color in (('x', 'tab:blue'), ('y', 'tab:orange'), ('z', 'tab:green')):
        ax[0].plot(ch['chord_length_um'], ch[f'length_fraction_{axis}'], color=color,
                   label=f"along {axis} (mean {a['pore_chord_mean_um'][axis]:.2f} µm)")
    ax[0].set_xscale('log')
    ax[0].set_xlabel('pore chord length / µm')
    ax[0].set_ylabel('pore length fraction per chord length / -')
    ax[0].set_title('chord length distribution (as GeoDict PoroDict)', fontsize=10)
    ax[0].legend(fontsize=8)
    # dV/dlog d on log-spaced bins (6 per decade): the one-voxel bins alias, because the diameters
    # on a voxel grid are 2 sqrt(n) for integers n, unevenly spread over the fine bins.
    lo_all = min(x for x in lt['diameter_lo_um'] if x > 0)
    hi_all = max(lt['diameter_hi_um'])
    per_decade = 6
    n_bins = max(1, int(math.ceil(per_decade * math.log10(hi_all / lo_all))))
    edges = [lo_all * 10 ** (k / per_decade) for k in range(n_bins + 1)]
    lt_sum, hg_sum = [0.0] * n_bins, [0.0] * n_bins
    for lo, hi, v, w in zip(lt['diameter_lo_um'], lt['diameter_hi_um'], lt['volume_fraction'],
                            lt['mercury_volume_fraction']):
        if lo <= 0:
            continue
        c = math.sqrt(lo * hi)
        k = min(n_bins - 1, max(0, int(per_decade * math.log10(c / lo_all))))
        lt_sum[k] += v
        hg_sum[k] += w
    mid = [math.sqrt(edges[k] * edges[k + 1]) for k in range(n_bins)]
    lt_dens = [v / (1.0 / per_decade) for v in lt_sum]
    hg_dens = [w / (1.0 / per_decade) for w in hg_sum]
    ax[1].plot(mid, lt_dens, color='k', marker='.', label=f"local thickness (peak {a['psd_peak_um']:.2f} µm)")
    ax[1].plot(mid, hg_dens, color='tab:purple', ls='--', marker='.',
               label=f"simulated mercury intrusion (median {a['mercury_median_um']:.2f} µm)")
    ax[1].set_xscale('log')
    ax[1].set_xlabel('pore diameter / µm')
    ax[1].set_ylabel('dV/dlog d / (pore volume fraction)')
    ax[1].set_title(f"pore size distribution (voxel {a['voxel_size_um']:.3g} µm, below {a['pore_top_um']:.1f} µm)",
                    fontsize=10)
    ax[1].legend(fontsize=8)
    # Cumulative curves: pore volume in pores finer than d, and the intrusion curve (volume reached
    # at diameter d or coarser, as a porosimeter records it with rising pressure).
    d_hi = lt['diameter_hi_um']
    ax[2].plot(d_hi, lt['cumulative_finer'], color='k', label='local thickness: volume in pores finer than d')
    ax[2].plot(lt['diameter_lo_um'][1:], lt['mercury_cumulative_intruded'][1:], color='tab:purple', ls='--',
               label='mercury: volume intruded at d or coarser')
    ax[2].set_xscale('log')
    ax[2].set_ylim(0, 1.02)
    ax[2].set_xlabel('pore diameter d / µm')
    ax[2].set_ylabel('cumulative pore volume fraction / -')
    ax[2].set_title('cumulative', fontsize=10)
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, 'pore_size.png'), dpi=120)
t = a.get('transport')
if t and 'convergence' not in t:  # every voxel size was over the limit: nothing solved
    t = None
b = table('binder_profile.csv')
if t or b:
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.4))
    if t:
        conv = t['convergence']
        vs = [c['voxel_size_um'] for c in conv]
        ax[0].plot(vs, [c['tortuosity_through_plane'] for c in conv], 'o-', color='tab:green',
                   label=f"through-plane τ = {t['tortuosity_factor']['through_plane']:.3f}")
        ax[0].plot(vs, [c['tortuosity_x'] for c in conv], 's--', color='tab:blue', label='in-plane x')
        ax[0].plot(vs, [c['tortuosity_y'] for c in conv], '^--', color='tab:orange', label='in-plane y')
        ax[0].set_xlabel('voxel size of the solve / µm')
        ax[0].set_ylabel('tortuosity factor τ = ε D₀/D_eff / -')
        br = t['bruggeman_exponent']['through_plane']
        ax[0].set_title(f"pores below {t['coating_top_um']:.1f} µm: ε = {t['porosity']:.3f}, "
                        f"Bruggeman α = {br if br is None else round(br, 3)}\n"
                        f"σ_e,eff = {t['electronic_conductivity_S_m']:.3g} S/m, CB network "
                        f"{'percolates' if t['cb_percolates'] else 'does not percolate'}", fontsize=9)
        ax[0].set_xlim(0, max(vs) * 1.15)
        ax[0].legend(fontsize=8)
    if b:
        bm = a['binder_migration']
        ax[1].plot(b['binder_over_mean'], b['z_um'], color='k',
                   label=f"run's drying rate (Pe {bm['peclet']:.2g}): bottom 10 % {bm['bottom10_over_mean']:.2f}")
        for key, style in zip([k for k in b if k.startswith('binder_over_mean_rate_x')], ['--', ':', '-.']):
            f = key.split('_x')[-1]
            ax[1].plot(b[key], b['z_um'], color='tab:red', ls=style, label=f'drying {f} x as fast')
        ax[1].axvline(1.0, color='grey', lw=0.8)
        ax[1].set_xlabel('binder per film volume / its mean / -')
        ax[1].set_ylabel('height above substrate z / µm')
        ax[1].set_title('binder after drying (paper Eq. 1, 1D)', fontsize=10)
        ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, 'transport.png'), dpi=120)
print('plots written to', plots)
