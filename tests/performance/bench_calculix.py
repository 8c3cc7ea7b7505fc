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


def add_calculix(result, case, ref_label, timeout, run_dir, wall, rss):
    """result["calculix"] = the harness' JSON line (without its profile_line),
    plus the time and memory ratios CalculiX / Coulomb"""
    if not os.path.exists(CCX):
        result["calculix"] = {"status": "not_run", "error": f"{CCX} not found"}
        return
    ccx = run_calculix(case, ref_label, timeout, run_dir)
    ccx.pop("profile_line", None)
    result["calculix"] = ccx
    if ccx.get("wall_s") and wall:
        result["time_ratio_calculix_over_coulomb"] = ccx["wall_s"] / wall
    if ccx.get("max_rss_mb") and rss:
        result["rss_ratio_calculix_over_coulomb"] = ccx["max_rss_mb"] / max(rss)
