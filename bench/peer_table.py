#!/usr/bin/python3
"""Table of the peer benchmark (bench/peer_bench.sh): particle-steps/s of DryDEM (drydem*.json) and
of LIGGGHTS/LAMMPS (*.log, parsed by ../shared/peers/parse_logs.py), and DryDEM's ratio per core to
the faster peer. Writes summary.md into the results folder."""
import glob
import json
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', '..', 'shared', 'peers'))
import parse_logs  # noqa: E402

out = sys.argv[1]
rows = []
for fn in sorted(glob.glob(os.path.join(out, 'drydem*.json'))):
    d = json.load(open(fn))
    rows.append(('DryDEM', os.path.basename(fn)[:-5], d['threads'], d['particles'], d['steps'],
                 d['seconds'], d['particle_steps_per_s'], d['contacts_per_particle']))
for fn in sorted(glob.glob(os.path.join(out, '*.log'))):
    r = parse_logs.parse(fn)
    if not r:
        continue
    rate = r['natoms'] * r['nsteps'] / r['t']
    rows.append((r['code'] + ('' if r['name'].startswith('lig') else ' ' + r['name'].rstrip('12')),
                 r['name'], r['procs'], r['natoms'], r['nsteps'], r['t'], rate, r.get('contacts') or float('nan')))
lines = ['| code | case | cores | particles | steps | seconds | particle-steps/s | per core | contacts/particle |',
         '|---|---|---|---|---|---|---|---|---|']
for code, case, cores, n, steps, t, rate, cavg in rows:
    lines.append(f'| {code} | {case} | {cores} | {n} | {steps} | {t:.2f} | {rate:.4g} | {rate / cores:.4g} | {cavg:.3f} |')
best = {}
for code, case, cores, n, steps, t, rate, cavg in rows:
    key = 'drydem' if code == 'DryDEM' else 'peer'
    best.setdefault((key, cores), 0.0)
    best[(key, cores)] = max(best[(key, cores)], rate / cores)
for cores in (1, 2):
    if ('drydem', cores) in best and ('peer', cores) in best:
        lines.append(f'\nDryDEM / fastest peer, per core, {cores} core(s): '
                     f'{best[("drydem", cores)] / best[("peer", cores)]:.2f}x')
text = '\n'.join(lines)
print(text)
open(os.path.join(out, 'summary.md'), 'w').write(text + '\n')
