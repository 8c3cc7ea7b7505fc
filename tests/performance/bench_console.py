"""Parsing for scripts/bench: coulomb's console (Newton table, step and
summary lines, Teuchos timers) and the /usr/bin/time -v reports of a run.

  parse_console(text)  dofs, elements, ranks, per-iteration seconds / linear
                       iterations (+ active / changed with contact columns),
                       per-step Newton counts and times, totals, cutbacks
  parse_timers(text)   {timer: (total s, calls)} of the Teuchos summary
                       (MaxOverProcs with several ranks); per_call(timers, name)
  parse_time_v(path), parse_cpu_time(path)   elapsed s, max RSS MB, user+sys s
  rnd(x, digits)       significant-digit rounding of floats (and lists)
"""
import os
import re

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
TIMER_ROW = re.compile(r"^(\S.*?)\s{2,}((?:" + NUM + r"\s+\(\d+\)\s*)+)$")
TIMER_CELL = re.compile(r"(" + NUM + r")\s+\((\d+)\)")


def parse_timers(text):
    """{name: (total seconds, calls)}: one processor -> 'Global time', several ->
    'MaxOverProcs' (3rd column; calls of that column)."""
    timers, inside = {}, False
    for line in text.splitlines():
        if "TimeMonitor results over" in line:
            inside = True
            continue
        if not inside:
            continue
        m = TIMER_ROW.match(line.rstrip())
        if not m:
            continue
        cells = [(float(v), int(c)) for v, c in TIMER_CELL.findall(m.group(2))]
        timers[m.group(1).strip()] = cells[2] if len(cells) >= 4 else cells[0]
    return timers


def per_call(timers, name):
    total, calls = timers.get(name, (None, 0))
    return (total / calls if calls else None), calls, total


# Newton table row: iter |residual| |increment| lin.it time[s], with contact
# followed by: active changed |r_normal| [ratio] set(yes/no)
ITER_ROW = re.compile(r"^\s+(\d+)\s+(" + NUM + r")\s+(\S+)\s+(\d+)\s+(" + NUM + r")"
                      r"(?:\s+(\d+)\s+(\d+)\s+(\S+)(?:\s+\S+)?\s+(yes|no))?\s*$")


def parse_console(text):
    out = {"iteration_seconds": [], "iteration_linear": [], "step_lines": 0}
    m = re.search(r"coulomb: (\d+) elements, (\d+) DoFs, (\d+) rank", text)
    if m:
        out["elements"], out["dofs"], out["ranks"] = map(int, m.groups())
    for line in text.splitlines():
        row = ITER_ROW.match(line)
        if row and int(row.group(1)) >= 1:
            out["iteration_seconds"].append(float(row.group(5)))
            out["iteration_linear"].append(int(row.group(4)))
            if row.group(6) is not None:
                out.setdefault("iteration_active", []).append(int(row.group(6)))
                out.setdefault("iteration_changed", []).append(int(row.group(7)))
    m = re.search(r"coulomb: (\d+) steps, (\d+) Newton and (\d+) linear iterations, (\d+) cutbacks, (" + NUM + r") s",
                  text)
    if m:
        out["steps"], out["newton_iterations"], out["linear_iterations"], out["cutbacks"] = map(int, m.groups()[:4])
        out["solver_wall_s"] = float(m.group(5))
    out["step_newton"] = [int(x) for x in re.findall(r"step \d+ converged: t = \S+, (\d+) Newton", text)]
    out["preconditioner_kept"] = sum(int(x) for x in re.findall(r"preconditioner kept in (\d+) solves", text))
    out["corner_level_kept"] = sum(int(x) for x in re.findall(r"corner level kept in (\d+) solves", text))
    out["step_time"] = [float(x) for x in re.findall(r"step \d+ converged: t = (" + NUM + r"),", text)]
    out["not_converged"] = len(re.findall(r"not converged after \d+ iterations", text))
    return out


def parse_time_v(path):
    """(elapsed seconds, max RSS MB) from a /usr/bin/time -v report."""
    if not os.path.exists(path):
        return None, None
    text = open(path, errors="replace").read()
    elapsed = rss = None
    m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
    if m:
        parts = [float(p) for p in m.group(1).split(":")]
        elapsed = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    if m:
        rss = int(m.group(1)) / 1024.0
    return elapsed, rss


def parse_cpu_time(path):
    """User + System seconds of a /usr/bin/time -v report (includes waited-for children)."""
    if not os.path.exists(path):
        return None
    text = open(path, errors="replace").read()
    u = re.search(r"User time \(seconds\): (\S+)", text)
    s = re.search(r"System time \(seconds\): (\S+)", text)
    return float(u.group(1)) + float(s.group(1)) if u and s else None


def rnd(x, digits=4):
    if isinstance(x, float):
        return float(f"{x:.{digits}g}")
    if isinstance(x, list):
        return [rnd(v, digits) for v in x]
    return x

