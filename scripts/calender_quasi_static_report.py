#!/usr/bin/python3
"""The runs of bench/calender_quasi_static.sh as Markdown tables: per case (pressure, plate speed
V, CB density scaling S) the mean and sample s.d. over the seeds of the porosity at the peak and
after unloading, the springback and whether the relaxation reached rest; then each case against
the reference (the slowest plate, then the smallest S: the most nearly quasi-static) as the
mean of the per-seed differences with its standard error, beside the seeds' spread. A knob
moves the result when the mean difference exceeds twice its standard error and the reference's
s.d.
usage: /usr/bin/python3 scripts/calender_quasi_static_report.py DIR"""
import json
import math
import os
import re
import statistics
import sys

QUANTITIES = [('peak', 'peak porosity'), ('unloaded', 'unloaded porosity'),
              ('springback', 'springback [%]')]


def runs(folder):
    """{(P, V, S): {seed: values}} of the completed runs in folder."""
    found = {}
    for name in sorted(os.listdir(folder)):
        m = re.fullmatch(r'p([0-9.]+)_v([0-9.]+)_S([0-9.]+)_s(\d+)', name)
        path = os.path.join(folder, name, 'summary.json')
        if not m or not os.path.isfile(path):
            continue
        with open(path) as f:
            s = json.load(f)
        if s.get('status') != 'completed':
            continue
        key = (float(m.group(1)), float(m.group(2)), float(m.group(3)))
        found.setdefault(key, {})[int(m.group(4))] = {
            'peak': s['peak']['porosity'], 'unloaded': s['unloaded']['porosity'],
            'springback': s['unloaded']['springback_percent'],
            'at_rest': bool(s['unloaded'].get('at_rest', False)), 'steps': s['steps'],
            'wall': s['wall_time_s']}
    return found


def mean_sd(values):
    return statistics.fmean(values), (statistics.stdev(values) if len(values) > 1 else math.nan)


def main(folder):
    found = runs(folder)
    if not found:
        sys.exit(f'{folder}: no completed run')
    cases = sorted(found)
    print('| P [MPa] | V [m/s] | S | seeds | ' + ' | '.join(q for _, q in QUANTITIES) +
          ' | at rest | steps (mean) | wall [s] (mean) |')
    print('|---' * (7 + len(QUANTITIES)) + '|')
    for k in cases:
        per = found[k]
        cells = []
        for q, _ in QUANTITIES:
            m, sd = mean_sd([v[q] for v in per.values()])
            cells.append(f'{m:.4f} ± {sd:.4f}' if q != 'springback' else f'{m:.2f} ± {sd:.2f}')
        rest = sum(v['at_rest'] for v in per.values())
        steps = sum(v['steps'] for v in per.values()) / len(per)
        wall = sum(v['wall'] for v in per.values()) / len(per)
        print(f'| {k[0]:g} | {k[1]:g} | {k[2]:g} | {len(per)} | ' + ' | '.join(cells) +
              f' | {rest}/{len(per)} | {steps:,.0f} | {wall:.0f} |')
    print()
    print('| case against the reference | quantity | mean difference ± s.e. (paired) | '
          'reference s.d. | moves? |')
    print('|---|---|---|---|---|')
    for p in sorted({k[0] for k in cases}):
        group = [k for k in cases if k[0] == p]
        ref = group[0]
        for k in group[1:]:
            seeds = sorted(set(found[ref]) & set(found[k]))
            if len(seeds) < 2:
                continue
            for q, name in QUANTITIES:
                d = [found[k][s][q] - found[ref][s][q] for s in seeds]
                m, sd = mean_sd(d)
                se = sd / math.sqrt(len(d))
                _, ref_sd = mean_sd([found[ref][s][q] for s in seeds])
                moves = abs(m) > 2 * se and abs(m) > ref_sd
                print(f'| {p:g} MPa: V {k[1]:g}, S {k[2]:g} against V {ref[1]:g}, S {ref[2]:g} '
                      f'({len(seeds)} seeds) | {name} | {m:+.4f} ± {se:.4f} | {ref_sd:.4f} | '
                      f'{"yes" if moves else "no"} |')


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
