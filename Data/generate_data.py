#!/usr/bin/env python3
"""Writes the project's own generated meshes into Data/ (small, committed).

    PYTHONPATH=build/vtk/lib/python3/dist-packages /usr/bin/python3 Data/generate_data.py

Every file is produced by vtkAnalyticMeshSource (Filters/), so it can be regenerated at any time;
the same source makes larger or distorted variants on the fly for tests and the benchmark.
"""
import os
import sys

from unstructuredvolume import vtkAnalyticMeshSource
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

HERE = os.path.dirname(os.path.abspath(__file__))

# name: (resolution, field, distortion, cells)
MESHES = {
    # The default dataset of the README's main command: a twisted hexahedral grid carrying the
    # Marschner-Lobb signal, a hard case for volume renderers (fine ripples, curved cells).
    "marschner_lobb_twisted_hex.vtu": (16, vtkAnalyticMeshSource.MARSCHNER_LOBB,
                                       vtkAnalyticMeshSource.TWIST, vtkAnalyticMeshSource.HEXAHEDRA),
}


def main(out_dir=HERE):
    for name, (resolution, field, distortion, cells) in MESHES.items():
        source = vtkAnalyticMeshSource()
        source.SetResolution(resolution, resolution, resolution)
        source.SetField(field)
        source.SetDistortion(distortion)
        source.SetCellKind(cells)
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputConnection(source.GetOutputPort())
        writer.SetDataModeToAppended()
        writer.SetCompressorTypeToZLib()
        writer.SetFileName(os.path.join(out_dir, name))
        if not writer.Write():
            sys.exit("could not write " + name)
        print("wrote", os.path.join(out_dir, name))


if __name__ == "__main__":
    main(*sys.argv[1:])
