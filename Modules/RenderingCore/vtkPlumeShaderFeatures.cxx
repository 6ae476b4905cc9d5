#include "vtkPlumeShaderFeatures.h"

#include <stdexcept>

namespace
{
void CheckName(const std::string& name)
{
  if (name.empty() || name.find_first_not_of(
                        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
  {
    throw std::invalid_argument("shader feature or define name '" + name + "' is not an identifier");
  }
}
}

vtkPlumeShaderFeatures& vtkPlumeShaderFeatures::Enable(const std::string& feature, bool on)
{
  CheckName(feature);
  if (on)
  {
    this->Enabled.insert(feature);
  }
  else
  {
    this->Enabled.erase(feature);
  }
  return *this;
}

vtkPlumeShaderFeatures& vtkPlumeShaderFeatures::Define(const std::string& name, const std::string& value)
{
  CheckName(name);
  this->Defines[name] = value;
  return *this;
}

vtkPlumeShaderFeatures& vtkPlumeShaderFeatures::Define(const std::string& name, long long value)
{
  return this->Define(name, std::to_string(value));
}

std::string vtkPlumeShaderFeatures::GetDefines() const
{
  std::string out;
  for (const auto& d : this->Defines)
  {
    out += "#define " + d.first + " " + d.second + "\n";
  }
  for (const std::string& feature : this->Enabled)
  {
    out += "#define PLUME_FEATURE_" + feature + " 1\n";
  }
  return out;
}

std::string vtkPlumeShaderFeatures::GetKey() const
{
  // the sources depend on exactly the enabled set and the define lines
  std::string key;
  for (const std::string& feature : this->Enabled)
  {
    key += feature + ",";
  }
  return key + "|" + this->GetDefines();
}
