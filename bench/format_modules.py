#!/usr/bin/env python3
"""What opening the format modules on demand (src/io/FormatModules.h) saves a conescope-cli run: the
median CPU time (user + system) of each command as built, against the same command with both modules
preloaded (LD_PRELOAD), which maps, relocates and initialises VTK's and assimp's libraries before
main as linking them would. Runs alternate between the two.

  bench/format_modules.py [BUILD_DIR] [RUNS]      # defaults: build, 20
"""
import os
import resource
import statistics
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def cpu_seconds(command, env):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def main():
    build = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    cli = os.path.join(build, "src", "cli", "conescope-cli")
    modules = " ".join(os.path.join(build, "src", "io", name)
                       for name in ("libconescope_vtk_formats.so", "libconescope_gltf_format.so"))
    output = os.path.join(build, "format-modules.json")
    commands = {"--version": [cli, "--version"]}
    for mesh in ("torus.off", "elephant.off"):
        commands[f"stats {mesh} --views 1"] = [cli, "stats", os.path.join(ROOT, "datasets", mesh), "--views", "1", "-o", output]
    print("| command | modules on demand (ms) | linked: modules preloaded (ms) | ratio |")
    print("|---|---:|---:|---:|")
    for name, command in commands.items():
        apart, linked = [], []
        for _ in range(runs):
            apart.append(cpu_seconds(command, dict(os.environ)))
            linked.append(cpu_seconds(command, dict(os.environ, LD_PRELOAD=modules)))
        a, b = statistics.median(apart), statistics.median(linked)
        print(f"| `{name}` | {1000 * a:.1f} | {1000 * b:.1f} | {b / a:.2f}x |")


if __name__ == "__main__":
    main()
