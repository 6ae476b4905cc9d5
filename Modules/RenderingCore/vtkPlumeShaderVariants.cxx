#include "vtkPlumeShaderVariants.h"

#include <sstream>
#include <vector>

std::string vtkPlumeShaderVariants::Select(
  const char* source, const std::set<std::string>& enabled, const std::string& defines)
{
  std::istringstream in(source ? source : "");
  std::string line;
  std::string out;
  // one entry per open block: whether its lines are kept (a nested block is
  // kept only inside a kept one)
  std::vector<bool> open;
  bool keep = true;
  while (std::getline(in, line))
  {
    const size_t first = line.find_first_not_of(" \t");
    const std::string trimmed = first == std::string::npos ? std::string() : line.substr(first);
    if (trimmed.compare(0, 12, "//PLUME::IF ") == 0)
    {
      // terms separated by spaces are ORed; names joined by '+' in a term are ANDed
      std::istringstream terms(trimmed.substr(12));
      std::string term;
      bool any = false;
      while (terms >> term)
      {
        bool all = true;
        std::istringstream names(term);
        std::string name;
        while (std::getline(names, name, '+'))
        {
          all = all && enabled.count(name) > 0;
        }
        any = any || all;
      }
      open.push_back(keep);
      keep = keep && any;
      continue;
    }
    if (trimmed.compare(0, 14, "//PLUME::ENDIF") == 0)
    {
      keep = open.empty() ? true : static_cast<bool>(open.back());
      if (!open.empty())
      {
        open.pop_back();
      }
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
