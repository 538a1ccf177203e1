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
runs = []  # (code, case, cores, particles, steps, seconds, rate, contacts)
for fn in sorted(glob.glob(os.path.join(out, 'drydem*.json')) + glob.glob(os.path.join(out, 'old*.json'))):
    d = json.load(open(fn))
    case = os.path.basename(fn)[:-5].split('_r')[0]
    # old1/old2: a second DryDEM build (OLD_DRYDEM), not a peer
    runs.append(('DryDEM' if case.startswith('drydem') else 'DryDEM (OLD_DRYDEM)', case, d['threads'], d['particles'], d['steps'], d['seconds'],
                 d['particle_steps_per_s'], d['contacts_per_particle']))
for fn in sorted(glob.glob(os.path.join(out, '*.log'))):
    r = parse_logs.parse(fn)
    if not r:
        continue
    case = r['name'].split('_r')[0]
    rate = r['natoms'] * r['nsteps'] / r['t']
    code = r['code'] + ('' if case.startswith('lig') else ' ' + case.rstrip('12'))
    runs.append((code, case, r['procs'], r['natoms'], r['nsteps'], r['t'], rate,
                 r.get('contacts') or float('nan')))
# Best round of each case (the machine is shared; its speed drifts), and how many rounds.
rows, rounds = {}, {}
for run in runs:
    rounds[run[1]] = rounds.get(run[1], 0) + 1
    if run[1] not in rows or run[6] > rows[run[1]][6]:
        rows[run[1]] = run
rows = [rows[k] for k in sorted(rows)]
lines = ['| code | case | cores | particles | steps | best seconds | particle-steps/s | per core | contacts/particle | rounds |',
         '|---|---|---|---|---|---|---|---|---|---|']
for code, case, cores, n, steps, t, rate, cavg in rows:
    lines.append(f'| {code} | {case} | {cores} | {n} | {steps} | {t:.2f} | {rate:.4g} | {rate / cores:.4g} | {cavg:.3f} | {rounds[case]} |')
best = {}
for code, case, cores, n, steps, t, rate, cavg in rows:
    if code.startswith('DryDEM') and code != 'DryDEM':
        continue  # the older build is compared with DryDEM, not with the peers
    key = 'drydem' if code == 'DryDEM' else 'peer'
    best.setdefault((key, cores), 0.0)
    best[(key, cores)] = max(best[(key, cores)], rate / cores)
for cores in (1, 2):
    if ('drydem', cores) in best and ('peer', cores) in best:
        lines.append(f'\nDryDEM / fastest peer, per core, {cores} core(s): '
                     f'{best[("drydem", cores)] / best[("peer", cores)]:.2f}x')
for cores in (1, 2):
    new = [r for r in rows if r[0] == 'DryDEM' and r[2] == cores]
    old = [r for r in rows if r[0] == 'DryDEM (OLD_DRYDEM)' and r[2] == cores]
    if new and old:
        lines.append(f'\nDryDEM / OLD_DRYDEM, {cores} core(s): {new[0][6] / old[0][6]:.3f}x')
text = '\n'.join(lines)
print(text)
open(os.path.join(out, 'summary.md'), 'w').write(text + '\n')
