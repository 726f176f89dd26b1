#!/usr/bin/env python3
"""The README's main job: renders the bundled default dataset and names the PNG files it wrote.

The default hexahedral mesh ray-cast as hexahedra by this project's vtkHexahedralRayCastMapper,
split by vtkHexahedraToTetrahedra and volume-rendered with vtkPreIntegratedTetrahedraMapper (alone,
then with a lit isosurface), beside VTK's own vtkProjectedTetrahedraMapper for comparison, and the
gradient from vtkVertexGradientFilter on a cut plane.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import uvrender  # noqa: E402

from unstructuredvolume import vtkHexahedraToTetrahedra, vtkVertexGradientFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--input", default=os.path.join(uvrender.ROOT, "Data", "marschner_lobb_twisted_hex.vtu"))
    parser.add_argument("--scalar", default="MarschnerLobb")
    parser.add_argument("--output", default=os.path.join(uvrender.ROOT, "out"))
    parser.add_argument("--size", type=int, default=512)
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.input)
    reader.Update()
    mesh = reader.GetOutput()
    if mesh.GetNumberOfCells() == 0:
        sys.exit("no cells read from " + args.input)
    print(f"read {args.input}: {mesh.GetNumberOfPoints()} points, {mesh.GetNumberOfCells()} cells")

    split = vtkHexahedraToTetrahedra()
    split.SetInputData(mesh)
    split.Update()
    tets = split.GetOutput()
    print(f"vtkHexahedraToTetrahedra: {tets.GetNumberOfCells()} tetrahedra")

    gradient = vtkVertexGradientFilter()
    gradient.SetInputData(mesh)
    gradient.SetInputArrayToProcess(0, 0, 0, 0, args.scalar)
    gradient.Update()
    print("vtkVertexGradientFilter: array 'Gradients' on", gradient.GetOutput().GetNumberOfPoints(), "points")

    low, high = tets.GetPointData().GetArray(args.scalar).GetRange()
    written = [
        uvrender.render_hexahedral_ray_cast(
            mesh, args.scalar, os.path.join(args.output, "default_hexahedral_ray_cast.png"), args.size),
        uvrender.render_preintegrated_tetrahedra(
            tets, args.scalar, os.path.join(args.output, "default_preintegrated_tetrahedra.png"), args.size),
        uvrender.render_preintegrated_tetrahedra(
            tets, args.scalar, os.path.join(args.output, "default_preintegrated_isosurface.png"), args.size,
            isovalue=low + 0.6 * (high - low)),
        uvrender.render_barycentric_shells(
            tets, args.scalar, os.path.join(args.output, "default_barycentric_shells.png"), args.size),
        uvrender.render_projected_tetrahedra(
            tets, args.scalar, os.path.join(args.output, "default_split_projected_tetrahedra.png"), args.size),
        uvrender.render_gradient_cut(
            gradient.GetOutput(), "Gradients", os.path.join(args.output, "default_gradient_cut.png"), args.size),
    ]
    for path in written:
        print("wrote", path)


if __name__ == "__main__":
    main()
