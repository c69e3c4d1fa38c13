#!/usr/bin/env python3
"""Compares the error-against-time fronts of two `vct bench` runs over the same scenes: for each
point of the first run's front, the least time the second run's front needs for an error at least
as low, and the ratio. Timings move up to 2x between days on a shared machine, so both runs
should come from the same hour (for issue 13: the binary of the day it was filed, ba68095, built
in a worktree, and today's, run one after the other).

    python3 tools/compare_fronts.py OLD/bench.json NEW/bench.json [--scenes a,b,c]

A setting counts over the scenes both runs share (or those named): its time is the mean static
frame (GPU ms) and its error the geometric mean of full-light relMSE, as the bench's own front.
"""
import json
import math
import sys


def settings(results, scenes):
    by_setting = {}
    for result in results:
        if result["scene"] in scenes:
            by_setting.setdefault(result["setting"], []).append(result)
    points = []
    for name, results in by_setting.items():
        if len(results) != len(scenes):
            continue  # not measured on every scene
        time = sum(r["static"]["gpu_ms"] for r in results) / len(results)
        error = math.exp(sum(math.log(r["error"]["full"]["relmse"]) for r in results) / len(results))
        points.append((time, error, name))
    return sorted(points)


def front(points):
    kept, best = [], math.inf
    for time, error, name in points:
        if error < best:
            kept.append((time, error, name))
            best = error
    return kept


def main():
    args = sys.argv[1:]
    if len(args) not in (2, 4) or (len(args) == 4 and args[2] != "--scenes"):
        sys.exit(__doc__)
    old_results, new_results = (json.load(open(path))["results"] for path in args[:2])
    shared = {r["scene"] for r in old_results} & {r["scene"] for r in new_results}
    scenes = set(args[3].split(",")) if len(args) == 4 else shared
    old, new = front(settings(old_results, scenes)), front(settings(new_results, scenes))
    if not old or not new:
        sys.exit("no setting was measured on every scene of " + ", ".join(sorted(scenes)))
    print("scenes:", ", ".join(sorted(scenes)))
    for label, points in (("first run's front", old), ("second run's front", new)):
        print(label + ":")
        for time, error, name in points:
            print("  %8.2f ms  relMSE %.4f  %s" % (time, error, name))
    for time, error, _ in old:
        reaching = [t for t, e, _ in new if e <= error]
        if reaching:
            print("error <= %.4f: %.1f ms, then %.2f ms: %.1fx less time" % (error, time, min(reaching),
                                                                            time / min(reaching)))
        else:
            print("error <= %.4f: %.1f ms, not reached by the second run" % (error, time))


if __name__ == "__main__":
    main()
