#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The search of `drydem calibrate` (docs/calibration.md), started by the drydem command after it
validated the config and wrote DIR/calibration.json and DIR/config.toml.

    calibrate.py DIR [--jobs N] [--threads T] [--no-plots] [--quiet]

Method: a space-filling start (SciPy qmc, Sobol or Latin hypercube), then Bayesian optimisation:
one Gaussian process per target (scikit-learn; Matern 5/2 + white noise, inputs in the unit
cube, log scale where asked) and expected improvement of the misfit chi2 = sum_t ((y_t - v_t) /
sigma_t)^2, estimated by sampling the targets' posteriors. Every evaluation is `seeds` drydem runs
in DIR/eval_NNN_sSEED; DIR/ledger.json records every evaluation as it is planned and as its runs
end, so a stopped calibration continues where it stopped.
"""
import argparse
import csv
import json
import math
import os
import signal
import subprocess
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import slurm_array  # noqa: E402

try:
    import numpy as np
    from scipy.stats import qmc
    from sklearn.exceptions import ConvergenceWarning
    from sklearn.gaussian_process import GaussianProcessRegressor
    from sklearn.gaussian_process.kernels import ConstantKernel, Matern, WhiteKernel
except ImportError as e:  # pragma: no cover - a missing Debian package
    print(f"error: calibrate needs NumPy, SciPy and scikit-learn for /usr/bin/python3 ({e}); "
          "install them with scripts/install_deps.sh (python3-scipy, python3-sklearn)", file=sys.stderr)
    sys.exit(2)

warnings.filterwarnings("ignore", category=ConvergenceWarning)
warnings.filterwarnings("ignore", message=".*balance properties of Sobol.*")

STOP = {"signal": 0}
CHILDREN = {}
EDGE = 0.02  # a surrogate minimum within 2 % of the range from a bound counts as at the bound


def curve_value(timeseries_csv, column, at):
    """The run's `column` at process time `at` [s], linear between the time series' rows. A run
    that ended before `at` gives its last row: it ends when the film is dry, and a dry film keeps
    its thickness. None when the file or the column is missing."""
    try:
        with open(timeseries_csv, newline="") as f:
            rows = [(float(r["process_time_s"]), float(r[column])) for r in csv.DictReader(f)]
    except (OSError, KeyError, ValueError):
        return None
    if not rows:
        return None
    t = [r[0] for r in rows]
    return float(np.interp(at, t, [r[1] for r in rows]))


def bounds_reached(surrogate_minimum, region):
    """For each parameter (unit-cube coordinates): "lower" or "upper" when the surrogate's minimum
    lies at that bound, so the best fit may lie outside the search box and the bound, not the
    targets, set the calibrated value; None otherwise. `region` (points x parameters) is the part
    of the cube within chi2 + 1 of the minimum; a minimum at the edge of a region that does not
    reach the bound is not flagged."""
    flags = []
    for j, x in enumerate(surrogate_minimum):
        lo, hi = float(np.min(region[:, j])), float(np.max(region[:, j]))
        if x <= EDGE and lo <= EDGE:
            flags.append("lower")
        elif x >= 1.0 - EDGE and hi >= 1.0 - EDGE:
            flags.append("upper")
        else:
            flags.append(None)
    return flags


def on_signal(sig, frame):
    STOP["signal"] = sig
    for p in list(CHILDREN.values()):
        if p.poll() is None:
            p.send_signal(signal.SIGTERM)  # the run finishes its step, writes a checkpoint, exits


def wait_for_folder(run_dir, timeout=300.0):
    """A run of a killed driver may still be writing its checkpoint (it got SIGTERM when the
    driver died): wait until it has let go of its folder's lock before continuing the folder."""
    import fcntl
    lock = os.path.join(run_dir, ".drydem.lock")
    if not os.path.exists(lock):
        return
    end = time.time() + timeout
    with open(lock, "a") as f:
        while True:
            try:
                fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
                fcntl.flock(f, fcntl.LOCK_UN)
                return
            except BlockingIOError:
                if time.time() > end:
                    return  # drydem run then refuses the folder and names the process holding it
                time.sleep(0.5)


def folder_free(run_dir):
    """Whether no process holds the run folder's lock (its run has exited)."""
    import fcntl
    lock = os.path.join(run_dir, ".drydem.lock")
    if not os.path.exists(lock):
        return True
    with open(lock, "a") as f:
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
            fcntl.flock(f, fcntl.LOCK_UN)
            return True
        except BlockingIOError:
            return False


def parent_death_signal():
    """A run gets SIGTERM when the driver dies (also on SIGKILL): it checkpoints and stops, and a
    resumed calibration continues it instead of finding it still running."""
    try:
        import ctypes
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except OSError:
        pass


class Calibration:
    def __init__(self, args):
        self.dir = os.path.abspath(args.dir)
        self.args = args
        with open(os.path.join(self.dir, "calibration.json")) as f:
            self.spec = json.load(f)
        self.params = self.spec["parameters"]
        self.targets = self.spec["targets"]
        for tg in self.targets:  # a point of a curve carries its own name ("film_thickness_at_40s")
            tg.setdefault("name", tg["quantity"])
        self.d = len(self.params)
        self.ledger_path = os.path.join(self.dir, "ledger.json")
        self.log = open(os.path.join(self.dir, "log.txt"), "a")
        if os.path.exists(self.ledger_path):
            with open(self.ledger_path) as f:
                self.ledger = json.load(f)
        else:
            self.ledger = {"format": 1, "evaluations": []}

    # ---- bookkeeping -------------------------------------------------------------------------
    def say(self, line):
        stamp = time.strftime("%H:%M:%S")
        if not self.args.quiet:
            print(line, file=sys.stderr, flush=True)
        self.log.write(f"[{stamp}] {line}\n")
        self.log.flush()

    def save(self):
        tmp = self.ledger_path + ".tmp"
        with open(tmp, "w") as f:
            json.dump(self.ledger, f, indent=1)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, self.ledger_path)

    def to_unit(self, values):
        u = []
        for p, v in zip(self.params, values):
            lo, hi, v = p["min"], p["max"], v
            if p["log"]:
                lo, hi, v = math.log(lo), math.log(hi), math.log(v)
            u.append((v - lo) / (hi - lo))
        return u

    def from_unit(self, u):
        out = []
        for p, x in zip(self.params, u):
            lo, hi = p["min"], p["max"]
            if p["log"]:
                out.append(float(math.exp(math.log(lo) + x * (math.log(hi) - math.log(lo)))))
            else:
                out.append(float(lo + x * (hi - lo)))
        return out

    def seeds(self):
        return [self.spec["base_seed"] + k for k in range(self.spec["seeds"])]

    def run_dir(self, ev, seed):
        return os.path.join(self.dir, f"eval_{ev['id']:03d}_s{seed}")

    def task(self, ev, seed):
        rd = self.run_dir(ev, seed)
        args = ["run", os.path.join(self.dir, "config.toml"), "-o", rd,
                "--set", f"run.seed={seed}", "--set", f'run.name="{self.spec["name"]}-eval_{ev["id"]:03d}_s{seed}"']
        for p, v in zip(self.params, ev["parameters"]):
            args += ["--set", f"{p['key']}={v!r}"]
        return {"dir": rd, "args": args, "eval": ev["id"], "seed": seed}

    # ---- running -----------------------------------------------------------------------------
    def run_local(self, tasks):
        """The runs through `drydem pool`, the job pool `drydem study` uses (app/job_pool.cpp):
        --jobs at a time, each folder brought to its end by its state (a stopped run resumed, a
        partial one restarted). Ctrl-C/SIGTERM reach the pool, which stops its runs at a
        checkpoint."""
        queue = [t for t in tasks if slurm_array.run_state(t["dir"]) not in ("completed", "failed")
                 and self.ledger_state(t) not in ("completed", "failed")]
        if not queue:
            return
        for t in queue:
            wait_for_folder(t["dir"])
        os.makedirs(os.path.join(self.dir, "logs"), exist_ok=True)
        tasks_file = os.path.join(self.dir, "pool_tasks.json")
        with open(tasks_file + ".tmp", "w") as f:
            json.dump({"tasks": [{"dir": t["dir"], "args": t["args"]} for t in queue]}, f, indent=1)
        os.replace(tasks_file + ".tmp", tasks_file)
        cmd = [self.spec["drydem"], "pool", tasks_file, "--jobs", str(max(1, self.args.jobs)),
               "--threads", str(self.args.threads), "--no-plots"]
        self.say(f"pool: {len(queue)} run(s), {max(1, self.args.jobs)} at a time: "
                 + ", ".join(os.path.basename(t["dir"]) for t in queue))
        with open(os.path.join(self.dir, "logs", "pool.txt"), "a") as console:
            p = subprocess.Popen(cmd, stdout=console, stderr=subprocess.STDOUT,
                                 preexec_fn=parent_death_signal)
        CHILDREN[p.pid] = p
        # Each run is recorded in the ledger as soon as it has ended (its folder completed or failed
        # and its lock let go), not when the whole batch has: a calibration killed mid-batch keeps
        # every finished evaluation.
        pending = list(queue)
        while True:
            try:
                p.wait(timeout=0.5)
                ended = True
            except subprocess.TimeoutExpired:
                ended = False
            except InterruptedError:
                continue
            for t in list(pending):
                if slurm_array.run_state(t["dir"]) in ("completed", "failed") and folder_free(t["dir"]):
                    pending.remove(t)
                    self.collect(t, final=True)
            if ended:
                break
        CHILDREN.pop(p.pid, None)
        for t in pending:
            self.collect(t, final=not STOP["signal"])

    def run_slurm(self, tasks):
        sched = self.spec["scheduler"]
        sub = slurm_array.Submitter(self.spec["drydem"], self.dir, self.spec["name"], sched, say=self.say)
        self.submitter = sub
        sub.run(tasks)
        for t in tasks:
            self.collect(t, final=not STOP["signal"])

    def ledger_state(self, t):
        r = self.ledger["evaluations"][t["eval"] - 1]["runs"].get(str(t["seed"]))
        return r["state"] if r else None

    def console_tail(self, t):
        for f in (os.path.join(t["dir"], "console.txt"), os.path.join(t["dir"], "log.txt")):
            try:
                with open(f) as fh:
                    lines = [ln.strip() for ln in fh if ln.strip()]
                if lines:
                    return lines[-1]
            except OSError:
                pass
        return ""

    def collect(self, t, final=False, code=None):
        """Records one run's results in the ledger (saved at once). `final`: the run's process has
        ended on its own, so a run without summary and checkpoint failed for good."""
        ev = self.ledger["evaluations"][t["eval"] - 1]
        state = slurm_array.run_state(t["dir"])
        values, error = {}, ""
        try:
            with open(os.path.join(t["dir"], "summary.json")) as f:
                s = json.load(f)
            error = s.get("error", "")
            for tg in self.targets:
                if "at_s" in tg:
                    values[tg["name"]] = curve_value(os.path.join(t["dir"], "timeseries.csv"),
                                                     tg["summary_key"], tg["at_s"])
                    continue
                v = s.get(tg["summary_key"])
                if v is None and tg["summary_key"] != "final_thickness_um":
                    try:
                        with open(os.path.join(t["dir"], "analysis", "analysis.json")) as f:
                            v = json.load(f).get(tg["summary_key"])
                    except (OSError, ValueError):
                        v = None
                values[tg["name"]] = v
        except (OSError, ValueError):
            error = "no summary.json" + (f" (exit code {code})" if code is not None else "") + f": {self.console_tail(t)}"
        if final and state in ("partial", "new"):
            state = "failed"
        if state == "completed" and any(values.get(tg["name"]) is None for tg in self.targets):
            state, error = "failed", "a target quantity is missing from the run's summary.json, analysis.json or timeseries.csv (analysis.at_end = false?)"
        ev["runs"][str(t["seed"])] = {"dir": os.path.basename(t["dir"]), "state": state, "values": values,
                                      "error": error}
        self.save()
        self.say(f"  {os.path.basename(t['dir'])}: {state}"
                 + ("" if state != "completed" else ": " + ", ".join(f"{k} {v:.5g}" for k, v in values.items()))
                 + (f" ({error})" if error and state != "completed" else ""))
        if ev["status"] == "pending":
            self.finish_evaluation(ev)  # an evaluation is done as soon as its last run is

    def finish_evaluation(self, ev):
        runs = [ev["runs"].get(str(s)) for s in self.seeds()]
        if any(r is None or r["state"] not in ("completed", "failed") for r in runs):
            return False  # still to run (stopped, or never started)
        ok = [r for r in runs if r["state"] == "completed"]
        if len(ok) < len(runs):
            ev["status"] = "failed"
            ev["misfit"] = None
            ev["error"] = "; ".join(f"{r['dir']}: {r['error']}" for r in runs if r["state"] != "completed")
        else:
            ev["status"] = "done"
            ev["mean"], ev["std"] = {}, {}
            chi2 = 0.0
            for tg in self.targets:
                ys = [float(r["values"][tg["name"]]) for r in ok]
                m = float(np.mean(ys))
                ev["mean"][tg["name"]] = m
                ev["std"][tg["name"]] = float(np.std(ys, ddof=1)) if len(ys) > 1 else 0.0
                chi2 += ((m - tg["value"]) / tg["uncertainty"]) ** 2
            ev["misfit"] = chi2
        self.save()
        self.say(f"evaluation {ev['id']} {ev['status']}: "
                 + ", ".join(f"{p['key']} = {v:.6g}" for p, v in zip(self.params, ev["parameters"]))
                 + (f"; misfit chi2 = {ev['misfit']:.4g}" if ev["misfit"] is not None else f"; {ev.get('error', '')}"))
        return True

    # ---- the search --------------------------------------------------------------------------
    def initial_design(self):
        n = self.spec["initial_points"]
        seed = int(self.spec["base_seed"]) % (2**32)
        if self.spec["sampler"] == "lhs":
            return qmc.LatinHypercube(d=self.d, seed=seed).random(n)
        return qmc.Sobol(d=self.d, scramble=True, seed=seed).random(n)

    def done(self):
        return [e for e in self.ledger["evaluations"] if e["status"] == "done"]

    def fit(self, extra_x=(), extra_y=(), kernels=None):
        """One GP per target on the done evaluations (+ 'liar' points of a batch)."""
        ev = self.done()
        X = np.array([self.to_unit(e["parameters"]) for e in ev] + list(extra_x))
        gps = []
        for k, tg in enumerate(self.targets):
            y = np.array([e["mean"][tg["name"]] for e in ev] + [ey[k] for ey in extra_y])
            if kernels is None:
                kernel = (ConstantKernel(1.0, (1e-3, 1e3)) * Matern(length_scale=[0.5] * self.d, length_scale_bounds=(0.05, 20.0), nu=2.5)
                          + WhiteKernel(1e-2, (1e-6, 1.0)))
                gp = GaussianProcessRegressor(kernel=kernel, normalize_y=True, n_restarts_optimizer=3,
                                              random_state=int(self.spec["base_seed"]) % (2**32))
            else:
                gp = GaussianProcessRegressor(kernel=kernels[k], normalize_y=True, optimizer=None)
            gp.fit(X, y)
            gps.append(gp)
        return gps

    def predict(self, gps, U):
        mu = np.stack([gp.predict(U, return_std=True)[0] for gp in gps], axis=1)
        sd = np.stack([gp.predict(U, return_std=True)[1] for gp in gps], axis=1)
        return mu, sd

    def chi2(self, Y):
        v = np.array([t["value"] for t in self.targets])
        s = np.array([t["uncertainty"] for t in self.targets])
        return (((Y - v) / s) ** 2).sum(axis=-1)

    def propose(self, q, round_no):
        """q new points by expected improvement of chi2; a batch by the constant liar (each chosen
        point enters the GPs with its predicted targets before the next is chosen)."""
        rng = np.random.default_rng(int(self.spec["base_seed"]) + 7919 * round_no)
        gps = self.fit()
        kernels = [gp.kernel_ for gp in gps]
        done = self.done()
        Xd = np.array([self.to_unit(e["parameters"]) for e in done])
        best = float(self.chi2(self.predict(gps, Xd)[0]).min())
        Z = rng.standard_normal((256, len(self.targets)))
        cand = qmc.Sobol(d=self.d, scramble=True, seed=rng.integers(2**31)).random(1024)
        best_x = Xd[int(np.argmin(self.chi2(self.predict(gps, Xd)[0])))]
        local = np.clip(best_x + 0.05 * rng.standard_normal((256, self.d)), 0.0, 1.0)
        cand = np.vstack([cand, local])
        chosen, liar_x, liar_y = [], [], []
        for _ in range(q):
            mu, sd = self.predict(gps, cand)
            samples = self.chi2(mu[:, None, :] + sd[:, None, :] * Z[None, :, :])  # (n, 256)
            ei = np.maximum(best - samples, 0.0).mean(axis=1)
            k = int(np.argmax(ei))
            x = cand[k]
            chosen.append((x, float(ei[k])))
            liar_x.append(x)
            liar_y.append(mu[k])
            cand = np.delete(cand, k, axis=0)
            gps = self.fit(liar_x, liar_y, kernels)
        return chosen

    def plan(self):
        evs = self.ledger["evaluations"]
        n_init, n_total = self.spec["initial_points"], self.spec["evaluations"]
        if len(evs) < n_init:
            design = self.initial_design()
            new = [(design[k], None) for k in range(len(evs), n_init)]
            kind = "initial"
        else:
            if len(self.done()) < 2:
                raise SystemExit("error: fewer than 2 evaluations succeeded; the surrogate needs more "
                                 "(see the failed runs in evaluations.csv / log.txt)")
            q = max(1, self.args.jobs // self.spec["seeds"]) if self.spec["scheduler"]["type"] == "local" \
                else max(1, self.args.jobs)
            q = min(q, n_total - len(evs))
            new = self.propose(q, len(evs))
            kind = "expected improvement"
        for u, ei in new:
            ev = {"id": len(evs) + 1, "kind": kind, "unit": [float(x) for x in u],
                  "parameters": self.from_unit(u), "status": "pending", "runs": {}}
            if ei is not None:
                ev["expected_improvement"] = ei
            evs.append(ev)
            self.say(f"planned evaluation {ev['id']} ({kind}): "
                     + ", ".join(f"{p['key']} = {v:.6g}" for p, v in zip(self.params, ev["parameters"])))
        self.save()

    def loop(self):
        n_total = self.spec["evaluations"]
        while not STOP["signal"]:
            pending = [e for e in self.ledger["evaluations"] if e["status"] == "pending"]
            if not pending:
                if len(self.ledger["evaluations"]) >= n_total:
                    break
                self.plan()
                continue
            tasks = [self.task(e, s) for e in pending for s in self.seeds()]
            # what is already on disk (a resumed calibration) is collected, not run again
            for t in tasks:
                if slurm_array.run_state(t["dir"]) in ("completed", "failed") and self.ledger_state(t) is None:
                    self.collect(t)
            tasks = [t for t in tasks if self.ledger_state(t) not in ("completed", "failed")]
            if self.spec["scheduler"]["type"] == "slurm":
                self.run_slurm(tasks)
            else:
                self.run_local(tasks)
            progressed = any(e["status"] != "pending" for e in pending)
            if not progressed and not STOP["signal"]:
                raise SystemExit("error: runs were stopped and not continued; run drydem calibrate --resume again")
            self.write_tables()
        return not STOP["signal"]

    # ---- results -----------------------------------------------------------------------------
    def write_tables(self):
        path = os.path.join(self.dir, "evaluations.csv")
        with open(path + ".tmp", "w", newline="") as f:
            w = csv.writer(f)
            head = ["evaluation", "kind", "status"] + [p["key"] for p in self.params]
            for tg in self.targets:
                u = f"_{tg['unit']}".replace("/", "_").replace("^", "") if tg["unit"] else ""
                head += [f"{tg['name']}{u}", f"{tg['name']}_std{u}"]
            head += ["misfit_chi2", "runs"]
            w.writerow(head)
            for e in self.ledger["evaluations"]:
                row = [e["id"], e["kind"], e["status"]] + [f"{v:.10g}" for v in e["parameters"]]
                for tg in self.targets:
                    if e["status"] == "done":
                        row += [f"{e['mean'][tg['name']]:.8g}", f"{e['std'][tg['name']]:.4g}"]
                    else:
                        row += ["", ""]
                row += ["" if e.get("misfit") is None else f"{e['misfit']:.6g}",
                        " ".join(r["dir"] for r in e["runs"].values())]
                w.writerow(row)
        os.replace(path + ".tmp", path)

    def result(self):
        done = self.done()
        if len(done) < 2:
            raise SystemExit("error: fewer than 2 evaluations succeeded; no surrogate, no result")
        gps = self.fit()
        Xd = np.array([self.to_unit(e["parameters"]) for e in done])
        m_done = self.chi2(self.predict(gps, Xd)[0])
        ib = int(np.argmin(m_done))
        grid = np.vstack([qmc.Sobol(d=self.d, scramble=True, seed=1).random(4096), Xd])
        m_grid = self.chi2(self.predict(gps, grid)[0])
        chi_min = float(m_grid.min())
        region = grid[m_grid <= chi_min + 1.0]
        xs = grid[int(np.argmin(m_grid))]
        best = done[ib]
        res = {"best": {}, "surrogate_minimum": {}, "best_evaluation": best["id"],
               "best_evaluation_misfit_chi2": best["misfit"],
               "best_evaluation_predicted_chi2": float(m_done[ib]),
               "surrogate_minimum_chi2": chi_min, "evaluations": len(self.ledger["evaluations"]),
               "completed": len(done), "targets": {}, "region_points": int(len(region)),
               "method": "per-target Gaussian processes (Matern 5/2 + white noise); uncertainty: the range "
                         "of each parameter over the region where the predicted chi2 is within 1 of its minimum"}
        at_bound = bounds_reached(xs, region)
        for j, p in enumerate(self.params):
            lo_hi = self.from_unit([region[:, j].min() if k == j else 0.5 for k in range(self.d)])[j], \
                self.from_unit([region[:, j].max() if k == j else 0.5 for k in range(self.d)])[j]
            res["best"][p["key"]] = {"value": best["parameters"][j], "range_delta_chi2_1": list(lo_hi),
                                     "surrogate_minimum_at_bound": at_bound[j]}
            res["surrogate_minimum"][p["key"]] = self.from_unit(xs)[j]
        mu, sd = self.predict(gps, Xd[ib:ib + 1])
        for k, tg in enumerate(self.targets):
            res["targets"][tg["name"]] = {"measured": tg["value"], "uncertainty": tg["uncertainty"],
                                              "unit": tg["unit"], "at_best": best["mean"][tg["name"]],
                                              "predicted_at_best": float(mu[0, k]), "predicted_sd": float(sd[0, k])}
        with open(os.path.join(self.dir, "result.json"), "w") as f:
            json.dump(res, f, indent=2)
        self.write_calibrated(best, res)
        return res, gps

    def write_calibrated(self, best, res):
        """config.toml with the best parameters: a config `drydem run` takes as it is."""
        with open(os.path.join(self.dir, "config.toml")) as f:
            lines = f.read().splitlines()
        values = {p["key"]: v for p, v in zip(self.params, best["parameters"])}
        section, out, seen = "", [], set()
        for line in lines:
            s = line.strip()
            if s.startswith("[") and s.endswith("]"):
                section = s.strip("[]").strip()
            elif "=" in s and not s.startswith("#"):
                key = f"{section}.{s.split('=', 1)[0].strip()}"
                if key in values:
                    line = f"{s.split('=', 1)[0].strip()} = {values[key]!r}"
                    seen.add(key)
            out.append(line)
        missing = set(values) - seen
        if missing:
            raise SystemExit(f"error: config.toml has no line for {', '.join(sorted(missing))}")
        head = [f"# Calibrated by drydem calibrate ({len(self.done())} evaluations, best: evaluation "
                f"{best['id']}, chi2 = {best['misfit']:.4g}); details in result.json."]
        for k, v in res["best"].items():
            head.append(f"#   {k} = {v['value']:.6g}  (predicted chi2 within 1 of its minimum for "
                        f"{v['range_delta_chi2_1'][0]:.6g} .. {v['range_delta_chi2_1'][1]:.6g})")
        with open(os.path.join(self.dir, "calibrated.toml"), "w") as f:
            f.write("\n".join(head + out) + "\n")
        r = subprocess.run([self.spec["drydem"], "check", os.path.join(self.dir, "calibrated.toml")],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            raise SystemExit(f"error: calibrated.toml does not validate: {r.stderr.strip()}")

    def plots(self, gps, res):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        os.makedirs(os.path.join(self.dir, "plots"), exist_ok=True)
        done = self.done()
        Xd = np.array([self.to_unit(e["parameters"]) for e in done])
        P = np.array([e["parameters"] for e in done])
        # surrogate of the misfit over the parameters: the first two (others at the best value)
        fig, ax = plt.subplots(figsize=(6.4, 5.2))
        n = 80
        if self.d >= 2:
            g = np.linspace(0, 1, n)
            G1, G2 = np.meshgrid(g, g)
            U = np.tile(Xd[int(np.argmin([e["misfit"] for e in done]))], (n * n, 1))
            U[:, 0], U[:, 1] = G1.ravel(), G2.ravel()
            M = self.chi2(self.predict(gps, U)[0]).reshape(n, n)
            V = np.array([self.from_unit(u) for u in U])
            c = ax.contourf(V[:, 0].reshape(n, n), V[:, 1].reshape(n, n), np.log10(M + 1e-3), 30, cmap="viridis")
            fig.colorbar(c, label="log10 predicted misfit chi2")
            ax.contour(V[:, 0].reshape(n, n), V[:, 1].reshape(n, n), M,
                       levels=[res["surrogate_minimum_chi2"] + 1.0], colors="w", linewidths=1.5)
            ax.scatter(P[:, 0], P[:, 1], c="r", s=25, label="evaluations")
            for e, p in zip(done, P):
                ax.annotate(str(e["id"]), p[:2], fontsize=7, color="w")
            b = [res["best"][p["key"]]["value"] for p in self.params]
            ax.plot(b[0], b[1], "w*", ms=14, label="best")
            ax.set_xlabel(self.params[0]["key"])
            ax.set_ylabel(self.params[1]["key"])
            ax.set_title("surrogate misfit; white line: chi2 = min + 1")
        else:
            g = np.linspace(0, 1, 200)[:, None]
            M = self.chi2(self.predict(gps, g)[0])
            ax.plot([self.from_unit(u)[0] for u in g], M, label="predicted chi2")
            ax.scatter(P[:, 0], [e["misfit"] for e in done], c="r", label="evaluations")
            ax.set_xlabel(self.params[0]["key"])
            ax.set_ylabel("misfit chi2")
            ax.set_yscale("log")
        ax.legend(loc="best", fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(self.dir, "plots", "surrogate.png"), dpi=120)
        plt.close(fig)
        # every target vs evaluation, with the measured band
        T = len(self.targets)
        fig, axes = plt.subplots(T, 1, figsize=(6.4, 2.4 * T + 0.6), sharex=True, squeeze=False)
        for k, tg in enumerate(self.targets):
            ax = axes[k, 0]
            ids = [e["id"] for e in done]
            ax.errorbar(ids, [e["mean"][tg["name"]] for e in done],
                        yerr=[e["std"][tg["name"]] for e in done], fmt="o", ms=4, capsize=2)
            ax.axhspan(tg["value"] - tg["uncertainty"], tg["value"] + tg["uncertainty"], color="g", alpha=0.2)
            ax.axhline(tg["value"], color="g", lw=1, label="measured")
            ax.set_ylabel(f"{tg['name']}" + (f" [{tg['unit']}]" if tg["unit"] else ""))
        axes[-1, 0].set_xlabel("evaluation")
        axes[0, 0].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(self.dir, "plots", "targets.png"), dpi=120)
        plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args()
    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    cal = Calibration(args)
    done_before = len(cal.done())
    cal.say(f"calibration in {cal.dir}: {cal.d} parameter(s), {len(cal.targets)} target(s), "
            f"{cal.spec['seeds']} seed(s) per evaluation, {cal.spec['evaluations']} evaluations "
            f"({cal.spec['initial_points']} initial, {cal.spec['sampler']}); {done_before} done before; "
            f"scheduler {cal.spec['scheduler']['type']}")
    if cal.spec["scheduler"]["type"] == "slurm":
        def cancel(sig, frame):
            on_signal(sig, frame)
            sub = getattr(cal, "submitter", None)
            if sub:
                sub.cancel()
        signal.signal(signal.SIGTERM, cancel)
        signal.signal(signal.SIGINT, cancel)
    finished = cal.loop()
    cal.write_tables()
    if not finished:
        cal.say(f"stopped (signal {STOP['signal']}); `drydem calibrate CONFIG -o {cal.dir} --resume` continues")
        return 1
    res, gps = cal.result()
    for k, v in res["best"].items():
        cal.say(f"best {k} = {v['value']:.6g} (chi2 within 1 of the minimum: {v['range_delta_chi2_1'][0]:.6g} .. "
                f"{v['range_delta_chi2_1'][1]:.6g}; surrogate minimum {res['surrogate_minimum'][k]:.6g})")
    for k, v in res["best"].items():
        if v["surrogate_minimum_at_bound"]:
            p = next(p for p in cal.params if p["key"] == k)
            cal.say(f"warning: the surrogate's minimum of {k} lies at its {v['surrogate_minimum_at_bound']} bound "
                    f"({p['min' if v['surrogate_minimum_at_bound'] == 'lower' else 'max']:.6g}): the bound, not the "
                    f"targets, sets this value; if a value beyond it is physical, widen the bound and --resume")
    for q, t in res["targets"].items():
        cal.say(f"  {q}: {t['at_best']:.5g} at the best evaluation, measured {t['measured']:.5g} +- {t['uncertainty']:.3g} {t['unit']}")
    if not args.no_plots:
        try:
            cal.plots(gps, res)
        except Exception as e:  # plotting never fails the calibration
            cal.say(f"plotting failed: {e}")
    cal.say(f"done: evaluations.csv, ledger.json, result.json, calibrated.toml{', plots/' if not args.no_plots else ''} in {cal.dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
