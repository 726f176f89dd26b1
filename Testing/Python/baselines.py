"""Image baselines, one helper for the Python and the ParaView tests (which import it under their own
VTK): a PNG written by a test against Testing/Data/Baseline/<name> and its alternates <stem>_1.png,
<stem>_2.png, ... (VTK's convention for images that differ by platform), by vtkImageDifference's
thresholded error; the nearest counts. Needs only vtkmodules, so pvbatch's VTK serves as well."""
import os
import re

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkImagingCore import vtkImageDifference

BASELINES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Data", "Baseline")


def with_alternates(baseline):
    """`baseline` and its existing alternates <stem>_<n>.png, in that order."""
    stem, extension = os.path.splitext(baseline)
    folder = os.path.dirname(baseline) or "."
    pattern = re.compile(re.escape(os.path.basename(stem)) + r"_(\d+)" + re.escape(extension) + "$")
    numbered = sorted((int(m.group(1)), name) for name in os.listdir(folder) if (m := pattern.match(name)))
    return [baseline] + [os.path.join(folder, name) for _, name in numbered]


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader


def thresholded_error(candidate, baseline):
    """vtkImageDifference's thresholded error (0: the same image) between two PNG files."""
    readers = [read_png(path) for path in (candidate, baseline)]
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.Update()
    return difference.GetThresholdedError()


def nearest_baseline(candidate, baseline):
    """(error, path) of the baseline or alternate nearest to `candidate`. A missing baseline raises
    FileNotFoundError saying how to make one: look at the candidate first."""
    if not os.path.exists(baseline):
        raise FileNotFoundError(f"no baseline {baseline}: look at {candidate}; if it is right, copy it there")
    return min((thresholded_error(candidate, path), path) for path in with_alternates(baseline))
