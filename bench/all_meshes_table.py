"""Table of scripts/bench-all-meshes.sh: one row per mesh, ratios of culled back faces (default over
meshoptimizer's pipeline) at equal cluster counts, geometric means, and the meshes that did not read."""
import csv
import json
import math
import sys

rows_path, csv_path, md_path, seconds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
rows = [json.loads(line) for line in open(rows_path) if line.strip()]
measured = [r for r in rows if "diff" in r]
failed = [r for r in rows if "error" in r]


def ratio(r):
    a, b = r["diff"]["efficiency_a"], r["diff"]["efficiency_b"]
    return b / a if a > 0 else math.inf


with open(csv_path, "w", newline="") as out:
    writer = csv.writer(out)
    writer.writerow(["mesh", "triangles", "components", "clusters_meshopt", "clusters_default", "efficiency_meshopt",
                     "efficiency_default", "ratio", "culled_only_meshopt", "culled_only_default",
                     "mean_sphere_radius_meshopt", "mean_sphere_radius_default", "cull_fraction_default",
                     "oracle_fraction_default"])
    for r in measured:
        d = r["diff"]
        writer.writerow([r["mesh"], r["triangles"], r["components"], d["clusters_a"], d["clusters_b"], d["efficiency_a"],
                         d["efficiency_b"], ratio(r), d["triangles_culled_only_a"], d["triangles_culled_only_b"],
                         r["radius_a"], r["radius_b"], r["cull_b"], r["oracle_b"]])

# Geometric means over the meshes where both cull something (a ratio of zero or infinity has no mean).
finite = [r for r in measured if r["diff"]["efficiency_a"] > 0 and r["diff"]["efficiency_b"] > 0]
geomean = math.exp(sum(math.log(ratio(r)) for r in finite) / len(finite)) if finite else float("nan")
multi = [r for r in finite if r["components"] > 1]
geomean_multi = math.exp(sum(math.log(ratio(r)) for r in multi) / len(multi)) if multi else float("nan")
unequal = [r for r in measured if r["diff"]["cluster_count_warning"]]
losing = sorted([r for r in finite if ratio(r) < 1.0], key=ratio)
radius = [r["radius_b"] / r["radius_a"] for r in measured if r["radius_a"] > 0]
# How close the default test gets to the per-partition oracle, view-independently (CullMap.h).
closeness = [r["cull_b"] / r["oracle_b"] for r in measured if r["oracle_b"] > 0 and r["cull_b"] > 0]
closeness_mean = math.exp(sum(math.log(x) for x in closeness) / len(closeness)) if closeness else float("nan")
radius_mean = math.exp(sum(math.log(x) for x in radius) / len(radius)) if radius else float("nan")

with open(md_path, "w") as md:
    md.write("# Every CGAL demo mesh: default pipeline against meshoptimizer's\n\n")
    md.write(f"`scripts/bench-all-meshes.sh`, {len(rows)} files, {len(measured)} measured, {seconds} s. 64 orbit views "
             "at distance 3, limits 64/124; A = meshoptimizer's builder, cone and apex test (cone weight 1), "
             "B = the defaults (optimized builder at meshoptimizer's count, minimal cone, apex test).\n\n")
    md.write(f"- Geometric mean of culled back faces, default / meshoptimizer: **{geomean:.3f}x** over "
             f"{len(finite)} meshes where both cull something; {geomean_multi:.3f}x over the {len(multi)} multi-part ones.\n")
    md.write(f"- Meshes where the default culls less: {len(losing)}"
             + (": " + ", ".join(f"{r['mesh']} ({ratio(r):.3f}x)" for r in losing) if losing else "") + ".\n")
    md.write(f"- Cluster counts more than 5% apart: {len(unequal)}"
             + (": " + ", ".join(f"{r['mesh']} ({r['diff']['clusters_b']} vs {r['diff']['clusters_a']})" for r in unequal) if unequal else "")
             + ".\n")
    md.write(f"- Mean bounding-sphere radius, default / meshoptimizer (geometric mean of the per-mesh ratio): {radius_mean:.3f}.\n")
    md.write(f"- The default test against the per-partition oracle, view-independent (cull_fraction / "
             f"oracle_fraction, geometric mean over {len(closeness)} meshes): {closeness_mean:.3f}.\n")
    if failed:
        md.write(f"- Not measured ({len(failed)}): " + "; ".join(f"{r['mesh']}: {r['error']}" for r in failed) + "\n")
    md.write("\n| mesh | triangles | parts | clusters (meshopt / default) | efficiency meshopt | default | ratio | sphere radius ratio |\n")
    md.write("|---|---:|---:|---:|---:|---:|---:|---:|\n")
    for r in sorted(measured, key=lambda r: r["mesh"].lower()):
        d = r["diff"]
        rr = f"{ratio(r):.3f}" if math.isfinite(ratio(r)) else "-"
        radius_ratio = f"{r['radius_b'] / r['radius_a']:.3f}" if r["radius_a"] > 0 else "-"
        md.write(f"| {r['mesh']} | {r['triangles']} | {r['components']} | {d['clusters_a']} / {d['clusters_b']} | "
                 f"{d['efficiency_a']:.4f} | {d['efficiency_b']:.4f} | {rr} | {radius_ratio} |\n")
