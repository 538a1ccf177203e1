#!/usr/bin/env python3
"""Convergence of the force-ratio scheme (issue 29): tables and plots from docs/data/convergence.

Every step of bench/convergence.sh is a study whose runs are archived under
docs/data/convergence/STEP/RUN (config, summary, analysis, thinned time series). This script
writes docs/data/convergence/report.md and docs/figures/convergence_*.png: one row per step with
its knobs (scheme, k, b, e, the simulated Stokes number and expected overlap from the run's own
dimensionless groups) and the yardstick (final and relaxed thickness, density, porosity,
coordination per pair type, pore-size peak and median, when and where the film leaves the level,
p99 and max overlap), then each knob's series against q_base with the verdict: a difference
counts as zero below twice the combined standard error of the seeds (one seed: the seed spread of
q_paper stands in, and the verdict says so). Where two steps share seeds (the same seed starts from
the same film), the series also gives the paired reading: the mean of the seed-wise differences
against twice its own standard error, which the film-to-film spread does not blur.

usage: /usr/bin/python3 scripts/convergence_report.py [--data DIR] [--figures DIR]
"""
import argparse
import csv
import json
import math
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from validation_report import FRONT_GAP_UM, ROOT, mean_sd, runs  # noqa: E402

# The quick case leaves the level after a few seconds; the validation's 20 s applies to 20.1.
QUICK_FRONT_AFTER_S = 2.0
# Per series: its reference step and (step, knob value) points.
SERIES = {
    "overlap knob: scaling.stiffness_factor e": ("q_base", [("q_e1", 1), ("q_e2.4", 2.4), ("q_e7.5", 7.5), ("q_e24", 24),
                                                           ("q_base", 75), ("q_e240", 240)]),
    "Stokes knob: k b at f = k/b = 9e3": ("q_base", [("q_b33", 1e7), ("q_base", 9e7), ("q_b316", 9e8)]),
    "CB Young's modulus (GPa), at e = 24": ("q_e24", [("q_e24", 142), ("q_ecb400", 400)]),
    "density scaling of the CB: S (scaling.cb_density_scaling), at e = 24": ("q_e24", [("q_e24", 1), ("q_e24_s4", 4),
                                                                                       ("q_e24_s16", 16)]),
    "time step": ("q_base", [("q_base", 1.0), ("q_dt_half", 0.5)]),
    # The paper's scheme with the guard alone setting the semi-implicit step (issue 30's main job).
    "paper's scheme: 1 cap 1e-10 s (the default before 2026-12-07), 2 cap 1e-9 s, 3 cap 1e-9 s and f = 0.65 (the default since)": (
        "q_paper", [("q_paper", 1), ("q_paper_cap9", 2), ("q_paper_f065", 3)]),
    "paper's scheme, 20.1 recipe in a 40 µm box: 1 cap 1e-10 s, 3 cap 1e-9 s and f = 0.65": (
        "p20", [("p20", 1), ("p20_f065", 3)]),
    "paper's scheme, 20.1 recipe in a 40 µm box, cap 1e-9 s and f = 0.65: skin 0.3 and 0.2 µm": (
        "p20_f065", [("p20_f065", 0.3), ("p20_sk02", 0.2)]),
    "paper's scheme, quick case, implicit self-stiffness: step (s), the guarded kick's mean 2.2e-10 s": (
        "q_paper_new", [("q_paper_new", 2.2e-10), ("q_paper_is5", 5e-10), ("q_paper_is10", 1e-9)]),
    "paper's scheme, 20.1 recipe in a 40 µm box: 1 guarded kick (default), 2 implicit self-stiffness at 1e-9 s": (
        "p20_sk02", [("p20_sk02", 1), ("p20_is10", 2)]),
    "paper's scheme, the main job's recipe in its 75 µm box: 1 guarded kick, 2 implicit self-stiffness at 1e-9 s": (
        "m75", [("m75", 1), ("m75_is10", 2)]),
    "paper's scheme, quick case: 1 explicit reference, 2 semi-implicit default since 2026-12-07": (
        "q_paper_x", [("q_paper_x", 1), ("q_paper_new", 2)]),
    # The candidate for the converged setting, e = 7.5 and S = 4 (bench/convergence.sh), against
    # its neighbours in each knob, and the knobs not yet turned at it.
    "overlap knob e, at S = 4": ("q_e7.5_s4", [("q_e7.5_s4", 7.5), ("q_e24_s4", 24)]),
    "density scaling S, at e = 7.5": ("q_e7.5_s4", [("q_e7.5", 1), ("q_e7.5_s4", 4)]),
    "Stokes knob k b, at e = 7.5 and S = 4": ("q_e7.5_s4", [("q_e7.5_s4_b33", 1e7), ("q_e7.5_s4", 9e7)]),
    "integrator at e = 24 and S = 4 (the chosen setting): semi-implicit 1, explicit reference 2": (
        "q_e24_s4", [("q_e24_s4", 1), ("q_e24_s4_x", 2)]),
    "integrator at e = 7.5 and S = 4: semi-implicit 1, explicit reference 2": (
        "q_e7.5_s4", [("q_e7.5_s4", 1), ("q_e7.5_s4_x", 2)]),
    "implicit self-stiffness at e = 7.5 and S = 4: step (s), the guarded kick's mean 4.2e-11 s": (
        "q_e7.5_s4", [("q_e7.5_s4", 4.2e-11), ("q_e7.5_s4_is8", 8e-11), ("q_e7.5_s4_is16", 1.6e-10)]),
    "critical-step fraction f at e = 7.5 and S = 4 (numerics.critical_step_fraction)": (
        "q_e7.5_s4", [("q_e7.5_s4_f025", 0.25), ("q_e7.5_s4", 0.5), ("q_e7.5_s4_f065", 0.65)]),
    # The same steps against the explicit reference, by their mean step: paired by seed, this tells
    # which integrators give the reference's own films, not only its mean.
    "mean step (s) at e = 7.5 and S = 4, against the explicit reference (velocity Verlet, 4.8e-11 s)": (
        "q_e7.5_s4_x", [("q_e7.5_s4_f025", 2.05e-11), ("q_e7.5_s4", 4.21e-11), ("q_e7.5_s4_x", 4.81e-11),
                        ("q_e7.5_s4_f065", 5.54e-11), ("q_e7.5_s4_is8", 8e-11), ("q_e7.5_s4_is16", 1.6e-10)]),
    # The quasi-static step (issue 30) at the process's own settings (k = b = e = 1): against the
    # explicit reference at e = 24 (the Stokes number of the largest NCM, zone 2, is the knob that
    # differs, with the overlap), and its own two knobs.
    "integrator: explicit at St 0.36 (e = 24) vs quasi-static at the process's St": (
        "q_e24", [("q_e24", 0.356), ("q_qs", 3.96e-9)]),
    "solver tolerance of the quasi-static step": ("q_qs", [("q_qs", 1e-4), ("q_qs_tol3", 1e-3)]),
    "displacement per quasi-static step (nm)": ("q_qs", [("q_qs", 37.5), ("q_qs_d75", 75)]),
}
STEPS = ["q_paper", "q_paper_cap9", "q_paper_f065", "q_base", "q_e1", "q_e2.4", "q_e7.5", "q_e24", "q_e240", "q_b33", "q_b316", "q_ecb400", "q_e24_s4", "q_e24_s4_x", "q_e24_s16",
         "q_e7.5_s4", "q_e7.5_s4_b33", "q_e7.5_s4_b10", "q_e7.5_s4_x", "q_e7.5_s4_is8", "q_e7.5_s4_is16", "q_e7.5_s4_f025", "q_e7.5_s4_f065", "r20_e7.5_s4", "r20_e7.5_s4_x", "p20", "p20_f065", "p20_sk02", "q_paper_new", "q_paper_x", "q_paper_is5", "q_paper_is10", "p20_is10", "m75", "m75_is10", "q_dt_half", "q_qs", "q_qs_tol3", "q_qs_d75"]


def leaves_level(run_dir: Path, after_s: float):
    """Process time and level where the film's p99 top first stands FRONT_GAP_UM above the level."""
    ts = run_dir / "timeseries.csv"
    if not ts.is_file():
        return None, None
    for row in csv.DictReader(ts.open()):
        t, level, top = float(row["process_time_s"]), float(row["liquid_level_um"]), float(row["film_top_p99_um"])
        if t > after_s and top - level > FRONT_GAP_UM:
            return t, level
    return None, None


def peak_p99_overlap(run_dir: Path):
    """The largest p99 overlap of the time series (the film's worst moment, while it consolidates)."""
    ts = run_dir / "timeseries.csv"
    if not ts.is_file():
        return None
    values = [float(row["overlap_p99_rel"]) for row in csv.DictReader(ts.open()) if row.get("overlap_p99_rel")]
    return max(values) if values else None


def yardstick(r):
    """The quantities compared across a series, for one run."""
    a = json.loads((r["_dir"] / "analysis" / "analysis.json").read_text())
    t_leave, level_leave = leaves_level(r["_dir"], QUICK_FRONT_AFTER_S)
    co, ov = a["coordination"], a.get("overlap", {})
    zone2 = r["dimensionless_groups"]["zones"][-1]["simulated"]
    return {
        "run": r["_dir"].name, "thickness": r["final_thickness_um"], "relaxed": r["final_thickness_relaxed_um"],
        "half_solid": r["thickness_half_solid_um"],
        "density": r["density_g_cm3"], "porosity": r["porosity"],
        "z_ncm_ncm": co["ncm_ncm"], "z_ncm_cb": co["ncm_cb"], "z_cb_cb": co["cb_cb"],
        "psd_peak": a.get("psd_peak_um"), "psd_median": a.get("psd_median_um"),
        "t_leave": t_leave, "level_leave": level_leave,
        "p99": ov.get("all", {}).get("p99"), "max": ov.get("all", {}).get("max"),
        "p99_peak": peak_p99_overlap(r["_dir"]),
        "stokes": zone2["stokes_number_largest_ncm"], "overlap_expected": zone2["hertz_overlap_ncm_cb_capillary"],
        "push": zone2["push_number"], "wall": r["wall_time_s"], "steps": r["steps"],
        "dt": r["time_step_mean_s"], "k": r["scaling"]["time_factor_k"], "b": r["scaling"]["viscosity_reduction_b"],
        "e": r["scaling"].get("stiffness_factor_e", 1.0), "scheme": r["scaling"].get("scheme", "paper") + (
            " (quasi-static)" if r.get("integrator") == "quasi_static" else "") + (
            f", CB inertia × {r['scaling']['cb_density_scaling']:g}"
            if r["scaling"].get("cb_density_scaling", 1.0) != 1.0 else ""),
    }


COLUMNS = [("thickness", "final thickness (µm)", 2), ("relaxed", "relaxed (µm)", 2),
           ("half_solid", "half-solid thickness (µm)", 2), ("density", "density (g/cm³)", 3),
           ("porosity", "porosity", 3), ("z_ncm_ncm", "Z NCM-NCM", 2), ("z_ncm_cb", "Z NCM-CB", 2),
           ("z_cb_cb", "Z CB-CB", 2), ("psd_median", "pore median (µm)", 3), ("t_leave", "leaves level (s)", 2),
           ("level_leave", "at level (µm)", 2), ("p99", "p99 overlap", 3), ("max", "max overlap", 3),
           ("p99_peak", "peak p99 overlap (time series)", 3)]


# The quantities of the paired reading (the yardstick's structure, beside the thickness).
PAIRED = [("thickness", "final (µm)", 2), ("half_solid", "half-solid (µm)", 2), ("density", "density (g/cm³)", 3),
          ("z_ncm_cb", "Z NCM-CB", 2), ("z_cb_cb", "Z CB-CB", 2), ("psd_median", "pore median (µm)", 3)]


def paired_difference(runs_a, runs_b, key):
    """Seed-wise differences a − b over the runs both steps have (same run name: same seed, same
    initial film). Returns (mean, twice its standard error, rms of the differences, n); the error and
    the rms are None below two pairs."""
    b = {y["run"]: y[key] for y in runs_b if y[key] is not None}
    d = [y[key] - b[y["run"]] for y in runs_a if y["run"] in b and y[key] is not None]
    m, sd, n = mean_sd(d)
    if n < 2:
        return m, None, None, n
    return m, 2 * sd / math.sqrt(n), math.sqrt(sum(x * x for x in d) / n), n


def cell(values, digits):
    m, s, n = mean_sd(values)
    if m is None:
        return "–"
    return f"{m:.{digits}f} ± {s:.{digits}f}" if n > 1 else f"{m:.{digits}f}"


class Report:
    def __init__(self, data: Path, figures: Path):
        self.data, self.figures, self.lines = data, figures, []
        self.steps = {s: [yardstick(r) for r in runs(data / s)] for s in STEPS}

    def say(self, *lines):
        self.lines.extend(lines)

    def settings(self):
        self.say("## The runs", "",
                 "| step | scheme | k | b | e | seeds | St (largest NCM, zone 2) | expected overlap NCM-CB | "
                 "push number (zone 2) | mean Δt (s) | steps | wall (s, 1 thread) |",
                 "|---|---|---|---|---|---|---|---|---|---|---|---|")
        for s in STEPS:
            y = self.steps[s]
            if not y:
                self.say(f"| {s} | not run yet | | | | 0 | | | | | | |")
                continue
            f = y[0]
            self.say(f"| {s} | {f['scheme']} | {f['k']:g} | {f['b']:g} | {f['e']:g} | {len(y)} | {f['stokes']:.3g} | "
                     f"{f['overlap_expected']:.3g} | {f['push']:.3g} | {cell([x['dt'] for x in y], 13)} | "
                     f"{cell([x['steps'] for x in y], 0)} | {cell([x['wall'] for x in y], 0)} |")
        self.say("")

    def yardsticks(self):
        self.say("## Yardstick per step (mean ± s.d. over the seeds)", "",
                 "| step | " + " | ".join(c[1] for c in COLUMNS) + " |", "|---|" + "---|" * len(COLUMNS))
        for s in STEPS:
            y = self.steps[s]
            if y:
                self.say(f"| {s} | " + " | ".join(cell([x[k] for x in y], d) for k, _, d in COLUMNS) + " |")
        self.say("")

    def series(self):
        sd_ref = {k: self.seed_sd(k) for k in ("thickness", "half_solid")}
        self.say("## Series", "")
        self.say("Yardstick: twice the combined standard error of the two steps' seeds; where a step has one "
                 f"seed, the s.d. of {sd_ref['thickness'][1]} over its seeds stands in ({sd_ref['thickness'][0]:.3f} µm "
                 f"final, {sd_ref['half_solid'][0]:.3f} µm half-solid thickness).", "")
        for title, (ref, points) in SERIES.items():
            have = [(s, x) for s, x in points if self.steps[s]]
            if len(have) < 2 or not self.steps[ref]:
                continue
            self.say(f"### {title} (against {ref})", "",
                     "| step | knob | final thickness (µm) | Δ (µm) | 2 × s.e. | moves? | half-solid (µm) | Δ (µm) | 2 × s.e. | moves? |",
                     "|---|---|---|---|---|---|---|---|---|---|")
            xs, ms, es = [], {"thickness": [], "half_solid": []}, {"thickness": [], "half_solid": []}
            for s, x in have:
                cells = [s, f"{x:g}"]
                for key in ("thickness", "half_solid"):
                    m, sd, n = mean_sd([y[key] for y in self.steps[s]])
                    mr, sdr, nr = mean_sd([y[key] for y in self.steps[ref]])
                    sd, sdr = (sd if n > 1 else sd_ref[key][0]), (sdr if nr > 1 else sd_ref[key][0])
                    se2 = 2 * math.sqrt(sd ** 2 / n + sdr ** 2 / nr)
                    verdict = "–" if s == ref else ("no" if abs(m - mr) < se2 else "**yes**")
                    cells += [cell([y[key] for y in self.steps[s]], 2), f"{m - mr:+.2f}", f"{se2:.2f}", verdict]
                    ms[key].append(m), es[key].append(sd)
                xs.append(x)
                self.say("| " + " | ".join(cells) + " |")
            self.say("")
            self.paired(ref, [s for s, _ in have if s != ref])
            fig, ax = plt.subplots(figsize=(5, 3.5))
            for key, label in (("thickness", "final (highest top)"), ("half_solid", "half-solid")):
                ax.errorbar(xs, ms[key], yerr=es[key], fmt="o-", capsize=3, label=label)
            ax.set_xscale("log" if max(xs) / min(xs) > 5 else "linear")
            ax.set_xlabel(title, fontsize=8), ax.set_ylabel("thickness (µm), ± seed s.d.")
            ax.legend(fontsize=8)
            ax.set_title("quick case, force-ratio scheme", fontsize=9)
            fig.tight_layout()
            name = "_".join(re.findall(r"[a-z0-9]+", re.split("[:,]", title)[0].lower().replace("'", "")))
            fig.savefig(self.figures / f"convergence_{name}.png", dpi=120)
            plt.close(fig)

    def paired(self, ref, steps):
        """The series' steps against ref seed by seed: mean difference ± twice its standard error,
        bold where it exceeds that; the last column is the rms of the half-solid differences, how far
        one film lies from its twin (against the seed s.d. of the reference)."""
        rows = []
        for s in steps:
            cells, n_pairs, rms = [s], 0, None
            for key, _, digits in PAIRED:
                m, se2, key_rms, n = paired_difference(self.steps[s], self.steps[ref], key)
                n_pairs = max(n_pairs, n)
                if key == "half_solid":
                    rms = key_rms
                if se2 is None:
                    cells.append("–")
                else:
                    text = f"{m:+.{digits}f} ± {se2:.{digits}f}"
                    cells.append(f"**{text}**" if abs(m) > se2 else text)
            if n_pairs < 2 or rms is None:
                continue
            _, sd_ref, _ = mean_sd([y["half_solid"] for y in self.steps[ref]])
            rows.append("| " + " | ".join(cells[:1] + [str(n_pairs)] + cells[1:]) + f" | {rms:.2f} / {sd_ref:.2f} |")
        if rows:
            self.say(f"Paired by seed against {ref} (mean seed-wise difference ± twice its standard error; "
                     "**bold**: moves):", "",
                     "| step | pairs | " + " | ".join(f"Δ {label}" for _, label, _ in PAIRED) +
                     " | half-solid: rms of the differences / seed s.d. of the reference (µm) |",
                     "|---|---|" + "---|" * len(PAIRED) + "---|", *rows, "")

    def seed_sd(self, key):
        """The seed s.d. of a quantity: of the force-ratio film where it has several seeds (q_base, then
        q_e24), else q_paper's."""
        for s in ["q_base", "q_e24", "q_paper"]:
            m, sd, n = mean_sd([x[key] for x in self.steps[s]])
            if n > 1:
                return sd, s
        return 0.0, "none"

    def write(self):
        self.say("# Convergence of the force-ratio scheme (generated by scripts/convergence_report.py)", "",
                 "Runs: `bench/convergence.sh STEP` (one thread per run); quick case 3 mg/cm², 40 µm box. "
                 "Wall times are of runs that shared the 2-core machine with another run or a build: "
                 "not benchmarks.", "")
        self.settings()
        self.yardsticks()
        self.series()
        (self.data / "report.md").write_text("\n".join(self.lines) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--data", type=Path, default=ROOT / "docs/data/convergence")
    p.add_argument("--figures", type=Path, default=ROOT / "docs/figures")
    a = p.parse_args()
    Report(a.data, a.figures).write()
    print((a.data / "report.md").read_text())


if __name__ == "__main__":
    main()
