#include "plumeInfo.h"
#include "plumeSceneError.h"

#include "vtkPlumeDatasetReader.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace plume
{
namespace
{
// Keys in insertion order, so the JSON reads like the text form.
using json = nlohmann::ordered_json;

json Number(double v)
{
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json Range(vtkDataArray* array, int component)
{
  double range[2];
  array->GetRange(range, component);
  if (range[0] > range[1]) // empty array
  {
    return json(nullptr);
  }
  return json::array({ Number(range[0]), Number(range[1]) });
}

json DescribeArray(vtkAbstractArray* array)
{
  json a;
  a["name"] = array->GetName() ? array->GetName() : "";
  a["components"] = array->GetNumberOfComponents();
  a["type"] = array->GetDataTypeAsString();
  a["tuples"] = array->GetNumberOfTuples();
  auto* data = vtkDataArray::SafeDownCast(array);
  const bool text = array->GetDataType() == VTK_CHAR || array->GetDataType() == VTK_SIGNED_CHAR;
  if (data && text && data->GetNumberOfComponents() > 1)
  {
    a["text"] = true; // fixed-width character records (e.g. Exodus QA records): no ranges
  }
  else if (data)
  {
    const int nc = data->GetNumberOfComponents();
    if (nc == 1)
    {
      a["range"] = Range(data, 0);
    }
    else
    {
      json ranges = json::array();
      for (int c = 0; c < nc; ++c)
      {
        ranges.push_back(Range(data, c));
      }
      a["component_ranges"] = ranges;
      a["magnitude_range"] = Range(data, -1);
    }
  }
  return a;
}

json DescribeArrays(vtkFieldData* fd)
{
  json list = json::array();
  if (!fd)
  {
    return list;
  }
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
  {
    if (vtkAbstractArray* array = fd->GetAbstractArray(i))
    {
      list.push_back(DescribeArray(array));
    }
  }
  return list;
}

json Bounds(const double b[6])
{
  json list = json::array();
  for (int i = 0; i < 6; ++i)
  {
    list.push_back(Number(b[i]));
  }
  return list;
}

json DescribeDataSet(vtkDataSet* ds)
{
  json d;
  d["type"] = ds->GetClassName();
  d["points"] = ds->GetNumberOfPoints();
  d["cells"] = ds->GetNumberOfCells();
  if (ds->GetNumberOfPoints() > 0)
  {
    double b[6];
    ds->GetBounds(b);
    d["bounds"] = Bounds(b);
  }
  int dims[3] = { -1, -1, -1 };
  if (auto* image = vtkImageData::SafeDownCast(ds))
  {
    image->GetDimensions(dims);
    d["origin"] = json::array({ image->GetOrigin()[0], image->GetOrigin()[1], image->GetOrigin()[2] });
    d["spacing"] =
      json::array({ image->GetSpacing()[0], image->GetSpacing()[1], image->GetSpacing()[2] });
  }
  else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds))
  {
    sg->GetDimensions(dims);
  }
  else if (auto* rg = vtkRectilinearGrid::SafeDownCast(ds))
  {
    rg->GetDimensions(dims);
  }
  if (dims[0] >= 0)
  {
    d["dimensions"] = json::array({ dims[0], dims[1], dims[2] });
  }
  d["point_data"] = DescribeArrays(ds->GetPointData());
  d["cell_data"] = DescribeArrays(ds->GetCellData());
  d["field_data"] = DescribeArrays(ds->GetFieldData());
  return d;
}


// Leaves of a composite, depth first, with "/"-joined names (index when unnamed).
void CollectBlocks(vtkDataObject* node, const std::string& path, json& blocks)
{
  std::vector<std::pair<vtkDataObject*, std::string>> children;
  auto add = [&](vtkDataObject* child, unsigned int i) {
    const char* name = vtkPlumeDatasetReader::GetChildBlockName(node, i);
    const std::string component = name && *name ? std::string(name) : std::to_string(i);
    children.emplace_back(child, path.empty() ? component : path + "/" + component);
  };
  if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < mb->GetNumberOfBlocks(); ++i)
    {
      add(mb->GetBlock(i), i);
    }
  }
  else if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < pdc->GetNumberOfPartitionedDataSets(); ++i)
    {
      add(pdc->GetPartitionedDataSet(i), i);
    }
  }
  else if (auto* pd = vtkPartitionedDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < pd->GetNumberOfPartitions(); ++i)
    {
      add(pd->GetPartitionAsDataObject(i), i);
    }
  }
  for (const auto& child : children)
  {
    if (!child.first)
    {
      continue;
    }
    if (vtkCompositeDataSet::SafeDownCast(child.first))
    {
      CollectBlocks(child.first, child.second, blocks);
    }
    else if (auto* ds = vtkDataSet::SafeDownCast(child.first))
    {
      json block = DescribeDataSet(ds);
      block["name"] = child.second;
      blocks.push_back(block);
    }
    else
    {
      blocks.push_back({ { "name", child.second }, { "type", child.first->GetClassName() } });
    }
  }
}

json Describe(vtkPlumeDatasetReader* reader, vtkDataObject* data)
{
  json doc;
  doc["file"] = reader->GetFileName() ? reader->GetFileName() : "";
  doc["reader"] = reader->GetResolvedReaderName();
  doc["type"] = data->GetClassName();
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    json d = DescribeDataSet(ds);
    d.erase("type");
    doc.update(d);
  }
  else if (vtkCompositeDataSet::SafeDownCast(data))
  {
    json blocks = json::array();
    CollectBlocks(data, "", blocks);
    long long points = 0, cells = 0;
    double b[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
    for (const auto& block : blocks)
    {
      points += block.value("points", 0LL);
      cells += block.value("cells", 0LL);
      if (block.contains("bounds"))
      {
        for (int a = 0; a < 3; ++a)
        {
          const auto& lo = block["bounds"][2 * a];
          const auto& hi = block["bounds"][2 * a + 1];
          if (lo.is_number())
          {
            b[2 * a] = std::min(b[2 * a], lo.get<double>());
          }
          if (hi.is_number())
          {
            b[2 * a + 1] = std::max(b[2 * a + 1], hi.get<double>());
          }
        }
      }
    }
    doc["points"] = points;
    doc["cells"] = cells;
    if (points > 0)
    {
      doc["bounds"] = Bounds(b);
    }
    doc["blocks"] = blocks;
    doc["field_data"] = DescribeArrays(data->GetFieldData());
  }
  const auto& blockNames = reader->GetAvailableBlockNames();
  if (!blockNames.empty())
  {
    doc["source_blocks"] = blockNames;
  }
  json time;
  time["count"] = reader->GetTimeValues().size();
  time["values"] = reader->GetTimeValues();
  if (reader->GetTimeStepRead() >= 0 && !reader->GetTimeValues().empty())
  {
    time["step"] = reader->GetTimeStepRead();
    time["value"] = reader->GetTimeValues()[reader->GetTimeStepRead()];
  }
  doc["time"] = time;
  return doc;
}

// ---- text form
std::string Fmt(const json& v)
{
  if (v.is_null())
  {
    return "n/a";
  }
  if (v.is_number_integer() || v.is_number_unsigned())
  {
    return std::to_string(v.get<long long>());
  }
  if (v.is_number())
  {
    std::ostringstream s;
    s << std::setprecision(6) << v.get<double>();
    return s.str();
  }
  if (v.is_string())
  {
    return v.get<std::string>();
  }
  return v.dump();
}

std::string FmtRange(const json& r)
{
  if (!r.is_array() || r.size() != 2)
  {
    return "n/a";
  }
  return "[" + Fmt(r[0]) + ", " + Fmt(r[1]) + "]";
}

void PrintArrays(std::ostream& out, const char* title, const json& arrays, const std::string& indent)
{
  if (!arrays.is_array() || arrays.empty())
  {
    return;
  }
  out << indent << title << " (" << arrays.size() << "):\n";
  size_t width = 4;
  for (const auto& a : arrays)
  {
    width = std::max(width, a["name"].get<std::string>().size());
  }
  for (const auto& a : arrays)
  {
    out << indent << "  " << std::left << std::setw(static_cast<int>(width))
        << a["name"].get<std::string>() << "  " << std::setw(14) << a["type"].get<std::string>()
        << std::right << std::setw(2) << a["components"].get<int>() << "  ";
    if (a.contains("range"))
    {
      out << FmtRange(a["range"]);
    }
    else if (a.contains("magnitude_range"))
    {
      out << "|v| " << FmtRange(a["magnitude_range"]);
      const auto& ranges = a["component_ranges"];
      const char* axes[] = { "x", "y", "z" };
      for (size_t c = 0; c < ranges.size(); ++c)
      {
        out << "  " << (ranges.size() == 3 ? axes[c] : std::to_string(c).c_str()) << " "
            << FmtRange(ranges[c]);
      }
    }
    out << "\n";
  }
}

void PrintDataSet(std::ostream& out, const json& d, const std::string& indent)
{
  out << indent << "Points: " << Fmt(d["points"]) << "   Cells: " << Fmt(d["cells"]) << "\n";
  if (d.contains("dimensions"))
  {
    const auto& dims = d["dimensions"];
    out << indent << "Dimensions: " << Fmt(dims[0]) << " x " << Fmt(dims[1]) << " x "
        << Fmt(dims[2]) << "\n";
  }
  if (d.contains("origin"))
  {
    const auto& o = d["origin"];
    const auto& s = d["spacing"];
    out << indent << "Origin: (" << Fmt(o[0]) << ", " << Fmt(o[1]) << ", " << Fmt(o[2])
        << ")   Spacing: (" << Fmt(s[0]) << ", " << Fmt(s[1]) << ", " << Fmt(s[2]) << ")\n";
  }
  if (d.contains("bounds"))
  {
    const auto& b = d["bounds"];
    out << indent << "Bounds: x [" << Fmt(b[0]) << ", " << Fmt(b[1]) << "]  y [" << Fmt(b[2])
        << ", " << Fmt(b[3]) << "]  z [" << Fmt(b[4]) << ", " << Fmt(b[5]) << "]\n";
  }
  PrintArrays(out, "Point data", d.value("point_data", json::array()), indent);
  PrintArrays(out, "Cell data", d.value("cell_data", json::array()), indent);
  PrintArrays(out, "Field data", d.value("field_data", json::array()), indent);
}

void PrintText(std::ostream& out, const json& doc)
{
  out << "File: " << Fmt(doc["file"]) << "\n";
  out << "Reader: " << Fmt(doc["reader"]) << "\n";
  out << "Type: " << Fmt(doc["type"]) << "\n";
  PrintDataSet(out, doc, "");
  if (doc.contains("blocks"))
  {
    out << "Blocks (" << doc["blocks"].size() << "):\n";
    for (const auto& block : doc["blocks"])
    {
      out << "  " << Fmt(block["name"]) << ": " << Fmt(block["type"]) << "\n";
      if (block.contains("points"))
      {
        PrintDataSet(out, block, "    ");
      }
    }
  }
  if (doc.contains("source_blocks"))
  {
    out << "Blocks in the file:";
    for (const auto& name : doc["source_blocks"])
    {
      out << " " << Fmt(name) << ";";
    }
    out << "\n";
  }
  const auto& time = doc["time"];
  const auto& values = time["values"];
  out << "Time steps: " << Fmt(time["count"]);
  if (!values.empty())
  {
    out << " [";
    for (size_t i = 0; i < values.size(); ++i)
    {
      out << (i ? ", " : "") << Fmt(values[i]);
    }
    out << "]";
  }
  if (time.contains("step"))
  {
    out << "  (read step " << Fmt(time["step"]) << ", t = " << Fmt(time["value"]) << ")";
  }
  out << "\n";
}
}

int RunInfo(vtkPlumeDatasetReader* reader, bool json, std::ostream& out, std::ostream& err)
{
  if (!reader)
  {
    err << "plume: error: no reader\n";
    return 2;
  }
  reader->Update();
  vtkDataObject* data = reader->GetOutputDataObject(0);
  if (!reader->GetLastError().empty() || !data)
  {
    // the command line's one error line and exit code for bad input
    err << "plume: error: "
        << (reader->GetLastError().empty() ? std::string("the reader produced no data")
                                           : OneLine(reader->GetLastError()))
        << "\n";
    return 2;
  }
  const nlohmann::ordered_json doc = Describe(reader, data);
  if (json)
  {
    out << doc.dump(2) << "\n";
  }
  else
  {
    PrintText(out, doc);
  }
  return 0;
}
}
