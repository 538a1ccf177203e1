#!/usr/bin/python3
"""The calendering runs of bench/calender_validation.sh as Markdown tables (docs/calendering.md):
  - sg_p<P>...: the Sangros Gimenez 2019 film pressed to P MPa, beside the article's porosity at
    that pressure (values from secondary summaries, unconfirmed: docs/calendering.md);
  - m20_e<E>...: the 20.1 mg/cm2 main-job film pressed to a porosity, with the through-plane
    tortuosity factor and electronic conductivity of the dried and the calendered film.
Each row: the porosity at the peak and after unloading, springback, broken bonds, the largest
overlap and inertial number, steps and wall time (without the structure analysis).
usage: /usr/bin/python3 scripts/calender_validation_report.py DIR"""
import json
import os
import re
import sys

# Sangros Gimenez et al., Powder Technol. 349 (2019) 1, Table 1 as quoted (unconfirmed).
SANGROS = {19.8: 0.416, 42.7: 0.372, 79.1: 0.295, 159.4: 0.217}
SANGROS_UNCALENDERED = 0.522


def load(path):
    with open(path) as f:
        return json.load(f)


def max_overlap(run):
    """The largest overlap over the smaller radius in compaction.csv, and the last row's."""
    import csv
    worst = 0.0
    with open(os.path.join(run, 'compaction.csv')) as f:
        for row in csv.DictReader(f):
            worst = max(worst, float(row['max_overlap_rel']))
    return worst


def row(run, s):
    b = s.get('bonds', {})
    return {
        'dried': s['dried_film']['porosity'], 'settled': s['settled_film']['porosity'],
        'pressure': s['peak']['pressure_MPa'], 'peak': s['peak']['porosity'],
        'unloaded': s['unloaded']['porosity'], 'springback': s['unloaded']['springback_percent'],
        'bonds': b.get('made', 0), 'broken': b.get('broken_fraction', 0.0),
        'overlap': max_overlap(run), 'inertial': s['max_inertial_number'],
        'steps': s['steps'], 'wall': s['wall_time_s'], 'speed': s['plate_speed_m_s'],
        'scaling': s.get('cb_density_scaling', 1.0), 'tau': s.get('tortuosity_factor_z'),
        'sigma': s.get('electronic_conductivity_S_m'), 'status': s['status'],
        'cb_pc': s.get('cb_compaction', {}).get('pressure_MPa', 0.0),
        'cb_min': s.get('cb_compaction', {}).get('minimal_porosity'),
        'cb_peak': s['peak'].get('cb_inner_porosity'),
        'cb_end': s.get('cb_compaction', {}).get('inner_porosity_end'),
        # runs before the FIRE relaxation read the film while it still moved: no entry
        'at_rest': {True: 'yes', False: 'no'}.get(s['unloaded'].get('at_rest'), 'moving')}


def runs(d, prefix):
    out = []
    for name in sorted(os.listdir(d)):
        path = os.path.join(d, name, 'summary.json')
        if name.startswith(prefix) and os.path.exists(path):
            out.append((name, row(os.path.join(d, name), load(path))))
    return out


def fmt(v, spec):
    return '-' if v is None else format(v, spec)


def loading_curve(run):
    """(pressure [MPa], porosity) of the first pass's loading rows of compaction.csv."""
    import csv
    with open(os.path.join(run, 'compaction.csv')) as f:
        return [(float(r['pressure_MPa']), float(r['porosity'])) for r in csv.DictReader(f)
                if r['phase'] == '1' and r.get('pass', '1') in ('1', '1.0')]


def porosity_at(curve, p):
    """The loading curve's porosity where the pressure first reaches p (linear between rows)."""
    for (p0, e0), (p1, e1) in zip(curve, curve[1:]):
        if p1 >= p > p0:
            return e0 + (e1 - e0) * (p - p0) / (p1 - p0)
    return None


def sangros(d):
    rows = runs(d, 'sg_p')
    if not rows:
        return
    print('Sangros Gimenez 2019 film (uncalendered {:.3f} in the article). Loading branch: the '
          'porosity under the plate as it first carries each pressure; unloaded: after the run '
          'pressed to its own target.\n'.format(SANGROS_UNCALENDERED))
    print('| run | speed [m/s] | CB density x | settled | ' +
          ' | '.join('at {:g} MPa (article {:.3f})'.format(p, e) for p, e in SANGROS.items()) +
          ' | reached [MPa] | end | unloaded | springback [%] | bonds broken | max overlap | '
          'max I | steps | wall [s] |')
    print('|' + '---|' * (13 + len(SANGROS) - 4 + 4))
    for name, r in rows:
        run = os.path.join(d, name)
        curve = loading_curve(run)
        done = r['status'] == 'completed'
        reached = max((p for p, _ in curve), default=0.0)
        print('| {} | {:g} | {:g} | {:.3f} | {} | {:.1f} | {} | {} | {} | {:.0%} | {:.2f} | '
              '{:.3f} | {} | {:.0f} |'.format(
                  name, r['speed'], r['scaling'], r['settled'],
                  ' | '.join(fmt(porosity_at(curve, p), '.3f') for p in SANGROS), reached,
                  'completed' if done else 'stopped', fmt(r['unloaded'] if done else None, '.3f'),
                  fmt(r['springback'] if done else None, '.1f'), r['broken'], r['overlap'],
                  r['inertial'], r['steps'], r['wall']))
    print()


def compaction(d):
    """The Sangros film pressed with compacting agglomerates (docs/model.md M-2.11): the unloaded
    porosity against the article's at the run's target pressure."""
    rows = [(n, r) for n, r in runs(d, 'sg_p') if r['cb_pc'] > 0]
    if not rows:
        return
    print('Compacting agglomerates on the Sangros Gimenez 2019 film: unloaded porosity against '
          'the article at the target pressure.\n')
    print('| run | p_c [MPa] | eps_min | peak [MPa] | at peak | unloaded | article | difference | '
          'springback [%] | unloaded at rest | CB inner porosity at peak / end | bonds broken | '
          'max overlap | steps | wall [s] |')
    print('|' + '---|' * 15)
    for name, r in rows:
        target = float(re.match(r'sg_p([0-9.]+)', name).group(1))
        article = SANGROS.get(target)
        done = r['status'] == 'completed'
        print('| {} | {:g} | {:g} | {:.1f} | {:.3f} | {} | {} | {} | {} | {} | {} / {} | {:.0%} | '
              '{:.2f} | {} | {:.0f} |'.format(
                  name, r['cb_pc'], r['cb_min'], r['pressure'], r['peak'],
                  fmt(r['unloaded'] if done else None, '.3f'), fmt(article, '.3f'),
                  fmt(r['unloaded'] - article if done and article else None, '+.3f'),
                  fmt(r['springback'] if done else None, '.1f'), r['at_rest'],
                  fmt(r['cb_peak'], '.3f'),
                  fmt(r['cb_end'], '.3f'), r['broken'], r['overlap'], r['steps'], r['wall']))
    print()


def main_film(d):
    rows = runs(d, 'm20_e')
    if not rows:
        return
    dried = os.path.join(d, 'm20_dry_s12345', 'analysis', 'analysis.json')
    if os.path.exists(dried):
        a = load(dried)
        t = a.get('transport', {})
        print('dried film: porosity {:.3f}, tortuosity factor {}, electronic conductivity {} S/m\n'
              .format(a['porosity'], fmt(t.get('tortuosity_factor', {}).get('through_plane'),
                                         '.3f'),
                      fmt(t.get('electronic_conductivity_S_m'), '.3g')))
    print('| run | speed [m/s] | CB density x | dried | porosity at peak | unloaded | springback '
          '[%] | tortuosity factor | electronic conductivity [S/m] | bonds broken | max overlap '
          '| max I | steps | wall [s] |')
    print('|' + '---|' * 14)
    for name, r in rows:
        print('| {} | {:g} | {:g} | {:.3f} | {:.3f} | {:.3f} | {:.1f} | {} | {} | {:.0%} | {:.2f} '
              '| {:.3f} | {} | {:.0f} |'.format(
                  name, r['speed'], r['scaling'], r['dried'], r['peak'], r['unloaded'],
                  r['springback'], fmt(r['tau'], '.3f'), fmt(r['sigma'], '.3g'), r['broken'],
                  r['overlap'], r['inertial'], r['steps'], r['wall']))


d = sys.argv[1]
sangros(d)
compaction(d)
main_film(d)
