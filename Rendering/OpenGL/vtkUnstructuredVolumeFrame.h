/**
 * @class vtkUnstructuredVolumeFrame
 * @brief What one frame of a mapper looks through: renderer, volume, viewport and camera matrices.
 *
 * Made once per frame by vtkUnstructuredVolumeMapper::Render and handed to each step (Prepare,
 * Upload, Draw), so no mapper reads the camera twice or differently. "Model" space is the volume's
 * coordinates moved by -center: the mappers recentre their mesh in double before converting it to
 * float, so positions keep their precision on meshes far from the origin.
 * (A plain struct of the OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeFrame_h
#define vtkUnstructuredVolumeFrame_h

#include "uvBoundaryGapOrder.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

struct vtkUnstructuredVolumeFrame
{
  vtkRenderer* Renderer = nullptr;
  vtkVolume* Volume = nullptr;
  vtkVolumeProperty* Property = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkCamera* Camera = nullptr;
  int OriginX = 0, OriginY = 0, TileWidth = 0, TileHeight = 0; // the renderer's tile of the window
  int Width = 0, Height = 0; // the image the mapper draws: the tile's size, or less (ReduceImage)
  // An interactive frame's image sample distance over the still frame's (AutoAdjustSampleDistances;
  // 1 for still frames): a mapper may coarsen other work by it, as the image is.
  double InteractiveReduction = 1.0;
  bool Parallel = false;
  double NearDepth = 0.0; // eye distance of the near clipping plane, where rays begin
  bool OpaqueDepth = true; // the depth buffer may hold geometry drawn before the volume
  glm::dmat4 VolumeToWorld{ 1.0 }, WorldToEye{ 1.0 }, EyeToClip{ 1.0 };

  /// The frame `renderer` shows `volume` in; Width and Height are 0 when the tile is empty.
  static vtkUnstructuredVolumeFrame Make(vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window)
  {
    vtkUnstructuredVolumeFrame frame;
    frame.Renderer = renderer;
    frame.Volume = volume;
    frame.Property = volume->GetProperty();
    frame.Window = window;
    frame.Camera = renderer->GetActiveCamera();
    renderer->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.OriginX, &frame.OriginY);
    if (frame.Width < 1 || frame.Height < 1)
    {
      frame.Width = frame.Height = 0;
      return frame;
    }
    frame.TileWidth = frame.Width;
    frame.TileHeight = frame.Height;
    const double aspect = static_cast<double>(frame.Width) / frame.Height;
    frame.Parallel = frame.Camera->GetParallelProjection() != 0;
    double clippingRange[2];
    frame.Camera->GetClippingRange(clippingRange);
    frame.NearDepth = clippingRange[0];
    frame.VolumeToWorld = uvgl::ToGlm(volume->GetMatrix());
    frame.WorldToEye = uvgl::ToGlm(frame.Camera->GetModelViewTransformMatrix());
    frame.EyeToClip = uvgl::ToGlm(frame.Camera->GetProjectionTransformMatrix(aspect, -1, 1));
    frame.OpaqueDepth = MayHaveDrawnDepth(renderer);
    return frame;
  }

  /// An image of one pixel per `distance` pixels of the tile along each axis (rounded up, so that
  /// it spans the whole tile); the camera's matrices stay the tile's.
  void ReduceImage(double distance)
  {
    if (this->IsEmpty() || !(distance > 1.0))
      return;
    this->Width = std::max(1, static_cast<int>(std::ceil(this->TileWidth / distance)));
    this->Height = std::max(1, static_cast<int>(std::ceil(this->TileHeight / distance)));
  }

  /// Whether anything may have been drawn into the depth buffer before the volumes: a visible prop
  /// that is not a volume and has opaque or translucent geometry (a prop that cannot tell says it
  /// has), or a depth buffer kept from an earlier layer. Where nothing was, every pixel's depth is
  /// the far plane, and the mappers need not read it.
  static bool MayHaveDrawnDepth(vtkRenderer* renderer)
  {
    if (renderer->GetPreserveDepthBuffer())
      return true;
    vtkPropCollection* props = renderer->GetViewProps();
    vtkCollectionSimpleIterator position;
    props->InitTraversal(position);
    while (vtkProp* prop = props->GetNextProp(position))
    {
      if (prop->GetVisibility() && !vtkVolume::SafeDownCast(prop) &&
        (prop->HasOpaqueGeometry() || prop->HasTranslucentPolygonalGeometry()))
        return true;
    }
    return false;
  }

  bool IsEmpty() const { return this->Width < 1 || this->Height < 1; }

  glm::dmat4 ModelToWorld(const glm::dvec3& center) const
  {
    return this->VolumeToWorld * glm::translate(glm::dmat4(1.0), center);
  }
  glm::dmat4 ModelToEye(const glm::dvec3& center) const { return this->WorldToEye * this->ModelToWorld(center); }
  glm::dmat4 ModelToClip(const glm::dvec3& center) const { return this->EyeToClip * this->ModelToEye(center); }
  /// The eye's position in model space (perspective; under parallel projection a point on the view axis).
  glm::dvec3 EyeInModel(const glm::dvec3& center) const
  {
    return glm::dvec3(glm::inverse(this->ModelToEye(center)) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  }
  /// The view direction in model space, unit length.
  glm::dvec3 ViewInModel(const glm::dvec3& center) const
  {
    return glm::normalize(glm::dvec3(glm::inverse(this->ModelToEye(center)) * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
  }
  /// The rays of this frame's pixels in model space (uvBoundaryGapOrder.h).
  uv::PixelGrid Pixels(const glm::dvec3& center) const
  {
    uv::PixelGrid grid;
    grid.ModelToClip = this->ModelToClip(center);
    grid.Width = this->Width;
    grid.Height = this->Height;
    return grid;
  }
  /// Eye-space normals from model-space ones (inverse transpose).
  glm::dmat3 ModelToEyeNormals(const glm::dvec3& center) const
  {
    return glm::transpose(glm::inverse(glm::dmat3(this->ModelToEye(center))));
  }
};

#endif
