#!/usr/bin/python3
"""A* side by side (perf/README.md "A* side by side", issue 47 stage e).

Times agvbench's A* (`agvbench scen MAP SCEN --planner astar --param heuristic=octile`), the
plain binary-heap A* of perf/peers/plain_astar.cpp and, when given, warthog-core's A*
(`warthog --alg astar`, built from its public source outside this project; perf/README.md says
how) on every query of each MovingAI map's scenario file: the octile heuristic, 8-connected,
no corner cutting (MovingAI's and GPPC's rules). Per map: ROUNDS rounds, each running every
tool once (interleaved, so a slow spell of a shared machine falls on all of them); per tool the
median of (a) whole-process CPU less start-up (the same tool on the scenario's first query
alone, a search of a few cells: map loading and set-up; warthog refuses an empty scenario) and
(b) the tool's own timer over its searches. Then ours / theirs per map and the geometric mean
over the maps. Every tool's lengths are checked against the scenario optima
(relative 1e-5): a run that disagrees fails the script.

Usage: astar_side_by_side.py [--maps DIR] [--only MAP...] [--rounds N] [--agvbench BIN]
                             [--plain BIN] [--warthog BIN]
Without --warthog (or $WARTHOG_BIN) the warthog columns are left out, with a message.
"""
import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd):
    """(process CPU seconds, stdout) of one run; raises on a non-zero exit."""
    before = child_cpu()
    p = subprocess.run(cmd, capture_output=True, text=True)
    cpu = child_cpu() - before
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()[:300]}")
    return cpu, p.stdout


def ours(bin_, map_, scen):
    cpu, out = timed([bin_, "scen", map_, scen, "--planner", "astar", "--param",
                      "heuristic=octile", "--json"])
    doc = json.loads(out)
    return cpu, doc["timing"]["total_ns"] * 1e-9, doc["queries"], doc["mismatches"]


def plain(bin_, map_, scen):
    cpu, out = timed([bin_, map_, scen])
    f = out.split()
    return cpu, int(f[5]) * 1e-9, int(f[1]), int(f[3])


def warthog(bin_, map_, scen):
    cpu, out = timed([bin_, "--alg", "astar", "--scen", scen, "--map", map_])
    own, queries, mismatches = 0.0, 0, 0
    for line in out.splitlines()[1:]:  # id alg expanded generated reopen surplus heapops nanos plen pcost scost map
        f = line.split("\t")
        if len(f) < 11:
            continue
        own += int(f[7]) * 1e-9
        queries += 1
        pcost, scost = float(f[9]), float(f[10])
        mismatches += abs(pcost - scost) > 1e-5 * max(1.0, scost)
    return cpu, own, queries, mismatches


def first_query(scen, tmp):
    path = os.path.join(tmp, os.path.basename(scen))
    with open(scen) as f, open(path, "w") as out:
        out.write(f.readline() + f.readline())
    return path


def measure(tools, map_, scen, empty, rounds):
    """Per tool: (median CPU less the median start-up, median own time, queries). Each round
    runs every tool once, start-up run then the whole scenario, so that a slow spell of a shared
    machine falls on all the tools alike instead of on one tool's rounds."""
    startup = {n: [] for n, _, _ in tools}
    cpus = {n: [] for n, _, _ in tools}
    owns = {n: [] for n, _, _ in tools}
    queries = {}
    for _ in range(rounds):
        for n, tool, bin_ in tools:
            startup[n].append(tool(bin_, map_, empty)[0])
            cpu, own, queries[n], mismatches = tool(bin_, map_, scen)
            if mismatches:
                raise RuntimeError(f"{n}: {mismatches} of {queries[n]} lengths differ from the optima of {scen}")
            cpus[n].append(cpu)
            owns[n].append(own)
    med = statistics.median
    return {n: (med(cpus[n]) - med(startup[n]), med(owns[n]), queries[n]) for n, _, _ in tools}


def default_maps():
    env = os.environ.get("AGVBENCH_MOVINGAI_DIR")
    return env or os.path.normpath(os.path.join(ROOT, "..", "shared", "maps"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--maps", default=default_maps())
    ap.add_argument("--only", nargs="*", help="map file names (default: every .map with a .scen)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--agvbench", default=os.path.join(ROOT, "build", "agvbench"))
    ap.add_argument("--plain", default=os.path.join(ROOT, "build", "perf", "plain_astar"))
    ap.add_argument("--warthog", default=os.environ.get("WARTHOG_BIN"))
    args = ap.parse_args()
    if not os.path.isdir(args.maps):
        print(f"astar_side_by_side: no MovingAI maps in {args.maps} (--maps or AGVBENCH_MOVINGAI_DIR)")
        return 77
    maps = args.only or sorted(f for f in os.listdir(args.maps)
                               if f.endswith(".map") and os.path.exists(os.path.join(args.maps, f + ".scen")))
    tools = [("agvbench", ours, args.agvbench), ("plain", plain, args.plain)]
    if args.warthog:
        tools.append(("warthog", warthog, args.warthog))
    else:
        print("astar_side_by_side: no warthog build given (--warthog BIN or WARTHOG_BIN): "
              "its columns are left out")
    for name, _, bin_ in tools:
        if not os.access(bin_, os.X_OK):
            sys.exit(f"astar_side_by_side: {name}: no program at {bin_}")
    ratios = {(o, k): [] for o, _, _ in tools[1:] for k in ("cpu", "own")}
    print(f"{args.rounds} rounds a map, each running every tool once; medians; CPU less start-up / own timer, seconds\n")
    print("| map | queries | " + " | ".join(f"{n} CPU | {n} own" for n, _, _ in tools) + " | " +
          " | ".join(f"ours/{n} CPU | ours/{n} own" for n, _, _ in tools[1:]) + " |")
    print("| --- | ---: |" + " ---: | ---: |" * (len(tools) + len(tools) - 1))
    with tempfile.TemporaryDirectory() as tmp:
        for m in maps:
            map_, scen = os.path.join(args.maps, m), os.path.join(args.maps, m + ".scen")
            empty = first_query(scen, tmp)
            got = measure(tools, map_, scen, empty, args.rounds)
            cells = [f"{got[n][0]:.3f} | {got[n][1]:.3f}" for n, _, _ in tools]
            for n, _, _ in tools[1:]:
                rc, ro = got["agvbench"][0] / got[n][0], got["agvbench"][1] / got[n][1]
                ratios[(n, "cpu")].append(rc)
                ratios[(n, "own")].append(ro)
                cells.append(f"{rc:.2f} | {ro:.2f}")
            print(f"| {m} | {got['agvbench'][2]} | " + " | ".join(cells) + " |", flush=True)
    print()
    for (n, k), rs in ratios.items():
        geo = math.exp(sum(map(math.log, rs)) / len(rs))
        print(f"agvbench / {n}, {'CPU less start-up' if k == 'cpu' else 'own timer'}: geometric mean {geo:.2f} over {len(rs)} maps")
    return 0


if __name__ == "__main__":
    sys.exit(main())
