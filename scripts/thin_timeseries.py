#!/usr/bin/python3
"""Copy a run's timeseries.csv with at most ~500 of its rows (every n-th, the last row always kept):
the archived studies in docs/data keep the curve's shape (Fig. 5, the jamming point) at a
thousandth of its size.
usage: /usr/bin/python3 scripts/thin_timeseries.py SOURCE.csv DEST.csv [ROWS]"""
import sys


def thin(rows, target):
    head, body = rows[0], rows[1:]
    stride = max(1, -(-len(body) // target))
    kept = body[::stride]
    if body and kept[-1] != body[-1]:
        kept.append(body[-1])
    return [head] + kept


if __name__ == "__main__":
    target = int(sys.argv[3]) if len(sys.argv) > 3 else 500
    rows = open(sys.argv[1]).read().splitlines()
    open(sys.argv[2], "w").write("\n".join(thin(rows, target)) + "\n")
