#!/usr/bin/env python3
"""Issue 37's "no part split twice in a row for the same reason", counted
from the logs of a bench/coverage.sh run (REPARAM_COVERAGE_LOGS=DIR): for
each mesh, the splits whose part was cut from a part split one level up for
the same reason (numbers in the reasons ignored), by reason, then the
totals. The layout does not depend on the mesh size: only the logs of the
bench's own size (MESH-map6.log) are read.

usage: bench/split-repeats.py LOGDIR
"""
import collections
import glob
import os
import re
import sys

SPLIT = re.compile(r"Reparam: - level (\d+) part of \d+ triangles split in "
                   r"\d+ parts because (.*)")


def repeats(path):
    """Same-reason splits one level below each other, by reason. The log
    lists a part's splits depth first (the layout cuts a part down before
    the next), so a split's parent is the last split one level up."""
    last = {}  # depth -> reason of the last split at that depth
    counts = collections.Counter()
    with open(path, errors="replace") as f:
        for line in f:
            m = SPLIT.search(line)
            if not m:
                continue
            depth = int(m.group(1))
            # the reason without numbers nor the cut's own remarks
            reason = re.sub(r" \((cut where|the cut moved).*$", "",
                            m.group(2).strip())
            reason = re.sub(r"[0-9][0-9.e+-]*", "N", reason)
            if last.get(depth - 1) == reason:
                counts[reason] += 1
            last[depth] = reason
            for d in [d for d in last if d > depth]:
                del last[d]
    return counts


def main(argv):
    logs = sorted(glob.glob(os.path.join(argv[1], "*-map6.log")))
    total = collections.Counter()
    print("| mesh | same-reason splits | of which \"conformal maps fold\" |")
    print("|---|---:|---:|")
    for path in logs:
        c = repeats(path)
        total.update(c)
        fold = sum(v for k, v in c.items() if "conformal maps fold" in k)
        name = os.path.basename(path)[: -len("-map6.log")]
        print("| %s | %d | %d |" % (name, sum(c.values()), fold))
    print()
    print("Total %d:" % sum(total.values()))
    for reason, n in total.most_common():
        print("- %d: %s" % (n, reason))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv)
