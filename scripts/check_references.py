#!/usr/bin/python3
"""Fails when a reference tag cited in the repository is not defined inside it (issue 12: every
cited model section resolves from a clean clone).

Tags: M-x[.y] model sections, C-n modelling choices, I-n inconsistencies of the paper (all in
docs/model.md), V-n verification cases (docs/validation.md), D-x[.y] dryer-model sections
(docs/dryer.md). A tag is *defined* by a Markdown heading that contains it as a whole word, or by a
table row whose first cell starts with it (`| C-17 | ... |`, `| V-1 restitution | ... |`), in
docs/*.md or ARCHITECTURE.md. A tag is *cited* anywhere in the sources, tests, scripts, benches,
examples and documents. The design documents outside the repository must not be cited either (a
bare name such as scaling.md; a path inside the repository, like docs/calendering.md, is fine).
usage: check_references.py [REPO_DIR]   (ctest: `references`)
"""
import re
import sys
from pathlib import Path

TAG = re.compile(r"(?<![\w.\-/])([MCIVD]-\d+(?:\.\d+)?)(?![\w\-]|\.\d)")
OUTSIDE = re.compile(r"shared/(design|paper)|dryer_ref\.py|(?<![\w/])(interface|ecosystem|style|scaling|calendering|architecture)\.md")
CITING = ("src", "tests", "scripts", "bench", "examples", "docs", "cmake", ".ci")
SUFFIXES = {".cpp", ".hpp", ".h", ".def", ".py", ".sh", ".toml", ".md", ".txt", ".cmake", ""}
# The tags of the paper's own numbering are Eq./Fig./Table numbers, never these forms; the check
# script itself names the forms only in its docstring.
SKIP = {"scripts/check_references.py"}


def defined(repo: Path):
    tags = {}
    docs = sorted((repo / "docs").glob("*.md")) + [repo / "ARCHITECTURE.md"]
    for doc in docs:
        for n, line in enumerate(doc.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("#"):
                found = TAG.findall(line)
            elif line.startswith("|"):
                first = line.strip("|").split("|")[0].strip()
                found = TAG.findall(first.split(" ")[0]) if first else []
            else:
                continue
            for t in found:
                tags.setdefault(t, f"{doc.relative_to(repo)}:{n}")
    return tags


def citing_files(repo: Path):
    for top in [repo / "README.md", repo / "ARCHITECTURE.md", repo / "CMakeLists.txt"]:
        yield top
    for folder in CITING:
        for f in sorted((repo / folder).rglob("*")):
            if f.is_file() and f.suffix in SUFFIXES and "data" not in f.relative_to(repo).parts[:2]:
                yield f


def main():
    repo = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent)
    tags = defined(repo)
    missing, outside, cited = {}, [], 0
    for f in citing_files(repo):
        rel = f.relative_to(repo).as_posix()
        if rel in SKIP:
            continue
        for n, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            for t in TAG.findall(line):
                cited += 1
                if t not in tags:
                    missing.setdefault(t, f"{rel}:{n}")
            if OUTSIDE.search(line):
                outside.append(f"{rel}:{n}: {line.strip()[:100]}")
    for t, where in sorted(missing.items()):
        print(f"undefined tag {t} (first cited at {where}): define it in a heading or a tag table of docs/")
    for o in outside:
        print(f"cites a document outside the repository: {o}")
    print(f"{cited} citations of {len(tags)} defined tags; {len(missing)} undefined, {len(outside)} outside")
    return 1 if missing or outside else 0


if __name__ == "__main__":
    sys.exit(main())
