#!/usr/bin/python3
"""Run the zoo of frictional contact problems with the solver's defaults and tabulate the outcome.

    /usr/bin/python3 tests/zoo/run_zoo.py [--exe PATH] [--np N] [--cases a,b,...] [--out DIR]
                                          [--markdown] [--mu-sweep] [--timeout S]
                                          [--order 2 [--serendipity] [--setnumber NAME VALUE ...]]

Every tests/zoo/<case>.json (keys: geo, mesh_args, dim, check, expected) is a case
with the deck tests/zoo/<case>.xml. For each case the runner
  1. meshes it when tests/zoo/meshes/<case>.e is missing or older than the .geo
     (or the .json, which holds the mesh arguments): scripts/make_mesh with
     COULOMB_BUILD_DIR = the folder of --exe (its coulomb_gmsh2exo);
  2. runs `EXE deck -o OUT/<case>.e` (np 1) or
     `mpirun --oversubscribe [--allow-run-as-root] -np N EXE deck -o OUT/<case>.e`,
     the console kept in OUT/<case>.log;
  3. parses the console: the DoFs line, the step lines (`step K converged: ...
     I Newton / L linear iterations`, `not converged after ...`), the summary
     `coulomb: S steps, N Newton and L linear iterations, C cutbacks, T s`, the
     first error line; and the deck's planned steps (Load Stepping/Number of
     Steps, default 1);
  4. runs the case's check script on OUT/<case>.e (one JSON line; a run that
     failed leaves only OUT/<case>.e.part and is reported without a check).
It prints a table (plain, or markdown with --markdown) and writes one JSON line
per case to OUT/zoo.jsonl. Exit code 0 when every case converged and passed.

--order 2 meshes every case at order 2 into OUT/meshes/<case>_order2.e
(QUAD9 / TRI6 / HEX27 / TET10 cells; with --serendipity QUAD8 / HEX20,
<case>_order2s.e) and runs the unchanged deck on it (`coulomb deck -m mesh`):
the same problems on quadratic cells, with the defaults. --setnumber NAME VALUE
(repeatable, order 2 only) overrides a mesh parameter of the .geo (e.g. the
element size h, for a coarser quadratic mesh).

--mu-sweep runs xml/friction_punch.xml with the contact friction coefficient
replaced by 0.1, 0.3, 0.5, 0.7, 0.9 and 1.0 (copies of the deck in OUT, its
Mesh/File made absolute) and reports converged, steps, cutbacks, Newton per
increment and Q/P at the last step (reaction_top_x / -reaction_top_z) against
mu; OUT/mu_sweep.jsonl. With --mu-sweep only the sweep runs, unless --cases is
given as well. Defaults: --exe build/coulomb of this repository, --np 1,
--out /tmp/zoo.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
SUMMARY = re.compile(rf"^coulomb: (\d+) steps, (\d+) Newton and (\d+) linear iterations, (\d+) cutbacks, ({NUM}) s")
STEP_DONE = re.compile(rf"^\s*step (\d+) converged: t = ({NUM}), (\d+) Newton / (\d+) linear iterations")
NOT_CONVERGED = re.compile(r"^\s*not converged after (\d+) iterations")
DOFS = re.compile(r"^coulomb: (\d+) elements, (\d+) DoFs, (\d+) rank")
MU_SWEEP = (0.1, 0.3, 0.5, 0.7, 0.9, 1.0)


# ------------------------------------------------------------------ deck
def _sublist(node, name):
    if node is None:
        return None
    return next((c for c in node.findall("ParameterList") if c.get("name") == name), None)


def _parameter(node, name):
    if node is None:
        return None
    return next((p for p in node.findall("Parameter") if p.get("name") == name), None)


def planned_steps(deck):
    """Load Stepping/Number of Steps of a deck (the solver's default 1 when absent)"""
    try:
        root = ET.parse(deck).getroot()
    except (ET.ParseError, OSError):
        return None
    p = _parameter(_sublist(root, "Load Stepping"), "Number of Steps")
    return int(p.get("value")) if p is not None else 1


# ------------------------------------------------------------------ console
def parse_console(text):
    out = {"dofs": None, "ranks": None, "summary": None, "steps_done": 0, "newton_steps": 0, "linear_steps": 0,
           "failed_attempts": 0, "last_time": None, "error": None, "step_newton": []}
    for line in text.splitlines():
        m = DOFS.match(line)
        if m:
            out["dofs"], out["ranks"] = int(m.group(2)), int(m.group(3))
            continue
        m = STEP_DONE.match(line)
        if m:
            out["steps_done"] += 1
            out["newton_steps"] += int(m.group(3))
            out["linear_steps"] += int(m.group(4))
            out["last_time"] = float(m.group(2))
            out["step_newton"].append(int(m.group(3)))
            continue
        if NOT_CONVERGED.match(line):
            out["failed_attempts"] += 1
            continue
        m = SUMMARY.match(line)
        if m:
            out["summary"] = {"steps": int(m.group(1)), "newton": int(m.group(2)), "linear": int(m.group(3)),
                              "cutbacks": int(m.group(4)), "seconds": float(m.group(5))}
            continue
        if out["error"] is None and re.search(r"\berror\b|Error|exception|Abort|Segmentation|Killed", line):
            out["error"] = line.strip()
    return out


# ------------------------------------------------------------------ running
def mpi_command(exe, np_):
    if np_ <= 1:
        return [exe]
    cmd = ["mpirun", "--oversubscribe"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    return cmd + ["-np", str(np_), exe]


def make_mesh(case, spec, build_dir, args=None):
    """tests/zoo/meshes/<case>.e from the case's .geo when missing or stale; returns (path, error).
    With args.order 2: OUT/meshes/<case>_order2[s].e, made every run."""
    geo = os.path.join(HERE, spec["geo"])
    if args is not None and args.order == 2:
        mesh = os.path.join(args.out, "meshes", case + ("_order2s.e" if args.serendipity else "_order2.e"))
        extra = ["-order", "2"] + (["-string", "Mesh.SecondOrderIncomplete=1;"] if args.serendipity else [])
        for name, value in args.setnumber:
            extra += ["-setnumber", name, value]
        return run_make_mesh(geo, mesh, list(spec.get("mesh_args", [])) + extra, build_dir)
    mesh = os.path.join(HERE, "meshes", case + ".e")
    sources = [geo, os.path.join(HERE, case + ".json")]
    if os.path.exists(mesh) and all(os.path.getmtime(mesh) >= os.path.getmtime(s) for s in sources if
                                    os.path.exists(s)):
        return mesh, None
    return run_make_mesh(geo, mesh, spec.get("mesh_args", []), build_dir)


def run_make_mesh(geo, mesh, args, build_dir):
    os.makedirs(os.path.dirname(mesh), exist_ok=True)
    env = dict(os.environ, COULOMB_BUILD_DIR=build_dir)
    proc = subprocess.run([os.path.join(REPO, "scripts", "make_mesh"), geo, mesh] + list(args), env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if proc.returncode != 0 or not os.path.exists(mesh):
        lines = [l for l in proc.stdout.splitlines() if l.strip()]
        return mesh, "make_mesh failed: " + (lines[-1] if lines else "rc %d" % proc.returncode)
    return mesh, None


def run_solver(exe, np_, deck, result, log, timeout, mesh=None):
    for stale in (result, result + ".part"):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = mpi_command(exe, np_) + [deck, "-o", result] + (["-m", mesh] if mesh else [])
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout,
                              cwd=REPO)
        text, rc = proc.stdout, proc.returncode
    except subprocess.TimeoutExpired as e:
        text = (e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or ""))
        text += "\nrun_zoo: error: timed out after %g s\n" % timeout
        rc = None
    seconds = time.monotonic() - start
    with open(log, "w") as f:
        f.write("$ " + " ".join(cmd) + "\n" + text)
    return rc, text, seconds


def run_check(script, result):
    try:
        proc = subprocess.run(["/usr/bin/python3", script, result], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return {"passed": False, "error": "check timed out"}, None
    lines = [l for l in proc.stdout.splitlines() if l.strip()]
    try:
        record = json.loads(lines[-1])
    except (IndexError, json.JSONDecodeError):
        err = [l for l in proc.stderr.splitlines() if l.strip()]
        record = {"passed": False, "error": "check printed no JSON" + (": " + err[-1] if err else "")}
    return record, proc.returncode


def outcome(name, np_, rc, text, seconds, result, planned):
    c = parse_console(text)
    s = c["summary"]
    converged = rc == 0 and s is not None and os.path.exists(result)
    steps = s["steps"] if s else c["steps_done"]
    newton = s["newton"] if s else c["newton_steps"]
    linear = s["linear"] if s else c["linear_steps"]
    cutbacks = s["cutbacks"] if s else c["failed_attempts"]
    error = None
    if not converged:
        error = c["error"] or ("exit code %s, no summary line" % rc)
    return {"case": name, "np": np_, "dofs": c["dofs"], "converged": converged, "rc": rc, "steps": steps,
            "planned": planned, "last_time": c["last_time"], "cutbacks": cutbacks, "newton": newton,
            "linear": linear, "newton_per_increment": newton / steps if steps else None,
            "linear_per_solve": linear / newton if newton else None,
            "wall_s": s["seconds"] if s else None, "run_s": round(seconds, 2), "error": error,
            "partial_result": os.path.exists(result + ".part")}


def run_case(name, spec, args, build_dir):
    deck = os.path.join(HERE, name + ".xml")
    result = os.path.join(args.out, name + ".e")
    log = os.path.join(args.out, name + ".log")
    planned = planned_steps(deck)
    missing = [k for k in ("geo", "check") if k not in spec]
    if missing:
        mesh_error = "%s.json lacks %s" % (name, ", ".join(missing))
    elif not os.path.exists(deck):
        mesh_error = "no deck %s" % deck
    else:
        mesh, mesh_error = make_mesh(name, spec, build_dir, args)
    if mesh_error:
        rec = {"case": name, "np": args.np, "converged": False, "rc": None, "steps": 0, "planned": planned,
               "cutbacks": 0, "newton": 0, "linear": 0, "newton_per_increment": None, "linear_per_solve": None,
               "wall_s": None, "run_s": 0.0, "error": mesh_error, "dofs": None}
    else:
        rc, text, seconds = run_solver(args.exe, args.np, deck, result, log, args.timeout,
                                       mesh if args.order == 2 else None)
        rec = outcome(name, args.np, rc, text, seconds, result, planned)
    rec["dim"] = spec.get("dim")
    rec["expected_text"] = spec.get("expected")
    rec["log"] = log
    if os.path.exists(result) and "check" in spec:
        rec["check"], rec["check_rc"] = run_check(os.path.join(HERE, spec["check"]), result)
    else:
        rec["check"], rec["check_rc"] = None, None
    rec["passed"] = bool(rec["check"] and rec["check"].get("passed"))
    return rec


# ------------------------------------------------------------------ mu sweep
def mu_sweep(args, build_dir):
    source = os.path.join(REPO, "xml", "friction_punch.xml")
    tree = ET.parse(source)
    root = tree.getroot()
    mesh_param = _parameter(_sublist(root, "Mesh"), "File")
    mesh = os.path.normpath(os.path.join(os.path.dirname(source), mesh_param.get("value")))
    if not os.path.exists(mesh):  # not built here: mesh it into OUT
        mesh, err = run_make_mesh(os.path.join(REPO, "exodus_meshes", "friction_punch.geo"),
                                  os.path.join(args.out, "meshes", "friction_punch.e"), [], build_dir)
        if err:
            print("run_zoo: mu sweep: " + err, file=sys.stderr)
            return []
    with open(source) as f:
        text = f.read()
    records = []
    for mu in MU_SWEEP:
        name = "friction_punch_mu%02d" % round(10 * mu)
        deck_text = text.replace('value="%s"' % mesh_param.get("value"), 'value="%s"' % mesh, 1)
        deck_text, count = re.subn(r'(<Parameter name="Friction Coefficient" type="double" value=")[^"]*(")',
                                   r"\g<1>%g\g<2>" % mu, deck_text)
        if count == 0:
            print("run_zoo: mu sweep: no Friction Coefficient in %s" % source, file=sys.stderr)
            return records
        deck = os.path.join(args.out, name + ".xml")
        with open(deck, "w") as f:
            f.write(deck_text)
        result = os.path.join(args.out, name + ".e")
        rc, console, seconds = run_solver(args.exe, args.np, deck, result, os.path.join(args.out, name + ".log"),
                                          args.timeout)
        rec = outcome(name, args.np, rc, console, seconds, result, planned_steps(deck))
        rec["mu"] = mu
        rec["q_over_p"] = None
        path = result if os.path.exists(result) else (result + ".part" if os.path.exists(result + ".part") else None)
        if path:
            try:
                import zoo_exodus
                r = zoo_exodus.Result(path)
                qx, pz = r.glob_last("reaction_top_x"), r.glob_last("reaction_top_z")
                rec["q_over_p"] = abs(qx) / abs(pz) if pz else None
                rec["q_over_p_time"] = float(r.times[-1])
                for key, var in (("stick_nodes_end", "contact_stick_nodes_"), ("active_nodes_end", "contact_active_nodes_")):
                    names = [g for g in r.global_names if g.startswith(var)]
                    rec[key] = int(sum(r.glob_last(g) for g in names)) if names else None
            except Exception as e:  # noqa: BLE001
                rec["q_over_p_error"] = str(e)
        if rec["q_over_p"] is not None:
            rec["q_over_p_rel_error"] = (rec["q_over_p"] - mu) / mu
        records.append(rec)
        print("  %s: %s" % (name, "converged" if rec["converged"] else "FAILED"), file=sys.stderr, flush=True)
    return records


# ------------------------------------------------------------------ tables
def _fmt(x, spec="%.2f"):
    return "-" if x is None else spec % x


def check_text(rec):
    chk = rec.get("check")
    if not chk:
        return "run failed, no .e (.e.part kept)" if rec.get("partial_result") else "no result"
    if "value" not in chk:
        return "ERROR " + str(chk.get("error", ""))[:60]
    return "%.6g vs %.6g (err %.2e, tol %.0e) %s" % (chk["value"], chk["expected"], chk["error"],
                                                    chk.get("tolerance", float("nan")),
                                                    "pass" if chk.get("passed") else "FAIL")


def table(rows, headers, markdown):
    if markdown:
        out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
        out += ["| " + " | ".join(str(c).replace("|", "/") for c in row) + " |" for row in rows]
        return "\n".join(out)
    widths = [max(len(str(h)), *(len(str(r[i])) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    fmt = "  ".join("%%-%ds" % w for w in widths)
    return "\n".join([fmt % tuple(headers), fmt % tuple("-" * w for w in widths)] +
                     [fmt % tuple(str(c) for c in row) for row in rows])


def case_table(records, markdown):
    headers = ["case", "np", "DoFs", "converged", "steps/planned", "cutbacks", "Newton/incr", "linear/solve",
               "wall s", "check", "first error"]
    rows = []
    for r in records:
        rows.append([r["case"], r["np"], _fmt(r.get("dofs"), "%d"), "yes" if r["converged"] else "NO",
                     "%s/%s" % (r["steps"], r["planned"]), r["cutbacks"], _fmt(r["newton_per_increment"]),
                     _fmt(r["linear_per_solve"], "%.1f"), _fmt(r["wall_s"] if r["wall_s"] is not None else r["run_s"]),
                     check_text(r), (r.get("error") or "")[:110]])
    return table(rows, headers, markdown)


def sweep_table(records, markdown):
    headers = ["mu", "np", "converged", "steps/planned", "cutbacks", "Newton/incr", "linear/solve", "wall s",
               "Q/P end", "t end", "(Q/P - mu)/mu", "stick/active end", "first error"]
    rows = []
    for r in records:
        rows.append([r["mu"], r["np"], "yes" if r["converged"] else "NO", "%s/%s" % (r["steps"], r["planned"]),
                     r["cutbacks"], _fmt(r["newton_per_increment"]), _fmt(r["linear_per_solve"], "%.1f"),
                     _fmt(r["wall_s"] if r["wall_s"] is not None else r["run_s"]), _fmt(r.get("q_over_p"), "%.4f"),
                     _fmt(r.get("q_over_p_time"), "%g"), _fmt(r.get("q_over_p_rel_error"), "%+.2e"),
                     "%s/%s" % (_fmt(r.get("stick_nodes_end"), "%d"), _fmt(r.get("active_nodes_end"), "%d")),
                     (r.get("error") or "")[:100]])
    return table(rows, headers, markdown)


# ------------------------------------------------------------------ main
def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(REPO, "build", "coulomb"))
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--cases", default=None, help="comma-separated case names (default: every tests/zoo/*.json)")
    ap.add_argument("--out", default="/tmp/zoo")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--mu-sweep", action="store_true", help="run xml/friction_punch.xml for mu = 0.1 ... 1.0")
    ap.add_argument("--timeout", type=float, default=900, help="seconds per run before it counts as failed")
    ap.add_argument("--order", type=int, choices=(1, 2), default=1,
                    help="2: every case meshed at order 2 into OUT/meshes (quadratic cells)")
    ap.add_argument("--serendipity", action="store_true", help="with --order 2: QUAD8 / HEX20 cells")
    ap.add_argument("--setnumber", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                    help="with --order 2: a mesh parameter of the .geo, after the case's own")
    args = ap.parse_args()
    if (args.serendipity or args.setnumber) and args.order != 2:
        print("run_zoo: --serendipity and --setnumber need --order 2", file=sys.stderr)
        return 2
    args.exe = os.path.abspath(args.exe)
    args.out = os.path.abspath(args.out)
    if not os.access(args.exe, os.X_OK):
        print("run_zoo: no executable %s" % args.exe, file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    build_dir = os.path.dirname(args.exe)

    specs = {}
    for f in sorted(os.listdir(HERE)):
        if f.endswith(".json"):
            with open(os.path.join(HERE, f)) as fh:
                specs[f[:-5]] = json.load(fh)
    selected = list(specs)
    if args.cases:
        selected = [c.strip() for c in args.cases.split(",") if c.strip()]
        unknown = [c for c in selected if c not in specs]
        if unknown:
            print("run_zoo: unknown case(s): %s (have: %s)" % (", ".join(unknown), ", ".join(specs)), file=sys.stderr)
            return 2
    run_cases = not args.mu_sweep or args.cases
    ok = True

    if run_cases:
        records = []
        with open(os.path.join(args.out, "zoo.jsonl"), "w") as jl:
            for name in selected:
                print("run_zoo: %s (np %d) ..." % (name, args.np), file=sys.stderr, flush=True)
                rec = run_case(name, specs[name], args, build_dir)
                records.append(rec)
                jl.write(json.dumps(rec) + "\n")
                jl.flush()
        print(case_table(records, args.markdown))
        ok = all(r["converged"] and r["passed"] for r in records)
        print("\n%d case(s): %d converged, %d passed their check (results and logs in %s)" % (
            len(records), sum(r["converged"] for r in records), sum(r["passed"] for r in records), args.out))

    if args.mu_sweep:
        print("run_zoo: mu sweep of xml/friction_punch.xml (np %d) ..." % args.np, file=sys.stderr, flush=True)
        sweep = mu_sweep(args, build_dir)
        with open(os.path.join(args.out, "mu_sweep.jsonl"), "w") as jl:
            for rec in sweep:
                jl.write(json.dumps(rec) + "\n")
        if run_cases:
            print()
        print("mu sweep, xml/friction_punch.xml (Q/P = reaction_top_x / -reaction_top_z at the last written step)")
        print(sweep_table(sweep, args.markdown))
        ok = ok and bool(sweep) and all(r["converged"] for r in sweep)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
