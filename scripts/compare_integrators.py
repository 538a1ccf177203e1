#!/usr/bin/python3
"""Compares drying runs of two integrators (issue 11 item 5): the results that matter to a user,
per run, as mean and seed-to-seed standard deviation per integrator, and whether the difference
of the means sits inside the seed spread; plus a plot of the thickness vs process time (paper
Fig. 5) and the CB profile, overlaid.

usage: compare_integrators.py [--by-ranks] OUT_PREFIX RUN_DIR... (each run's config.toml names its
integrator; runs with a run.time_step cap form their own group, compared with the explicit
reference). --by-ranks groups the runs by their MPI rank count instead (summary.json `ranks`),
compared with the one-rank runs (docs/parallel.md).
writes OUT_PREFIX.md (table) and OUT_PREFIX.png
"""
import csv, json, os, statistics, sys
import tomllib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

QUANTITIES = [
    ("final thickness [um]", lambda s, a: s["final_thickness_um"]),
    ("relaxed thickness [um]", lambda s, a: s["final_thickness_relaxed_um"]),
    ("density [g/cm3]", lambda s, a: s["density_g_cm3"]),
    ("porosity", lambda s, a: s["porosity"]),
    ("p99 top [um]", lambda s, a: s["film_top_p99_um"]),
    ("process time final [s]", lambda s, a: s["process_time_final_s"]),
    ("coordination NCM-CB per NCM", lambda s, a: a["coordination"]["ncm_cb"]),
    ("coordination CB-CB per CB", lambda s, a: a["coordination"]["cb_cb"]),
    ("coordination NCM-NCM per NCM", lambda s, a: a["coordination"]["ncm_ncm"]),
    ("CB on substrate fraction", lambda s, a: a["coordination"]["cb_substrate_fraction"]),
    ("Eq. 2 CB-binder porosity", lambda s, a: a["cb_binder_porosity_eq2"]),
    # The peak is the argmax of a flat-topped histogram whose bins alternate between even and
    # odd voxel diameters: it jumps by whole bins between runs that agree otherwise. The median
    # of the same distribution is the stable measure of the pore size; the simulated mercury
    # median is quantised as well (it jumps between breakthrough levels ~0.07 um apart).
    ("pore-size peak [um]", lambda s, a: a.get("psd_peak_um")),
    ("pore-size median [um]", lambda s, a: a.get("psd_median_um")),
    ("mercury-intrusion median [um]", lambda s, a: a.get("mercury_median_um")),
    ("pore chord mean z [um]", lambda s, a: a["pore_chord_mean_um"]["z"]),
    ("p99 overlap CB-CB / r", lambda s, a: a["overlap"]["cb_cb"]["p99"]),
    ("p99 overlap NCM-CB / r", lambda s, a: a["overlap"]["ncm_cb"]["p99"]),
    ("wall time [s]", lambda s, a: s["wall_time_s"]),
    ("steps", lambda s, a: s["steps"]),
    ("mean time step [s]", lambda s, a: s.get("time_step_mean_s")),
]


def load(run, by_ranks=False):
    with open(os.path.join(run, "config.toml"), "rb") as f:
        cfg = tomllib.load(f)
    s = json.load(open(os.path.join(run, "summary.json")))
    a = json.load(open(os.path.join(run, "analysis", "analysis.json")))
    if by_ranks:
        ranks = s.get("ranks", 1)
        return f"{ranks} rank" + ("s" if ranks > 1 else ""), s, a
    integ = cfg.get("numerics", {}).get("integrator", "semi_implicit")
    cap = cfg.get("run", {}).get("time_step", 0)
    if isinstance(cap, str) or cap:  # a scheme at another step cap is its own group
        integ += f" (dt <= {cap} s)"
    return integ, s, a


def main():
    args = sys.argv[1:]
    by_ranks = "--by-ranks" in args
    args = [x for x in args if x != "--by-ranks"]
    prefix, runs = args[0], args[1:]
    groups = {}
    for run in runs:
        integ, s, a = load(run, by_ranks)
        groups.setdefault(integ, []).append((run, s, a))
    # The reference first (the explicit integrator, or one rank); every other group is compared
    # with it, the seed spread (the larger of the two groups' standard deviations) as the yardstick.
    if by_ranks:
        names = sorted(groups, key=lambda n: int(n.split()[0]))
    else:
        names = sorted(groups, key=lambda n: (not n.startswith("explicit"), n))
    ref = names[0]
    others = names[1:]
    head = "| quantity | " + " | ".join(f"{n} (n={len(groups[n])}) mean ± s.d." for n in names)
    head += "".join(f" | {n} − {ref} | inside spread" for n in others) + " |"
    lines = [head, "|---|" + "---|" * (len(names) + 2 * len(others))]
    for label, get in QUANTITIES:
        stats = {}
        for n in names:
            vals = [get(s, a) for _, s, a in groups[n]]
            vals = [v for v in vals if v is not None]
            m = statistics.mean(vals) if vals else float("nan")
            sd = statistics.stdev(vals) if len(vals) > 1 else float("nan")
            stats[n] = (m, sd)
        cells = [f"{stats[n][0]:.4g} ± {stats[n][1]:.2g}" for n in names]
        for n in others:
            if label.startswith(("wall", "steps", "mean time")):
                cells += ["", ""]
                continue
            d = stats[n][0] - stats[ref][0]
            sds = [x for x in (stats[ref][1], stats[n][1]) if x == x]  # a one-seed group has none
            spread = max(sds) if sds else float("nan")
            cells.append(f"{d:+.3g}")
            if abs(d) <= spread or abs(d) <= 1e-12 * abs(stats[ref][0]):  # inside, or rounding
                cells.append("yes")
            elif spread > 0:
                cells.append(f"no ({abs(d) / spread:.1f} s.d.)")
            else:  # every seed gave the same value (a voxel-quantised peak, say)
                cells.append("no (no spread)")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    open(prefix + ".md", "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    palette = ["tab:blue", "tab:red", "tab:green", "tab:orange", "tab:purple"]
    colors = {n: palette[k % len(palette)] for k, n in enumerate(names)}
    for n in names:
        for k, (run, s, a) in enumerate(groups[n]):
            rows = list(csv.DictReader(open(os.path.join(run, "timeseries.csv"))))
            t = [float(r["process_time_s"]) for r in rows]
            ax1.plot(t, [float(r["film_thickness_um"]) for r in rows], color=colors.get(n),
                     lw=1, alpha=0.8, label=n if k == 0 else None)
            if k == 0:
                ax1.plot(t, [float(r["liquid_level_um"]) for r in rows], color="gray", lw=0.8,
                         ls="--", label="liquid level" if n == names[0] else None)
            prof = list(csv.DictReader(open(os.path.join(run, "analysis", "profiles.csv"))))
            ax2.plot([float(r["cb_envelope"]) for r in prof], [float(r["z_um"]) for r in prof],
                     color=colors.get(n), lw=1, alpha=0.8, label=n if k == 0 else None)
    ax1.set_xlabel("process time [s]")
    ax1.set_ylabel("film thickness (highest top) [um]")
    ax1.set_title("thickness vs time (paper Fig. 5), every seed")
    ax1.legend()
    ax2.set_xlabel("CB envelope volume fraction [-]")
    ax2.set_ylabel("height z [um]")
    ax2.set_title("CB profile of the dried film, every seed")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=120)


if __name__ == "__main__":
    main()
