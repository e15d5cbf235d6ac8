#!/usr/bin/env python3
"""Prints the tables of bench/README.md from the JSON that rise_accel_bench
writes (--benchmark_format=json): rays per second by structure and mesh size,
build times, and RISE's BVH against Embree. Of repeated runs the best counts,
since the noise of a shared machine only ever adds time."""
import json
import sys


def best_runs(report):
    """The fastest run of each benchmark, by name: by processor time for the
    rays, traced on one thread; by wall-clock time for the builds, which use
    several."""
    best = {}
    for run in report["benchmarks"]:
        if run.get("run_type") == "aggregate":
            continue
        name = run["run_name"]
        time = "cpu_time" if name.startswith("primary_rays") else "real_time"
        if name not in best or run[time] < best[name][time]:
            best[name] = run
    return best


def mesh_order(mesh):
    return (mesh == "bunny", int(mesh.split("_")[1]) if "_" in mesh else 0)


def ray_table(runs):
    rates, triangles = {}, {}
    for name, run in runs.items():
        kind, accel, mesh = name.split("/")[:3]
        if kind != "primary_rays":
            continue
        rates[(accel, mesh)] = run
        triangles[mesh] = int(run["triangles"])
    accels = [a for a in ("none", "spheres", "bvh", "embree") if any(k[0] == a for k in rates)]
    meshes = sorted(triangles, key=mesh_order)
    print("Primary rays per second (millions, one thread); tests and boxes per ray for the BVH\n")
    print("| mesh | triangles | " + " | ".join(accels) + " | BVH tests / boxes | BVH / Embree |")
    print("|---" * (len(accels) + 4) + "|")
    for mesh in meshes:
        cells = []
        for accel in accels:
            run = rates.get((accel, mesh))
            cells.append(f"{run['rays_per_second'] / 1e6:.3f}" if run else "—")
        bvh, embree = rates.get(("bvh", mesh)), rates.get(("embree", mesh))
        work = f"{bvh['tests_per_ray']:.1f} / {bvh['nodes_per_ray']:.1f}" if bvh else "—"
        ratio = f"{bvh['rays_per_second'] / embree['rays_per_second']:.2f}" if bvh and embree else "—"
        print(f"| {mesh} | {triangles[mesh]:,} | " + " | ".join(cells) + f" | {work} | {ratio} |")


def build_table(runs):
    print("\nBuild time (seconds, wall clock)\n")
    print("| structure | mesh | triangles | threads | seconds |")
    print("|---|---|---|---|---|")
    for name, run in sorted(runs.items()):
        parts = name.split("/")
        if parts[0] != "build":
            continue
        seconds = run["real_time"] / 1e3 if run["time_unit"] == "ms" else run["real_time"]
        print(f"| {parts[1]} | {parts[2]} | {int(run['triangles']):,} | {int(run['threads'])} "
              f"| {seconds:.3f} |")


def main():
    with open(sys.argv[1]) as file:
        report = json.load(file)
    runs = best_runs(report)
    ray_table(runs)
    build_table(runs)


if __name__ == "__main__":
    main()
