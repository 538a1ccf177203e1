#!/usr/bin/python3
"""Seeded fuzz suite of the drydem command line (issue 14): malformed configs, hostile --set values,
CLI integers and particle files, run against the real executable.

Asserted for every case: the exit code is 0 or 2 (never a signal, an abort, exit 1 or a sanitizer
report), the command ends within its time limit (no hang), a refusal says "error:", and every
accepted config has finite, positive derived quantities (`drydem check`: particles, wet film
height, steps, memory) and every accepted particle file a possible density and porosity
(`drydem analyze`). Impossible particle files must be refused (exit 2) before a run's first step.

usage: fuzz_cli.py DRYDEM WORKDIR [--seed N] [--cases N]
Prints the counts tried / crashed / hung / accepted-nonsense (docs/validation.md) and exits 1 when
any of the last three is not zero, listing the cases to reproduce.
"""
import argparse
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tomllib
from concurrent.futures import ThreadPoolExecutor

TIMEOUT_S = 20  # per command; `drydem check` takes milliseconds, a hang takes forever

# ------------------------------------------------------------------ hostile values
HOSTILE_NUMBERS = ["0", "-0", "-1", "1", "40", "1e308", "-1e308", "1.7976931348623157e308", "1e-300",
                   "5e-324", "nan", "inf", "-inf", "+inf", "1e3", "3.5", "-2.5e-6", "0.5",
                   "9223372036854775807", "-9223372036854775808", "18446744073709551615", "1e20",
                   "0x10", "1_000", "007"]
HOSTILE_QUANTITIES = ['"10 nm"', '"40 um"', '"1e308 um"', '"1e-300 um"', '"1e308 kg/m^3"',
                      '"1e-9 m/min"', '"1e-9 s"', '"1e308 s"', '"-5 um"', '"nan um"', '"inf m"',
                      '"3 kg"', '"80 degC"', '"5 degC^2"', '"1 um^9^9"', '"1 ((((m))))"',
                      '"1 m' + '*m' * 200 + '"', '"1 ' + '(' * 30000 + 'm' + ')' * 30000 + '"',
                      '"1 ' + '(' * 20 + 'm^9' + ')^9' * 20 + '"', '"1 deg' + ' deg^9' * 500 + '"',
                      '"1e99999 um"', '"1e-99999 m"', '"1 Tm^9 Tm^9 Tm^9"', '"20.1 mg/cm^2"',
                      '"0.1 mg/cm^2"', '"1e-12 mg/cm^2"', '"1e6 mg/cm^2"', '"2 mm"', '"1 µm"',
                      '"1 uu"', '"um"', '""', '"1 / / s"', '"1 m/"', '"1e"', '"- 1 m"']
HOSTILE_OTHERS = ["true", "false", "[]", "[1e308]", "[0]", '["10 nm", "1 m"]', "[1, [2]]",
                  "{}", "{a = 1}", '"x\\"y"', "'a\\b'", '"a/b"', '".."', '"\\u0000"', '"line\\nbreak"',
                  '"ünïcödé µm"', "1\nfoo=2", "1 # comment", '"' + "x" * 300 + '"', "1979-05-27",
                  "\xff\xfe", "'''multi\nline'''", "=", "[run]", '"\\ud800"']


def hostile_value(rng):
    pool = rng.choice([HOSTILE_NUMBERS, HOSTILE_QUANTITIES, HOSTILE_OTHERS])
    return rng.choice(pool)


def schema_keys(drydem):
    """Every dotted key of the embedded default configuration."""
    text = subprocess.run([drydem, "config", "default"], capture_output=True, text=True, check=True).stdout
    keys = []

    def walk(t, prefix):
        for k, v in t.items():
            if isinstance(v, dict):
                walk(v, prefix + k + ".")
            else:
                keys.append(prefix + k)

    walk(tomllib.loads(text), "")
    return keys, text


# Keys that change counts, heights and steps: hit them more often than the others.
DERIVED_KEYS = ["film.areal_loading", "film.box_x", "film.box_y", "formulation.cb_diameter",
                "formulation.ncm_diameters", "materials.solvent_density", "materials.ncm_density",
                "scaling.time_factor", "drying.relaxation", "run.time_step", "dryer.time_step",
                "dryer.line_speed", "dryer.schedule", "formulation.pvdf_mass_fraction", "run.name"]


def set_case(rng, keys):
    sets = []
    for _ in range(rng.randint(1, 3)):
        key = rng.choice(DERIVED_KEYS if rng.random() < 0.5 else keys)
        if rng.random() < 0.05:
            key = rng.choice(["run.", ".seed", "run..seed", "x" * 60, "run.seed.x", "film"])
        sets.append(f"{key}={hostile_value(rng)}")
    if rng.random() < 0.15:  # the model schedule runs the dryer model inside `check`
        sets.append("dryer.schedule=model")
    return ["check"] + [a for s in sets for a in ("--set", s)]


def mutate_config(rng, text):
    """A broken copy of the default configuration."""
    lines = text.splitlines()
    for _ in range(rng.randint(1, 4)):
        if not lines:  # an earlier mutation removed every line
            lines = [""]
        kind = rng.randrange(7)
        i = rng.randrange(len(lines))
        if kind == 0:
            del lines[i]
        elif kind == 1:
            lines.insert(i, lines[rng.randrange(len(lines))])  # duplicate keys / tables
        elif kind == 2 and "=" in lines[i]:
            lines[i] = lines[i].split("=")[0] + "= " + hostile_value(rng)
        elif kind == 3:
            lines[i] = lines[i][: rng.randrange(len(lines[i]) + 1)]  # truncated line
        elif kind == 4:
            lines.insert(i, "".join(chr(rng.randrange(1, 0x250)) for _ in range(rng.randint(1, 12))))
        elif kind == 5:
            lines.insert(i, rng.choice(["[film]", "[[film]]", "[run.name]", "film = 3", "a.b.c = 1",
                                        "[" * 5000, "x = " + "[" * 5000]))
        else:
            lines = lines[: rng.randrange(len(lines) + 1)]  # truncated file
            if not lines:
                lines = [""]
    return "\n".join(lines) + ("\n" if rng.random() < 0.8 else "")


# ------------------------------------------------------------------ particle files
def packing(rng, n, box):
    """n spheres on a loose lattice in a box x box base: a valid dried film."""
    parts, side, r = [], max(1, int(n ** (1 / 3)) + 1), box / 12
    for k in range(n):
        i, j, l = k % side, (k // side) % side, k // (side * side)
        parts.append([k + 1, rng.choice([1, 2]), r, 4740.0,
                      (i + 0.5) * box / side, (j + 0.5) * box / side, r + l * 2.2 * r])
    return parts


IMPOSSIBLE = ["coincident", "below", "sunk", "huge_radius", "far_outside", "overlap"]


def break_packing(rng, parts, box, kind):
    p = [list(x) for x in parts]
    if kind == "coincident":
        p[1][4:7] = p[0][4:7]
    elif kind == "below":
        p[0][6] = -p[0][2] * rng.uniform(0.01, 3)
    elif kind == "sunk":
        p[0][6] = p[0][2] * 0.05
    elif kind == "huge_radius":
        p[0][2] = rng.choice([box, 1.0, 1e300])
    elif kind == "far_outside":
        p[0][4] = box * rng.choice([50, 1e6, 1e300])
    elif kind == "overlap":
        p[1][4:7] = [p[0][4] + 0.3 * p[0][2], p[0][5], p[0][6]]
    return p


def csv_text(parts):
    rows = ["id,type,radius_m,density_kg_m3,x_m,y_m,z_m"]
    rows += [",".join(repr(v) for v in q) for q in parts]
    return "\n".join(rows) + "\n"


def dump_text(parts, box, lo=0.0, hi=None):
    hi = box if hi is None else hi
    out = ["ITEM: TIMESTEP", "0", "ITEM: NUMBER OF ATOMS", str(len(parts)),
           "ITEM: BOX BOUNDS pp pp fm", f"{lo} {hi}", f"{lo} {hi}", f"0 {box * 4}",
           "ITEM: ATOMS id type radius x y z"]
    out += [f"{q[0]} {q[1]} {q[2]!r} {q[4]!r} {q[5]!r} {q[6]!r}" for q in parts]
    return "\n".join(out) + "\n"


def mutate_text(rng, text):
    """Byte-level damage: the reader must name the line, never crash."""
    b = bytearray(text.encode())
    for _ in range(rng.randint(1, 5)):
        if not b:
            break
        i = rng.randrange(len(b))
        op = rng.randrange(5)
        if op == 0:
            b[i] = rng.randrange(256)
        elif op == 1:
            del b[i: i + rng.randint(1, 40)]
        elif op == 2:
            b[i:i] = rng.choice([b",", b"\n", b"nan", b"-", b"1e999", b"\x00", b" ", b"ITEM: ATOMS"])
        elif op == 3:
            b = b[:i]
        else:
            b[i:i] = b[rng.randrange(len(b)):][:60]
    return bytes(b)


def particle_case(rng, work, idx):
    box = 40e-6
    parts = packing(rng, rng.randint(2, 40), box)
    kind = rng.choice(["valid", "mutated", "impossible", "inverted", "empty"])
    expect_refusal = kind in ("impossible", "inverted", "empty")
    path = os.path.join(work, f"p{idx}")
    fmt = rng.choice(["csv", "dump"])
    if kind == "impossible":
        parts = break_packing(rng, parts, box, rng.choice(IMPOSSIBLE))
    if kind == "inverted":
        fmt = "dump"
        data = dump_text(parts, box, lo=box, hi=rng.choice([0.0, box, -box])).encode()
    elif kind == "empty":
        data = rng.choice([b"", b"\n\n", b"id,type,radius_m,x_m,y_m,z_m\n", b"\x1f\x8b\x08"])
    else:
        data = (csv_text(parts) if fmt == "csv" else dump_text(parts, box)).encode()
        if kind == "mutated":
            data = mutate_text(rng, data.decode())
    path += ".csv" if fmt == "csv" else ".lammpstrj"
    with open(path, "wb") as f:
        f.write(data)
    args = ["analyze", path, "--no-voxels", "--no-plots", "--quiet", "-o", path + ".out",
            "--set", "film.box_x=40um", "--set", "film.box_y=40um"]
    if expect_refusal and kind == "impossible" and rng.random() < 0.3:
        # The same file as the start of a run: refused before step 1 (never blamed on the forces).
        args = ["run", "--particles", path, "-o", path + ".run", "--no-plots", "--quiet",
                "--set", "film.box_x=40um", "--set", "film.box_y=40um",
                "--set", "formulation.ncm_diameters=[\"3.33 um\"]"]
    return args, ("refuse" if expect_refusal else "any")


def cli_int_case(rng, work, idx):
    option = rng.choice(["--seed", "--threads"])
    # Only values no run may start with (a valid one would start a real run).
    value = rng.choice(["-1", "-5", "1e3", "18446744073709551615", "9223372036854775808", "abc", "1.5",
                        "0x10", " 1", "+3", "99999999999999999999999", "", "-0"] +
                       (["1000", "1025", "4294967297"] if option == "--threads" else []))
    return ["run", option, value, "-o", os.path.join(work, f"cli{idx}"), "--no-plots"], "refuse"


# ------------------------------------------------------------------ checks of accepted output
def number_after(label, text):
    m = re.search(re.escape(label) + r"\s+~?([-+0-9.eEnainf]+)", text)
    return float(m.group(1)) if m else None


def check_nonsense(args, out):
    """Why an accepted command's numbers are impossible, or None."""
    if args[0] == "check":
        for label in ("wet film height (Eq. 3)", "particles", "steps", "memory", "solids density (Eq. 4)"):
            v = number_after(label, out)
            if v is None or not math.isfinite(v) or v <= 0:
                return f"{label} = {v}"
        for m in re.finditer(r"^\s{4}(carbon black|NCM622)\s+\d+\s+\S+\s+(-?\d+)", out, re.M):
            if int(m.group(2)) < 0:
                return f"negative count in: {m.group(0).strip()}"
    elif args[0] == "analyze":
        m = re.search(r"density ([-+0-9.eEnainf]+) g/cm3, porosity ([-+0-9.eEnainf]+)", out)
        if not m:
            return "no density/porosity line"
        rho, eps = float(m.group(1)), float(m.group(2))
        if not (math.isfinite(rho) and rho > 0 and 0 <= eps < 1):
            return f"density {rho}, porosity {eps}"
    return None


def run_case(drydem, args, expect, stdin_file=None):
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=0", UBSAN_OPTIONS="print_stacktrace=1")
    try:
        r = subprocess.run([drydem] + args, capture_output=True, timeout=TIMEOUT_S, env=env)
    except subprocess.TimeoutExpired:
        return "hung", "timeout"
    out = r.stdout.decode(errors="replace") + r.stderr.decode(errors="replace")
    if r.returncode < 0 or r.returncode not in (0, 2) or "runtime error:" in out or "AddressSanitizer" in out:
        return "crashed", f"exit {r.returncode}: {out[-600:]}"
    if r.returncode == 2 and "error:" not in out:
        return "crashed", f"exit 2 without an error message: {out[-300:]}"
    if expect == "refuse" and r.returncode != 2:
        return "nonsense", f"accepted an impossible input (exit {r.returncode}): {out[-300:]}"
    if r.returncode == 0:
        why = check_nonsense(args, out)
        if why:
            return "nonsense", why
        return "accepted", ""
    return "refused", ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("drydem")
    ap.add_argument("work")
    ap.add_argument("--seed", type=int, default=14)
    ap.add_argument("--cases", type=int, default=500)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    rng = random.Random(a.seed)
    keys, default_text = schema_keys(a.drydem)

    cases = []  # (class, args, expectation)
    for idx in range(a.cases):
        kind = rng.random()
        if kind < 0.55:
            cases.append(("--set", set_case(rng, keys), "any"))
        elif kind < 0.72:
            path = os.path.join(a.work, f"c{idx}.toml")
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as f:
                f.write(mutate_config(rng, default_text))
            cases.append(("config", ["check", path], "any"))
        elif kind < 0.97:
            args, expect = particle_case(rng, a.work, idx)
            cases.append(("particles", args, expect))
        else:
            args, expect = cli_int_case(rng, a.work, idx)
            cases.append(("cli-int", args, expect))

    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda c: run_case(a.drydem, c[1], c[2]), cases))

    counts = {"crashed": 0, "hung": 0, "nonsense": 0, "accepted": 0, "refused": 0}
    by_class = {}
    for (cls, args, _), (outcome, why) in zip(cases, results):
        counts[outcome] += 1
        by_class.setdefault(cls, [0, 0])[0] += 1
        by_class[cls][1] += outcome == "accepted"
        if outcome in ("crashed", "hung", "nonsense"):
            print(f"{outcome.upper()}: drydem {' '.join(repr(x) for x in args)}\n    {why}")
    print("per class (tried / accepted): " +
          ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in sorted(by_class.items())))
    print(f"fuzz seed {a.seed}: tried {len(cases)} / crashed {counts['crashed']} / hung {counts['hung']} / "
          f"accepted-nonsense {counts['nonsense']} (accepted {counts['accepted']}, refused {counts['refused']})")
    return 1 if counts["crashed"] or counts["hung"] or counts["nonsense"] else 0


if __name__ == "__main__":
    sys.exit(main())
