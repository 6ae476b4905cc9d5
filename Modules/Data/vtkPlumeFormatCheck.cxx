#include "vtkPlumeFormatCheck.h"

#include "vtksys/FStream.hxx"
#include "vtksys/SystemTools.hxx"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

// The sanitizers' death callback (libFuzzer writes its crash file from it);
// weak: absent (null) in a build without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace
{
// A bounds-checked big-endian cursor over a file (netCDF classic is big-endian).
class Cursor
{
public:
  explicit Cursor(const std::string& path)
    : File(path.c_str(), std::ios::in | std::ios::binary)
  {
    if (this->File)
    {
      this->File.seekg(0, std::ios::end);
      this->Size = static_cast<uint64_t>(this->File.tellg());
      this->File.seekg(0);
    }
  }
  bool Good() const { return static_cast<bool>(this->File); }
  uint64_t Size = 0;
  uint64_t Position = 0;

  bool Read(void* out, uint64_t n)
  {
    if (n > this->Size - this->Position)
    {
      return false;
    }
    this->File.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
    this->Position += n;
    return static_cast<bool>(this->File);
  }
  bool Skip(uint64_t n)
  {
    if (n > this->Size - this->Position)
    {
      return false;
    }
    this->Position += n;
    this->File.seekg(static_cast<std::streamoff>(this->Position));
    return static_cast<bool>(this->File);
  }
  bool Seek(uint64_t at)
  {
    if (at > this->Size)
    {
      return false;
    }
    this->Position = at;
    this->File.clear();
    this->File.seekg(static_cast<std::streamoff>(at));
    return static_cast<bool>(this->File);
  }
  bool U32(uint64_t& v)
  {
    unsigned char b[4];
    if (!this->Read(b, 4))
    {
      return false;
    }
    v = (uint64_t(b[0]) << 24) | (uint64_t(b[1]) << 16) | (uint64_t(b[2]) << 8) | uint64_t(b[3]);
    return true;
  }
  bool U64(uint64_t& v)
  {
    unsigned char b[8];
    if (!this->Read(b, 8))
    {
      return false;
    }
    v = 0;
    for (int i = 0; i < 8; ++i)
    {
      v = (v << 8) | b[i];
    }
    return true;
  }

private:
  vtksys::ifstream File;
};

uint64_t TypeSize(uint64_t type)
{
  switch (type)
  {
    case 1: case 2: case 7: return 1; // byte, char, ubyte
    case 3: case 8: return 2;         // short, ushort
    case 4: case 5: case 9: return 4; // int, float, uint
    case 6: case 10: case 11: return 8; // double, int64, uint64
    default: return 0;
  }
}

struct Variable
{
  std::string Name;
  std::vector<uint64_t> Dims;
  uint64_t Type = 0;
  uint64_t Begin = 0;
};
}

std::string vtkPlumeFormatCheck::CheckNetCDFClassic(const std::string& path)
{
  Cursor in(path);
  if (!in.Good())
  {
    return std::string();
  }
  char magic[4] = {};
  if (in.Size < 4 || !in.Read(magic, 4) || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F')
  {
    // not netCDF classic: an HDF5-based file or not netCDF at all (its reader says so)
    return in.Size < 8 ? "the file is " + std::to_string(in.Size) + " bytes long, too short for any netCDF header"
                       : std::string();
  }
  const int version = magic[3];
  if (version != 1 && version != 2 && version != 5)
  {
    return "unknown netCDF classic version " + std::to_string(version) + " in the header";
  }
  const bool big = version == 5;     // CDF-5: 64-bit counts
  const bool offset64 = version != 1; // CDF-2 and CDF-5: 64-bit offsets
  auto count = [&](uint64_t& v) { return big ? in.U64(v) : in.U32(v); };
  const std::string truncated = "the netCDF header is cut short (truncated file?)";

  uint64_t numrecs = 0;
  if (!count(numrecs))
  {
    return truncated;
  }
  if (numrecs == (big ? ~uint64_t(0) : 0xFFFFFFFFu))
  {
    numrecs = 0; // streaming: unknown number of records
  }
  auto name = [&](std::string& out) {
    uint64_t n = 0;
    if (!count(n) || n > in.Size - in.Position)
    {
      return false;
    }
    out.resize(static_cast<size_t>(n));
    return in.Read(&out[0], n) && in.Skip((4 - n % 4) % 4);
  };
  // a list: tag then element count, each count bounded by the bytes left
  auto list = [&](uint64_t expectedTag, uint64_t& n) {
    uint64_t tag = 0;
    if (!in.U32(tag) || !count(n))
    {
      return false;
    }
    if (tag == 0 && n == 0)
    {
      return true;
    }
    return tag == expectedTag && n <= (in.Size - in.Position) / 4;
  };
  auto attributes = [&]() {
    uint64_t n = 0;
    if (!list(0x0C, n))
    {
      return false;
    }
    for (uint64_t i = 0; i < n; ++i)
    {
      std::string attr;
      uint64_t type = 0, values = 0;
      if (!name(attr) || !in.U32(type) || !count(values) || TypeSize(type) == 0)
      {
        return false;
      }
      const uint64_t bytes = values * TypeSize(type);
      if (values > in.Size || !in.Skip(bytes + (4 - bytes % 4) % 4))
      {
        return false;
      }
    }
    return true;
  };

  uint64_t ndims = 0;
  if (!list(0x0A, ndims))
  {
    return truncated + " or corrupt (dimension list)";
  }
  std::vector<uint64_t> dimLength(static_cast<size_t>(ndims));
  std::map<std::string, uint64_t> dimByName;
  for (uint64_t i = 0; i < ndims; ++i)
  {
    std::string dim;
    if (!name(dim) || !count(dimLength[i]))
    {
      return truncated + " (dimension " + std::to_string(i) + ")";
    }
    dimByName[dim] = dimLength[i];
  }
  if (!attributes())
  {
    return truncated + " or corrupt (global attributes)";
  }
  uint64_t nvars = 0;
  if (!list(0x0B, nvars))
  {
    return truncated + " or corrupt (variable list)";
  }
  std::vector<Variable> vars(static_cast<size_t>(nvars));
  for (auto& var : vars)
  {
    uint64_t rank = 0;
    if (!name(var.Name) || !count(rank) || rank > 1024)
    {
      return truncated + " or corrupt (variables)";
    }
    for (uint64_t r = 0; r < rank; ++r)
    {
      uint64_t id = 0;
      if (!count(id))
      {
        return truncated + " (variable '" + var.Name + "')";
      }
      if (id >= ndims)
      {
        return "variable '" + var.Name + "' names dimension " + std::to_string(id) + " of " + std::to_string(ndims);
      }
      var.Dims.push_back(id);
    }
    uint64_t vsize = 0;
    if (!attributes() || !in.U32(var.Type) || !count(vsize) ||
      !(offset64 ? in.U64(var.Begin) : in.U32(var.Begin)) || TypeSize(var.Type) == 0)
    {
      return truncated + " or corrupt (variable '" + var.Name + "')";
    }
  }

  // every variable's data inside the file
  auto isRecord = [&](const Variable& v) { return !v.Dims.empty() && dimLength[v.Dims[0]] == 0; };
  uint64_t recordSize = 0;
  for (const auto& v : vars)
  {
    if (isRecord(v))
    {
      double bytes = double(TypeSize(v.Type));
      for (size_t d = 1; d < v.Dims.size(); ++d)
      {
        bytes *= double(dimLength[v.Dims[d]]);
      }
      recordSize += static_cast<uint64_t>(bytes) + (4 - static_cast<uint64_t>(bytes) % 4) % 4;
    }
  }
  for (const auto& v : vars)
  {
    double bytes = double(TypeSize(v.Type));
    for (size_t d = isRecord(v) ? 1 : 0; d < v.Dims.size(); ++d)
    {
      bytes *= double(dimLength[v.Dims[d]]);
    }
    const double end = double(v.Begin) + (isRecord(v) && numrecs > 0 ? double(numrecs - 1) * double(recordSize) : 0.0) +
      (isRecord(v) && numrecs == 0 ? 0.0 : bytes);
    if (end > double(in.Size))
    {
      return "variable '" + v.Name + "' ends at byte " + std::to_string(static_cast<unsigned long long>(end)) +
        " but the file has " + std::to_string(in.Size) + " bytes (truncated file?)";
    }
  }

  // Exodus II: element connectivity must name existing nodes (1-based)
  auto nodes = dimByName.find("num_nodes");
  if (nodes == dimByName.end())
  {
    return std::string();
  }
  for (const auto& v : vars)
  {
    if (v.Name.compare(0, 7, "connect") != 0 || isRecord(v) || (v.Type != 4 && v.Type != 10))
    {
      continue;
    }
    uint64_t n = 1;
    for (uint64_t d : v.Dims)
    {
      n *= dimLength[d];
    }
    if (!in.Seek(v.Begin))
    {
      return "variable '" + v.Name + "' starts beyond the end of the file";
    }
    for (uint64_t i = 0; i < n; ++i)
    {
      uint64_t id = 0;
      if (!(v.Type == 4 ? in.U32(id) : in.U64(id)))
      {
        return "variable '" + v.Name + "' is cut short (truncated file?)";
      }
      const int64_t value = v.Type == 4 ? int64_t(int32_t(uint32_t(id))) : int64_t(id);
      if (value < 1 || uint64_t(value) > nodes->second)
      {
        return "element connectivity '" + v.Name + "' entry " + std::to_string(i) + " names node " +
          std::to_string(value) + ", but the file has " + std::to_string(nodes->second) +
          " nodes (valid 1 to " + std::to_string(nodes->second) + ")";
      }
    }
  }
  return std::string();
}

namespace
{
// Nodes per element of EnSight Gold's fixed-size element types ("g_" variants alike).
int NodesPerElement(std::string type)
{
  if (type.compare(0, 2, "g_") == 0)
  {
    type = type.substr(2);
  }
  static const std::map<std::string, int> sizes = { { "point", 1 }, { "bar2", 2 }, { "bar3", 3 },
    { "tria3", 3 }, { "tria6", 6 }, { "quad4", 4 }, { "quad8", 8 }, { "tetra4", 4 }, { "tetra10", 10 },
    { "pyramid5", 5 }, { "pyramid13", 13 }, { "penta6", 6 }, { "penta15", 15 }, { "hexa8", 8 },
    { "hexa20", 20 } };
  auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

std::string Trim(const char* text, size_t n)
{
  std::string s(text, strnlen(text, n));
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
}

std::string vtkPlumeFormatCheck::CheckEnSightGold(const std::string& casePath)
{
  // the geometry file named by the case file ("model: [ts] [fs] name")
  vtksys::ifstream caseFile(casePath.c_str());
  std::string line, model;
  while (caseFile && std::getline(caseFile, line))
  {
    if (line.compare(0, 6, "model:") == 0)
    {
      std::istringstream words(line.substr(6));
      std::string word;
      while (words >> word)
      {
        model = word; // the last word (time and file set numbers come first)
      }
    }
  }
  if (model.empty() || model.find('*') != std::string::npos)
  {
    return std::string();
  }
  std::string geometry = model;
  if (!vtksys::SystemTools::FileIsFullPath(geometry))
  {
    geometry = vtksys::SystemTools::GetFilenamePath(casePath) + "/" + model;
    if (vtksys::SystemTools::GetFilenamePath(casePath).empty())
    {
      geometry = model;
    }
  }
  Cursor in(geometry);
  if (!in.Good())
  {
    return "cannot open its geometry file " + geometry;
  }
  char text[81] = {};
  auto word = [&](std::string& out) {
    if (!in.Read(text, 80))
    {
      return false;
    }
    out = Trim(text, 80);
    return true;
  };
  std::string head;
  if (!word(head) || head.find("Binary") == std::string::npos)
  {
    return std::string(); // ASCII: VTK's parser checks as it reads
  }
  if (head.find("Fortran") != std::string::npos)
  {
    return std::string();
  }
  const std::string where = "geometry file " + geometry;
  const std::string cut = where + " is cut short (truncated file?)";
  std::string desc, nodeIds, elementIds;
  if (!word(desc) || !word(desc) || !word(nodeIds) || !word(elementIds))
  {
    return cut;
  }
  const bool nodeIdsStored = nodeIds.find("given") != std::string::npos || nodeIds.find("ignore") != std::string::npos;
  const bool elementIdsStored =
    elementIds.find("given") != std::string::npos || elementIds.find("ignore") != std::string::npos;
  // 4-byte integers, little- or big-endian: the one giving plausible counts
  int order = 0; // 0 unknown, 1 little, 2 big
  auto integer = [&](int64_t& v) {
    unsigned char b[4];
    if (!in.Read(b, 4))
    {
      return false;
    }
    const int32_t little = int32_t(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24);
    const int32_t bigEndian = int32_t(uint32_t(b[3]) | uint32_t(b[2]) << 8 | uint32_t(b[1]) << 16 | uint32_t(b[0]) << 24);
    if (order == 0)
    {
      order = (little >= 0 && uint64_t(little) <= in.Size) ? 1 : 2;
    }
    v = order == 1 ? little : bigEndian;
    return true;
  };
  std::string key;
  if (!word(key))
  {
    return cut;
  }
  if (key.compare(0, 7, "extents") == 0)
  {
    if (!in.Skip(24) || !word(key))
    {
      return cut;
    }
  }
  while (true)
  {
    if (key != "part")
    {
      return where + ": expected 'part', found '" + key + "'";
    }
    int64_t part = 0, nodes = 0;
    std::string kind;
    if (!integer(part) || !word(desc) || !word(kind))
    {
      return cut;
    }
    if (kind.compare(0, 11, "coordinates") != 0)
    {
      return std::string(); // structured "block" parts: not checked
    }
    if (!integer(nodes) || nodes < 0 || uint64_t(nodes) > in.Size / 12)
    {
      return where + ": part " + std::to_string(part) + " claims " + std::to_string(nodes) +
        " nodes, more than the file can hold";
    }
    if (!in.Skip(uint64_t(nodes) * (nodeIdsStored ? 16 : 12)))
    {
      return cut + " (coordinates of part " + std::to_string(part) + ")";
    }
    // element blocks until the next part or the end of the file
    while (true)
    {
      if (in.Position == in.Size)
      {
        return std::string();
      }
      if (!word(key))
      {
        return cut;
      }
      if (key == "part")
      {
        break;
      }
      if (key.compare(0, 6, "nfaced") == 0 || key.compare(0, 8, "g_nfaced") == 0)
      {
        return std::string(); // polyhedra: not checked
      }
      const bool nsided = key.compare(0, 6, "nsided") == 0 || key.compare(0, 8, "g_nsided") == 0;
      const int per = nsided ? 0 : NodesPerElement(key);
      if (!nsided && per == 0)
      {
        return where + ": unknown element type '" + key + "' in part " + std::to_string(part);
      }
      int64_t elements = 0;
      if (!integer(elements) || elements < 0 || uint64_t(elements) > in.Size / 4)
      {
        return where + ": part " + std::to_string(part) + " claims " + std::to_string(elements) + " '" + key +
          "' elements, more than the file can hold";
      }
      if (elementIdsStored && !in.Skip(uint64_t(elements) * 4))
      {
        return cut + " (element ids of part " + std::to_string(part) + ")";
      }
      uint64_t ids = uint64_t(elements) * per;
      if (nsided)
      {
        ids = 0;
        for (int64_t e = 0; e < elements; ++e)
        {
          int64_t n = 0;
          if (!integer(n) || n < 0)
          {
            return cut + " (nsided counts of part " + std::to_string(part) + ")";
          }
          ids += uint64_t(n);
        }
      }
      if (ids > (in.Size - in.Position) / 4)
      {
        return cut + " ('" + key + "' connectivity of part " + std::to_string(part) + ")";
      }
      for (uint64_t i = 0; i < ids; ++i)
      {
        int64_t id = 0;
        if (!integer(id))
        {
          return cut;
        }
        if (id < 1 || id > nodes)
        {
          return where + ": a '" + key + "' element of part " + std::to_string(part) + " names node " +
            std::to_string(id) + ", but the part has " + std::to_string(nodes) + " nodes (valid 1 to " +
            std::to_string(nodes) + ")";
        }
      }
    }
  }
}

std::string vtkPlumeFormatCheck::CheckLegacyVTK(const std::string& path)
{
  vtksys::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line))
  {
    return std::string(); // VTK's reader reports unreadable and empty files itself
  }
  const auto version = line.find("Version");
  if (line.compare(0, 5, "# vtk") != 0 || version == std::string::npos ||
    std::atof(line.c_str() + version + 7) >= 5.0)
  {
    return std::string();
  }
  std::string title, format;
  if (!std::getline(in, title) || !std::getline(in, format))
  {
    return std::string();
  }
  const bool binary = format.compare(0, 6, "BINARY") == 0;
  in.seekg(0, std::ios::end);
  const std::streamoff fileSize = in.tellg();
  in.seekg(0);
  std::getline(in, line);
  std::getline(in, line);
  std::getline(in, line);
  // VTK matches a keyword by its first letters in any case ("POLYGONS[" is
  // POLYGONS) and reads the counts as the next words, on that line or later
  static const char* const keywords[] = { "vertices", "lines", "polygons", "triangle_strips", "cells" };
  // `count` integers follow (ASCII: each a whole word; strtoll stops at a NUL
  // byte inside one, "3\0\0\x13" is no integer to VTK), or 4-byte ones (binary)
  auto checkList = [&](const std::string& where, long long count) -> std::string {
    if (binary)
    {
      const std::streamoff at = in.tellg();
      if (at < 0 || double(count) * 4.0 > double(fileSize - at))
      {
        return where + " needs " + std::to_string(count * 4) + " bytes, but the file ends after " +
          std::to_string(at < 0 ? 0 : fileSize - at) + " (truncated file?)";
      }
      in.seekg(at + static_cast<std::streamoff>(count) * 4);
      return std::string();
    }
    long long read = 0;
    std::string token;
    while (read < count && in >> token)
    {
      char* end = nullptr;
      const long long v = std::strtoll(token.c_str(), &end, 10);
      (void)v;
      if (!end || end != token.c_str() + token.size() || end == token.c_str())
      {
        std::string shown = token.substr(0, 40);
        for (char& ch : shown)
        {
          ch = std::isprint(static_cast<unsigned char>(ch)) ? ch : '?'; // NUL and control bytes
        }
        return where + ": value " + std::to_string(read) + " is '" + shown + "', not an integer";
      }
      ++read;
    }
    if (read < count)
    {
      return where + " ends after " + std::to_string(read) + " values (truncated file?)";
    }
    std::string rest;
    std::getline(in, rest); // the rest of the last line
    return std::string();
  };
  auto lowered = [](std::string word) {
    std::transform(word.begin(), word.end(), word.begin(),
      [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return word;
  };
  long long gridCells = -1, gridTypes = -1; // an unstructured grid's CELLS and CELL_TYPES counts
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword))
    {
      continue;
    }
    const std::string lower = lowered(keyword);
    if (lower.compare(0, 10, "cell_types") == 0)
    {
      // VTK's unstructured grid reader leaks its cell arrays when this list
      // is short (every error return after CELLS) and pairs the two lists by
      // index, so the counts must agree
      long long types = -1;
      if (!(words >> types))
      {
        if (!(in >> types))
        {
          return std::string(); // no count: VTK's reader fails with its own error
        }
        if (in.peek() == '\n')
        {
          in.get(); // the values start on the next line
        }
      }
      const std::string where = "the " + keyword + " section (" + std::to_string(types) + " types)";
      if (types < 0 || (gridCells >= 0 && types != gridCells))
      {
        return where + (types < 0 ? " has an impossible header"
                                  : " does not match the CELLS section's " + std::to_string(gridCells) + " cells");
      }
      gridTypes = types;
      const std::string bad = checkList(where, types);
      if (!bad.empty())
      {
        return bad;
      }
      continue;
    }
    bool isCells = false;
    for (const char* k : keywords)
    {
      isCells = isCells || lower.compare(0, std::strlen(k), k) == 0;
    }
    if (!isCells)
    {
      continue;
    }
    long long cells = -1, size = -1;
    const bool haveCells = static_cast<bool>(words >> cells);
    const bool onLine = haveCells && static_cast<bool>(words >> size);
    if (!onLine)
    {
      if ((!haveCells && !(in >> cells)) || !(in >> size))
      {
        return std::string(); // no counts: VTK's reader fails with its own error
      }
      if (in.peek() == '\n')
      {
        in.get(); // the values start on the next line
      }
    }
    const std::string where = "the " + keyword + " section (" + std::to_string(cells) + " cells, " +
      std::to_string(size) + " values)";
    if (cells < 0 || size < cells)
    {
      return where + " has an impossible header";
    }
    if (lower.compare(0, 5, "cells") == 0)
    {
      if (gridTypes >= 0 && cells != gridTypes)
      {
        return where + " does not match the CELL_TYPES section's " + std::to_string(gridTypes) + " types";
      }
      gridCells = cells;
    }
    const std::string bad = checkList(where, size);
    if (!bad.empty())
    {
      return bad;
    }
  }
  return std::string();
}

std::string vtkPlumeFormatCheck::CheckPlot3DGrid(const std::string& path, bool bigEndian, bool byteCounts,
  bool multiGrid, bool twoDimensional, bool doublePrecision, bool iblanking)
{
  Cursor in(path);
  if (!in.Good())
  {
    return std::string();
  }
  auto integer = [&](int64_t& v) {
    unsigned char b[4];
    if (!in.Read(b, 4))
    {
      return false;
    }
    const uint32_t u = bigEndian ? (uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | b[3])
                                 : (uint32_t(b[3]) << 24 | uint32_t(b[2]) << 16 | uint32_t(b[1]) << 8 | b[0]);
    v = int32_t(u);
    return true;
  };
  const std::string cut = "the grid header is cut short (truncated file?)";
  int64_t count = 0, blocks = 1;
  if (multiGrid)
  {
    if ((byteCounts && !integer(count)) || !integer(blocks) || (byteCounts && !integer(count)))
    {
      return cut;
    }
    if (blocks < 1 || uint64_t(blocks) > in.Size / 8)
    {
      return "the header announces " + std::to_string(blocks) + " grids";
    }
  }
  const int axes = twoDimensional ? 2 : 3;
  if (byteCounts && !integer(count))
  {
    return cut;
  }
  double need = 0;
  for (int64_t b = 0; b < blocks; ++b)
  {
    double points = 1;
    std::string dims;
    for (int a = 0; a < axes; ++a)
    {
      int64_t d = 0;
      if (!integer(d))
      {
        return cut;
      }
      dims += (a ? " x " : "") + std::to_string(d);
      if (d < 1)
      {
        return "grid " + std::to_string(b) + " has dimensions " + dims + "... (each must be at least 1)";
      }
      points *= double(d);
    }
    need += points * (axes * (doublePrecision ? 8.0 : 4.0) + (iblanking ? 4.0 : 0.0));
    if (need > double(in.Size))
    {
      return "grid " + std::to_string(b) + " (" + dims + ") needs more coordinates than the file's " +
        std::to_string(in.Size) + " bytes hold";
    }
  }
  return std::string();
}

std::string vtkPlumeFormatCheck::CheckXMLAppended(const std::string& path)
{
  Cursor in(path);
  if (!in.Good())
  {
    return std::string();
  }
  // the XML part: everything before the raw appended data ("_" after <AppendedData ...>)
  const uint64_t headLength = std::min<uint64_t>(in.Size, 1 << 24);
  std::string head(static_cast<size_t>(headLength), '\0');
  if (!in.Read(&head[0], headLength))
  {
    return std::string();
  }
  const auto appended = head.find("<AppendedData");
  if (appended == std::string::npos)
  {
    return std::string();
  }
  const auto tagEnd = head.find('>', appended);
  if (tagEnd == std::string::npos || head.find("encoding=\"raw\"", appended) > tagEnd)
  {
    return std::string(); // base64 appended data: not checked
  }
  const auto underscore = head.find('_', tagEnd);
  if (underscore == std::string::npos)
  {
    return "the appended data section has no '_' marker (truncated file?)";
  }
  const uint64_t base = underscore + 1;
  const std::string xml = head.substr(0, appended);
  auto attribute = [](const std::string& text, size_t from, size_t to, const std::string& name) {
    const auto at = text.find(" " + name + "=\"", from);
    if (at == std::string::npos || at > to)
    {
      return std::string();
    }
    const auto start = at + name.size() + 3;
    const auto end = text.find('"', start);
    return end == std::string::npos ? std::string() : text.substr(start, end - start);
  };
  const auto fileTag = xml.find("<VTKFile");
  const auto fileTagEnd = xml.find('>', fileTag == std::string::npos ? 0 : fileTag);
  if (fileTag == std::string::npos || fileTagEnd == std::string::npos)
  {
    return std::string();
  }
  const bool compressed = !attribute(xml, fileTag, fileTagEnd, "compressor").empty();
  const int headerSize = attribute(xml, fileTag, fileTagEnd, "header_type") == "UInt64" ? 8 : 4;
  const bool bigEndian = attribute(xml, fileTag, fileTagEnd, "byte_order") == "BigEndian";
  auto word = [&](uint64_t& v) {
    unsigned char b[8];
    if (!in.Read(b, headerSize))
    {
      return false;
    }
    v = 0;
    for (int i = 0; i < headerSize; ++i)
    {
      v |= uint64_t(b[bigEndian ? headerSize - 1 - i : i]) << (8 * i);
    }
    return true;
  };
  for (size_t at = xml.find("<DataArray"); at != std::string::npos; at = xml.find("<DataArray", at + 1))
  {
    const auto end = xml.find('>', at);
    if (end == std::string::npos || attribute(xml, at, end, "format") != "appended")
    {
      continue;
    }
    const std::string name = attribute(xml, at, end, "Name");
    const std::string offsetText = attribute(xml, at, end, "offset");
    char* stop = nullptr;
    const unsigned long long offset = std::strtoull(offsetText.c_str(), &stop, 10);
    const std::string what = "array '" + name + "' (appended offset " + offsetText + ")";
    if (offsetText.empty() || *stop != '\0' || base + offset + headerSize > in.Size)
    {
      return what + " starts beyond the end of the file's " + std::to_string(in.Size) + " bytes (truncated file?)";
    }
    in.Seek(base + offset);
    uint64_t first = 0;
    if (!word(first))
    {
      return what + ": its header is cut short";
    }
    const uint64_t left = in.Size - in.Position;
    if (!compressed)
    {
      if (first > left)
      {
        return what + " announces " + std::to_string(first) + " bytes, but only " + std::to_string(left) +
          " follow (truncated file?)";
      }
      continue;
    }
    const uint64_t blocks = first;
    uint64_t blockSize = 0, lastSize = 0;
    if (!word(blockSize) || !word(lastSize) || blocks > (in.Size - in.Position) / headerSize)
    {
      return what + " announces " + std::to_string(blocks) + " compressed blocks, more than the file holds";
    }
    double compressedTotal = 0;
    for (uint64_t b = 0; b < blocks; ++b)
    {
      uint64_t size = 0;
      if (!word(size))
      {
        return what + ": its block sizes are cut short (truncated file?)";
      }
      compressedTotal += double(size);
    }
    const double dataLeft = double(in.Size - in.Position);
    if (compressedTotal > dataLeft)
    {
      return what + ": its compressed blocks need " + std::to_string(static_cast<unsigned long long>(compressedTotal)) +
        " bytes, but only " + std::to_string(static_cast<unsigned long long>(dataLeft)) + " follow (truncated file?)";
    }
    const double uncompressed = blocks == 0 ? 0.0 : double(blocks - 1) * double(blockSize) + double(lastSize ? lastSize : blockSize);
    if (lastSize > blockSize)
    {
      return what + ": its last block (" + std::to_string(lastSize) + " bytes) is larger than the block size (" +
        std::to_string(blockSize) + ") (corrupt header)";
    }
    if (uncompressed > 1032.0 * compressedTotal + 65536.0)
    {
      return what + " promises " + std::to_string(static_cast<unsigned long long>(uncompressed)) +
        " bytes from " + std::to_string(static_cast<unsigned long long>(compressedTotal)) +
        " compressed ones, more than compression allows (corrupt header)";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkPlumeFormatCheck::RunIsolated(
  const std::function<std::string()>& read, std::string* result, double timeoutSeconds)
{
  if (result)
  {
    result->clear();
  }
  if (!(timeoutSeconds > 0))
  {
    const char* env = std::getenv("PLUME_READER_TIMEOUT");
    char* end = nullptr;
    const double value = env ? std::strtod(env, &end) : 0.0;
    timeoutSeconds = env && end != env && value > 0 && std::isfinite(value) ? value : 300.0;
  }
  int fds[2];
  if (pipe(fds) != 0)
  {
    return std::string();
  }
  // what is buffered now would be written twice (by the child too)
  std::fflush(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0)
  {
    close(fds[0]);
    close(fds[1]);
    return std::string();
  }
  if (pid == 0)
  {
    close(fds[0]);
    // A crash of the reader ends the child by its signal, as in a plain build:
    // the parent's crash handlers (AddressSanitizer's report, libFuzzer's crash
    // file) are not for it, and it leaves no core file.
    for (const int sig : { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP })
    {
      std::signal(sig, SIG_DFL);
    }
    if (__sanitizer_set_death_callback)
    {
      __sanitizer_set_death_callback(nullptr);
    }
    const rlimit noCore{ 0, 0 };
    setrlimit(RLIMIT_CORE, &noCore);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      dup2(null, 1);
      dup2(null, 2);
    }
    std::string message(1, '\1'); // returned
    try
    {
      message += read();
    }
    catch (...)
    {
      // an exception (bad_alloc) is reported by the in-process read
    }
    for (size_t at = 0; at < message.size();)
    {
      const ssize_t written = write(fds[1], message.data() + at, message.size() - at);
      if (written <= 0)
      {
        break;
      }
      at += static_cast<size_t>(written);
    }
    _exit(0); // no static destructors or atexit handlers of the parent's state
  }
  close(fds[1]);
  std::string received;
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  for (;;)
  {
    const double left =
      std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0)
    {
      timedOut = true;
      break;
    }
    pollfd p{ fds[0], POLLIN, 0 };
    const int ready = poll(&p, 1, static_cast<int>(std::min(left * 1000.0 + 1.0, 1e9)));
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready <= 0)
    {
      continue; // the deadline check above ends the wait
    }
    char bytes[4096];
    const ssize_t n = ::read(fds[0], bytes, sizeof(bytes));
    if (n > 0)
    {
      received.append(bytes, static_cast<size_t>(n));
      continue; // until end of file: the child has exited
    }
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    break;
  }
  close(fds[0]);
  int status = 0;
  if (timedOut)
  {
    kill(pid, SIGKILL);
  }
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  const bool returned = !received.empty() && received[0] == '\1';
  if (returned && result)
  {
    *result = received.substr(1);
  }
  std::ostringstream why;
  if (timedOut)
  {
    why << "did not finish within " << timeoutSeconds << " s (PLUME_READER_TIMEOUT)";
  }
  else if (WIFSIGNALED(status))
  {
    why << "crashed (signal " << WTERMSIG(status) << ", " << strsignal(WTERMSIG(status)) << ")";
  }
  else if (WIFEXITED(status) && (!returned || WEXITSTATUS(status) != 0))
  {
    why << "ended the process (exit code " << WEXITSTATUS(status) << ")";
  }
  return why.str();
}

//------------------------------------------------------------------------------
bool vtkPlumeFormatCheck::IsNetCDFClassic(const std::string& path)
{
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  char magic[4] = { 0, 0, 0, 0 };
  in.read(magic, 4);
  return in.gcount() == 4 && magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F' &&
    (magic[3] == 1 || magic[3] == 2 || magic[3] == 5);
}

//------------------------------------------------------------------------------
bool vtkPlumeFormatCheck::HasInlineXMLData(const std::string& path)
{
  // chunk by chunk (a 16-byte overlap finds a match cut between two chunks), up to the appended section
  static const char* const formats[] = { "format=\"ascii\"", "format=\"binary\"", "format='ascii'",
    "format='binary'" };
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  std::string window;
  std::vector<char> chunk(1 << 16);
  while (in)
  {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    window.append(chunk.data(), static_cast<size_t>(in.gcount()));
    const size_t appended = window.find("<AppendedData");
    if (appended != std::string::npos)
    {
      window.resize(appended);
    }
    for (const char* format : formats)
    {
      if (window.find(format) != std::string::npos)
      {
        return true;
      }
    }
    if (appended != std::string::npos)
    {
      return false;
    }
    window.erase(0, window.size() > 16 ? window.size() - 16 : 0);
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkPlumeFormatCheck::MayHoldLegacyFieldData(const std::string& path)
{
  // chunk by chunk, lowercased, with a 4-byte overlap for a word cut between two chunks
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  std::string window;
  std::vector<char> chunk(1 << 16);
  while (in)
  {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const size_t kept = window.size();
    window.append(chunk.data(), static_cast<size_t>(in.gcount()));
    for (size_t i = kept; i < window.size(); ++i)
    {
      window[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(window[i])));
    }
    if (window.find("field") != std::string::npos)
    {
      return true;
    }
    window.erase(0, window.size() > 4 ? window.size() - 4 : 0);
  }
  return false;
}
