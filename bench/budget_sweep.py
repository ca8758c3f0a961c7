"""The budget sweep of scripts/bench-budget-sweep.sh: runs conescope-cli stats per mesh and budget,
and meshoptimizer's pipeline at several vertex limits, then writes one CSV row per run and a
Markdown table per mesh with the flags (over: more clusters made than asked; cliff: less culled at
a larger made count than the budget step before, by more than 2 %; "expected rises" when the
expected efficiency over view directions from afar, the builder's objective, did not drop by as much:
the step is then in what close eyes see)."""
import csv
import json
import os
import subprocess
import sys

FRACTIONS = [0.8, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2]
MESHOPT_VERTICES = [80, 72, 68, 64, 60, 56, 53]
COMMON = ["--views", "64", "--distance", "3", "--no-per-view", "--no-per-cluster", "--format", "json", "-q"]
MESHOPT = ["--builder", "meshopt", "--cone", "meshopt", "--test", "apex"]


def stats(cli, mesh, extra):
    run = subprocess.run([cli, "stats", mesh] + extra + COMMON, capture_output=True, text=True)
    if run.returncode:
        return None
    result = json.loads(run.stdout)
    return result["clusters"], result["results"][0]["efficiency"], result["results"][0]["expected_efficiency"]


def sweep(cli, mesh):
    """Rows of (side, asked, made, efficiency, expected efficiency), or None when the mesh does not read."""
    base = stats(cli, mesh, MESHOPT)
    if base is None:
        return None
    count = base[0]
    rows = []
    for vertices in MESHOPT_VERTICES:
        rows.append(("meshoptimizer", vertices) + stats(cli, mesh, MESHOPT + ["--max-verts", str(vertices)]))
    for fraction in FRACTIONS:
        asked = max(1, round(count * fraction))
        rows.append(("default", asked) + stats(cli, mesh, ["--clusters", str(asked)]))
    return count, base[1], rows


def flags(rows):
    found = []
    ours = [r for r in rows if r[0] == "default"]
    for i, (_, asked, made, efficiency, expected) in enumerate(ours):
        if made > asked:
            found.append(f"over {asked}->{made}")
        if i and made > ours[i - 1][2] and efficiency < ours[i - 1][3] * 0.98:
            fromAfar = " (expected rises)" if expected >= ours[i - 1][4] * 0.98 else ""
            found.append(f"cliff {ours[i - 1][2]}:{ours[i - 1][3]:.3f} -> {made}:{efficiency:.3f}{fromAfar}")
    return found


def main():
    cli, prefix, meshes = sys.argv[1], sys.argv[2], sys.argv[3:]
    table, records = [], []
    for mesh in meshes:
        name = os.path.basename(mesh)
        result = sweep(cli, mesh)
        if result is None:
            table.append(f"| {name} | does not read | | | |")
            continue
        count, efficiency, rows = result
        for side, asked, made, eff, expected in rows:
            records.append({"mesh": name, "side": side, "asked": asked, "made": made, "efficiency": eff,
                            "expected_efficiency": expected})
        ours = " ".join(f"{made}:{eff:.3f}" for side, _, made, eff, _ in rows if side == "default")
        theirs = " ".join(f"{made}:{eff:.3f}" for side, _, made, eff, _ in rows if side == "meshoptimizer")
        table.append(f"| {name} | {count}: {efficiency:.3f} | {ours} | {theirs} | {'; '.join(flags(rows))} |")
        print(table[-1], flush=True)
    with open(prefix + ".csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=["mesh", "side", "asked", "made", "efficiency", "expected_efficiency"])
        writer.writeheader()
        writer.writerows(records)
    cliffs = sum("cliff" in line for line in table)
    fromAfar = sum("cliff" in line and all("expected rises" in f for f in line.split("; ") if "cliff" in f) for line in table)
    overs = sum("over" in line for line in table)
    with open(prefix + ".md", "w") as out:
        out.write("# Budget sweep: the default at 0.8x to 1.2x meshoptimizer's count\n\n")
        out.write(f"{len(meshes)} meshes; {cliffs} with a cliff ({fromAfar} of them where the expected efficiency from afar does not drop), {overs} where a budget below the count the limits allow "
                  "made more clusters (with a warning). Cells are made clusters : efficiency (64 views, distance 3).\n\n")
        out.write("| mesh | meshoptimizer at 64/124 | default at 0.8x ... 1.2x its count | meshoptimizer at 80 ... 53 vertices | flags |\n")
        out.write("|---|---|---|---|---|\n")
        out.write("\n".join(table) + "\n")


if __name__ == "__main__":
    main()
