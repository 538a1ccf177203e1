#!/usr/bin/python3
"""Fails on a function in src/drydem longer than LIMIT lines (issue 12: no function longer than a
screen), measured from its first to its last line by Universal Ctags (Debian's universal-ctags).
The few that are still longer are listed in KNOWN_EXCEPTIONS with the reason; an exception that
is no longer long must be removed from the list (the test fails), so the list only shrinks.
usage: check_function_length.py [SRC_DIR]   (ctest: `function_length`)
"""
import shutil
import subprocess
import sys
from pathlib import Path

LIMIT = 100

KNOWN_EXCEPTIONS = {
}


def functions(src: Path):
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        sys.exit("check_function_length: universal-ctags is missing (scripts/install_deps.sh)")
    out = subprocess.run([ctags, "-R", "--languages=C++", "--kinds-C++=f", "--fields=+ne", "-f", "-", str(src)],
                         capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split("\t")
        fields = dict(p.split(":", 1) for p in parts[3:] if ":" in p)
        if "line" in fields and "end" in fields:
            rel = Path(parts[1]).resolve().relative_to(src.resolve()).as_posix()
            yield rel, parts[0], int(fields["line"]), int(fields["end"]) - int(fields["line"]) + 1


def main():
    src = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "src" / "drydem")
    long = {}
    for rel, name, line, length in functions(src):
        if length > LIMIT:
            long[(rel, name)] = (line, length)
    failed = False
    for key, (line, length) in sorted(long.items()):
        if key in KNOWN_EXCEPTIONS:
            print(f"known: {key[0]}:{line} {key[1]} {length} lines ({KNOWN_EXCEPTIONS[key]})")
        else:
            print(f"TOO LONG: {key[0]}:{line} {key[1]} has {length} lines (limit {LIMIT}): split it")
            failed = True
    for key in KNOWN_EXCEPTIONS:
        if key not in long:
            print(f"STALE EXCEPTION: {key[0]} {key[1]} is no longer over {LIMIT} lines: remove it from the list")
            failed = True
    print("function length " + ("FAILED" if failed else "OK"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
