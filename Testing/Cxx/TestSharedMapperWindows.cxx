// One mapper rendered in two windows: when it moves to the second window it frees what it made in the
// first, and must do so in the first window's context. The windows' contexts share no objects, so a
// buffer or vertex-array name deleted while the second window is current would be one of that
// window's own objects: every name the second window holds must still be valid after the switch.
#include "vtkAnalyticMeshSource.h"
#include "vtkBarycentricShellMapper.h"
#include "vtkHexahedralRayCastMapper.h"
#include "vtkPreIntegratedTetrahedraMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace
{
constexpr int Names = 2048; // more than both windows' contexts have made by the switch

vtkSmartPointer<vtkRenderWindow> OffScreenWindow()
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(16, 16);
  window->AddRenderer(vtkSmartPointer<vtkRenderer>::New());
  return window;
}

vtkSmartPointer<vtkVolume> RampVolume(vtkUnstructuredVolumeMapper* mapper)
{
  vtkNew<vtkAnalyticMeshSource> source;
  source->SetResolution(3, 3, 3);
  source->SetCellKind(vtkAnalyticMeshSource::SIX_TETRAHEDRA);
  source->Update();
  mapper->SetInputData(source->GetOutput());
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.8);
  vtkNew<vtkColorTransferFunction> colours;
  colours->AddRGBPoint(0.0, 0.2, 0.3, 0.9);
  colours->AddRGBPoint(1.0, 0.9, 0.3, 0.1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(colours);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  return volume;
}

/// Buffers and vertex arrays made (and bound once, so that they exist) in `window`'s context.
struct HeldNames
{
  std::vector<GLuint> Buffers = std::vector<GLuint>(Names), Arrays = std::vector<GLuint>(Names);

  explicit HeldNames(vtkRenderWindow* window)
  {
    window->MakeCurrent();
    glGenBuffers(Names, this->Buffers.data());
    glGenVertexArrays(Names, this->Arrays.data());
    for (int k = 0; k < Names; ++k)
    {
      glBindBuffer(GL_ARRAY_BUFFER, this->Buffers[k]);
      glBindVertexArray(this->Arrays[k]);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
    vtkOpenGLRenderWindow::SafeDownCast(window)->GetState()->Reset(); // VTK's cache of those bindings
  }

  /// How many of them `window`'s context no longer knows.
  int Lost(vtkRenderWindow* window) const
  {
    window->MakeCurrent();
    int lost = 0;
    for (int k = 0; k < Names; ++k)
      lost += (glIsBuffer(this->Buffers[k]) ? 0 : 1) + (glIsVertexArray(this->Arrays[k]) ? 0 : 1);
    return lost;
  }

  void Delete(vtkRenderWindow* window)
  {
    window->MakeCurrent();
    glDeleteBuffers(Names, this->Buffers.data());
    glDeleteVertexArrays(Names, this->Arrays.data());
  }
};

void ExpectSwitchKeepsTheOtherWindowsNames(vtkUnstructuredVolumeMapper* mapper)
{
  vtkSmartPointer<vtkRenderWindow> first = OffScreenWindow(), second = OffScreenWindow();
  second->Render(); // its context exists
  vtkSmartPointer<vtkVolume> volume = RampVolume(mapper);
  first->GetRenderers()->GetFirstRenderer()->AddVolume(volume);
  first->Render(); // the mapper's objects, in the first window's context
  HeldNames names(second);
  second->GetRenderers()->GetFirstRenderer()->AddVolume(volume);
  second->Render(); // the mapper moves to the second window
  EXPECT_EQ(names.Lost(second), 0) << mapper->GetClassName() << " deleted names of the other window";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  names.Delete(second);
  // A renderer of the window the mapper left drops the volume: the mapper holds nothing of that
  // window, and keeps what it holds in the second (the tetrahedra and shells mappers count GPU
  // buffers in their mesh memory, which a release would empty).
  const vtkIdType held = mapper->GetMeshMemoryInBytes();
  first->GetRenderers()->GetFirstRenderer()->RemoveAllViewProps();
  EXPECT_EQ(mapper->GetMeshMemoryInBytes(), held) << mapper->GetClassName() << " released for another window";
  second->GetRenderers()->GetFirstRenderer()->RemoveAllViewProps();
}
}

TEST(SharedMapperWindows, MovingToAnotherWindowDeletesNothingOfIt)
{
  if (!std::getenv("DISPLAY"))
  {
    GTEST_SKIP() << "no X display (the test suite runs under Xvfb)";
  }
  ExpectSwitchKeepsTheOtherWindowsNames(vtkNew<vtkPreIntegratedTetrahedraMapper>());
  ExpectSwitchKeepsTheOtherWindowsNames(vtkNew<vtkBarycentricShellMapper>());
  ExpectSwitchKeepsTheOtherWindowsNames(vtkNew<vtkHexahedralRayCastMapper>());
}
