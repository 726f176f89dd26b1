#include "vtkUnstructuredVolumeFrameStatistics.h"

#include "vtkObjectFactory.h"

#include <limits>

vtkStandardNewMacro(vtkUnstructuredVolumeFrameStatistics);

vtkUnstructuredVolumeFrameStatistics::vtkUnstructuredVolumeFrameStatistics() = default;
vtkUnstructuredVolumeFrameStatistics::~vtkUnstructuredVolumeFrameStatistics() = default;

int vtkUnstructuredVolumeFrameStatistics::GetNumberOfValues()
{
  return static_cast<int>(this->Values.size());
}

const char* vtkUnstructuredVolumeFrameStatistics::GetName(int index)
{
  if (index < 0 || index >= this->GetNumberOfValues())
  {
    vtkErrorMacro("no value " << index << " (there are " << this->Values.size() << ")");
    return nullptr;
  }
  return this->Values[static_cast<std::size_t>(index)].first.c_str();
}

std::pair<std::string, double>* vtkUnstructuredVolumeFrameStatistics::Find(const char* name)
{
  for (auto& value : this->Values)
  {
    if (name && value.first == name)
    {
      return &value;
    }
  }
  return nullptr;
}

bool vtkUnstructuredVolumeFrameStatistics::HasValue(const char* name)
{
  return this->Find(name) != nullptr;
}

double vtkUnstructuredVolumeFrameStatistics::GetValue(const char* name)
{
  if (const auto* value = this->Find(name))
  {
    return value->second;
  }
  std::string names;
  for (const auto& value : this->Values)
  {
    names += (names.empty() ? "" : ", ") + value.first;
  }
  vtkErrorMacro("no value named " << (name ? name : "(null)") << "; there are: " << names);
  return std::numeric_limits<double>::quiet_NaN();
}

void vtkUnstructuredVolumeFrameStatistics::Clear()
{
  this->Values.clear();
}

void vtkUnstructuredVolumeFrameStatistics::SetValue(const std::string& name, double value)
{
  if (auto* known = this->Find(name.c_str()))
  {
    known->second = value;
    return;
  }
  this->Values.emplace_back(name, value);
}

void vtkUnstructuredVolumeFrameStatistics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const auto& value : this->Values)
  {
    os << indent << value.first << ": " << value.second << "\n";
  }
}
