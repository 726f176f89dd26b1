/**
 * @class vtkUnstructuredVolumeFrameStatistics
 * @brief What a mapper of this module did in its last frame and since its mesh was built: named
 * numbers (cells walked, peels, sorts, table builds, whether it ray-cast...) for tests and the
 * benchmark, kept out of the mappers' own API.
 *
 * vtkUnstructuredVolumeMapper::GetFrameStatistics fills it from the mapper when asked. Each mapper
 * reports its own names (GetName); GetValue of a name it does not report is an error and NaN, so a
 * test that asks for the wrong one fails. Flags read as 0 or 1.
 */
#ifndef vtkUnstructuredVolumeFrameStatistics_h
#define vtkUnstructuredVolumeFrameStatistics_h

#include "vtkObject.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkUnstructuredVolumeFrameStatistics : public vtkObject
{
public:
  static vtkUnstructuredVolumeFrameStatistics* New();
  vtkTypeMacro(vtkUnstructuredVolumeFrameStatistics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How many named values there are, and the name of each.
  int GetNumberOfValues();
  const char* GetName(int index);
  /// Whether the mapper reports `name`.
  bool HasValue(const char* name);
  /// The value of `name`; NaN, with an error naming the values there are, when there is none.
  double GetValue(const char* name);

  /// For the mappers: forget every value, or set one (added where new, replaced where not).
  void Clear();
  void SetValue(const std::string& name, double value);

protected:
  vtkUnstructuredVolumeFrameStatistics();
  ~vtkUnstructuredVolumeFrameStatistics() override;

private:
  vtkUnstructuredVolumeFrameStatistics(const vtkUnstructuredVolumeFrameStatistics&) = delete;
  void operator=(const vtkUnstructuredVolumeFrameStatistics&) = delete;

  /// The value named `name`, or null.
  std::pair<std::string, double>* Find(const char* name);

  std::vector<std::pair<std::string, double>> Values;
};

#endif
