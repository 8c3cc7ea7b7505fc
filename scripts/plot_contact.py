#!/usr/bin/python3
"""Plots of a Coulomb contact result (run by scripts/render).

usage: plot_contact.py RESULT.e PREFIX [--small]

Writes, when the result holds contact (nothing otherwise):
  PREFIX_qp.png             frictional pairs: Q/P over pseudo time, Q and P the
                            magnitudes of the tangential and normal contact
                            forces (globals contact_tangential_force_<pair>,
                            contact_normal_force_<pair>), with mu when the
                            result holds contact_friction_coefficient_<pair>;
  PREFIX_pressure_line.png  contact pressure at the last step along a line of
                            slave nodes: along the slave surface's longer
                            in-plane axis, through the row of nodes nearest
                            the middle of the other one (2D: all slave nodes),
                            each node marked by its state (open, slip, stick).
Slave nodes are those with a contact normal (|contact_normal| > 0.5), as in
render_paraview.py. Reads the file with netCDF4 (an Exodus II file is netCDF).
--small: 480 x 320 pixels instead of 640 x 400 (the README's gallery).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import netCDF4  # noqa: E402
import numpy  # noqa: E402

FIGURE_SIZE = [6.4, 4.0]  # inches at 100 dpi
STATES = {0: ("open", "#b0b0b0"), 1: ("slip", "#f08c1a"), 2: ("stick", "#2666d9")}


def names(dataset, variable):
    """The strings of an Exodus name variable (char array, one name a row)."""
    if variable not in dataset.variables:
        return []
    return [str(n).strip() for n in netCDF4.chartostring(dataset.variables[variable][:])]


def read(path):
    with netCDF4.Dataset(path) as d:
        d.set_auto_mask(False)
        times = numpy.array(d.variables["time_whole"][:])
        globals_ = {}
        for i, name in enumerate(names(d, "name_glo_var")):
            globals_[name] = numpy.array(d.variables["vals_glo_var"][:, i])
        nodal = {}
        for i, name in enumerate(names(d, "name_nod_var")):
            nodal[name] = numpy.array(d.variables["vals_nod_var%d" % (i + 1)][-1, :])
        dimension = d.dimensions["num_dim"].size
        coordinates = numpy.stack([numpy.array(d.variables["coord" + c][:]) for c in "xyz"[:dimension]], axis=1)
    return times, globals_, nodal, coordinates


def plot_qp(prefix, base, times, globals_):
    pairs = sorted(n[len("contact_normal_force_"):] for n in globals_ if n.startswith("contact_normal_force_"))
    if not pairs:
        return None
    figure, axes = plt.subplots(figsize=FIGURE_SIZE, dpi=100)
    for pair in pairs:
        normal = globals_["contact_normal_force_" + pair]
        tangential = globals_["contact_tangential_force_" + pair]
        ratio = numpy.where(normal > 0, tangential / numpy.where(normal > 0, normal, 1.0), numpy.nan)
        axes.plot(times, ratio, "o-", markersize=3, label="Q/P, pair '%s'" % pair)
        mu = globals_.get("contact_friction_coefficient_" + pair)
        if mu is not None and numpy.all(mu > 0):
            axes.axhline(mu[-1], color="k", linestyle="--", linewidth=1, label="mu = %g" % mu[-1])
    axes.set_xlabel("pseudo time")
    axes.set_ylabel("Q / P (tangential / normal contact force)")
    axes.set_title("%s: friction ratio" % base)
    axes.set_ylim(bottom=0)
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    out = prefix + "_qp.png"
    figure.savefig(out)
    plt.close(figure)
    return out


def plot_pressure_line(prefix, base, times, nodal, coordinates):
    if "contact_pressure" not in nodal:
        return None
    dimension = coordinates.shape[1]
    normals = numpy.stack([nodal["contact_normal_" + c] for c in "xyz"[:dimension]], axis=1)
    slave = (normals ** 2).sum(axis=1) > 0.25
    if not slave.any():
        return None
    points = coordinates[slave]
    mean_normal = numpy.abs(normals[slave].mean(axis=0))
    in_plane = [c for c in range(dimension) if c != int(numpy.argmax(mean_normal))]
    extent = [numpy.ptp(points[:, c]) for c in in_plane]
    along = in_plane[int(numpy.argmax(extent))]
    chosen = numpy.ones(len(points), dtype=bool)
    where = ""
    if dimension == 3:
        across = in_plane[1 - int(numpy.argmax(extent))]
        values = points[:, across]
        middle = 0.5 * (values.min() + values.max())
        row = values[numpy.argmin(numpy.abs(values - middle))]
        tolerance = 1e-6 * max(numpy.ptp(values), 1e-300)
        chosen = numpy.abs(values - row) <= tolerance
        where = " at %s = %.4g" % ("xyz"[across], row)
    x = points[chosen, along]
    pressure = nodal["contact_pressure"][slave][chosen]
    state = nodal["contact_state"][slave][chosen].round().astype(int)
    order = numpy.argsort(x)
    figure, axes = plt.subplots(figsize=FIGURE_SIZE, dpi=100)
    axes.plot(x[order], pressure[order], "-", color="0.3", linewidth=1)
    for value, (label, colour) in STATES.items():
        mask = state[order] == value
        if mask.any():
            axes.plot(x[order][mask], pressure[order][mask], "o", color=colour, label=label)
    axes.set_xlabel("%s (reference position on the slave surface%s)" % ("xyz"[along], where))
    axes.set_ylabel("contact pressure")
    axes.set_ylim(bottom=0)
    axes.set_title("%s: contact pressure at t = %g" % (base, times[-1]))
    axes.grid(True, alpha=0.3)
    axes.legend(title="node state")
    figure.tight_layout()
    out = prefix + "_pressure_line.png"
    figure.savefig(out)
    plt.close(figure)
    return out


def main(argv):
    if len(argv) == 4 and argv[3] == "--small":
        FIGURE_SIZE[:] = [4.8, 3.2]
        argv = argv[:3]
    if len(argv) != 3:
        print("usage: plot_contact.py RESULT.e PREFIX [--small]", file=sys.stderr)
        return 2
    path, prefix = argv[1], argv[2]
    times, globals_, nodal, coordinates = read(path)
    if len(times) == 0:
        print("plot_contact: %s holds no time step" % path, file=sys.stderr)
        return 1
    base = path.rsplit("/", 1)[-1]
    for out in (plot_qp(prefix, base, times, globals_), plot_pressure_line(prefix, base, times, nodal, coordinates)):
        if out:
            print("  %s (%d kB)" % (os.path.abspath(out), (os.path.getsize(out) + 512) // 1024))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
