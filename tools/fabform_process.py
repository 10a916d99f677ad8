"""Running fabform from the benchmark tools: where it is, starting it (retrying while it is being
relinked), waiting for it within a time budget with its peak memory, what it printed and how it
ended, and the positions it wrote.

Imported by tools/bench_solvers.py and tools/bench_scale.py. Standard library only.
FABFORM_BINARY names the fabform to run (default build/fabform).
"""
import array
import math
import os
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
FABFORM = pathlib.Path(os.environ.get("FABFORM_BINARY", ROOT / "build" / "fabform"))
MAX_ITERATIONS = 1_000_000_000        # fabform's largest cap: the budget stops a run, not the scene's cap
RETRIES = 3                           # launching fabform while it is being relinked fails


def scene_path(name: str) -> pathlib.Path:
    return ROOT / "scenes" / f"{name}.toml"


def launch(command: list, log: pathlib.Path) -> subprocess.Popen:
    """Start fabform, retrying while the binary is being relinked (ENOENT, ETXTBSY)."""
    for attempt in range(RETRIES):
        try:
            with log.open("w") as err:
                return subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err)
        except OSError as error:
            if attempt == RETRIES - 1:
                raise
            print(f"    cannot start fabform ({error}); retrying in 10 s", file=sys.stderr)
            time.sleep(10)


def wait_within(child: subprocess.Popen, budget: float) -> tuple:
    """(exit code or None if killed at the budget, peak resident MiB, wall seconds)."""
    started = time.monotonic()
    try:
        while True:
            pid, raw, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                code = os.waitstatus_to_exitcode(raw)
                break
            if time.monotonic() - started > budget:
                child.kill()
                _, raw, usage = os.wait4(child.pid, 0)
                code = None
                break
            time.sleep(0.02)
    except BaseException:  # Ctrl-C: leave no fabform behind
        child.kill()
        os.wait4(child.pid, 0)
        raise
    child.returncode = code if code is not None else -9  # reaped here, not by Popen
    return code, usage.ru_maxrss / 1024.0, time.monotonic() - started


def last_line(log: pathlib.Path) -> str:
    lines = log.read_text(errors="replace").strip().splitlines() if log.exists() else []
    return lines[-1] if lines else ""


def status_of(code: int, result: dict) -> str:
    if code == 0 and result.get("converged"):
        return "converged"
    if code == 3 or (code == 0 and result):
        return "not converged"
    return "failed"


def read_positions(out: pathlib.Path):
    """fabric.obj's `v x y z` lines as one flat array (x0, y0, z0, x1, ...); the file is then deleted."""
    positions = array.array("d")
    with (out / "fabric.obj").open() as f:
        for line in f:
            if line.startswith("v "):
                positions.extend(float(v) for v in line.split()[1:4])
    for bulky in ("fabric.obj", "fabric.vtk"):
        (out / bulky).unlink(missing_ok=True)
    return positions


def largest_distance(a, b) -> float:
    """max over nodes i of |a_i - b_i|, m; NaN when the node counts differ."""
    if len(a) != len(b):
        return math.nan
    return math.sqrt(max((a[i] - b[i]) ** 2 + (a[i + 1] - b[i + 1]) ** 2 + (a[i + 2] - b[i + 2]) ** 2
                         for i in range(0, len(a), 3)))


def fabform_version() -> str:
    shown = subprocess.run([str(FABFORM), "--version"], capture_output=True, text=True)
    return shown.stdout.strip() or "fabform (version unknown)"
