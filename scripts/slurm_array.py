#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Runs a list of `drydem run` cases as a Slurm job array (docs/calibration.md "Slurm").

One array task per run; each task takes its thread count from SLURM_CPUS_PER_TASK (and, with
`ranks_per_run` > 1, runs `srun drydem run ...` over its --ntasks MPI ranks), and resumes
from the run folder's checkpoint when it has one (a task that hit its time limit was stopped by
SIGTERM, wrote a checkpoint and a summary saying so). After the array has ended, every task
whose run was stopped (not completed, not failed for good) is submitted again, up to
`resubmits` times. Used by `drydem study` (command line below) and by scripts/calibrate.py
(import).

    slurm_array.py TASKS_JSON

TASKS_JSON: {"drydem": EXE, "work": DIR, "name": NAME, "scheduler": {"partition": "",
"time_limit_s": 0, "cpus_per_task": 1, "ranks_per_run": 1, "resubmits": 3}, "tasks": [{"dir": RUN_DIR, "args":
["run", CONFIG, "-o", RUN_DIR, ...]}]}. Prints one line per submission; exit 0 when every task
ended (completed or failed), 1 when sbatch could not submit.
"""
import json
import os
import shlex
import signal
import subprocess
import sys

# The stop reasons (summary.json `stop_reason`, core/error.hpp) of a run that stopped on request
# (SIGTERM at a time limit, Ctrl-C, the test option): such a run resumes from its checkpoint.
# Every other failure is final.
STOPPED_REASONS = ("interrupted", "stop_after_steps")


def run_state(run_dir):
    """'completed', 'failed' (for good), 'stopped' (resumable), 'partial' (a run without
    checkpoint or summary: restarted cleanly) or 'new'."""
    summary = os.path.join(run_dir, "summary.json")
    has_checkpoint = os.path.isfile(os.path.join(run_dir, "checkpoint", "state.bin"))
    if os.path.isfile(summary):
        try:
            with open(summary) as f:
                s = json.load(f)
        except (OSError, ValueError):
            s = {}
        if s.get("status") == "completed":
            return "completed"
        if s.get("stop_reason") in STOPPED_REASONS and has_checkpoint:
            return "stopped"
        if s.get("status") == "failed":
            return "failed"
    if has_checkpoint:
        return "stopped"  # killed without warning: resumes from its last checkpoint
    if os.path.isfile(os.path.join(run_dir, "config.toml")):
        return "partial"
    return "new"


def run_args(drydem, task, threads, quiet=True, plots=False):
    """The command that brings one run folder to its end, by its state now (local runs)."""
    state = run_state(task["dir"])
    tail = ["--threads", str(threads)] + (["--quiet"] if quiet else []) + ([] if plots else ["--no-plots"])
    if state == "stopped":
        return [drydem, "run", "--resume", task["dir"]] + tail
    if state == "partial":
        return [drydem] + task["args"] + ["--overwrite"] + tail
    return [drydem] + task["args"] + tail


def task_script(drydem, task, plots=False, ranks=1):
    """The same decision as run_args, made by the task itself when it starts (bash). A run of
    several ranks is started by srun over the task's --ntasks (the cluster's MPI plugin, e.g.
    MpiDefault=pmix in slurm.conf or SLURM_MPI_TYPE, connects Open MPI to it)."""
    d = shlex.quote(task["dir"])
    exe = ("srun " if ranks > 1 else "") + shlex.quote(drydem)
    args = " ".join(shlex.quote(a) for a in task["args"])
    flags = "--quiet" + ("" if plots else " --no-plots")
    markers = "|".join(f'"stop_reason": "{r}"' for r in STOPPED_REASONS)
    return f"""#!/bin/bash
# One drydem run of a Slurm array task (scripts/slurm_array.py).
threads=${{SLURM_CPUS_PER_TASK:-1}}
dir={d}
if [[ -f $dir/summary.json ]] && grep -q '"status": "completed"' "$dir/summary.json"; then
  echo "already completed: $dir"; exit 0
fi
if [[ -f $dir/checkpoint/state.bin ]]; then
  if [[ ! -f $dir/summary.json ]] || grep -Eq '{markers}' "$dir/summary.json"; then
    echo "resuming $dir from its checkpoint with $threads thread(s)"
    exec {exe} run --resume "$dir" --threads "$threads" {flags}
  fi
  echo "failed for good: $dir"; exit 1
fi
extra=()
[[ -f $dir/config.toml ]] && extra=(--overwrite)
echo "starting $dir with $threads thread(s)"
exec {exe} {args} "${{extra[@]}}" --threads "$threads" {flags}
"""


class Submitter:
    """Submits rounds of job arrays with `sbatch --wait`; SIGINT/SIGTERM cancel the array."""

    def __init__(self, drydem, work, name, scheduler, say=print):
        self.drydem, self.work, self.name, self.sched, self.say = drydem, work, name, scheduler, say
        self.rounds = 0
        self.job_id = None

    def cancel(self):
        if self.job_id:
            subprocess.run(["scancel", "--signal=TERM", "--full", self.job_id], check=False)

    def run(self, tasks, plots=False):
        """Runs `tasks` until each is completed or failed for good (or resubmits are used up)."""
        ranks = int(self.sched.get("ranks_per_run", 1))
        for attempt in range(int(self.sched.get("resubmits", 3)) + 1):
            todo = [t for t in tasks if run_state(t["dir"]) not in ("completed", "failed")]
            if not todo:
                return
            # rounds numbered on from those in the folder (a calibration submits many)
            base = os.path.join(self.work, "slurm")
            os.makedirs(base, exist_ok=True)
            self.rounds = 1 + sum(1 for n in os.listdir(base) if n.startswith("round_"))
            rdir = os.path.join(base, f"round_{self.rounds:03d}")
            os.makedirs(rdir, exist_ok=True)
            for k, t in enumerate(todo):
                os.makedirs(t["dir"], exist_ok=True)
                with open(os.path.join(rdir, f"task_{k}.sh"), "w") as f:
                    f.write(task_script(self.drydem, t, plots, ranks))
            job = os.path.join(rdir, "job.sh")
            with open(job, "w") as f:
                f.write(f"#!/bin/bash\nexec bash {shlex.quote(rdir)}/task_${{SLURM_ARRAY_TASK_ID}}.sh\n")
            cmd = ["sbatch", "--parsable", "--wait", f"--array=0-{len(todo) - 1}",
                   f"--cpus-per-task={int(self.sched.get('cpus_per_task', 1))}",
                   f"--ntasks={ranks}",
                   f"--job-name=drydem-{self.name}"[:64], f"--output={rdir}/task_%a.out",
                   f"--chdir={self.work}"]
            if self.sched.get("partition"):
                cmd.append(f"--partition={self.sched['partition']}")
            if float(self.sched.get("time_limit_s", 0)) > 0:
                cmd.append(f"--time={max(1, int(-(-float(self.sched['time_limit_s']) // 60)))}")
            cmd.append(job)
            self.say(f"slurm: submitting {len(todo)} run(s) as a job array"
                     + (f" (resubmission {attempt})" if attempt else "") + f": {shlex.join(cmd)}")
            p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            # --parsable prints the job id at submission; --wait then blocks until the array ends.
            first = p.stdout.readline().strip()
            self.job_id = first.split(";")[0] if first else None
            if self.job_id:
                self.say(f"slurm: job {self.job_id} submitted; waiting for it to end")
            out, err = p.communicate()
            self.job_id_done, self.job_id = self.job_id, None
            if not self.job_id_done:
                raise RuntimeError(f"sbatch failed (exit {p.returncode}): {err.strip()}")
            states = [run_state(t["dir"]) for t in todo]
            self.say(f"slurm: job {self.job_id_done} ended: "
                     + ", ".join(f"{s} {states.count(s)}" for s in sorted(set(states))))
        left = [t["dir"] for t in tasks if run_state(t["dir"]) == "stopped"]
        if left:
            self.say(f"slurm: {len(left)} run(s) still stopped after {self.sched.get('resubmits', 3)} "
                     f"resubmission(s): {', '.join(left)}")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        spec = json.load(f)
    sub = Submitter(spec["drydem"], spec["work"], spec["name"], spec["scheduler"],
                    say=lambda s: print(s, file=sys.stderr, flush=True))

    def stop(sig, frame):
        sub.cancel()
        sys.exit(1)

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    try:
        sub.run(spec["tasks"], plots=bool(spec.get("plots", False)))
    except RuntimeError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
