#include "vtkPlumeShaderVariants.h"

#include <sstream>

std::string vtkPlumeShaderVariants::Select(
  const char* source, const std::set<std::string>& enabled, const std::string& defines)
{
  std::istringstream in(source ? source : "");
  std::string line;
  std::string out;
  bool keep = true;
  while (std::getline(in, line))
  {
    const size_t first = line.find_first_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? std::string() : line.substr(first);
    if (trimmed.compare(0, 12, "//PLUME::IF ") == 0)
    {
      std::istringstream names(trimmed.substr(12));
      std::string name;
      keep = false;
      while (names >> name)
      {
        keep = keep || enabled.count(name) > 0;
      }
      continue;
    }
    if (trimmed.compare(0, 14, "//PLUME::ENDIF") == 0)
    {
      keep = true;
      continue;
    }
    if (!keep)
    {
      continue;
    }
    if (trimmed.compare(0, 16, "//PLUME::Defines") == 0)
    {
      out += defines;
      continue;
    }
    out += line;
    out += '\n';
  }
  return out;
}
