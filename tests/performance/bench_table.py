"""The summary table the run_*.sh scripts print after their JSON lines.

rows: the JSON objects of scripts/bench; cols: (title, getter, format), the
getter a key of the row or a function of the row.
"wall s" gets a * when the run was disturbed, "ccx wall s" CalculiX's status
when it did not end ok.
"""
import json


def ccx_getter(key):
    return lambda row: ccx(row, key)


def cost_columns(per="step", solve_time=False):
    """the columns every contact table shows: size, Newton and Krylov work,
    time and memory (`per`: "step" or "inc" for the Newton maximum)"""
    cols = [("dofs", "dofs", "{}"), ("Newton", "newton_iterations", "{}"),
            (f"its/{per} max", f"newton_per_{'increment' if per == 'inc' else per}_max", "{}"),
            ("lin.it", "linear_iterations", "{}"),
            ("s/Newton", "time_per_newton_s", "{:.3f}")]
    if solve_time:
        cols.append(("solve s", "linear_solve_s_per_solve", "{:.3f}"))
    return cols + [("contact s", "contact_s", "{:.2f}"),
                   ("wall s", "wall_s", "{:.2f}"), ("RSS MB", "max_rss_mb", "{:.0f}")]


# CalculiX's Newton iterations and time, and the ratio (--calculix runs)
CALCULIX_COST = [("ccx Newton", ccx_getter("newton_iterations"), "{}"),
                 ("ccx wall s", ccx_getter("wall_s"), "{:.2f}"),
                 ("ccx/coulomb time", "time_ratio_calculix_over_coulomb", "{:.2f}")]


def read_rows(stream):
    rows = []
    for line in stream:
        try:
            rows.append(json.loads(line))
        except ValueError:
            pass
    return rows


def ccx(row, key):
    return (row.get("calculix") or {}).get(key)


def cell(row, get, fmt, name):
    value = row.get(get) if isinstance(get, str) else get(row)
    if value is None:
        return "-"
    try:
        text = fmt.format(value)
    except (ValueError, TypeError):
        text = str(value)
    if name == "wall s" and row.get("disturbed"):
        text += "*"
    if name == "ccx wall s" and ccx(row, "status") not in (None, "ok"):
        text += " (" + str(ccx(row, "status")) + ")"
    return text


def print_table(rows, cols, title):
    table = [[c[0] for c in cols]] + [[cell(r, g, f, n) for n, g, f in cols] for r in rows]
    widths = [max(len(t[i]) for t in table) for i in range(len(cols))]
    print(title + "* = disturbed: other processes used > max(0.3 s, 10 % of the wall time) of CPU")
    for j, line in enumerate(table):
        print("  ".join(s.rjust(widths[i]) for i, s in enumerate(line)))
        if j == 0:
            print("  ".join("-" * w for w in widths))
