"""Contact cases of scripts/bench (hertz2d, hertz3d, friction, ironing): the
case table, the analysis of a run's result (hertz_post.py, friction_post.py,
ironing_post.py: numpy + netCDF4, imported when used), the keys of the JSON
line (solver effort, per-case keys, timers) and the plots.
"""
import os
import re
import subprocess
import sys

from bench_console import per_call

PERF = os.path.dirname(os.path.abspath(__file__))
# case: (deck relative to the repository, mesh file pattern in the mesh folder,
# kind: hertz | friction | ironing)
CASES = {"hertz2d": ("xml/hertz2d.xml", "hertz2d_2d_r{}.e", "hertz"),
         "hertz3d": ("xml/hertz3d.xml", "hertz3d_r{}.e", "hertz"),
         "friction": ("xml/friction_punch.xml", "friction_r{}.e", "friction"),
         "ironing": ("tests/performance/ironing_hertz3d.xml", "hertz3d_r{}.e", "ironing")}
# what --frictionless removes from the friction deck's contact pairs
FRICTION_KEYS = ("Friction Law", "Friction Coefficient")
HERTZ_KEYS = ("p0_hertz", "a_hertz", "p_max", "p_max_rel_err", "r_at_p_max", "a_fit", "p0_fit",
              "a_fit_rel_err", "p0_fit_rel_err", "a_line_last_active", "a_line_first_inactive",
              "a_bracket_mid", "a_bracket_rel_err", "max_penetration", "active_slave_nodes", "a_active",
              "slave_nodes", "E_star", "thickness")
# ironing: these keys first in the JSON line, in this order
IRONING_HEAD = ("case", "ref", "np", "status", "dofs", "wall_s", "max_rss_mb", "increments", "newton_iterations",
                "newton_per_increment", "linear_iterations", "time_per_newton_s", "history", "Q_over_P_end")


def kind(case):
    return CASES[case][2]


def post_module(name):
    """tests/performance/<name>.py, imported on first use (no __pycache__)"""
    sys.path.insert(0, PERF)
    sys.dont_write_bytecode = True  # no __pycache__ in the source tree
    return __import__(name)


def find_result(run_dir):
    """result.e, else the first result*.e / result*.e.part (a failed run keeps
    its converged steps in result.e.part), else None"""
    result_file = os.path.join(run_dir, "result.e")
    if os.path.exists(result_file):
        return result_file
    partial = sorted(f for f in os.listdir(run_dir) if f.startswith("result") and
                     (f.endswith(".e") or f.endswith(".e.part")))
    return os.path.join(run_dir, partial[0]) if partial else None


def analyze(case, result_file, run_dir, deck):
    """the accuracy / friction keys of a result (raises on a broken file)"""
    log = os.path.join(run_dir, "stdout.txt")
    if kind(case) == "friction":
        return post_module("friction_post").analyze_files(result_file, log, deck)
    if kind(case) == "ironing":
        return post_module("ironing_post").analyze_files(result_file, log, deck)
    post = post_module("hertz_post")
    return post.analyze(case, post.read_result(result_file))


def ok_keys(case, keys):
    """the result was analysed far enough for status ok"""
    return keys.get("P_end") is not None if kind(case) != "hertz" else "p_max" in keys


def result_keys(case, keys, console, timers, stdout, run):
    """the keys of the JSON line after case/ref/np/code/status: solver effort,
    the per-case keys, the timers (Coulomb extras); `run` = bench_launch.launch()"""
    friction = kind(case) != "hertz"
    wall, rss = run["wall"], run["rss"]
    out = {}
    iters, linear_per_solve = console["iteration_seconds"], console["iteration_linear"]
    if friction:
        # the iteration rows matched on their first columns only (new friction columns)
        loose = post_module("friction_post").console_keys(stdout)
        if len(loose["iteration_seconds"]) > len(iters):
            iters, linear_per_solve = loose["iteration_seconds"], loose["iteration_linear"]
    per_step_newton = console.get("step_newton", [])
    out.update({
        "nodes": keys.get("nodes"),
        "elements": console.get("elements", keys.get("elements")),
        "dofs": console.get("dofs"),
        "wall_s": wall,
        "cpu_s": run["cpu"],
        "max_rss_mb": max(rss) if rss else None,
        # ccxbench: increments = converged increments, newton_iterations = sum
        # over them, per_step = per analysis step (Hertz: one, the 5 load steps
        # are its increments; friction, ironing: 1 = pressing, 2 = sliding);
        # newton_per_step / newton_per_increment = Newton iterations of every
        # converged load step
        "increments": len(per_step_newton),
        "cutbacks": console.get("cutbacks"),
        "newton_iterations": console.get("newton_iterations"),
        "newton_iterations_all_attempts": len(iters),
    })
    if friction:
        out.update({
            "contact": keys.get("formulation") or "ALM",
            "per_step": keys.get("per_step"),
            "newton_per_increment": per_step_newton,
            "newton_per_increment_max": max(per_step_newton) if per_step_newton else None,
        })
    else:
        out.update({
            "per_step": [{"step": 1, "increments": len(per_step_newton), "iterations": sum(per_step_newton)}],
            "newton_per_step": per_step_newton,
            "newton_per_step_max": max(per_step_newton) if per_step_newton else None,
        })
    out.update({
        "linear_iterations": console.get("linear_iterations"),
        "time_per_newton_s": sum(iters) / len(iters) if iters else None,
    })
    post = post_module(kind(case) + "_post") if friction else None
    if friction:
        out.update({k: keys.get(k) for k in post.BENCH_KEYS})
    else:
        load_key = "P" if case == "hertz3d" else "P_per_length"
        out[load_key] = keys.get(load_key)
        out.update({k: keys[k] for k in HERTZ_KEYS if k in keys})
    # Coulomb extras
    if friction:
        out.update({k: keys.get(k) for k in post.BENCH_EXTRAS if k in keys or
                    not k.startswith(("slip_", "stick_"))})
    else:
        out.update({k: keys.get(k) for k in ("contact_force", "contact_force_vs_reaction_rel",
                                             "contact_active_nodes", "active_nodes_state", "min_pressure",
                                             "line_nonmonotone")})
    out.update({
        "solver_wall_s": console.get("solver_wall_s"),
        "sum_rss_mb": sum(rss) if rss else None,
        "other_cpu_s": run["other"],
        "disturbed": (run["other"] > max(0.3, 0.1 * wall)) if run["other"] is not None else None,
        "load_avg_1m_before": round(run["load_before"], 2),
        "linear_iterations_per_solve": linear_per_solve,
        "preconditioner_kept": console.get("preconditioner_kept"),
        "corner_level_kept": console.get("corner_level_kept"),
        "active_per_iteration": console.get("iteration_active"),
    })
    out.update(timer_keys(timers, console))
    return out


def timer_keys(timers, console):
    """per-call times of the Teuchos timers, the contact total and the time of
    the load-step loop outside them"""
    assembly, assembly_calls, _ = per_call(timers, "Coulomb: bulk assembly")
    solve, solves, _ = per_call(timers, "Stratimikos: BelosLOWS")
    prec, precs, prec_total = per_call(timers, "NOX Total Preconditioner Construction")
    muelu, muelu_calls, _ = per_call(timers, "ThyraMueLu::initializePrec")
    # a solve that keeps the last preconditioner (Newton/Reuse Preconditioner)
    # passes NOX's construction timer without a setup: per setup, not per call
    setups = muelu_calls or precs
    prec = prec_total / setups if setups else None
    assembly_total = timers.get("Coulomb: bulk assembly", (0.0, 0))[0]
    solve_total = timers.get("Stratimikos: BelosLOWS", (0.0, 0))[0]
    # contact: the two top-level timers of ContactModel ("update" contains
    # search, mortar values and the triplet matrices; "condensed tangent"
    # contains "tangent rows", the mortar derivatives and derivative rows
    # an update leaves for it, and "K + interface rows"; in builds before
    # the deferred tangent rows both were in "update"); absent in older builds
    update, update_calls, update_total = per_call(timers, "Coulomb: contact update")
    tangent, tangent_calls, tangent_total = per_call(timers, "Coulomb: contact condensed tangent")
    contact_total = (update_total or 0.0) + (tangent_total or 0.0)
    # time of the load-step loop outside all the timers above
    untimed = (console["solver_wall_s"] - assembly_total - solve_total - (prec_total or 0.0) - contact_total
               if console.get("solver_wall_s") is not None and timers else None)
    return {
        "assembly_s_per_call": assembly,
        "assembly_calls": assembly_calls,
        "linear_solve_s_per_solve": solve,
        "linear_solves": solves,
        "preconditioner_s_per_setup": prec,
        "preconditioner_setups": setups,
        "muelu_setup_s": muelu,
        "contact_update_s_per_call": update,
        "contact_update_calls": update_calls,
        "contact_tangent_s_per_call": tangent,
        "contact_tangent_calls": tangent_calls,
        "contact_s": contact_total if (update_calls or tangent_calls) else None,
        "untimed_s": untimed,
    }


def contact_timers(timers):
    """every contact / mortar timer: {name: [total s, calls]}"""
    return {k: [v[0], v[1]] for k, v in timers.items() if re.search(r"contact|mortar", k, re.I)}


def plot(result, script, result_file, png, extra):
    """run a plot script of tests/performance into png; result["plot"] or
    result["plot_error"] (a failure is reported, not fatal)"""
    try:
        proc = subprocess.run(["/usr/bin/python3", os.path.join(PERF, script), result_file, png] + extra,
                              capture_output=True, text=True, timeout=300)
        if proc.returncode == 0 and os.path.exists(png):
            result["plot"] = png
        else:
            result["plot_error"] = (proc.stderr.strip() or f"exit code {proc.returncode}")[-300:]
    except (OSError, subprocess.TimeoutExpired) as exc:
        result["plot_error"] = str(exc)


def ironing_order(result):
    """the ironing line: IRONING_HEAD first, then the rest in their order"""
    return dict({k: result.get(k) for k in IRONING_HEAD}, **{k: v for k, v in result.items() if k not in IRONING_HEAD})
