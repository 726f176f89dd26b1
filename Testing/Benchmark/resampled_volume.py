"""ParaView's "Resample To Image" volume rendering of an unstructured grid, for the benchmark.

ParaView's Volume representation of an unstructured grid (vtkUnstructuredGridVolumeRepresentation), in
that mode, runs vtkResampleToImage on the input (SamplingDimensions over the input's bounds, 128^3 by
default) in its update and hands the image, as the filter made it, to vtkSmartVolumeMapper, which
renders it with VTK's GPU ray caster. It never reads the filter's valid-point mask
("vtkValidPointMask") itself: the filter also marks the points outside the input hidden, and the
cells that touch them, in the image's ghost arrays (vtkGhostType), and the GPU ray caster skips the
samples next to hidden points and cells. ResampleToImage(n) does the same; ResampleToImage(n,
binary_mask=True) drops the ghost arrays and gives the mask to the GPU ray caster as its binary mask
input instead (the mask that the ray caster samples at the nearest point), to show what the
blanking costs and gains.
"""
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes, vtkImageData
from vtkmodules.vtkFiltersCore import vtkResampleToImage
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401


class ResampleToImage:
    """The benchmark's factory for Resample To Image at samples^3 points: mapper_for(mesh, array)
    resamples the mesh (the filter runs there, so that its time can count in the first frame) and
    returns VTK's GPU ray caster on the image."""

    def __init__(self, samples, binary_mask=False):
        self.samples = samples
        self.binary_mask = binary_mask

    def mapper_for(self, mesh, array):
        """VTK's GPU ray caster on the mesh resampled, colouring by the mesh's point or cell array
        named `array` (None: its active point scalars), which the image holds as point data."""
        resample = vtkResampleToImage()  # UseInputBounds (on by default): the input's bounds
        resample.SetInputDataObject(mesh)
        resample.SetSamplingDimensions(self.samples, self.samples, self.samples)
        resample.Update()
        image = vtkImageData()
        image.ShallowCopy(resample.GetOutput())
        name = array or image.GetPointData().GetScalars().GetName()

        mapper = vtkGPUVolumeRayCastMapper()
        # As vtkSmartVolumeMapper sets it up for ParaView's still renders (their desired update rate is
        # below its interactive rate): the sample distance locked to half the image's average spacing,
        # not adjusted to a frame rate (the GPU ray caster's own default samples at the smallest spacing).
        mapper.SetAutoAdjustSampleDistances(False)
        mapper.LockSampleDistanceToInputSpacingOn()
        mapper.SetSampleDistance(sum(image.GetSpacing()) / 6.0)
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectScalarArray(name)
        if self.binary_mask:
            ghosts = vtkDataSetAttributes.GhostArrayName()
            image.GetPointData().RemoveArray(ghosts)
            image.GetCellData().RemoveArray(ghosts)
            # The ray caster reads the mask's array with its own scalar selection: the mask's array
            # takes the scalar's name. Unsigned char, as a binary mask must be.
            valid = vtkUnsignedCharArray()
            valid.DeepCopy(image.GetPointData().GetArray(resample.GetMaskArrayName()))
            valid.SetName(name)
            mask = vtkImageData()
            mask.CopyStructure(image)
            mask.GetPointData().SetScalars(valid)
            mapper.SetMaskTypeToBinary()
            mapper.SetMaskInput(mask)
        mapper.SetInputData(image)
        return mapper
