// Times this project's filters against VTK's on the same grids, in one process:
//   vtkHexahedraToTetrahedra vs vtkDataSetTriangleFilter, vtkVertexGradientFilter vs vtkGradientFilter.
// Median of --repeats runs after one warm-up run; ratios are VTK's time over ours.
//
//   uvBenchmarkFilters [--resolution N] [--repeats R]
#include "vtkAnalyticMeshSource.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkVertexGradientFilter.h"

#include "vtkAlgorithm.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkGradientFilter.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace
{
struct Timing
{
  double Median = 0.0;
  double Minimum = 0.0;
  double Maximum = 0.0;
};

/// Runs `prepare` then `run` (the timed part) repeats + 1 times; the first is the warm-up.
Timing Measure(int repeats, const std::function<void()>& run, const std::function<void()>& prepare)
{
  std::vector<double> seconds;
  for (int r = 0; r <= repeats; ++r)
  {
    prepare();
    const auto start = std::chrono::steady_clock::now();
    run();
    const auto stop = std::chrono::steady_clock::now();
    if (r > 0)
    {
      seconds.push_back(std::chrono::duration<double>(stop - start).count());
    }
  }
  std::sort(seconds.begin(), seconds.end());
  return { seconds[seconds.size() / 2], seconds.front(), seconds.back() };
}

/// Times an algorithm's Update() on fresh executions (Modified() before each run).
Timing TimeAlgorithm(int repeats, vtkAlgorithm* algorithm)
{
  return Measure(
    repeats, [&] { algorithm->Update(); }, [&] { algorithm->Modified(); });
}

void Row(const char* what, const char* grid, const Timing& ours, const Timing& vtks, long long cellsOut)
{
  std::printf("%-10s %-13s %10.3f %10.3f %8.2fx   (ours %.3f-%.3f s, VTK %.3f-%.3f s, %lld cells out)\n",
    what, grid, ours.Median, vtks.Median, vtks.Median / ours.Median, ours.Minimum, ours.Maximum,
    vtks.Minimum, vtks.Maximum, cellsOut);
}
} // namespace

int main(int argc, char* argv[])
{
  int resolution = 100;
  int repeats = 5;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--resolution") && i + 1 < argc)
    {
      resolution = std::max(2, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc)
    {
      repeats = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::fprintf(stderr, "usage: %s [--resolution N] [--repeats R]\n", argv[0]);
      return 2;
    }
  }
  std::printf("UnstructuredVolume filter benchmark: %d^3 hexahedra, median of %d runs after a warm-up, "
              "vtkSMPTools backend %s with %d threads\n\n",
    resolution, repeats, vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads());

  // The same cells twice: as vtkImageData (VTK's structured fast paths) and as an unstructured grid.
  vtkNew<vtkAnalyticMeshSource> source;
  source->SetResolution(resolution, resolution, resolution);
  source->SetField(vtkAnalyticMeshSource::MARSCHNER_LOBB);
  source->Update();
  vtkUnstructuredGrid* hexahedra = source->GetOutput();
  vtkNew<vtkImageData> image;
  image->SetDimensions(resolution + 1, resolution + 1, resolution + 1);
  image->SetOrigin(-1, -1, -1);
  image->SetSpacing(2.0 / resolution, 2.0 / resolution, 2.0 / resolution);
  image->GetPointData()->SetScalars(hexahedra->GetPointData()->GetArray("MarschnerLobb"));

  std::printf("%-10s %-13s %10s %10s %9s\n", "filter", "input", "ours (s)", "VTK (s)", "VTK/ours");
  struct Input
  {
    const char* Name;
    vtkDataSet* Data;
  };
  for (const Input& input : { Input{ "image data", image }, Input{ "unstructured", hexahedra } })
  {
    vtkNew<vtkHexahedraToTetrahedra> ours;
    ours->SetInputData(input.Data);
    vtkNew<vtkDataSetTriangleFilter> vtks;
    vtks->SetInputData(input.Data);
    const Timing oursTime = TimeAlgorithm(repeats, ours);
    const Timing vtksTime = TimeAlgorithm(repeats, vtks);
    Row("split(6)", input.Name, oursTime, vtksTime, ours->GetOutput()->GetNumberOfCells());
    if (vtkImageData::SafeDownCast(input.Data))
    {
      ours->SetSplitModeToFiveTetrahedra();
      const Timing fiveTime = TimeAlgorithm(repeats, ours);
      Row("split(5)", input.Name, fiveTime, vtksTime, ours->GetOutput()->GetNumberOfCells());
    }
  }
  for (const Input& input : { Input{ "image data", image }, Input{ "unstructured", hexahedra } })
  {
    vtkNew<vtkVertexGradientFilter> ours;
    ours->SetInputData(input.Data);
    ours->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "MarschnerLobb");
    vtkNew<vtkGradientFilter> vtks;
    vtks->SetInputData(input.Data);
    vtks->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "MarschnerLobb");
    const Timing oursTime = TimeAlgorithm(repeats, ours);
    const Timing vtksTime = TimeAlgorithm(repeats, vtks);
    Row("gradient", input.Name, oursTime, vtksTime, ours->GetOutput()->GetNumberOfCells());
  }
  return 0;
}
