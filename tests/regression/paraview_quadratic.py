"""Opens the quadratic meshes Coulomb writes (coulomb_gmsh2exo output of the
order-2 meshes, exodus_meshes/block*_<type>.e) with ParaView's Exodus reader
and checks that it makes quadratic cells of them, not linear ones (run by
pvpython from tests/regression/paraview.cmake).

usage: pvpython paraview_quadratic.py MESH_DIR

Checks, per file: every cell of the block has the VTK cell type of its
Exodus type (QUAD8 -> VTK_QUADRATIC_QUAD, QUAD9 -> VTK_BIQUADRATIC_QUAD,
TRI6 -> VTK_QUADRATIC_TRIANGLE, HEX20 -> VTK_QUADRATIC_HEXAHEDRON, HEX27 ->
VTK_TRIQUADRATIC_HEXAHEDRON, TET10 -> VTK_QUADRATIC_TETRA). Exit code 0 when
all hold, 1 otherwise.
"""
import os
import sys

from vtkmodules.vtkCommonDataModel import (VTK_BIQUADRATIC_QUAD, VTK_QUADRATIC_HEXAHEDRON, VTK_QUADRATIC_QUAD,
                                           VTK_QUADRATIC_TETRA, VTK_QUADRATIC_TRIANGLE, VTK_TRIQUADRATIC_HEXAHEDRON)
from vtkmodules.vtkIOExodus import vtkExodusIIReader

EXPECTED = {
    "block2d_quad8.e": VTK_QUADRATIC_QUAD,
    "block2d_quad9.e": VTK_BIQUADRATIC_QUAD,
    "block2d_tri6.e": VTK_QUADRATIC_TRIANGLE,
    "block3d_hex20.e": VTK_QUADRATIC_HEXAHEDRON,
    "block3d_hex27.e": VTK_TRIQUADRATIC_HEXAHEDRON,
    "block3d_tet10.e": VTK_QUADRATIC_TETRA,
}


def cell_types(path):
    reader = vtkExodusIIReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    reader.SetObjectArrayStatus(vtkExodusIIReader.ELEM_BLOCK, 0, 1)
    reader.Update()
    grid = reader.GetOutput().GetBlock(0).GetBlock(0)
    return {grid.GetCellType(i) for i in range(grid.GetNumberOfCells())}


def main(directory):
    failures = 0
    for name, vtk_type in sorted(EXPECTED.items()):
        path = os.path.join(directory, name)
        types = cell_types(path) if os.path.isfile(path) else set()
        ok = types == {vtk_type}
        print(("ok:     " if ok else "FAILED: ") + "%s: VTK cell types %s, expected {%d}" % (name, sorted(types), vtk_type))
        failures += not ok
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
