#!/usr/bin/env python3
"""Run time against error: every mapper, every scene, one process, against the exact reference.

    PYTHONPATH=build/vtk/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Testing/Benchmark/benchmark.py [--quick] [--size 384] [--views 4] [--all-variants] [--output out/benchmark]

For each scene (mesh, scalar, transfer function, an orbit of camera positions) and each mapper:
preparation time (the first frame), then the median and spread of the frame time over the orbit
(each frame ends with WaitForCompletion, i.e. glFinish), the process's resident memory after the
first frame, the GPU buffers the mesh takes per cell of the scene (this project's mappers), the
error of every frame against vtkUnstructuredVolumeReferenceRenderer at the same view (on the float
image for this project's mappers, which keep it; on the 8-bit window for VTK's). Writes results.csv, results.json, results.md (a table), and per scene a log-log plot of time against error with the
Pareto front (<scene>_time_vs_error.png) and a montage (<scene>_montage.png: top row the reference
then each mapper's first view, bottom row their error heat maps). Reference images are cached in
<output>/reference-cache, keyed by everything that determines them. With --write-readme it also
writes Testing/Benchmark/README.md (or the path given): how and where the run was made, its one
table, and its ratios against VTK's mappers, so that the published numbers are always one run's.

Mappers register in MAPPERS below: a name, a factory, and the input it takes: "tets" (the scene's
mesh split into tetrahedra), "hexahedra" (the mesh itself; run on scenes of the cells the hexahedral
walk takes: hexahedra, voxels, wedges, pyramids, tetrahedra), "image" (image-data scenes only: the
image itself, whose voxels the other mappers take) or "any" (the mesh itself, whatever its cells:
every scene). ParaView's Resample To Image (resampled_volume.py) takes "any": its factory resamples
the mesh, and the resampling counts in its first frame (the preparation).
"""
import argparse
import csv
import hashlib
import json
import math
import os
import shlex
import statistics
import sys
import time

from unstructuredvolume import (vtkAnalyticMeshSource, vtkBarycentricShellMapper, vtkHexahedraToTetrahedra,
                                vtkHigherOrderSubdivision,
                                vtkHexahedralRayCastMapper, vtkPreIntegratedTetrahedraMapper,
                                vtkUnstructuredVolumeReferenceRenderer, vtkVolumeImageErrorMetrics)
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartLegend, vtkChartXY, vtkPlotPoints
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction, vtkTable, vtkUnstructuredGrid
from vtkmodules.vtkImagingCore import vtkImageConstantPad
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkImageAppend, vtkPointDataToCellData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter
from vtkmodules.vtkRenderingCore import (vtkCamera, vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingVolume import (vtkGPUVolumeRayCastMapper, vtkProjectedTetrahedraMapper,
                                           vtkUnstructuredGridVolumeRayCastMapper,
                                           vtkUnstructuredGridVolumeZSweepMapper)
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Python"))
import uvrender  # noqa: E402
from fixtures import analytic, grab_rgba, hex_dominant, sampled_color_map  # noqa: E402
from resampled_volume import ResampleToImage  # noqa: E402
from shared_data import (SHARED, bluntfin, bucky_image, can, disk_out_ref, image_as_voxels, legacy,  # noqa: E402
                         neghip_image, openfoam_cavity_cells)
INTERACTIVE = ", interactive"
INTERACTIVE_RATE = 10.0  # the render window's desired update rate while the camera moves (frames a second)
STILL_RATE = 0.0001      # vtkRenderWindowInteractor's still rate
REFERENCE_VERSION = "3"  # bump when the reference renderer's output changes (2: no lost cells, superposition; 3: rounding overlaps touch)

# ---------------------------------------------------------------------------------------------
# Mappers: (name, factory, input: "tets", "hexahedra", "image" or "any"). This project's mappers register
# here as they land.
MAPPERS = [
    # Image-data scenes only: VTK's GPU ray caster on the image itself (the others take its voxels).
    ("VTK GPUVolumeRayCast", vtkGPUVolumeRayCastMapper, "image"),
    # ParaView's Resample To Image (128^3 its default): the mesh resampled, then VTK's GPU ray caster,
    # blanking the points outside the mesh as ParaView does; and once with the valid-point mask as the
    # ray caster's binary mask instead of the blanking.
    *[(f"VTK Resample {n}^3", ResampleToImage(n), "any") for n in (64, 128, 256)],
    ("VTK Resample 128^3 masked", ResampleToImage(128, binary_mask=True), "any"),
    ("VTK ProjectedTetrahedra", vtkProjectedTetrahedraMapper, "tets"),
    ("VTK UGVolumeRayCast", vtkUnstructuredGridVolumeRayCastMapper, "tets"),
    ("VTK UGZSweep", vtkUnstructuredGridVolumeZSweepMapper, "tets"),
    ("UV PreIntegratedTetrahedra", vtkPreIntegratedTetrahedraMapper, "tets"),
    # The default chooses by size (RenderMode AUTOMATIC): each way forced.
    ("UV PreIntegratedTetrahedra, ray casting",
     lambda: configured(vtkPreIntegratedTetrahedraMapper, RenderModeToRayCasting=None), "tets"),
    ("UV PreIntegratedTetrahedra, projection",
     lambda: configured(vtkPreIntegratedTetrahedraMapper, RenderModeToProjection=None), "tets"),
    # Fewer rays or fragments (ImageSampleDistance): the image drawn at half and a quarter of the
    # viewport's width and height, stretched over it.
    *[(f"UV PreIntegratedTetrahedra, image sample distance {n}",
       (lambda n=n: configured(vtkPreIntegratedTetrahedraMapper, ImageSampleDistance=float(n))), "tets")
      for n in (2, 4)],
    # Exact segments (cut at every node) where the default reads its segment table.
    ("UV PreIntegratedTetrahedra, exact segments",
     lambda: configured(vtkPreIntegratedTetrahedraMapper, SegmentIntegration=2), "tets"),
    ("UV PreIntegrated (geometry shader)", lambda: configured(vtkPreIntegratedTetrahedraMapper,
                                                             ProjectionRouteToGeometryShader=None,
                                                             RenderModeToProjection=None), "tets"),
    ("UV AverageScalarTetrahedra", lambda: configured(vtkPreIntegratedTetrahedraMapper,
                                                      IntegrationModeToAverageScalar=None), "tets"),
    ("UV HexRayCast Accurate", vtkHexahedralRayCastMapper, "hexahedra"),
    ("UV HexRayCast Fast", lambda: configured(vtkHexahedralRayCastMapper, IntegrationModeToFast=None), "hexahedra"),
    ("UV HexRayCast 8 steps", lambda: configured(vtkHexahedralRayCastMapper, IntegrationModeToFixedSteps=None),
     "hexahedra"),
    ("UV HexRayCast Accurate, image sample distance 2",
     lambda: configured(vtkHexahedralRayCastMapper, ImageSampleDistance=2.0), "hexahedra"),
    # Accurate without early ray termination: what stopping at opacity 0.999 saves and costs.
    ("UV HexRayCast Accurate, no early stop", lambda: configured(vtkHexahedralRayCastMapper, OpacityThreshold=1.0),
     "hexahedra"),
    # Against the default's SkipInvisibleCells: what skipping saves; skipping_table() pairs each
    # "<mapper>, no skipping" (or "<mapper>, skipping", for a mapper whose default is off) with "<mapper>".
    ("UV HexRayCast Accurate, no skipping",
     lambda: configured(vtkHexahedralRayCastMapper, SkipInvisibleCells=False), "hexahedra"),
    # Every transfer-function node kept (TransferFunctionTolerance 0): what dropping nodes saves.
    ("UV PreIntegratedTetrahedra, every node",
     lambda: configured(vtkPreIntegratedTetrahedraMapper, TransferFunctionTolerance=0.0), "tets"),
    ("UV BarycentricShells 128, every node",
     lambda: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=128, TransferFunctionTolerance=0.0), "tets"),
    ("UV BarycentricCellProjection, every node",
     lambda: configured(vtkBarycentricShellMapper, RenderModeToCellProjection=None, TransferFunctionTolerance=0.0),
     "tets"),
    ("UV PreIntegratedTetrahedra, no skipping",
     lambda: configured(vtkPreIntegratedTetrahedraMapper, SkipInvisibleCells=False), "tets"),
    ("UV BarycentricShells 128, no skipping",
     lambda: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=128, SkipInvisibleCells=False), "tets"),
    # Barycentric shells from coarse to fine sampling (samples across the mesh's bounding box diagonal;
    # 128 is the default), the paper's geometry-shader route, and the same pipeline's
    # cell projection.
    *[(f"UV BarycentricShells {n}", (lambda n=n: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=n)),
       "tets") for n in (32, 64, 128, 256, 512)],
    ("UV BarycentricShells 512, exact segments",
     lambda: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=512, SegmentIntegration=2), "tets"),
    ("UV BarycentricShells 512, no early stop",
     lambda: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=512, OpacityThreshold=1.0), "tets"),
    ("UV BarycentricShells 256 (geometry shader)",
     lambda: configured(vtkBarycentricShellMapper, ProjectionRouteToGeometryShader=None, AutomaticSamplesAcross=256),
     "tets"),
    ("UV BarycentricCellProjection", lambda: configured(vtkBarycentricShellMapper, RenderModeToCellProjection=None),
     "tets"),
    # Frames while the camera moves (INTERACTIVE_RATE): each mapper's default, its automatic image sample
    # distance sizing the image to the time the window allows, measured as the window shows it.
    ("UV PreIntegratedTetrahedra" + INTERACTIVE, vtkPreIntegratedTetrahedraMapper, "tets"),
    ("UV BarycentricShells 128" + INTERACTIVE, lambda: configured(vtkBarycentricShellMapper, AutomaticSamplesAcross=128),
     "tets"),
    ("UV HexRayCast Accurate" + INTERACTIVE, vtkHexahedralRayCastMapper, "hexahedra"),
]

# The variants a run takes unless --all-variants: VTK's mappers, Resample To Image at three resolutions
# and with its mask, each of this project's mappers at its defaults, a few points along each one's
# time-against-error curve, and the interactive frames. The others measure one setting each.
DEFAULT_VARIANTS = (
    "VTK GPUVolumeRayCast", "VTK Resample 64^3", "VTK Resample 128^3", "VTK Resample 256^3", "VTK Resample 128^3 masked",
    "VTK ProjectedTetrahedra", "VTK UGVolumeRayCast", "VTK UGZSweep",
    "UV PreIntegratedTetrahedra", "UV PreIntegratedTetrahedra, image sample distance 2",
    "UV PreIntegratedTetrahedra, exact segments", "UV HexRayCast Accurate",
    "UV BarycentricShells 64", "UV BarycentricShells 128", "UV BarycentricShells 256", "UV BarycentricCellProjection",
    "UV PreIntegratedTetrahedra" + INTERACTIVE, "UV BarycentricShells 128" + INTERACTIVE,
    "UV HexRayCast Accurate" + INTERACTIVE,
)

# VTK's CPU mappers above these many cells of their input take minutes a frame on this machine: left
# out there (the README says where), as a user would.
CELL_LIMITS = {"VTK UGZSweep": 300_000, "VTK UGVolumeRayCast": 1_500_000}


def configured(factory, **settings):
    """A mapper with Set<name>(value) applied for each setting (value None: Set<name>())."""
    mapper = factory()
    for name, value in settings.items():
        setter = getattr(mapper, "Set" + name)
        setter() if value is None else setter(value)
    return mapper


# ---------------------------------------------------------------------------------------------
# Scenes
def wavelet_through(conversion, points=64):
    """VTK's wavelet on points^3 points through `conversion` (a filter), updated."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(*(-points // 2, points // 2 - 1) * 3)
    conversion.SetInputConnection(wavelet.GetOutputPort())
    conversion.Update()
    return conversion.GetOutput()


def wavelet_tets(points=64):
    """The wavelet, five tetrahedra per cell: 1.25 M tetrahedra (10.2 M on 128^3 points)."""
    split = vtkHexahedraToTetrahedra()
    split.SetSplitModeToFiveTetrahedra()
    return wavelet_through(split, points)


def wavelet_hexahedra():
    """The wavelet as an unstructured grid of 250,047 hexahedra."""
    return wavelet_through(vtkAppendFilter())


def split_tets(load):
    """The 6-tet split of a mesh: renders the tets' own (piecewise-linear) field."""
    def loader():
        split = vtkHexahedraToTetrahedra()
        split.SetInputData(load())
        split.Update()
        return split.GetOutput()
    return loader


def smooth_ramp(low, high):
    """Opacity ramping up over the range, cool-to-warm colours."""
    return [(low, 0.0), (low + 0.2 * (high - low), 0.02), (high, 0.6)], \
        [(low, (0.23, 0.30, 0.75)), (0.5 * (low + high), (0.87, 0.87, 0.87)), (high, (0.71, 0.02, 0.15))]


def spikes(low, high):
    """Three thin opaque spikes: hard for every method that samples or averages."""
    opacity, colors = [(low, 0.0)], [(low, (0.2, 0.2, 0.9))]
    for fraction, color in ((0.3, (1.0, 0.6, 0.1)), (0.55, (0.1, 0.9, 0.3)), (0.8, (0.9, 0.1, 0.2))):
        centre = low + fraction * (high - low)
        width = 0.02 * (high - low)
        opacity += [(centre - width, 0.0), (centre, 0.9), (centre + width, 0.0)]
        colors += [(centre, color)]
    opacity.append((high, 0.0))
    colors.append((high, (0.9, 0.9, 0.9)))
    return opacity, colors


def top_tenth(low, high):
    """Only the top tenth of the range visible, ramping up: most of the mesh is empty space."""
    start = low + 0.9 * (high - low)
    return [(low, 0.0), (start, 0.0), (high, 0.8)], [(low, (0.2, 0.3, 0.9)), (start, (0.9, 0.8, 0.3)),
                                                     (high, (0.9, 0.1, 0.1))]


def on_cells(scalar):
    """A scene's scalar "cells:NAME" is the cell array NAME; any other the point array of that name."""
    return bool(scalar) and scalar.startswith("cells:")


def array_name(scalar):
    return scalar[len("cells:"):] if on_cells(scalar) else scalar


def with_cell_data(load):
    """The mesh's point scalar averaged to its cells, the point data removed: a cell-data scene."""
    def loaded():
        average = vtkPointDataToCellData()
        average.SetInputData(load())
        average.Update()
        cells = vtkUnstructuredGrid()
        cells.CopyStructure(average.GetOutput())
        cells.GetCellData().ShallowCopy(average.GetOutput().GetCellData())
        return cells
    return loaded


# Run only when --scenes names them: the 10.2 M-tetrahedron wavelet, too large for every run, and the
# 1.25 M wavelet's other transfer functions, whose exact references alone would take most of a run's
# budget on this machine (the default run keeps the wavelet with the ramp).
ON_REQUEST = ("wavelet128_tets", "wavelet128_tets_colormap256", "wavelet_tets_colormap256", "wavelet_tets_opaque")
# The default image: 384 px a side keeps a run of every default scene and variant, with its exact
# references, within about 45 minutes on this machine; --size 512 for the figures at 512.
DEFAULT_SIZE = 384


def scenes(quick):
    """(name, loader, scalar, transfer-function maker, unit distance as a fraction of the diagonal[,
    subdivision level of a higher-order mesh: the mappers draw that, the reference the mesh itself]).
    Scenes named "NAME@..." share NAME's reference images."""
    ml, steiner = vtkAnalyticMeshSource.MARSCHNER_LOBB, vtkAnalyticMeshSource.STEINER
    twist, jitter = vtkAnalyticMeshSource.TWIST, vtkAnalyticMeshSource.JITTER
    hexahedra, tets = vtkAnalyticMeshSource.HEXAHEDRA, vtkAnalyticMeshSource.SIX_TETRAHEDRA
    resolution = 8 if quick else 24
    found = [
        ("ml_tets", lambda: analytic(resolution, ml, 0, tets), "MarschnerLobb", smooth_ramp, 0.05),
        ("ml_twisted_hex", lambda: analytic(resolution, ml, twist, hexahedra), "MarschnerLobb", smooth_ramp, 0.05),
        ("steiner_jittered_hex_spikes", lambda: analytic(resolution, steiner, jitter, hexahedra), "Steiner",
         spikes, 0.02),
    ]
    if quick:
        return found[:2]
    found.append(("wavelet_tets", wavelet_tets, "RTData", smooth_ramp, 0.05))
    # A colour map sampled at 256 nodes, as ParaView's presets are (TransferFunctionTolerance).
    found.append(("wavelet_tets_colormap256", wavelet_tets, "RTData", sampled_color_map, 0.05))
    # Dense and nearly opaque: most rays saturate well inside the mesh (early termination).
    found.append(("wavelet_tets_opaque", wavelet_tets, "RTData", smooth_ramp, 0.002))
    # 10.2 M tetrahedra, with the ramp and the sampled map: run only when --scenes names them.
    found.append(("wavelet128_tets", lambda: wavelet_tets(128), "RTData", smooth_ramp, 0.05))
    found.append(("wavelet128_tets_colormap256", lambda: wavelet_tets(128), "RTData", sampled_color_map, 0.05))
    # Empty space: the same wavelet's hexahedra with only the top tenth of the range visible.
    found.append(("wavelet_hex_top_tenth", wavelet_hexahedra, "RTData", top_tenth, 0.05))
    found.append(("ml_twisted_hex_cells", with_cell_data(lambda: analytic(resolution, ml, twist, hexahedra)),
                  "cells:MarschnerLobb", smooth_ramp, 0.05))
    # Hex-dominant: wedge columns, pyramids and tetrahedra among jittered hexahedra (fixtures.hex_dominant).
    found.append(("ml_hex_dominant_mixed", lambda: hex_dominant(resolution), "MarschnerLobb", smooth_ramp, 0.05))
    if os.path.isdir(SHARED):
        found += [
            ("bluntfin_hex", bluntfin, "Density", smooth_ramp, 0.03),
            ("bluntfin_tets", split_tets(bluntfin), "Density", smooth_ramp, 0.03),
            ("disk_out_ref_hex", disk_out_ref, "Temp", smooth_ramp, 0.05),
            ("can_hex", can, "DISPL_magnitude", smooth_ramp, 0.05),
            ("spx_tets", lambda: legacy("spx", "spx.vtk"), None, smooth_ramp, 0.05),
            ("lox_post_tets", lambda: legacy("lox_post", "post.vtk"), "Pressure", smooth_ramp, 0.05),
            ("openfoam_cavity_cells_hex", openfoam_cavity_cells, "cells:p", smooth_ramp, 0.05),
            # Image data (the loader returns the image; the mappers but VTK's GPU ray caster take its voxels).
            ("bucky_voxels", bucky_image, "density", top_tenth, 0.05),
            ("neghip_voxels", neghip_image, "density", smooth_ramp, 0.02),
        ]
        # The quadratic cylinder: the reference renders its quadratic tetrahedra exactly, the mappers
        # draw vtkHigherOrderSubdivision's linear cells at each level (error against level).
        found += [(f"cylinder_quadratic@L{level}", lambda: legacy("quadratic", "CylinderQuadratic.vtk"),
                   "velocity_norm", smooth_ramp, 0.05, level) for level in (1, 2, 4, 8)]
    return found


def subdivided(mesh, level):
    """The higher-order mesh as linear cells at `level` (None: the mesh itself)."""
    if not level:
        return mesh
    subdivision = vtkHigherOrderSubdivision()
    subdivision.SetInputData(mesh)
    subdivision.SetLevel(level)
    subdivision.Update()
    return subdivision.GetOutput()


def volume_property(mesh, scalar, maker, unit_fraction):
    arrays = mesh.GetCellData() if on_cells(scalar) else mesh.GetPointData()
    low, high = (arrays.GetArray(array_name(scalar)) if scalar else arrays.GetScalars()).GetRange()
    opacity_nodes, color_nodes = maker(low, high)
    opacity = vtkPiecewiseFunction()
    for s, a in opacity_nodes:
        opacity.AddPoint(s, a)
    colors = vtkColorTransferFunction()
    colors.SetColorSpaceToRGB()
    for s, rgb in color_nodes:
        colors.AddRGBPoint(s, *rgb)
    prop = vtkVolumeProperty()
    prop.SetColor(colors)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    prop.SetScalarOpacityUnitDistance(unit_fraction * mesh.GetLength())
    return prop, opacity_nodes, color_nodes


def orbit(mesh, views):
    """Cameras around the mesh at 20 degrees elevation, 8 by default; a perspective orbit."""
    bounds = mesh.GetBounds()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    radius = 1.9 * mesh.GetLength()
    cameras = []
    for k in range(views):
        azimuth = 2 * math.pi * k / views
        camera = vtkCamera()
        camera.SetFocalPoint(*centre)
        camera.SetPosition(centre[0] + radius * math.cos(azimuth) * math.cos(0.35),
                           centre[1] + radius * math.sin(azimuth) * math.cos(0.35),
                           centre[2] + radius * math.sin(0.35))
        camera.SetViewUp(0, 0, 1)
        camera.SetViewAngle(30)
        camera.SetClippingRange(radius - mesh.GetLength(), radius + mesh.GetLength())
        cameras.append(camera)
    return cameras


# ---------------------------------------------------------------------------------------------
def reference_image(cache, key_parts, mesh, scalar, prop, camera, size):
    """The reference at this view, from the cache when it was computed before."""
    key = hashlib.sha1(json.dumps(key_parts, sort_keys=True).encode()).hexdigest()[:20]
    path = os.path.join(cache, key + ".vti")
    if os.path.exists(path):
        reader = vtkXMLImageDataReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput(), 0.0
    renderer = vtkUnstructuredVolumeReferenceRenderer()
    renderer.SetInputData(mesh)
    if scalar:
        renderer.SetScalarArrayName(array_name(scalar))
    if on_cells(scalar):
        renderer.SetScalarModeToUseCellFieldData()
    renderer.SetVolumeProperty(prop)
    renderer.SetCamera(camera)
    renderer.SetImageSize(size, size)
    start = time.perf_counter()
    if not renderer.Render():
        raise RuntimeError("reference renderer failed")
    seconds = time.perf_counter() - start
    image = vtkImageData()
    image.DeepCopy(renderer.GetOutput())
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()
    return image, seconds


def resident_megabytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def run_mapper(name, factory, mesh, scalar, prop, cameras, size):
    renderer = vtkRenderer()
    renderer.SetBackground(0, 0, 0)
    renderer.SetBackgroundAlpha(0.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    filtering, filter_memory = 0.0, 0.0
    if isinstance(factory, ResampleToImage):
        # ParaView resamples in its representation's update, before the first render: the filter's time
        # and memory count in the first frame's. The image holds a cell array as point data.
        before, start = resident_megabytes(), time.perf_counter()
        mapper = factory.mapper_for(mesh, array_name(scalar) if scalar else None)
        filtering, filter_memory = time.perf_counter() - start, resident_megabytes() - before
    else:
        mapper = factory()
        mapper.SetInputData(mesh)
        if scalar:
            if on_cells(scalar):
                mapper.SetScalarModeToUseCellFieldData()
            else:
                mapper.SetScalarModeToUsePointFieldData()
            mapper.SelectScalarArray(array_name(scalar))
    # This project's mappers keep their float image: the error is then the integral's, not the 8-bit
    # window's rounding (about 0.0011 RMSE). Reading it back adds a little to a frame. An image drawn
    # smaller than the viewport (ImageSampleDistance) is measured as the window shows it, stretched.
    # Interactive frames are reduced too: the window shows them stretched.
    interactive = name.endswith(INTERACTIVE)
    float_image = hasattr(mapper, "SetKeepFloatImage") and mapper.GetImageSampleDistance() == 1.0 and not interactive
    if float_image:
        mapper.SetKeepFloatImage(True)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)

    before = resident_megabytes()
    renderer.SetActiveCamera(cameras[0])
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    preparation = filtering + time.perf_counter() - start
    memory = filter_memory + resident_megabytes() - before
    if interactive:
        window.SetDesiredUpdateRate(INTERACTIVE_RATE)
        for _ in range(3):  # the image size settles from the still frame's time (it at most doubles a frame)
            window.Render()
    frames, images = [], []
    for camera in cameras:
        renderer.SetActiveCamera(camera)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        frames.append(time.perf_counter() - start)
        if float_image:
            image = vtkImageData()
            image.DeepCopy(mapper.GetFloatImage())
            images.append(image)
        else:
            images.append(grab_rgba(window))
    mesh_bytes = mapper.GetMeshMemoryInBytes() if hasattr(mapper, "GetMeshMemoryInBytes") else None
    host_bytes = mapper.GetHostMemoryInBytes() if hasattr(mapper, "GetHostMemoryInBytes") else None
    window.SetDesiredUpdateRate(STILL_RATE)
    work = work_done(mapper, window, renderer, cameras[0])
    window.Finalize()
    return preparation, frames, memory, images, (mesh_bytes, host_bytes), work


def work_done(mapper, window, renderer, camera):
    """What the mapper's skipping is measured by, at the first view, as {unit: count}: the
    tetrahedra drawn and the fragments shaded that were not discarded (the tetrahedra mapper,
    counted in one extra frame, as counting waits on each batch), the cells the hexahedral walk
    takes, the tetrahedra the shells draw; empty for other mappers."""
    if hasattr(mapper, "SetCountShadedFragments"):
        mapper.SetCountShadedFragments(True)
        renderer.SetActiveCamera(camera)
        window.Render()
        mapper.SetCountShadedFragments(False)
        statistics = mapper.GetFrameStatistics()
        return {"tetrahedra drawn": int(statistics.GetValue("DrawnTetrahedra")),
                "fragments shaded": int(statistics.GetValue("ShadedFragments"))}
    statistics = mapper.GetFrameStatistics() if hasattr(mapper, "GetFrameStatistics") else None
    if statistics and statistics.HasValue("VisibleCells"):
        return {"cells walked": int(statistics.GetValue("VisibleCells"))}
    if statistics and statistics.HasValue("DrawnTetrahedra"):
        return {"tetrahedra drawn": int(statistics.GetValue("DrawnTetrahedra"))}
    return {}


def pareto(points):
    """Indices of the points no other point beats in both time and error (lower is better)."""
    front = []
    for i, (t, e) in enumerate(points):
        if not any((t2 <= t and e2 <= e) and (t2 < t or e2 < e) for t2, e2 in points):
            front.append(i)
    return front


# Plot colours by family (the first prefix that matches), each further member of a family lighter.
FAMILIES = (("VTK Resample", (31, 119, 180)), ("VTK", (90, 90, 90)), ("UV PreIntegrated", (255, 127, 14)),
            ("UV AverageScalar", (255, 127, 14)), ("UV BarycentricShells", (44, 160, 44)),
            ("UV BarycentricCellProjection", (148, 103, 189)), ("UV HexRayCast", (214, 39, 40)))


def plot_style(rows):
    """Per row: (RGB, marker): colour by family, VTK's mappers squares, Resample To Image diamonds,
    this project's circles, interactive frames plus signs."""
    seen, styles = {}, []
    for row in rows:
        name = row["mapper"]
        family, rgb = next(((prefix, rgb) for prefix, rgb in FAMILIES if name.startswith(prefix)), ("", (0, 0, 0)))
        k = seen[family] = seen.get(family, -1) + 1
        lighter = 0.0 if name.endswith(INTERACTIVE) else min(0.6, 0.2 * k)
        rgb = tuple(int(c + (255 - c) * lighter) for c in rgb)
        marker = (vtkPlotPoints.PLUS if name.endswith(INTERACTIVE) else vtkPlotPoints.DIAMOND
                  if name.startswith("VTK Resample") else vtkPlotPoints.SQUARE if name.startswith("VTK")
                  else vtkPlotPoints.CIRCLE)
        styles.append((rgb, marker))
    return styles


def plot_scene(scene, rows, path):
    """Log-log frame time against covered RMSE, one point per mapper, Pareto front as a line."""
    view = vtkContextView()
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderWindow().SetSize(1100, 640)
    chart = vtkChartXY()
    chart.SetTitle(f"{scene}: median frame time vs RMSE against the reference")
    chart.SetShowLegend(True)
    # Beside the plot, not over its points.
    chart.GetLegend().SetInline(False)
    chart.GetLegend().SetHorizontalAlignment(vtkChartLegend.RIGHT)
    chart.GetLegend().SetVerticalAlignment(vtkChartLegend.TOP)
    view.GetScene().AddItem(chart)
    usable = [r for r in rows if r["median_s"] > 0 and r["rmse_covered"] > 0]
    for row, (rgb, marker) in zip(usable, plot_style(usable)):
        table = vtkTable()
        for column in ("time", "error"):
            array = vtkFloatArray()
            array.SetName(column if column == "time" else row["mapper"])
            table.AddColumn(array)
        table.SetNumberOfRows(1)
        table.SetValue(0, 0, row["median_s"])
        table.SetValue(0, 1, row["rmse_covered"])
        plot = chart.AddPlot(vtkChart.POINTS)
        plot.SetInputData(table, 0, 1)
        plot.SetMarkerStyle(marker)
        plot.SetMarkerSize(12)
        plot.SetColor(*rgb, 255)
    front = sorted(pareto([(r["median_s"], r["rmse_covered"]) for r in usable]),
                   key=lambda i: usable[i]["median_s"])
    if front:
        # The front: ringed in black, joined by a line when it has more than one point.
        table = vtkTable()
        for column in ("time", "Pareto front"):
            array = vtkFloatArray()
            array.SetName(column)
            table.AddColumn(array)
        table.SetNumberOfRows(len(front))
        for k, i in enumerate(front):
            table.SetValue(k, 0, usable[i]["median_s"])
            table.SetValue(k, 1, usable[i]["rmse_covered"])
        rings = chart.AddPlot(vtkChart.POINTS)
        rings.SetInputData(table, 0, 1)
        rings.SetMarkerStyle(vtkPlotPoints.CROSS)
        rings.SetMarkerSize(22)
        rings.SetColor(0, 0, 0, 255)
        if len(front) > 1:
            line = chart.AddPlot(vtkChart.LINE)
            line.SetInputData(table, 0, 1)
            line.SetColor(0, 0, 0, 255)
            line.SetWidth(1.5)
    for axis_id, title in ((vtkAxis.BOTTOM, "median frame time (s)"), (vtkAxis.LEFT, "RMSE, covered pixels")):
        axis = chart.GetAxis(axis_id)
        axis.SetTitle(title)
        axis.SetLogScale(True)
    view.GetRenderWindow().Render()
    uvrender.write_png(view.GetRenderWindow(), path)


def over_background(rgba, background=(0.1, 0.1, 0.12)):
    """8-bit RGB of a premultiplied RGBA image over a background, for the montage."""
    out = vtkImageData()
    out.SetDimensions(rgba.GetDimensions())
    out.AllocateScalars(3, 3)  # VTK_UNSIGNED_CHAR
    source = rgba.GetPointData().GetScalars()
    target = out.GetPointData().GetScalars()
    scale = 1.0 / 255.0 if source.GetDataType() == 3 else 1.0
    for i in range(source.GetNumberOfTuples()):
        r, g, b, a = (scale * v for v in source.GetTuple4(i))
        a = min(max(a, 0.0), 1.0)
        target.SetTuple3(i, *(round(255 * min(max(c + (1 - a) * bg, 0.0), 1.0)) for c, bg in zip((r, g, b), background)))
    return out


def montage(top, bottom, path):
    rows = []
    for images in (top, bottom):
        append = vtkImageAppend()
        append.SetAppendAxis(0)
        for image in images:
            append.AddInputData(image)
        append.Update()
        rows.append(append.GetOutput())
    width = max(r.GetDimensions()[0] for r in rows)
    stack = vtkImageAppend()
    stack.SetAppendAxis(1)
    for row in reversed(rows):  # image rows run bottom-up
        pad = vtkImageConstantPad()
        pad.SetInputData(row)
        dims = row.GetDimensions()
        pad.SetOutputWholeExtent(0, width - 1, 0, dims[1] - 1, 0, 0)
        pad.Update()
        stack.AddInputData(pad.GetOutput())
    stack.Update()
    writer = vtkPNGWriter()
    writer.SetInputData(stack.GetOutput())
    writer.SetFileName(path)
    writer.Write()


def per_cell(value):
    """A bytes-per-cell cell of the table: blank where not counted (None, or empty in a CSV)."""
    return "" if value is None or value == "" else round(float(value))


def markdown_table(rows):
    """The results as a Markdown table (for the README and issue notes)."""
    lines = ["| scene | mapper | prep (s) | median frame (s) [min-max] | RMSE covered | max error | memory (MB) "
             "| GPU mesh B/cell | host B/cell |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['mapper']} | {float(r['preparation_s']):.3f} | "
                     f"{float(r['median_s']):.3f} [{float(r['min_s']):.3f}-{float(r['max_s']):.3f}] | "
                     f"{float(r['rmse_covered']):.3g} | {float(r['max_error']):.3g} | {float(r['memory_mb']):.0f} | "
                     f"{per_cell(r.get('gpu_bytes_per_cell'))} | {per_cell(r.get('host_bytes_per_cell'))} |")
    return "\n".join(lines) + "\n"


SKIPPING_OFF, SKIPPING_ON = ", no skipping", ", skipping"


def skipping_table(rows):
    """Per scene, each mapper against itself with SkipInvisibleCells off: frame times, the measured
    speedup, the shares of work skipped (fragments, cells or tetrahedra; for fragments the iSBVR
    paper's culling rate alpha) and the speedup the paper's model bounds it by when the culled work
    costs nothing, 1 / (1 - alpha) of the largest share, and the error of both against the reference."""
    lines = ["| scene | mapper | frame with / without skipping (s) | speedup | work skipped | model bound "
             "| RMSE with / without |",
             "|---|---|---|---|---|---|---|"]
    for variant in (r for r in rows if r["mapper"].endswith((SKIPPING_OFF, SKIPPING_ON))):
        suffix = SKIPPING_OFF if variant["mapper"].endswith(SKIPPING_OFF) else SKIPPING_ON
        name = variant["mapper"][:-len(suffix)]
        default = next((r for r in rows if r["scene"] == variant["scene"] and r["mapper"] == name), None)
        if default is None:
            continue
        on, off = (default, variant) if suffix == SKIPPING_OFF else (variant, default)
        shares = {unit: 1.0 - on["work"][unit] / off["work"][unit] for unit in on["work"] if off["work"].get(unit)}
        skipped = "; ".join(f"{100 * alpha:.0f}% of {unit}" for unit, alpha in shares.items())
        alpha = max(shares.values(), default=0.0)
        bound = (times(1.0 / (1.0 - alpha)) if alpha < 1.0 else "inf") if shares else ""
        lines.append(f"| {on['scene']} | {on['mapper']} | {on['median_s']:.3f} / {off['median_s']:.3f} | "
                     f"{times(off['median_s'] / on['median_s'])} | {skipped} | {bound} | "
                     f"{on['rmse_covered']:.3g} / {off['rmse_covered']:.3g} |")
    return "\n".join(lines) + "\n" if len(lines) > 2 else ""


README_PATH = os.path.join(ROOT, "Testing", "Benchmark", "README.md")
PLOTS = "plots"  # beside the README: one time-against-error plot per scene


def cpu_model():
    """The CPU's model name from /proc/cpuinfo (first entry), or "unknown"."""
    try:
        with open("/proc/cpuinfo") as info:
            for line in info:
                key, _, value = line.partition(":")
                if key.strip() in ("model name", "Hardware", "Processor") and value.strip():
                    return value.strip()
    except OSError:
        pass
    return "unknown"


def opengl_strings():
    """(renderer, version) reported by an off-screen render window like the ones the mappers use."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(8, 8)
    window.AddRenderer(vtkRenderer())
    window.Render()
    found = {}
    for line in (window.ReportCapabilities() or "").splitlines():
        key, _, value = line.partition(":")
        found[key.strip()] = value.strip()
    window.Finalize()
    return found.get("OpenGL renderer string", "unknown"), found.get("OpenGL version string", "unknown")


def run_command():
    """The command line of this run as it could be typed again from the repository root."""
    script = os.path.abspath(sys.argv[0])
    if script.startswith(ROOT + os.sep):
        script = os.path.relpath(script, ROOT)
    return shlex.join([sys.executable, script] + sys.argv[1:])


def is_vtk(row):
    return row["mapper"].startswith("VTK ")


def times(ratio):
    return f"{ratio:.2g}x" if ratio < 10 else f"{ratio:.0f}x"


def ratios_against_vtk(rows):
    """Per scene, this project's fastest and most accurate mappers against the fastest of VTK's that
    ran on it (markdown lines; empty when no scene had both)."""
    lines = []
    for scene in dict.fromkeys(r["scene"] for r in rows):
        theirs = [r for r in rows if r["scene"] == scene and is_vtk(r)]
        ours = [r for r in rows if r["scene"] == scene and not is_vtk(r)]
        if not theirs or not ours:
            continue
        base = min(theirs, key=lambda r: r["median_s"])

        def against(row):
            time_ratio = row["median_s"] / base["median_s"]
            if row["rmse_covered"] > 0:
                error_ratio = base["rmse_covered"] / row["rmse_covered"]
                error = (f"{times(error_ratio)} lower error" if error_ratio >= 1
                         else f"{times(1 / error_ratio)} higher error")
            else:
                error = "no measurable error"
            return f"{row['mapper']} at {times(time_ratio)} the time with {error}"

        fastest = min(ours, key=lambda r: r["median_s"])
        best = min(ours, key=lambda r: r["rmse_covered"])
        parts = [f"fastest of ours {against(fastest)}"]
        if best is not fastest:
            parts.append(f"most accurate {against(best)}")
        both = [r["mapper"] for r in ours
                if r["median_s"] < base["median_s"] and r["rmse_covered"] < base["rmse_covered"]]
        parts.append("faster and more accurate than it: " + (", ".join(both) if both else "none"))
        lines.append(f"- **{scene}** against {base['mapper']} ({base['median_s']:.3f} s, RMSE "
                     f"{base['rmse_covered']:.3g}): " + "; ".join(parts) + ".")
    return lines


def readme_text(rows, command, started, machine, partial, left_out=()):
    """Testing/Benchmark/README.md for one run: how it was made, its table, its ratios."""
    renderer, version = machine["opengl"]
    sizes = sorted({(r["size"], r["views"]) for r in rows})
    scenes_cells = ", ".join(f"{scene} ({cells} cells)" for scene, cells in
                             dict.fromkeys((r["scene"], r["cells"]) for r in rows))
    out = [
        "# Benchmark: time against error",
        "",
        "Written by `Testing/Benchmark/benchmark.py --write-readme` from one run; do not edit by hand, run it",
        "again. The numbers are this machine's: compare ratios within a scene, not times across machines.",
        "",
        f"- Command: `{command}`",
        f"- Run started: {started}",
        f"- CPU: {machine['cpu']} ({machine['cpus']} logical CPUs)",
        f"- OpenGL renderer: {renderer}; OpenGL version: {version}; VTK {machine['vtk']}",
        f"- Images: {', '.join(f'{size}x{size} px, {views} views' for size, views in sizes)}",
        f"- Scenes: {scenes_cells}",
    ]
    if partial:
        out += ["", "**Partial run** (" + partial + "): a placeholder until the full run, not the benchmark's results."]
    out += [
        "",
        "Per scene and mapper: the first frame (preparation; for VTK Resample, ParaView's Resample To Image,",
        "the resampling and the first frame), the median frame time over an orbit of views [fastest-slowest]",
        "(each frame ends with glFinish), the RMSE of premultiplied RGB over the covered pixels against",
        "vtkUnstructuredVolumeReferenceRenderer at the same view (averaged over the views; this project's",
        "mappers on their float image, VTK's on the 8-bit window) and the largest error, the resident memory",
        "the first frame added, the GPU buffers of the mesh per cell of the scene (this project's mappers) and",
        "the host memory the mapper keeps beside its input per cell (where the mapper counts it).",
        "",
        "Each scene's plot of frame time against error (log-log; the black line is the Pareto front):",
        ", ".join(f"[{scene}]({PLOTS}/{scene}.png)" for scene in dict.fromkeys(r["scene"] for r in rows)) + ".",
        "Rows ending \"interactive\" are frames while the camera moves: the render window's desired update",
        f"rate at {INTERACTIVE_RATE:g} frames a second, as VTK's interactor sets it, so the mapper draws a reduced",
        "image (AutoAdjustSampleDistances) measured as the window shows it, stretched.",
        "",
        markdown_table(rows).rstrip("\n"),
        "",
        *(["Left out (above the mapper's cell limit, CELL_LIMITS: minutes a frame here): " +
           ", ".join(f"{name} on {scene}" for scene, name in left_out) + ".", ""] if left_out else []),
        "## What skipping saves",
        "",
        "Each mapper with SkipInvisibleCells (default) against itself without it, per scene: invisible cells",
        "left out, and for the tetrahedra mapper front-to-back compositing under an opacity mask (the iSBVR",
        "paper's pseudo early ray termination). The model bound is the paper's speedup when the skipped",
        "work costs nothing, 1 / (1 - share skipped).",
        "",
        skipping_table(rows).rstrip("\n") or "No scene of this run had a mapper with and without skipping.",
        "",
        "## Against VTK's mappers",
        "",
    ]
    ratios = ratios_against_vtk(rows)
    out += ratios if ratios else ["No scene of this run had both one of VTK's mappers and one of this project's."]
    out += [
        "",
        "## Running it",
        "",
        "```sh",
        'PYTHONPATH=build/vtk/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \\',
        f"  /usr/bin/python3 Testing/Benchmark/benchmark.py --write-readme   # every scene, {DEFAULT_SIZE} px, 4 views",
        "```",
        "",
        "`--quick` (two small scenes, 128 px), `--scenes a,b` and `--mappers substring,...` run less,",
        "`--all-variants` runs every registered variant (each measures one setting) besides DEFAULT_VARIANTS;",
        "the per-scene plots of time against error and montages go to `--output` (default `out/benchmark`).",
        "Other benchmarks: `deforming.py` (a mesh whose points move every frame), `time_series.py` and",
        "`paraview_time_series.py` (a reader's time steps: values or points changing, against a static frame),",
        "`paraview_ranks.py` (ParaView on 1, 2 and 4 ranks: [RANKS.md](RANKS.md)), `mesh_errors.py` (the hexahedral caster's "
        "error on every mesh of ../shared/data: [MESH_ERRORS.md](MESH_ERRORS.md)), `reference_render.py` (the reference alone),",
        "`scale.py` (each mapper from 1e4 to 1e7 cells, one process a run: [SCALE.md](SCALE.md)) and",
        "`build/vtk/bin/uvBenchmarkFilters` (the filters against VTK's).",
        "",
    ]
    return "\n".join(out)


def settle_allocator():
    """Puts the process's allocator where a process that has loaded and freed real data already is.
    Until glibc frees one large mapped block (it then raises its thresholds to that block's size, up
    to 32 MB), it hands the top of the heap back after every frame and takes it again on the next
    (page faults), so whichever mapper ran first would pay for that alone."""
    block = bytearray(16 << 20)
    del block


def view_errors(images, references):
    """Each view's errors against its reference (RMSE, covered RMSE, PSNR, maximum, 99th percentile),
    and the first view's error image."""
    errors, heat = [], None
    for k, (image, reference) in enumerate(zip(images, references)):
        metrics = vtkVolumeImageErrorMetrics()
        metrics.SetChannels(3)  # RGB over black = premultiplied colour; VTK's alpha varies by mapper
        if not metrics.Compare(image, reference):
            raise RuntimeError("image comparison failed")
        errors.append((metrics.GetRMSE(), metrics.GetCoveredRMSE(), metrics.GetPSNR(),
                       metrics.GetMaximumError(), metrics.GetPercentile99Error()))
        if k == 0:
            heat = vtkImageData()
            heat.DeepCopy(metrics.GetErrorImage())
    return errors, heat


def result_row(scene, name, mesh, size, views, preparation, frames, memory, mesh_bytes, host_bytes, errors, work):
    """One mapper's row of the results on one scene."""
    quartiles = statistics.quantiles(frames, n=4) if len(frames) > 1 else [frames[0]] * 3
    return {
        "scene": scene, "mapper": name, "cells": mesh.GetNumberOfCells(), "size": size, "views": views,
        "preparation_s": preparation, "median_s": statistics.median(frames),
        "p25_s": quartiles[0], "p75_s": quartiles[2], "min_s": min(frames), "max_s": max(frames),
        "memory_mb": memory,
        # GPU buffers of the mesh per cell of the scene's mesh (a hexahedron, or its tetrahedra).
        "gpu_bytes_per_cell": None if mesh_bytes is None else mesh_bytes / mesh.GetNumberOfCells(),
        # What the mapper keeps in host memory beside its input (where it counts it).
        "host_bytes_per_cell": None if host_bytes is None else host_bytes / mesh.GetNumberOfCells(),
        "rmse": statistics.mean(e[0] for e in errors), "rmse_covered": statistics.mean(e[1] for e in errors),
        "psnr": statistics.mean(min(e[2], 200.0) for e in errors), "max_error": max(e[3] for e in errors),
        "p99_error": statistics.mean(e[4] for e in errors),
        "work": work,
    }


def write_results(rows, output):
    """results.json, results.csv and results.md in `output`."""
    with open(os.path.join(output, "results.json"), "w") as out:
        json.dump(rows, out, indent=1)
    with open(os.path.join(output, "results.csv"), "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(output, "results.md"), "w") as out:
        out.write(markdown_table(rows))
        out.write("\n" + skipping_table(rows))


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="two small scenes, 128 px, 4 views (a smoke test)")
    parser.add_argument("--size", type=int, default=None)
    parser.add_argument("--views", type=int, default=None)
    parser.add_argument("--output", default=os.path.join(ROOT, "out", "benchmark"))
    parser.add_argument("--scenes", default=None, help="comma-separated scene names to run (default: all)")
    parser.add_argument("--mappers", default=None, help="comma-separated substrings of mapper names (default: all)")
    parser.add_argument("--all-variants", action="store_true",
                        help="every registered variant, not only DEFAULT_VARIANTS (each measures one setting)")
    parser.add_argument("--write-readme", nargs="?", const=README_PATH, default=None, metavar="PATH",
                        help=f"also write this run's README (default path: {os.path.relpath(README_PATH, ROOT)})")
    return parser.parse_args()


def main():
    args = parse_arguments()
    settle_allocator()
    started = time.strftime("%Y-%m-%d %H:%M %Z")
    if args.write_readme:
        machine = {"cpu": cpu_model(), "cpus": os.cpu_count(), "opengl": opengl_strings(),
                   "vtk": vtkVersion.GetVTKVersion()}
    wanted_scenes = args.scenes.split(",") if args.scenes else None
    mappers = [m for m in MAPPERS if (args.all_variants or m[0] in DEFAULT_VARIANTS) and
               (not args.mappers or any(w in m[0] for w in args.mappers.split(",")))]
    if args.quick:
        # A smoke test: resampling to 256^3 points would outlast the rest of it, and 64^3 and 128^3 run
        # the same code.
        mappers = [m for m in mappers if not (isinstance(m[1], ResampleToImage) and m[1].samples > 128)]
    size = args.size or (128 if args.quick else DEFAULT_SIZE)
    views = args.views or 4
    os.makedirs(args.output, exist_ok=True)
    cache = os.path.join(args.output, "reference-cache")
    os.makedirs(cache, exist_ok=True)

    rows, left_out = [], []
    for scene, load, scalar, maker, unit_fraction, *level in scenes(args.quick):
        if (wanted_scenes and scene not in wanted_scenes) or (scene in ON_REQUEST and not wanted_scenes):
            continue
        mesh, scene_image = load(), None
        if mesh.IsA("vtkImageData"):
            scene_image, mesh = mesh, image_as_voxels(mesh)
        prop, opacity_nodes, color_nodes = volume_property(mesh, scalar, maker, unit_fraction)
        cameras = orbit(mesh, views)
        drawn = subdivided(mesh, level[0] if level else None)
        split = vtkHexahedraToTetrahedra()
        split.SetInputData(drawn)
        split.Update()
        tets = split.GetOutput()
        print(f"\n{scene}: {mesh.GetNumberOfCells()} cells ({tets.GetNumberOfCells()} tets), {views} views, {size} px",
              flush=True)
        references, reference_seconds = [], 0.0
        for k, camera in enumerate(cameras):
            key = [REFERENCE_VERSION, scene.split("@")[0], args.quick, scalar, opacity_nodes, color_nodes, unit_fraction,
                   size, camera.GetPosition(), camera.GetFocalPoint(), mesh.GetNumberOfCells()]
            image, seconds = reference_image(cache, key, mesh, scalar, prop, camera, size)
            references.append(image)
            reference_seconds += seconds
        print(f"  reference: {reference_seconds:.1f} s (0 when cached)", flush=True)

        scene_rows, first_views, heat_maps = [], [over_background(references[0])], [over_background(references[0])]
        walkable = (10, 11, 12, 13, 14)  # tetrahedra, voxels, hexahedra, wedges, pyramids
        hexahedral = all(drawn.GetCellType(c) in walkable for c in range(drawn.GetNumberOfCells()))
        for name, factory, takes in mappers:
            if (takes == "hexahedra" and not hexahedral) or (takes == "image" and scene_image is None):
                continue
            if tets.GetNumberOfCells() > CELL_LIMITS.get(name, math.inf):
                left_out.append((scene, name))
                continue
            preparation, frames, memory, images, (mesh_bytes, host_bytes), work = run_mapper(
                name, factory, {"tets": tets, "hexahedra": drawn, "image": scene_image, "any": drawn}[takes], scalar,
                prop, cameras, size)
            errors, heat = view_errors(images, references)
            first_views.append(over_background(images[0]))
            heat_maps.append(heat)
            row = result_row(scene, name, mesh, size, views, preparation, frames, memory, mesh_bytes, host_bytes,
                             errors, work)
            scene_rows.append(row)
            print(f"  {name:28s} prep {preparation:7.3f} s  frame {row['median_s']:7.3f} s "
                  f"[{row['min_s']:.3f}-{row['max_s']:.3f}]  RMSE {row['rmse_covered']:.3g} (covered)  "
                  f"max {row['max_error']:.3f}  mem +{memory:.0f} MB", flush=True)
        rows += scene_rows
        plot_scene(scene, scene_rows, os.path.join(args.output, f"{scene}_time_vs_error.png"))
        if args.write_readme:
            folder = os.path.join(os.path.dirname(args.write_readme), PLOTS)
            os.makedirs(folder, exist_ok=True)
            plot_scene(scene, scene_rows, os.path.join(folder, f"{scene}.png"))
        heat_maps[0] = over_background(references[0])  # the reference has no error: show it again
        montage(first_views, heat_maps, os.path.join(args.output, f"{scene}_montage.png"))

    write_results(rows, args.output)
    bad = [r for r in rows if not all(math.isfinite(r[k]) for k in ("median_s", "rmse", "preparation_s"))]
    print(f"\nwrote {len(rows)} rows to {args.output}/results.csv and results.json")
    if bad:
        sys.exit(f"non-finite results: {bad}")
    if args.write_readme:
        # Anything short of every scene and mapper at the default size says so in the README itself.
        partial = ", ".join(label for label, given in (
            ("--quick", args.quick), ("--scenes", args.scenes), ("--mappers", args.mappers),
            ("--size", args.size not in (None, DEFAULT_SIZE)), ("--views", args.views not in (None, 4)),
            ("no ../shared/data meshes", not os.path.isdir(SHARED))) if given)
        with open(args.write_readme, "w", encoding="utf-8") as out:
            out.write(readme_text(rows, run_command(), started, machine, partial, left_out))
        print(f"wrote {args.write_readme}")


if __name__ == "__main__":
    main()
