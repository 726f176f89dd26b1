#!/usr/bin/env python3
"""How each mapper scales with the mesh: 1e4 to 1e7 tetrahedra, 1e4 to 2e6 hexahedra (a command, not a
test: timings are never asserted).

    PYTHONPATH=build/vtk/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \\
        /usr/bin/python3 Testing/Benchmark/scale.py [--output out/scale] [--write-readme]

The wavelet (vtkRTAnalyticSource on (2R)^3 cells, its field normalised to the extent, so every size
shows the same picture) split into five tetrahedra per cell (vtkHexahedraToTetrahedra) for VTK's
projected tetrahedra, the tetrahedra mapper, the shells and the cell projection; the same wavelet's
cells as an unstructured grid (vtkAppendFilter: voxels) for the hexahedral ray caster.

Every (mesh, mapper) runs in its own process (this script with --run), so that its peak resident
memory is its own: VmHWM at the end minus VmHWM right after building the mesh (the mapper's peak),
and VmHWM itself (the process's). Each process renders, through benchmark.run_mapper, a first frame
(its time less a second frame at the same view is the preparation) and 3 more views of an orbit
(their median is the frame time), 256x256 px. Host bytes per cell are the mapper's
GetHostMemoryInBytes where it has one, else the resident memory its first frame added; GPU bytes
per cell are GetMeshMemoryInBytes. A process that runs past its time limit, goes over the memory
cap (the parent watches its VmRSS: the machine is shared), or dies, is recorded as such: the
largest mesh each mapper renders is a result.

Order: every mapper on the smallest mesh first (a smoke test of the whole chain), then the largest
meshes (so their limits are known early), then the rest. Writes results.json (after every run, so
--resume continues an interrupted run), results.md and scale.png (log-log preparation, frame time
and the mapper's peak memory against cells, with the slope fitted from 1e5 cells up) to --output.
--write-readme also writes Testing/Benchmark/SCALE.md and scale.png beside it: a file of its own,
because benchmark.py --write-readme rewrites Testing/Benchmark/README.md whole (its text links here).
"""
import argparse
import json
import math
import os
import shutil
import signal
import statistics
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Benchmark"))
import benchmark  # noqa: E402
import time_series  # noqa: E402

MAPPERS = {"tets": time_series.TETRAHEDRAL_MAPPERS, "hexahedra": time_series.HEXAHEDRAL_MAPPERS}
# Half the cells per side, R, of each mesh: five tetrahedra per cell of (2R)^3, or (2R)^3 hexahedra.
SIZES = {"tets": (6, 14, 29, 63), "hexahedra": (11, 23, 50, 63)}
# --limit: the 256^3 wavelet (83.9 M tetrahedra, 16.8 M hexahedra), this project's mappers only, one
# view drawn twice (preparation, then the frame). Its rows go to a section of SCALE.md of their own.
LIMIT_HALF = 128
LIMIT_BEGIN, LIMIT_END = "<!-- limit run: begin -->", "<!-- limit run: end -->"
SIZE_PX = 256
FIT_FROM = 8e4  # slopes from about 1e5 cells up: below, fixed costs (a GL context) dominate
README_SCALE = os.path.join(ROOT, "Testing", "Benchmark", "SCALE.md")


def limit_section(rows, run):
    """SCALE.md's section on the limit mesh, between its markers."""
    machine = run["machine"]
    return "\n".join([
        LIMIT_BEGIN,
        "## At the limit: the 256^3 wavelet",
        "",
        f"Written by `{run['command']}`" + "".join(f"; resumed by `{again}`" for again in run["resumed"]) +
        f" on {run['started']} (load average {machine['load']}; limits: {machine['limits']}).",
        "Each of this project's mappers on the 256^3 wavelet: 83.9 M tetrahedra (split in five) and 16.8 M",
        "hexahedra, and a larger mesh past a limit. One view drawn twice: preparation as above, the frame is",
        "the second. The status gives the pixels the frame drew (a mapper that cannot draw the mesh must say",
        "so in one error and draw nothing: its error is then the status).",
        "",
        markdown_table(rows).rstrip("\n"),
        LIMIT_END,
    ])


def with_limit_section(text, section):
    """`text` (SCALE.md) with its limit section replaced by `section`, or `section` added at its end."""
    if LIMIT_BEGIN in text and LIMIT_END in text:
        head, rest = text.split(LIMIT_BEGIN, 1)
        return head + section + rest.split(LIMIT_END, 1)[1]
    return text.rstrip("\n") + "\n\n" + section + "\n"


def cells_of(kind, half):
    return (5 if kind == "tets" else 1) * (2 * half) ** 3


def status_megabytes(field):
    """A memory field of /proc/self/status (VmRSS, VmHWM), in MB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


# ---------------------------------------------------------------------------------------------
# One (mesh, mapper) in this process.
def run_one(kind, half, name, views=4):
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)  # a mapper's error is the run's result, not only a log line
    factory = dict(MAPPERS[kind])[name]
    start = time.perf_counter()
    mesh = time_series.wavelet_grid(half, kind == "tets")
    build = time.perf_counter() - start
    mesh_hwm, mesh_rss = status_megabytes("VmHWM"), status_megabytes("VmRSS")
    print(f"STAGE mesh {mesh.GetNumberOfCells()} cells in {build:.1f} s, {mesh_rss:.0f} MB", flush=True)
    prop, _, _ = benchmark.volume_property(mesh, "RTData", benchmark.smooth_ramp, 0.05)
    orbit = benchmark.orbit(mesh, views)
    # The first view twice: the first frame less the second is the preparation; then the other views.
    cameras = [orbit[0]] + orbit
    # Skipping counts are not wanted here, and counting costs the tetrahedra mapper an extra frame.
    benchmark.work_done = lambda *args: {}
    first, frames, memory, images, (mesh_bytes, host_bytes), _ = benchmark.run_mapper(
        name, factory, mesh, "RTData", prop, cameras, SIZE_PX)
    # A frame that draws nothing is no frame: the pixels the last image covers.
    alpha = images[-1].GetPointData().GetScalars()
    covered = sum(1 for p in range(alpha.GetNumberOfTuples()) if alpha.GetComponent(p, 3) > 0.01)
    cells = mesh.GetNumberOfCells()
    # VTK's error text: "ERROR: In <file>, line <n>", then "<class> (<address>): <message>".
    lines = messages.GetOutput().splitlines()
    errors = [lines[i + 1].split("): ", 1)[-1] for i, line in enumerate(lines[:-1]) if line.startswith("ERROR")]
    return {
        "kind": kind, "half": half, "cells": cells, "mapper": name,
        "status": "ok" if not errors else f"error ({len(errors)}): {errors[0][:300]}",
        "covered_px": covered, "build_s": build, "first_s": first, "preparation_s": max(first - frames[0], 0.0),
        "frame_s": statistics.median(frames[1:] or frames), "frames_s": frames,
        "host_bytes_per_cell": (host_bytes if host_bytes is not None else memory * 2**20) / cells,
        "host_counted": host_bytes is not None,
        "gpu_bytes_per_cell": None if mesh_bytes is None else mesh_bytes / cells,
        "mesh_rss_mb": mesh_rss, "peak_rss_mb": status_megabytes("VmHWM"),
        "mapper_peak_mb": status_megabytes("VmHWM") - mesh_hwm,
    }


# ---------------------------------------------------------------------------------------------
# The parent: one process per run, watched.
def watch(command, log_path, limit_s, cap_mb):
    """Runs `command` with stdout and stderr to `log_path`; kills it past `limit_s` seconds or `cap_mb`
    MB resident. Returns (status, seconds, peak MB seen, its RESULT line or None)."""
    with open(log_path, "w") as log:
        child = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT)
        start, seen, status = time.monotonic(), 0.0, None
        while child.poll() is None:
            try:
                with open(f"/proc/{child.pid}/status") as proc:
                    rss = next((int(line.split()[1]) / 1024.0 for line in proc if line.startswith("VmRSS:")), 0.0)
                seen = max(seen, rss)
            except (OSError, StopIteration):
                pass
            if time.monotonic() - start > limit_s:
                status = f"timeout (> {limit_s:.0f} s)"
            elif seen > cap_mb:
                status = f"over the memory cap ({cap_mb / 1024:g} GB)"
            if status:
                child.kill()
                child.wait()
                break
            time.sleep(0.5)
        seconds = time.monotonic() - start
    with open(log_path) as log:
        text = log.read()
    result = next((line[len("RESULT "):] for line in text.splitlines() if line.startswith("RESULT ")), None)
    if status is None and child.returncode != 0:
        if child.returncode < 0:
            signame = signal.Signals(-child.returncode).name
            status = f"crash ({signame}{': out of memory?' if signame == 'SIGKILL' else ''})"
        else:
            lines = [line for line in text.splitlines() if line.strip()]
            status = f"crash (exit {child.returncode}: {lines[-1][:80] if lines else 'no output'})"
    stages = [line[len("STAGE "):] for line in text.splitlines() if line.startswith("STAGE ")]
    if status and stages:
        status += f", after {stages[-1]}"
    return status, seconds, seen, result


def planned_runs(kinds, mappers_wanted, limit=None):
    """(kind, R, mapper) in the order run: smallest meshes, largest, then the rest from small up; with
    `limit` (an R), this project's mappers on that mesh only."""
    if limit:
        return [(kind, limit, name) for kind in kinds for name, _ in MAPPERS[kind] if name.startswith("UV")
                and (not mappers_wanted or any(w in name for w in mappers_wanted))]
    runs = {}
    for kind in kinds:
        for name, _ in MAPPERS[kind]:
            if mappers_wanted and not any(w in name for w in mappers_wanted):
                continue
            sizes = SIZES[kind]
            runs.setdefault(0, []).append((kind, sizes[0], name))
            runs.setdefault(1, []).append((kind, sizes[-1], name))
            runs.setdefault(2, []).extend((kind, half, name) for half in sizes[1:-1])
    return [run for stage in sorted(runs) for run in runs[stage]]


def fitted_slope(points):
    """Least-squares slope of log y against log x (None with fewer than two positive points)."""
    points = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y and y > 0]
    if len(points) < 2:
        return None
    mx = statistics.mean(x for x, _ in points)
    my = statistics.mean(y for _, y in points)
    sxx = sum((x - mx) ** 2 for x, _ in points)
    return sum((x - mx) * (y - my) for x, y in points) / sxx if sxx else None


METRICS = (("preparation_s", "preparation (s)"), ("frame_s", "median frame (s)"),
           ("mapper_peak_mb", "mapper's peak resident memory (MB)"))


def slopes(rows):
    """{(kind, mapper): {metric: slope}} over the runs from FIT_FROM cells up that finished."""
    found = {}
    for key in dict.fromkeys((r["kind"], r["mapper"]) for r in rows):
        done = [r for r in rows if (r["kind"], r["mapper"]) == key and r["status"] == "ok" and r["cells"] >= FIT_FROM]
        found[key] = {metric: fitted_slope([(r["cells"], r[metric]) for r in done]) for metric, _ in METRICS}
    return found


def top_slopes(rows):
    """{(kind, mapper): {metric: slope}} between the two largest meshes that finished: fixed costs (a GL
    context, shader compilation) flatten the fit, the largest step is nearest the asymptote."""
    found = {}
    for key in dict.fromkeys((r["kind"], r["mapper"]) for r in rows):
        done = sorted((r for r in rows if (r["kind"], r["mapper"]) == key and r["status"] == "ok"),
                      key=lambda r: r["cells"])[-2:]
        found[key] = {metric: fitted_slope([(r["cells"], r[metric]) for r in done]) if len(done) == 2 else None
                      for metric, _ in METRICS}
    return found


def largest(rows):
    """{(kind, mapper): the largest mesh's cells it rendered, or None}."""
    found = {}
    for r in rows:
        best = found.get((r["kind"], r["mapper"]))
        if r["status"].startswith("ok") and (best is None or r["cells"] > best):
            best = r["cells"]
        found[(r["kind"], r["mapper"])] = best
    return found


def markdown_table(rows):
    lines = ["| cells | mapper | prep (s) | frame (s) | host B/cell | GPU B/cell | peak RSS (MB) | mapper's peak (MB) "
             "| mesh build (s) | status |",
             "|---:|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    order = [name for kind in MAPPERS for name, _ in MAPPERS[kind]]
    for r in sorted(rows, key=lambda r: (order.index(r["mapper"]), r["cells"])):
        unit = "tets" if r["kind"] == "tets" else "hex"
        if not r["status"].startswith("ok"):
            seen = f"{r['watched_peak_mb']:.0f} (seen)" if r.get("watched_peak_mb") else ""
            lines.append(f"| {r['cells']:,} {unit} | {r['mapper']} | | | | | {seen} | | | {r['status']} |")
            continue
        host = f"{r['host_bytes_per_cell']:.0f}" + ("" if r["host_counted"] else " (RSS)")
        gpu = "" if r["gpu_bytes_per_cell"] is None else f"{r['gpu_bytes_per_cell']:.0f}"
        lines.append(f"| {r['cells']:,} {unit} | {r['mapper']} | {r['preparation_s']:.3f} | {r['frame_s']:.3f} | "
                     f"{host} | {gpu} | {r['peak_rss_mb']:.0f} | {r['mapper_peak_mb']:.0f} | {r['build_s']:.1f} | {r['status']} |")
    return "\n".join(lines) + "\n"


def slope_lines(rows):
    def text(slope):
        return "n/a" if slope is None else f"{slope:.2f}" + (" (above 1.1)" if slope > 1.1 else "")

    lines, top = [], top_slopes(rows)
    for (kind, mapper), found in slopes(rows).items():
        parts = [f"{label.split(' (')[0]} {text(found[metric])} (largest step {text(top[(kind, mapper)][metric])})"
                 for metric, label in METRICS]
        lines.append(f"- {mapper} ({kind}): " + "; ".join(parts))
    return lines


def largest_lines(rows):
    lines = []
    for (kind, mapper), cells in largest(rows).items():
        failed = [r for r in rows if (r["kind"], r["mapper"]) == (kind, mapper) and r["status"] != "ok"]
        note = "; ".join(f"{r['cells']:,}: {r['status']}" for r in failed)
        lines.append(f"- {mapper}: {'none' if cells is None else f'{cells:,} {kind}'}" + (f" ({note})" if note else ""))
    return lines


def plot(rows, path):
    """Log-log preparation, frame time and the mapper's peak memory against cells; None without matplotlib."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    found = slopes(rows)
    figure, axes = plt.subplots(1, len(METRICS), figsize=(13.5, 4.2), dpi=80)
    for axis, (metric, label) in zip(axes, METRICS):
        for key in dict.fromkeys((r["kind"], r["mapper"]) for r in rows):
            done = sorted((r["cells"], r[metric]) for r in rows
                          if (r["kind"], r["mapper"]) == key and r["status"] == "ok" and r[metric] > 0)
            if not done:
                continue
            slope = found[key][metric]
            axis.plot(*zip(*done), marker="o", markersize=4,
                      label=f"{key[1]}" + ("" if slope is None else f" (slope {slope:.2f})"))
        axis.set_xscale("log")
        axis.set_yscale("log")
        low, high = axis.get_xlim()
        if all(math.isfinite(v) and v > 0 for v in (low, high)):
            # A guide of slope 1 through the middle of the panel.
            ylow, yhigh = axis.get_ylim()
            middle_x, middle_y = math.sqrt(low * high), math.sqrt(ylow * yhigh)
            axis.plot([low, high], [middle_y * low / middle_x, middle_y * high / middle_x], "k:", linewidth=1,
                      label="slope 1")
            axis.set_xlim(low, high)
            axis.set_ylim(ylow, yhigh)
        axis.set_xlabel("cells")
        axis.set_title(label, fontsize=10)
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=6.5)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)
    return path


def scale_text(rows, run, plotted):
    machine = run["machine"]
    renderer, version = machine["opengl"]
    smallest = [r for r in rows if r["status"] == "ok" and r["half"] == SIZES[r["kind"]][0]]
    fixed_mb = min((r["mapper_peak_mb"] for r in smallest), default=float("nan"))
    out = [
        "# Scale: 1e4 to 1e7 cells",
        "",
        "Written by `Testing/Benchmark/scale.py --write-readme` from one run; do not edit by hand, run it again.",
        "Each (mesh, mapper) ran in its own process, one at a time. The numbers are this machine's, which is",
        "shared: other work ran beside it (the load average below), so times carry noise.",
        "",
        f"- Command: `{run['command']}`" + "".join(f"; resumed by `{again}`" for again in run["resumed"]),
        f"- Run started: {run['started']}; load average at the start: {machine['load']}",
        f"- CPU: {machine['cpu']} ({machine['cpus']} logical CPUs); memory {machine['memory_gb']:.0f} GB",
        f"- OpenGL renderer: {renderer}; OpenGL version: {version}; VTK {machine['vtk']}",
        f"- Images: {SIZE_PX}x{SIZE_PX} px; limits: {machine['limits']}",
        "",
        "The wavelet on (2R)^3 cells: five tetrahedra per cell for VTK's projected tetrahedra and this",
        "project's tetrahedra mapper, shells (128 samples across) and cell projection; the cells themselves",
        "(voxels in an unstructured grid) for the hexahedral ray caster. Per run: preparation (the first",
        "frame less a second frame at the same view), the median frame over 3 further views of an orbit,",
        "host bytes per cell (GetHostMemoryInBytes; \"(RSS)\": the resident memory the first frame added, GL",
        "context included, for mappers that do not count theirs), GPU bytes per cell (GetMeshMemoryInBytes),",
        "the process's peak resident memory (VmHWM, the mesh included), the mapper's peak (VmHWM less VmHWM",
        "right after building the mesh) and the mesh's build time (not counted in the others). A run that",
        "did not finish shows the peak its parent saw and why it stopped.",
        "",
        markdown_table(rows).rstrip("\n"),
        "",
        f"## Slopes (log-log least squares from {FIT_FROM:.0e} cells up, and between the two largest meshes)",
        "",
        "n log n has slope 1 + 1/ln n, about 1.07 here: the issue asks for at most about 1.1. The mapper's peak",
        "carries a fixed part (the GL context and what the first frame loads: most of the",
        f"{fixed_mb:.0f} MB the smallest mesh takes), which flattens its slope.",
        "",
        *slope_lines(rows),
        "",
        "## Largest mesh each mapper rendered",
        "",
        *largest_lines(rows),
        "",
    ]
    out += (["![preparation, frame time and peak memory against cells](scale.png)", ""] if plotted
            else ["No plot: matplotlib is not importable by this Python.", ""])
    return "\n".join(out)


def machine_info(args):
    with open("/proc/loadavg") as load, open("/proc/meminfo") as meminfo:
        loads = " ".join(load.read().split()[:3])
        total_kb = int(meminfo.readline().split()[1])
    return {"cpu": benchmark.cpu_model(), "cpus": os.cpu_count(), "opengl": benchmark.opengl_strings(),
            "vtk": benchmark.vtkVersion.GetVTKVersion(), "load": loads, "memory_gb": total_kb / 2**20,
            "limits": f"{args.timeout:.0f} s a run ({args.large_timeout:.0f} s on the largest meshes), "
                      f"{args.memory_cap_gb:g} GB resident a run, {args.budget_minutes:g} minutes in all"}


def resumed_run(args, results_path, run_path):
    """The rows already run (with --resume) and the run's record, written back to run_path."""
    rows, run = [], None
    if args.resume and os.path.exists(results_path):
        with open(results_path) as saved:
            rows = json.load(saved)
        if os.path.exists(run_path):
            with open(run_path) as saved:
                run = json.load(saved)
            run["resumed"] = list(dict.fromkeys(run.get("resumed", []) + [benchmark.run_command()]))
    if run is None:
        # What the page says of the run: the first command's, not a resumption's.
        run = {"command": benchmark.run_command(), "started": time.strftime("%Y-%m-%d %H:%M %Z"),
               "machine": machine_info(args), "resumed": []}
    with open(run_path, "w") as out:
        json.dump(run, out, indent=1)
    return rows, run


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output", default=os.path.join(ROOT, "out", "scale"))
    parser.add_argument("--timeout", type=float, default=900, help="seconds a run may take")
    parser.add_argument("--large-timeout", type=float, default=None,
                        help="seconds a run on the largest meshes may take (default: --timeout)")
    parser.add_argument("--memory-cap-gb", type=float, default=12, help="resident memory a run may take")
    parser.add_argument("--budget-minutes", type=float, default=45,
                        help="no run starts after this, and none runs past it")
    parser.add_argument("--kinds", default="tets,hexahedra")
    parser.add_argument("--mappers", default=None, help="comma-separated substrings of mapper names")
    parser.add_argument("--resume", action="store_true", help="keep the runs of --output's results.json")
    parser.add_argument("--write-readme", nargs="?", const=README_SCALE, default=None, metavar="PATH",
                        help=f"also write this run's page (default {os.path.relpath(README_SCALE, ROOT)}) "
                             "and its plot beside it")
    parser.add_argument("--limit", nargs="?", type=int, const=LIMIT_HALF, default=None, metavar="R",
                        help=f"this project's mappers on the (2R)^3 wavelet only (default R {LIMIT_HALF}: 256^3), "
                             "into SCALE.md's limit section (--resume adds to it)")
    parser.add_argument("--run", nargs=3, metavar=("KIND", "R", "MAPPER"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.limit and args.output == parser.get_default("output"):
        args.output += "-limit"
    args.large_timeout = args.large_timeout or args.timeout
    return args


def main():
    args = parse_arguments()
    if args.run:
        half = int(args.run[1])
        views = 1 if half >= LIMIT_HALF else 4
        print("RESULT " + json.dumps(run_one(args.run[0], half, args.run[2], views)), flush=True)
        return
    os.makedirs(os.path.join(args.output, "logs"), exist_ok=True)
    results_path, run_path = os.path.join(args.output, "results.json"), os.path.join(args.output, "run.json")
    rows, run = resumed_run(args, results_path, run_path)
    done = {(r["kind"], r["half"], r["mapper"]) for r in rows}
    deadline = time.monotonic() + 60 * args.budget_minutes
    wanted = args.mappers.split(",") if args.mappers else None
    for kind, half, name in planned_runs(args.kinds.split(","), wanted, args.limit):
        if (kind, half, name) in done:
            continue
        cells = cells_of(kind, half)
        failed_smaller = [r for r in rows if (r["kind"], r["mapper"]) == (kind, name) and not r["status"].startswith("ok")
                          and r["cells"] < cells and not r["status"].startswith("not run")]
        left = deadline - time.monotonic()
        limit = min(args.large_timeout if half >= SIZES[kind][-1] else args.timeout, left)
        if failed_smaller:
            status, seconds, seen, result = f"not run ({failed_smaller[0]['cells']:,} failed)", 0.0, 0.0, None
        elif left < 10:
            status, seconds, seen, result = "not run (time budget spent)", 0.0, 0.0, None
        else:
            print(f"{cells:>10,} {kind:9s} {name:30s} (limit {limit:.0f} s) ...", end=" ", flush=True)
            log = os.path.join(args.output, "logs", f"{kind}_{cells}_{name.replace(' ', '_')}.log")
            status, seconds, seen, result = watch([sys.executable, os.path.abspath(__file__), "--run", kind,
                                                   str(half), name], log, limit, 1024 * args.memory_cap_gb)
        reported = json.loads(result) if result else None
        if reported and status is None and not reported["status"].startswith("error"):
            row = reported
            if args.limit:
                row["status"] = f"ok, {row.get('covered_px', 0):,} of {SIZE_PX ** 2:,} px drawn"
            print(f"prep {row['preparation_s']:.3f} s, frame {row['frame_s']:.3f} s, peak {row['peak_rss_mb']:.0f} MB "
                  f"(mapper {row['mapper_peak_mb']:.0f}), {seconds:.0f} s in all", flush=True)
        else:
            status = status or (reported["status"] if reported else None)
            row = {"kind": kind, "half": half, "cells": cells, "mapper": name, "status": status or "no result",
                   "watched_peak_mb": seen, "seconds": seconds}
            print(row["status"], flush=True)
        rows.append(row)
        with open(results_path, "w") as out:
            json.dump(rows, out, indent=1)

    if args.limit:
        print("\n" + markdown_table(rows))
        if args.write_readme:
            with open(args.write_readme) as page:
                text = page.read()
            with open(args.write_readme, "w") as page:
                page.write(with_limit_section(text, limit_section(rows, run)))
            print(f"wrote {args.write_readme}'s limit section")
        return
    with open(os.path.join(args.output, "results.md"), "w") as out:
        out.write(markdown_table(rows) + "\n" + "\n".join(slope_lines(rows) + [""] + largest_lines(rows)) + "\n")
    plotted = plot(rows, os.path.join(args.output, "scale.png"))
    print("\n" + markdown_table(rows) + "\n" + "\n".join(slope_lines(rows)) + "\n\n" + "\n".join(largest_lines(rows)))
    print(f"wrote {results_path}, results.md" + (", scale.png" if plotted else " (no plot: matplotlib not importable)"))
    if args.write_readme:
        if plotted:
            shutil.copyfile(plotted, os.path.join(os.path.dirname(os.path.abspath(args.write_readme)), "scale.png"))
        previous = open(args.write_readme).read() if os.path.exists(args.write_readme) else ""
        text = scale_text(rows, run, plotted)
        if LIMIT_BEGIN in previous and LIMIT_END in previous:
            text = with_limit_section(text, LIMIT_BEGIN + previous.split(LIMIT_BEGIN, 1)[1].split(LIMIT_END, 1)[0]
                                      + LIMIT_END)
        with open(args.write_readme, "w") as out:
            out.write(text)
        print(f"wrote {args.write_readme}")


if __name__ == "__main__":
    main()
