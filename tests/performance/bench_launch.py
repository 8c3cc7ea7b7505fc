"""Running a benchmark command for scripts/bench: wait for an idle machine,
launch coulomb (directly, or through mpirun with one /usr/bin/time -v per
rank), measure wall time, peak RSS per rank, CPU time and the CPU used by
other processes during the run; the short error text of a failed run.
"""
import os
import re
import shlex
import subprocess
import time

from bench_console import parse_cpu_time, parse_time_v


def busy_jiffies():
    """(busy, total) CPU jiffies of the machine from /proc/stat (busy excludes idle and iowait)."""
    try:
        fields = [int(x) for x in open("/proc/stat").readline().split()[1:]]
    except OSError:
        return None
    idle = fields[3] + (fields[4] if len(fields) > 4 else 0)
    return sum(fields[:8]) - idle, sum(fields[:8])


def wait_idle(limit, threshold=0.25):
    """Wait (at most limit seconds) until the machine has been idle for 3 s:
    less than `threshold` cores busy. Returns the seconds waited."""
    start = time.monotonic()
    hz = os.sysconf("SC_CLK_TCK")
    while time.monotonic() - start < limit:
        before = busy_jiffies()
        time.sleep(3)
        after = busy_jiffies()
        if before is None or (after[0] - before[0]) / hz / 3 < threshold:
            break
    return time.monotonic() - start


def launch(args, run_dir, exe, exe_args):
    """Run `exe exe_args` in run_dir under /usr/bin/time -v (np > 1: through
    mpirun, each rank under its own /usr/bin/time -v); console to stdout.txt /
    stderr.txt. Returns a dict: rc (None = killed at --timeout), stdout, wall,
    rss (list over ranks, MB), cpu, other (CPU s of other processes),
    waited, load_before."""
    # --verbose: the benchmarks read the Newton iteration table (bench_console.py)
    exe_args = list(exe_args) + ["--verbose"]
    outer = ["/usr/bin/time", "-v", "-o", os.path.join(run_dir, "time.txt")]
    if args.np == 1:
        command = outer + [exe] + exe_args
        rank_reports = [os.path.join(run_dir, "time.txt")]
    else:
        mpirun = ["mpirun", "--oversubscribe", "-np", str(args.np)]
        if os.geteuid() == 0:
            mpirun.insert(1, "--allow-run-as-root")
        # each rank under its own /usr/bin/time -v -> time.rank<r>.txt
        wrapper = ('exec /usr/bin/time -v -o ' + shlex.quote(run_dir) +
                   '/time.rank"${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}".txt "$@"')
        command = outer + mpirun + ["/bin/sh", "-c", wrapper, "sh", exe] + exe_args
        rank_reports = [os.path.join(run_dir, f"time.rank{r}.txt") for r in range(args.np)]
    with open(os.path.join(run_dir, "command.txt"), "w") as f:
        f.write(" ".join(shlex.quote(c) for c in command) + "\n")

    waited = wait_idle(args.wait_idle) if args.wait_idle > 0 else 0.0
    load_before = os.getloadavg()[0]
    jiffies_before = busy_jiffies()
    started = time.monotonic()
    with open(os.path.join(run_dir, "stdout.txt"), "w") as so, open(os.path.join(run_dir, "stderr.txt"), "w") as se:
        try:
            proc = subprocess.Popen(command, cwd=run_dir, stdout=so, stderr=se, start_new_session=True)
            rc = proc.wait(timeout=args.timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, 9)
            proc.wait()
            rc = None
    jiffies_after = busy_jiffies()

    stdout = open(os.path.join(run_dir, "stdout.txt"), errors="replace").read()
    wall, _ = parse_time_v(os.path.join(run_dir, "time.txt"))
    if wall is None:
        wall = time.monotonic() - started
    rss = [r for r in (parse_time_v(p)[1] for p in rank_reports) if r is not None]
    # CPU used by other processes during the run = machine busy time - our own
    # (outer /usr/bin/time: the run and all its children). It includes ~0.15 s
    # of Open MPI's daemon (orted, detached: not our child) and kernel threads;
    # more than max(0.3 s, 10 % of the wall time) marks the figures as disturbed.
    cpu = parse_cpu_time(os.path.join(run_dir, "time.txt"))
    other = None
    if cpu is not None and jiffies_before and jiffies_after:
        other = max(0.0, (jiffies_after[0] - jiffies_before[0]) / os.sysconf("SC_CLK_TCK") - cpu)
    return {"rc": rc, "stdout": stdout, "wall": wall, "rss": rss, "cpu": cpu, "other": other,
            "waited": waited, "load_before": load_before}


def error_text(run_dir, rc, timeout):
    """short error message: timeout, or the exit code + coulomb's own stderr lines"""
    if rc is None:
        return f"timeout after {timeout} s"
    err = [l.strip() for l in open(os.path.join(run_dir, "stderr.txt"), errors="replace") if l.strip()]
    # coulomb's own message first (mpirun adds its boilerplate after it)
    own = [l for l in err if re.search(r"coulomb|error|what\(\)", l, re.I) and not l.startswith("--")]
    pick = own[:2] or err[-3:]
    return f"exit code {rc}" + (": " + " | ".join(pick)[:400] if pick else "")

