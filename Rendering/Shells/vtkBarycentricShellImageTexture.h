/**
 * @class vtkBarycentricShellImageTexture
 * @brief The image bound to vtkBarycentricShellMapper (SetTextureImage) as a trilinear 3D float
 * texture, its values normalised as the transfer function's scalars are.
 *
 * Uploaded again only when the image, its scalar array, either's modification time or the
 * normalisation differs from what it holds (exact comparisons). (OpenGL layer of the barycentric
 * shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellImageTexture_h
#define vtkBarycentricShellImageTexture_h

#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <vector>

class vtkBarycentricShellImageTexture
{
public:
  /// `scalars` (component 0) of `image`, as (value - offset) * scale.
  void Sync(vtkOpenGLRenderWindow* window, vtkImageData* image, vtkDataArray* scalars, double offset, double scale)
  {
    const Source source{ image, scalars, image->GetMTime(), scalars->GetMTime(), offset, scale };
    if (window == this->Context && this->Texture->GetHandle() && source == this->Uploaded)
      return;
    image->GetDimensions(this->Dimensions);
    const vtkIdType count = image->GetNumberOfPoints();
    std::vector<float> values(count);
    vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const double value = (scalars->GetComponent(p, 0) - offset) * scale;
        values[p] = std::isfinite(value) ? static_cast<float>(value) : 0.0f;
      }
    });
    uvgl::UploadTrilinearVolume(
      this->Texture, window, this->Dimensions[0], this->Dimensions[1], this->Dimensions[2], 1, values.data());
    this->Context = window;
    this->Uploaded = source;
  }

  /// The texture and its size as uvBarycentricRayLib.glsl reads them (volumeTexture, volumeTextureSize).
  void Bind(vtkShaderProgram* program)
  {
    this->Texture->Activate();
    program->SetUniformi("volumeTexture", this->Texture->GetTextureUnit());
    const float size[3] = { static_cast<float>(this->Dimensions[0]), static_cast<float>(this->Dimensions[1]),
      static_cast<float>(this->Dimensions[2]) };
    program->SetUniform3f("volumeTextureSize", size);
  }
  void Unbind() { this->Texture->Deactivate(); }

  void Release()
  {
    if (this->Context)
      this->Texture->ReleaseGraphicsResources(this->Context);
    this->Context = nullptr;
    this->Uploaded = Source();
  }

private:
  struct Source
  {
    const void* Image = nullptr;
    const void* Scalars = nullptr;
    vtkMTimeType ImageTime = 0, ScalarsTime = 0;
    double Offset = 0.0, Scale = 0.0;
    bool operator==(const Source& o) const
    {
      return this->Image == o.Image && this->Scalars == o.Scalars && this->ImageTime == o.ImageTime &&
        this->ScalarsTime == o.ScalarsTime && this->Offset == o.Offset && this->Scale == o.Scale;
    }
  };

  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLRenderWindow* Context = nullptr;
  Source Uploaded;
  int Dimensions[3] = { 0, 0, 0 };
};

#endif
