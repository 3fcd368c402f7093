#!/usr/bin/env python3
"""Compares two autoplay JSON lines (the build tree's, the release's): equal means every key
and value is the same. Prints the game's seed and state hash when they are, else each
difference, and exits 1.

Usage: same_report.py TREE_LINE RELEASE_LINE
"""

import json
import sys


def main(argv):
    if len(argv) != 2:
        print("usage: same_report.py TREE_LINE RELEASE_LINE", file=sys.stderr)
        return 2
    reports = []
    for label, line in zip(("build tree", "release"), argv):
        try:
            report = json.loads(line)
        except ValueError:
            print("the %s printed no JSON line (%r)" % (label, line[:200]))
            return 1
        if not isinstance(report, dict) or "state_hash" not in report:
            print("the %s's JSON has no state_hash: %s" % (label, line[:200]))
            return 1
        reports.append(report)
    tree, release = reports
    if tree == release:
        print("seed %s, state_hash %s" % (tree.get("seed"), tree["state_hash"]))
        return 0
    for key in sorted(set(tree) | set(release)):
        if tree.get(key) != release.get(key):
            print("%s: build tree %r, release %r" % (key, tree.get(key), release.get(key)))
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
