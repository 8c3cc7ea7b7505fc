"""The summary table the run_*.sh scripts print after their JSON lines.

rows: the JSON objects of scripts/bench; cols: (title, getter, format), the
getter a key of the row or a function of the row.
"wall s" gets a * when the run was disturbed, "ccx wall s" CalculiX's status
when it did not end ok.
"""
import json


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
