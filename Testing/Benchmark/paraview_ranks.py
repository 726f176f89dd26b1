"""The rank-scaling table: each ParaView entry on 1, 2 and 4 MPI ranks (a command, not a test).

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" python3 paraview_ranks.py <plugin> [--write-readme]

with PYTHONPATH set for pvbatch as paraview_time_series.py asks. Runs paraview_time_series.py's
value-only series (a deep copy of the mesh every step, the values changed) under
`mpiexec -np N pvbatch` for each entry and rank count: on several ranks once with the entry's
KeepRankPartitions on (the default: the wavelet's slabs form a partition and stay where they are)
and once off (ParaView redistributes every step, as before). Reports the median still frame, the
median value step and their ratio, each rank's resident memory after the steps, and the last step's
image against one rank's (compared by the pvbatch run itself: this process loads no VTK).
--write-readme writes RANKS.md beside this file.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("--mappers", default="preintegrated,barycentric,hexahedral")
parser.add_argument("--ranks", default="1,2,4")
parser.add_argument("--steps", type=int, default=3)
parser.add_argument("--size", type=int, default=384)
parser.add_argument("--pvbatch", default="pvbatch")
parser.add_argument("--mpiexec", default="mpiexec")
parser.add_argument("--mpiexec-flags", default="--allow-run-as-root --oversubscribe")
parser.add_argument("--out", default=os.path.join(HERE, "..", "..", "out", "ranks"))
parser.add_argument("--timeout", type=int, default=600, help="seconds a run")
parser.add_argument("--write-readme", action="store_true")
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)
results = os.path.join(args.out, "results.jsonl")
if os.path.exists(results):
    os.remove(results)


def run(mapper, ranks, keep):
    image = os.path.join(args.out, f"{mapper}_{ranks}ranks_{'kept' if keep else 'moved'}.png")
    command = [args.mpiexec, *args.mpiexec_flags.split(), "-np", str(ranks), args.pvbatch,
               os.path.join(HERE, "paraview_time_series.py"), args.plugin, mapper, "--kinds", "values",
               "--steps", str(args.steps), "--size", str(args.size), "--keep-partitions", str(keep),
               "--image", image, "--json", results]
    if ranks > 1 and images.get((mapper, 1, 1)):
        command += ["--compare-to", images[(mapper, 1, 1)]]
    start = time.perf_counter()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout,
                              stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        print(f"{mapper}, {ranks} rank(s), keep {keep}: over {args.timeout} s, left out", flush=True)
        return None
    lines = [line for line in done.stdout.splitlines() if line.startswith("values")]
    print(f"{mapper}, {ranks} rank(s), keep {keep}: {lines[-1] if lines else done.stderr[-800:]} "
          f"({time.perf_counter() - start:.0f} s)", flush=True)
    return image if done.returncode == 0 else None


started = datetime.datetime.now(datetime.timezone.utc)
ranks_list = [int(r) for r in args.ranks.split(",")]
images = {}
for mapper in args.mappers.split(","):
    for ranks in ranks_list:
        for keep in ([1, 0] if ranks > 1 else [1]):
            images[(mapper, ranks, keep)] = run(mapper, ranks, keep)

rows = [json.loads(line) for line in open(results, encoding="utf-8")]
for row in rows:
    solo = [r for r in rows if r["mapper"] == row["mapper"] and r["ranks"] == 1]
    row["still_speedup"] = solo[0]["static"] / row["static"] if solo else float("nan")

header = ("| entry | ranks | partition | still frame (s) | x 1 rank | value step (s) | step / still | "
          "resident MB per rank (largest) | image vs 1 rank: pixels > 2 levels off, largest |")
table = [header, "|---|---:|---|---:|---:|---:|---:|---:|---|"]
for row in rows:
    image = ("(itself)" if row["ranks"] == 1 else
             f"{100 * row['image_off']:.2f}%, {row['image_worst']}" if row.get("image_off") is not None else "n/a")
    table.append(f"| {row['entry']} | {row['ranks']} | {row['partition']} | {row['static']:.3f} | "
                 f"{row['still_speedup']:.2f} | {row['step']:.3f} | {row['step'] / row['static']:.2f} | "
                 f"{max(row['memory_mb']):.0f} | {image} |")
print("\n".join(table))
if not args.write_readme:
    sys.exit(0)

cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")), "?")
cells = rows[0]["cells"] if rows else 0
text = f"""# Ranks: 1, 2 and 4 MPI ranks in ParaView

Written by `Testing/Benchmark/paraview_ranks.py --write-readme` from one run; do not edit by hand, run
it again. Each row is one `mpiexec -np N pvbatch paraview_time_series.py` run.

- Run started: {started:%Y-%m-%d %H:%M} UTC; {len(os.sched_getaffinity(0))} logical CPUs ({cpu}), so
  4 ranks are oversubscribed: they share 2 cores and show what the partition choice costs, not a speed-up
- Host: {platform.platform()}; pvbatch: `{args.pvbatch}`; {args.size} x {args.size} px, {args.steps} value steps a run
- Series: paraview_time_series.py's value-only kind: every step a deep copy of the mesh with the values
  changed, the camera still. The tetrahedral entries get the wavelet tetrahedralised ({cells:,} cells
  in the first row), the hexahedral entry its voxels as unstructured hexahedra. The wavelet is a
  parallel source: each rank gets a z-slab.

Columns: the still frame is the median of re-rendering with nothing changed; the value step is the
median frame after a new step (ParaView's update, delivery, redistribution where chosen, the mapper's
refresh and drawing; producing the step's data is not counted). "pieces kept": the entry's default
(KeepRankPartitions) found the ranks' pieces apart and balanced and rendered them where they are;
"redistributed": KeepRankPartitions off, ParaView's k-d tree redistribution on every change of the
data, as before the option existed. Resident memory: each rank's after the steps (ParaView's memory
inspector's figure). The image is the last step's, against one rank's.

{chr(10).join(table)}
"""
with open(os.path.join(HERE, "RANKS.md"), "w", encoding="utf-8") as stream:
    stream.write(text)
print("wrote RANKS.md")
