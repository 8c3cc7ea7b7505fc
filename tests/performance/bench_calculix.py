"""The CalculiX peer harness for scripts/bench --calculix (contact cases
hertz2d, hertz3d, friction): run ../shared/bench/calculix/run_case.sh on the
same case and level with LINMORTAR (friction: mu 0.3) into <run dir>/calculix
(nothing is written into ../shared) and add its JSON line to the result.
"""
import json
import os
import shlex
import subprocess

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
FRICTION_MU = 0.3  # the benchmark's (ccxbench.CASES["friction"]["mu"]), passed to CalculiX
CALCULIX_RUNNER = os.path.normpath(os.path.join(REPO, "..", "shared", "bench", "calculix", "run_case.sh"))
CCX = "/usr/bin/ccx"
CASES = ("hertz2d", "hertz3d", "friction")  # the cases the harness knows


def run_calculix(case, ref_label, timeout, run_dir):
    """the peer harness on the same case/level, LINMORTAR (friction: mu 0.3),
    run dir below ours; returns its JSON object (or a dict with status/error)"""
    out_dir = os.path.join(run_dir, "calculix")
    os.makedirs(out_dir, exist_ok=True)
    command = [CALCULIX_RUNNER, case, "--ref", ref_label, "--contact", "LINMORTAR",
               "--runs-dir", out_dir, "--timeout", str(int(timeout))]
    if case == "friction":
        command += ["--mu", repr(FRICTION_MU)]
    return harness_line(command, out_dir, timeout)


def harness_line(command, out_dir, timeout):
    """runs the harness command in out_dir; its JSON line (or status/error)"""
    with open(os.path.join(out_dir, "command.txt"), "w") as f:
        f.write(" ".join(shlex.quote(c) for c in command) + "\n")
    try:
        # PYTHONDONTWRITEBYTECODE: no __pycache__ in the (read-only) shared harness folder
        proc = subprocess.run(command, cwd=out_dir, capture_output=True, text=True, timeout=timeout + 120,
                              env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "error": f"run_case.sh did not return within {timeout + 120} s"}
    with open(os.path.join(out_dir, "stdout.txt"), "w") as f:
        f.write(proc.stdout)
    with open(os.path.join(out_dir, "stderr.txt"), "w") as f:
        f.write(proc.stderr)
    for line in reversed(proc.stdout.splitlines()):
        try:
            obj = json.loads(line)
        except ValueError:
            continue
        if isinstance(obj, dict):
            return obj
    return {"status": "failed", "error": f"run_case.sh exit code {proc.returncode}: " + proc.stderr.strip()[-300:]}


def run_calculix_on_mesh(case, ref_label, exodus_mesh, timeout, run_dir):
    """the harness' deck and analysis (LINMORTAR) on a mesh it does not export
    itself (--order 2: HEX20 -> C3D20, TET10 -> C3D10): the Exodus mesh
    written as .inp by exodus_to_inp.py (same node numbers), the deck by the
    harness' ccxbench.write_deck, the run and the analysis by
    run_case.sh --deck; everything in <run dir>/calculix"""
    out_dir = os.path.join(run_dir, "calculix", "job")
    os.makedirs(out_dir, exist_ok=True)
    mesh_inp = os.path.join(out_dir, os.path.splitext(os.path.basename(exodus_mesh))[0] + ".inp")
    here = os.path.dirname(os.path.realpath(__file__))
    convert = subprocess.run(["/usr/bin/python3", os.path.join(here, "exodus_to_inp.py"), exodus_mesh, mesh_inp],
                             capture_output=True, text=True)
    if convert.returncode != 0:
        return {"status": "failed", "error": "exodus_to_inp.py: " + (convert.stderr or convert.stdout).strip()[-300:]}
    deck = os.path.join(out_dir, "job.inp")
    write = ("import sys; sys.dont_write_bytecode = True; sys.path.insert(0, sys.argv[1]); import ccxbench; "
             "ccxbench.write_deck(sys.argv[2], sys.argv[3], 'LINMORTAR', sys.argv[4], sys.argv[5])")
    made = subprocess.run(["/usr/bin/python3", "-c", write, os.path.dirname(CALCULIX_RUNNER), case, ref_label,
                           deck, mesh_inp], capture_output=True, text=True)
    if made.returncode != 0:
        return {"status": "failed", "error": "ccxbench.write_deck: " + made.stderr.strip()[-300:]}
    return harness_line([CALCULIX_RUNNER, "--deck", deck, "--timeout", str(int(timeout))], out_dir, timeout)


def add_calculix(result, case, ref_label, timeout, run_dir, wall, rss, mesh=None):
    """result["calculix"] = the harness' JSON line (without its profile_line),
    plus the time and memory ratios CalculiX / Coulomb; `mesh`: an Exodus
    mesh of our own to run instead of the harness' level (run_calculix_on_mesh)"""
    if not os.path.exists(CCX):
        result["calculix"] = {"status": "not_run", "error": f"{CCX} not found"}
        return
    if mesh is None:
        ccx = run_calculix(case, ref_label, timeout, run_dir)
    else:
        ccx = run_calculix_on_mesh(case, ref_label, mesh, timeout, run_dir)
    ccx.pop("profile_line", None)
    result["calculix"] = ccx
    if ccx.get("wall_s") and wall:
        result["time_ratio_calculix_over_coulomb"] = ccx["wall_s"] / wall
    if ccx.get("max_rss_mb") and rss:
        result["rss_ratio_calculix_over_coulomb"] = ccx["max_rss_mb"] / max(rss)
