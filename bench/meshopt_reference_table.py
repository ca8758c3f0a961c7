"""Table of scripts/bench-meshopt-reference.sh: per mesh, meshoptimizer's meshlet count and its own
loop's efficiencies beside conescope-cli's on the same meshlets read from the JSON and from the OBJ,
and the largest difference (the issue's bound is 0.002)."""
import json
import sys

rows_path, md_path = sys.argv[1], sys.argv[2]
TESTS = ["meshopt-apex-f32", "meshopt-sphere-s8"]
lines = [
    "# Engine tests against meshoptimizer's own loop",
    "",
    "meshoptimizer 0.18's meshlets at cone weight 1 (64/124), 64 orbit views at distance 3. `reference` is",
    "tests/reference/meshopt_reference (links only the library); `json` and `obj` are conescope-cli",
    "reading the meshlet JSON (with bounds) and the OBJ with an object per meshlet it wrote.",
    "",
    "| mesh | triangles | meshlets | clusters json / obj | apex-f32 reference | json | obj | sphere-s8 reference | json | obj | largest difference | same triangles culled | false culls (reference / ours) |",
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
]
worst = 0.0
for line in open(rows_path):
    row = json.loads(line)
    ref = row["reference"]
    ours = {kind: {r["test"]: r for r in row[kind]["results"]} for kind in ("json", "obj")}
    cells = [row["mesh"], str(row["json"]["mesh"]["faces"]), str(ref["meshlets"]),
             f'{row["json"]["clusters"]} / {row["obj"]["clusters"]}']
    difference, false_ref, false_ours, same = 0.0, 0, 0, True
    for test in TESTS:
        cells.append(f'{ref[test]["efficiency"]:.4f}')
        false_ref += ref[test]["false_culls"]
        for kind in ("json", "obj"):
            cells.append(f'{ours[kind][test]["efficiency"]:.4f}')
            difference = max(difference, abs(ours[kind][test]["efficiency"] - ref[test]["efficiency"]))
            false_ours += ours[kind][test]["false_culls"]
            same = same and ours[kind][test]["triangles_culled"] == ref[test]["triangles_culled"]
    cells += [f"{difference:.6f}", "yes" if same else "no", f"{false_ref} / {false_ours}"]
    worst = max(worst, difference)
    lines.append("| " + " | ".join(cells) + " |")
lines += ["", f"Largest difference over every mesh, test and file: {worst:.6f} (bound 0.002)."]
open(md_path, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
