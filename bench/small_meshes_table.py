"""Table of scripts/bench-small-meshes.sh: per mesh, the default's preparation and whole stats run
as multiples of meshoptimizer's in the same run (the median over rounds), and geometric means."""
import math
import os
import statistics
import sys

runs_path, md_path, seconds = sys.argv[1], sys.argv[2], sys.argv[3]
prepare, whole, triangles = {}, {}, {}
mesh = None
for line in open(runs_path):
    if line.startswith("mesh: "):
        mesh = os.path.basename(line.split(",")[0][len("mesh: "):])
        triangles[mesh] = int(line.split(",")[1].split()[0])
    cells = [c.strip() for c in line.split("|")]
    if mesh is None or len(cells) < 9 or not cells[7].endswith("x"):
        continue
    if cells[1] == "ConeScope optimized, effort balanced":
        prepare.setdefault(mesh, []).append(float(cells[7][:-1]))
    elif cells[1] == "read + conescope-cli stats --views 1":
        whole.setdefault(mesh, []).append(float(cells[7][:-1]))


def geomean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


order = sorted(triangles, key=lambda m: triangles[m])
rows = [(m, triangles[m], statistics.median(prepare[m]), statistics.median(whole[m])) for m in order if m in prepare and m in whole]
with open(md_path, "w") as out:
    out.write("# Small and ordinary meshes: the default against meshoptimizer\n\n")
    out.write(f"`scripts/bench-small-meshes.sh`, {seconds} s. Wall time as a multiple of meshoptimizer's in the same run "
              "(median of 5 fresh processes; the median of three rounds). Preparation: world positions, face geometry, "
              "clusters, bounds and cull map against meshoptimizer's builder + bounds at cone weight 1. Whole run: "
              "read + `conescope-cli stats --views 1` against read + meshoptimizer's builder, bounds and one view.\n\n")
    out.write("| mesh | triangles | preparation | whole run |\n|---|---:|---:|---:|\n")
    for m, t, p, w in rows:
        out.write(f"| {m} | {t:,} | {p:.2f}x | {w:.2f}x |\n")
    for low, high, label in [(0, 5000, "2,000 to 5,000 triangles"), (5000, 20001, "5,000 to 20,000 triangles"), (0, 20001, "all")]:
        chosen = [r for r in rows if low <= r[1] < high]
        if chosen:
            out.write(f"| **geometric mean, {label}** ({len(chosen)}) | | **{geomean([r[2] for r in chosen]):.2f}x** | "
                      f"**{geomean([r[3] for r in chosen]):.2f}x** |\n")
