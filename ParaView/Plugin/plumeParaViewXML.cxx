// Writes the plugin's server-manager XML (PlumeParaView.xml) at build time.
//
// Every property of a Plume class comes from the class's
// vtkPlumeParameterTable: name (the table's Property: Set<Property>/
// Get<Property>), label, default, range, enumeration, documentation with
// units, panel group and advanced flag. Each also gets an information-only
// twin "<Property>Info" (Get<Property>) so scripts and tests can read the C++
// value back through the server manager. Only the representation scaffolding
// (inputs, colour maps, which ParaView representation each extends) is
// written here by hand.
//
// Usage: plumeParaViewXML OUTPUT.xml
#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSmokeSolver.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"

#include "vtkNew.h"
#include "vtkXMLUtilities.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Table = vtkPlumeParameterTable;
using Kind = vtkPlumeParameterTable::Kind;

// XML text and attribute values (file names and documentation may hold &, <,
// ", ...): VTK's own entity encoder, bytes otherwise passed through
std::string Escape(const std::string& s)
{
  std::ostringstream out;
  vtkXMLUtilities::EncodeString(s.c_str(), VTK_ENCODING_NONE, out, VTK_ENCODING_NONE, 1);
  return out.str();
}

std::string Number(double v)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

// "SampleDistance" -> "Sample Distance" (ParaView's own labels read that way).
std::string Label(const std::string& property)
{
  std::string out;
  for (size_t i = 0; i < property.size(); ++i)
  {
    const char c = property[i];
    if (i > 0 && std::isupper(static_cast<unsigned char>(c)) &&
      (std::islower(static_cast<unsigned char>(property[i - 1])) ||
        (i + 1 < property.size() && std::islower(static_cast<unsigned char>(property[i + 1])))))
    {
      out += ' ';
    }
    out += c;
  }
  return out;
}

std::string Documentation(const Table::Parameter& p)
{
  std::string doc = p.Documentation;
  if (!p.Unit.empty())
  {
    doc += " Unit: " + p.Unit + ".";
  }
  for (const auto& option : p.Options)
  {
    doc += " " + option.Key + ": " + option.Doc + ".";
  }
  if (p.IsAutomatic)
  {
    doc += " Default: automatic (nan): " + p.AutomaticMeaning + "; type nan to return to it.";
  }
  return Escape(doc);
}

// A parameter that applies only under some options of a choice
// (Parameter::OnlyWith) is hidden by ParaView's panel under the others, as
// ParaView's own XML does: a visibility decorator on the choice's property
// as the panel names it (`prefix` + property: the representation's exposed
// name). A key or option that is not in the table stops the build.
std::string OnlyWithHints(const Table& table, const Table::Parameter& p, const std::string& prefix)
{
  if (p.OnlyWithKey.empty())
  {
    return "";
  }
  const Table::Parameter* choice = table.Find(p.OnlyWithKey);
  if (!choice || choice->Type != Kind::Choice || p.OnlyWithOptions.empty())
  {
    throw std::runtime_error(table.GetClassName() + "." + p.Property + ": OnlyWith names '" + p.OnlyWithKey +
      "', not a choice of the table with options");
  }
  const std::string property = prefix + choice->Property;
  auto generic = [&property](int value) {
    return "<PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" property=\"" + property +
      "\" value=\"" + std::to_string(value) + "\"/>";
  };
  std::vector<int> values;
  for (const auto& key : p.OnlyWithOptions)
  {
    const Table::Option* option = choice->FindOption(key);
    if (!option)
    {
      throw std::runtime_error(table.GetClassName() + "." + p.Property + ": OnlyWith option '" + key +
        "' is not an option of '" + p.OnlyWithKey + "'");
    }
    values.push_back(option->Number);
  }
  std::string hints = "        <Hints>";
  if (values.size() == 1)
  {
    hints += generic(values[0]);
  }
  else
  {
    // shown when any of the options is chosen
    hints += "<PropertyWidgetDecorator type=\"CompositeDecorator\"><Expression type=\"or\">";
    for (int value : values)
    {
      hints += generic(value);
    }
    hints += "</Expression></PropertyWidgetDecorator>";
  }
  return hints + "</Hints>\n";
}

// Vector3 parameters whose C++ setter and getter take ints (the table's
// vectors are doubles): written as integer vectors.
bool IsIntegerVector(const Table& table, const Table::Parameter& p)
{
  return table.GetClassName() == "vtkPlumeSmokeSolver" && p.Property == "Dimensions";
}

// One property (and its information twin) of a proxy whose class is the
// table's; `prefix`: what the panel puts before the table's property names.
void WriteProperty(std::ostream& os, const Table& table, const Table::Parameter& p, const std::string& prefix,
  bool integerVector = false)
{
  const std::string name = p.Property;
  const std::string common = "name=\"" + name + "\" label=\"" + Escape(Label(name)) + "\" command=\"Set" +
    name + "\" information_property=\"" + name + "Info\"" +
    (p.IsAdvanced ? " panel_visibility=\"advanced\"" : "");
  const std::string doc =
    "        <Documentation>" + Documentation(p) + "</Documentation>\n" + OnlyWithHints(table, p, prefix);
  const bool finiteMin = std::isfinite(p.Minimum);
  const bool finiteMax = std::isfinite(p.Maximum);
  switch (p.Type)
  {
    case Kind::Boolean:
      os << "      <IntVectorProperty " << common << " number_of_elements=\"1\" default_values=\""
         << (std::get<bool>(p.Default) ? 1 : 0) << "\">\n        <BooleanDomain name=\"bool\"/>\n"
         << doc << "      </IntVectorProperty>\n";
      os << "      <IntVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\"><SimpleIntInformationHelper/></IntVectorProperty>\n";
      break;
    case Kind::Integer:
    {
      // Int properties are 32-bit; larger ranges (vtkIdType counts) stop at INT_MAX.
      const double lo = finiteMin ? std::max(p.Minimum, double(INT_MIN)) : double(INT_MIN);
      const double hi = finiteMax ? std::min(p.Maximum, double(INT_MAX)) : double(INT_MAX);
      os << "      <IntVectorProperty " << common << " number_of_elements=\"1\" default_values=\""
         << std::get<long long>(p.Default) << "\">\n        <IntRangeDomain name=\"range\" min=\""
         << static_cast<long long>(lo) << "\" max=\"" << static_cast<long long>(hi) << "\"/>\n"
         << doc << "      </IntVectorProperty>\n";
      os << "      <IntVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\"><SimpleIntInformationHelper/></IntVectorProperty>\n";
      break;
    }
    case Kind::Choice:
    {
      const Table::Option* def = p.FindOption(std::get<std::string>(p.Default));
      os << "      <IntVectorProperty " << common << " number_of_elements=\"1\" default_values=\""
         << (def ? def->Number : 0) << "\">\n        <EnumerationDomain name=\"enum\">\n";
      for (const auto& option : p.Options)
      {
        os << "          <Entry value=\"" << option.Number << "\" text=\"" << Escape(option.Key)
           << "\"/>\n";
      }
      os << "        </EnumerationDomain>\n" << doc << "      </IntVectorProperty>\n";
      os << "      <IntVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\"><SimpleIntInformationHelper/></IntVectorProperty>\n";
      break;
    }
    case Kind::Real:
      // "automatic" (NaN): no XML default; default_values="none" makes ParaView
      // take the initial value from the C++ object through the information
      // property (vtkSMDoubleVectorProperty::ReadXMLAttributes), so the panel
      // shows nan until the user types a value
      os << "      <DoubleVectorProperty " << common << " number_of_elements=\"1\" default_values=\""
         << (p.IsAutomatic ? std::string("none") : Number(std::get<double>(p.Default)))
         << "\">\n        <DoubleRangeDomain name=\"range\"";
      if (finiteMin)
      {
        os << " min=\"" << Number(p.Minimum) << "\"";
      }
      if (finiteMax)
      {
        os << " max=\"" << Number(p.Maximum) << "\"";
      }
      os << "/>\n" << doc << "      </DoubleVectorProperty>\n";
      os << "      <DoubleVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\"><SimpleDoubleInformationHelper/></DoubleVectorProperty>\n";
      break;
    case Kind::Text:
      os << "      <StringVectorProperty " << common << " number_of_elements=\"1\" default_values=\""
         << Escape(std::get<std::string>(p.Default)) << "\">\n"
         << doc << "      </StringVectorProperty>\n";
      os << "      <StringVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\"><SimpleStringInformationHelper/></StringVectorProperty>\n";
      break;
    case Kind::Vector3:
    case Kind::Color:
    {
      const auto& v = std::get<std::array<double, 3>>(p.Default);
      if (integerVector)
      {
        const auto lo = static_cast<long long>(finiteMin ? p.Minimum : INT_MIN);
        const auto hi = static_cast<long long>(finiteMax ? p.Maximum : INT_MAX);
        os << "      <IntVectorProperty " << common << " number_of_elements=\"3\" default_values=\""
           << std::llround(v[0]) << " " << std::llround(v[1]) << " " << std::llround(v[2])
           << "\">\n        <IntRangeDomain name=\"range\" min=\"" << lo << " " << lo << " " << lo
           << "\" max=\"" << hi << " " << hi << " " << hi << "\"/>\n"
           << doc << "      </IntVectorProperty>\n";
        os << "      <IntVectorProperty name=\"" << name << "Info\" command=\"Get" << name
           << "\" information_only=\"1\" number_of_elements=\"3\" default_values=\"0 0 0\">"
              "<SimpleIntInformationHelper/></IntVectorProperty>\n";
        break;
      }
      os << "      <DoubleVectorProperty " << common << " number_of_elements=\"3\" default_values=\""
         << Number(v[0]) << " " << Number(v[1]) << " " << Number(v[2]) << "\""
         << (p.Type == Kind::Color ? " panel_widget=\"color_selector\"" : "")
         << ">\n        <DoubleRangeDomain name=\"range\"";
      if (finiteMin)
      {
        os << " min=\"" << Number(p.Minimum) << " " << Number(p.Minimum) << " " << Number(p.Minimum)
           << "\"";
      }
      if (finiteMax)
      {
        os << " max=\"" << Number(p.Maximum) << " " << Number(p.Maximum) << " " << Number(p.Maximum)
           << "\"";
      }
      os << "/>\n" << doc << "      </DoubleVectorProperty>\n";
      os << "      <DoubleVectorProperty name=\"" << name << "Info\" command=\"Get" << name
         << "\" information_only=\"1\" number_of_elements=\"3\" default_values=\"0 0 0\">"
            "<SimpleDoubleInformationHelper/>"
            "</DoubleVectorProperty>\n";
      break;
    }
  }
}

void WriteMapperProxy(std::ostream& os, const std::string& proxyName, const Table& table, const std::string& prefix)
{
  os << "    <Proxy name=\"" << proxyName << "\" class=\"" << table.GetClassName()
     << "\" processes=\"client|dataserver|renderserver\">\n"
     << "      <Documentation>" << table.GetClassName()
     << "'s parameters (generated from its vtkPlumeParameterTable).</Documentation>\n";
  for (const auto& p : table.GetParameters())
  {
    WriteProperty(os, table, p, prefix);
  }
  os << "    </Proxy>\n";
}

// The groups of a table in declaration order, each with its properties.
std::vector<std::pair<std::string, std::vector<const Table::Parameter*>>> Groups(
  const Table& table, const std::string& mainGroup)
{
  std::vector<std::pair<std::string, std::vector<const Table::Parameter*>>> groups;
  for (const auto& p : table.GetParameters())
  {
    const std::string g = p.Group.empty() ? mainGroup : p.Group;
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == g; });
    if (it == groups.end())
    {
      groups.push_back({ g, {} });
      it = groups.end() - 1;
    }
    it->second.push_back(&p);
  }
  return groups;
}

struct Representation
{
  std::string Name;     // proxy name, e.g. PlumeVolumeRepresentation
  std::string Text;     // the Representation menu entry, e.g. "Plume Volume"
  std::string Prefix;   // top-level exposed-name prefix (names stay unique next to ParaView's)
  std::string Mapper;   // mapper proxy name
  const Table* MapperTable;
  std::string OwnProperties; // hand-written: inputs, colour map, ...
  std::vector<std::string> OwnNames; // of OwnProperties, linked to ParaView's same-named ones
  std::vector<std::pair<std::string, std::string>> Extends; // (ParaView representation, subproxy to share with)
};

void WriteRepresentationProxy(std::ostream& os, const Representation& r)
{
  os << "    <RepresentationProxy name=\"" << r.Name << "\" class=\"vtk" << r.Name
     << "\" processes=\"client|dataserver|renderserver\">\n"
     << "      <Documentation>" << Escape(r.Text) << ": " << r.MapperTable->GetClassName()
     << " as a ParaView representation.</Documentation>\n"
     << r.OwnProperties
     << "      <IntVectorProperty name=\"Visibility\" command=\"SetVisibility\" number_of_elements=\"1\""
        " default_values=\"1\"><BooleanDomain name=\"bool\"/></IntVectorProperty>\n"
     << "      <SubProxy command=\"SetMapper\">\n"
     << "        <Proxy name=\"Mapper\" proxygroup=\"plume_mappers\" proxyname=\"" << r.Mapper << "\"/>\n"
     << "        <ExposedProperties>\n";
  for (const auto& p : r.MapperTable->GetParameters())
  {
    os << "          <Property name=\"" << p.Property << "\"/>\n";
  }
  os << "        </ExposedProperties>\n      </SubProxy>\n    </RepresentationProxy>\n";
}

void WriteExtension(std::ostream& os, const Representation& r, const std::string& base,
  const std::string& shareWith, const std::string& subproxy)
{
  os << "    <Extension name=\"" << base << "\">\n"
     << "      <RepresentationType subproxy=\"" << subproxy << "\" text=\"" << r.Text << "\"/>\n"
     << "      <SubProxy>\n"
     << "        <Proxy name=\"" << subproxy << "\" proxygroup=\"representations\" proxyname=\"" << r.Name
     << "\"/>\n"
     << "        <ShareProperties subproxy=\"" << shareWith << "\">\n"
     << "          <Exception name=\"Input\"/>\n          <Exception name=\"Visibility\"/>\n";
  // The mapper's properties are Plume's own: never linked to ParaView's
  // same-named ones (e.g. LineWidth).
  for (const auto& p : r.MapperTable->GetParameters())
  {
    os << "          <Exception name=\"" << p.Property << "\"/>\n";
  }
  os << "        </ShareProperties>\n        <ExposedProperties>\n";
  for (const auto& [group, params] : Groups(*r.MapperTable, r.Text))
  {
    os << "          <PropertyGroup label=\"" << Escape(r.Text + (group == r.Text ? "" : " - " + group))
       << "\">\n";
    for (const auto* p : params)
    {
      os << "            <Property name=\"" << p->Property << "\" exposed_name=\"" << r.Prefix
         << p->Property << "\"/>\n";
    }
    os << "            <Hints><PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\""
          " property=\"Representation\" value=\""
       << r.Text << "\"/></Hints>\n          </PropertyGroup>\n";
  }
  os << "        </ExposedProperties>\n      </SubProxy>\n    </Extension>\n";
}

const char* ColorArrayProperty = R"(      <StringVectorProperty name="ColorArrayName" command="SetInputArrayToProcess"
        element_types="0 0 0 0 2" number_of_elements="5" default_values="0 0 0 0 ">
        <ArrayListDomain name="array_list" attribute_type="Scalars" input_domain_name="input_array">
          <RequiredProperties><Property name="Input" function="Input"/></RequiredProperties>
        </ArrayListDomain>
        <Documentation>The array coloured (and, for the volume, rendered).</Documentation>
      </StringVectorProperty>
      <ProxyProperty name="LookupTable" command="SetLookupTable">
        <ProxyGroupDomain name="groups"><Group name="lookup_tables"/></ProxyGroupDomain>
        <Documentation>ParaView's colour map.</Documentation>
      </ProxyProperty>
)";

std::string InputProperty(const std::string& types)
{
  std::string s = R"(      <InputProperty name="Input" command="SetInputConnection">
        <DataTypeDomain name="input_type" composite_data_supported="1">
)";
  std::istringstream in(types);
  std::string t;
  while (in >> t)
  {
    s += "          <DataType value=\"" + t + "\"/>\n";
  }
  s += R"(        </DataTypeDomain>
        <InputArrayDomain name="input_array" attribute_type="any"/>
      </InputProperty>
)";
  return s;
}
} // namespace

int Generate(const char* path);

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: plumeParaViewXML OUTPUT.xml\n";
    return 2;
  }
  try
  {
    return Generate(argv[1]);
  }
  catch (const std::exception& e)
  {
    std::cerr << "plumeParaViewXML: " << e.what() << "\n";
    return 1;
  }
}

int Generate(const char* path)
{
  std::ostringstream os;
  os << "<!-- Generated by plumeParaViewXML from the Plume classes' parameter tables: do not edit. -->\n"
     << "<ServerManagerConfiguration>\n";

  // Mappers: one proxy per class, every table property.
  os << "  <ProxyGroup name=\"plume_mappers\">\n";
  // (the prefixes: the representations' exposed names, below)
  WriteMapperProxy(os, "PlumeVolumeMapper", vtkPlumeVolumeMapper::GetParameterTable(), "PlumeVolume");
  WriteMapperProxy(os, "PlumeSheetMapper", vtkPlumeSheetMapper::GetParameterTable(), "PlumeSheet");
  WriteMapperProxy(os, "PlumeVelocityGlyphMapper", vtkPlumeVelocityGlyphMapper::GetParameterTable(), "PlumeLines");
  os << "  </ProxyGroup>\n";

  std::vector<Representation> reps;
  reps.push_back({ "PlumeVolumeRepresentation", "Plume Volume", "PlumeVolume", "PlumeVolumeMapper",
    &vtkPlumeVolumeMapper::GetParameterTable(),
    InputProperty(
      "vtkImageData vtkMultiBlockDataSet vtkPartitionedDataSet vtkPartitionedDataSetCollection vtkOverlappingAMR "
      "vtkNonOverlappingAMR") +
      ColorArrayProperty +
      R"(      <ProxyProperty name="ScalarOpacityFunction" command="SetScalarOpacity">
        <ProxyGroupDomain name="groups"><Group name="piecewise_functions"/></ProxyGroupDomain>
        <Documentation>ParaView's opacity transfer function.</Documentation>
      </ProxyProperty>
)",
    // No ScalarOpacityUnitDistance of its own: linked to ParaView's Volume
    // representation's, it took that one's default from the data (its
    // BoundsDomain "approximate_cell_length": 1.84 on carotid) in serial pvbatch
    // but stayed 1 under symmetric MPI. The mapper's OpacityUnitDistance
    // (PlumeVolumeOpacityUnitDistance; 0: one voxel) is the one setting.
    {},
    // AMR: ParaView shows vtkOverlappingAMR with its AMRRepresentation (its
    // "Volume" resamples the levels onto one grid, as vtkPlumeImageInput does)
    { { "UniformGridRepresentation", "VolumeRepresentation" }, { "AMRRepresentation", "VolumeRepresentation" } } });
  reps.push_back({ "PlumeSheetRepresentation", "Plume Smoke Sheet", "PlumeSheet", "PlumeSheetMapper",
    &vtkPlumeSheetMapper::GetParameterTable(),
    InputProperty("vtkPolyData vtkMultiBlockDataSet vtkPartitionedDataSet vtkPartitionedDataSetCollection"), {},
    { { "GeometryRepresentation", "SurfaceRepresentation" } } });
  reps.push_back({ "PlumeVelocityLinesRepresentation", "Plume Velocity Lines", "PlumeLines",
    "PlumeVelocityGlyphMapper", &vtkPlumeVelocityGlyphMapper::GetParameterTable(),
    InputProperty(
      "vtkDataSet vtkMultiBlockDataSet vtkPartitionedDataSet vtkPartitionedDataSetCollection vtkOverlappingAMR "
      "vtkNonOverlappingAMR") +
      ColorArrayProperty,
    {},
    { { "UniformGridRepresentation", "SurfaceRepresentation" }, { "AMRRepresentation", "SurfaceRepresentation" },
      { "UnstructuredGridRepresentation", "SurfaceRepresentation" },
      { "StructuredGridRepresentation", "SurfaceRepresentation" } } });

  os << "  <ProxyGroup name=\"representations\">\n";
  for (const auto& r : reps)
  {
    WriteRepresentationProxy(os, r);
  }
  for (const auto& r : reps)
  {
    for (const auto& [base, shareWith] : r.Extends)
    {
      WriteExtension(os, r, base, shareWith, r.Name);
    }
  }
  os << "  </ProxyGroup>\n";

  // The filter.
  const Table& splat = vtkPlumeGaussianSplatter::GetParameterTable();
  vtkNew<vtkPlumeGaussianSplatter> splatter; // Dimensions' default: the class's own
  const int* dims = splatter->GetDimensions();
  os << R"(  <ProxyGroup name="filters">
    <SourceProxy name="PlumeGaussianSplat" class="vtkPlumePGaussianSplatter" label="Plume Gaussian Splat">
      <Documentation short_help="Splat points or polylines into an image (velocity, density or distance).">
        Gaussian splatting of points (first input) and polylines (second input, optional) into
        a 3D image: the velocity of lines or the points' vectors, a density, or a distance-like
        field, ready for the Plume Volume and Plume Velocity Lines representations.
      </Documentation>
      <InputProperty name="Input" port_index="0" command="SetInputConnection">
        <ProxyGroupDomain name="groups"><Group name="sources"/><Group name="filters"/></ProxyGroupDomain>
        <DataTypeDomain name="input_type"><DataType value="vtkPointSet"/></DataTypeDomain>
        <Documentation>Points to splat (their vectors or scalars).</Documentation>
      </InputProperty>
      <InputProperty name="Lines" port_index="1" command="SetInputConnection">
        <ProxyGroupDomain name="groups"><Group name="sources"/><Group name="filters"/></ProxyGroupDomain>
        <DataTypeDomain name="input_type"><DataType value="vtkPolyData"/></DataTypeDomain>
        <Documentation>Optional polylines (e.g. stream lines) whose segments are splatted.</Documentation>
        <Hints><Optional/></Hints>
      </InputProperty>
      <IntVectorProperty name="Dimensions" command="SetDimensions" number_of_elements="3" default_values=")"
     << dims[0] << " " << dims[1] << " " << dims[2] << R"(">
        <IntRangeDomain name="range" min="1 1 1"/>
        <Documentation>Output image dimensions (over the inputs' bounds padded by the splat support).</Documentation>
      </IntVectorProperty>
)";
  for (const auto& p : splat.GetParameters())
  {
    WriteProperty(os, splat, p, "");
  }
  for (const auto& [group, params] : Groups(splat, "Splat"))
  {
    os << "      <PropertyGroup label=\"" << Escape(group) << "\">\n";
    for (const auto* p : params)
    {
      os << "        <Property name=\"" << p->Property << "\"/>\n";
    }
    os << "      </PropertyGroup>\n";
  }
  os << R"(      <Hints><ShowInMenu category="Plume"/></Hints>
    </SourceProxy>
  </ProxyGroup>
)";

  // The smoke solver: a time-aware image source with three optional inputs.
  const Table& smoke = vtkPlumeSmokeSolver::GetParameterTable();
  os << R"(  <ProxyGroup name="sources">
    <SourceProxy name="PlumeSmokeSolver" class="vtkPlumeSmokeSolver" label="Plume Smoke Solver">
      <Documentation short_help="Eulerian smoke simulation on a grid (buoyancy, sources, obstacles).">
        Smoke simulated on a MAC grid: semi-Lagrangian or MacCormack advection, buoyancy, point
        sources, obstacles and a pressure projection (Jacobi or hypre's PCG). A time-aware image
        source: time k * TimeStep is simulation step k. Output point arrays velocity, density,
        temperature, pressure, divergence, obstacle.
      </Documentation>
      <InputProperty name="Obstacles" port_index="0" command="SetInputConnection">
        <ProxyGroupDomain name="groups"><Group name="sources"/><Group name="filters"/></ProxyGroupDomain>
        <DataTypeDomain name="input_type"><DataType value="vtkImageData"/></DataTypeDomain>
        <Documentation>Optional image whose point array ObstacleArrayName (&gt; 0.5) marks solid cells (nearest input point).</Documentation>
        <Hints><Optional/></Hints>
      </InputProperty>
      <InputProperty name="Velocity" port_index="1" command="SetInputConnection">
        <ProxyGroupDomain name="groups"><Group name="sources"/><Group name="filters"/></ProxyGroupDomain>
        <DataTypeDomain name="input_type"><DataType value="vtkImageData"/></DataTypeDomain>
        <Documentation>Optional velocity image (VelocityArrayName) in which the smoke is released passively.</Documentation>
        <Hints><Optional/></Hints>
      </InputProperty>
      <InputProperty name="SourcePoints" port_index="2" command="SetInputConnection">
        <ProxyGroupDomain name="groups"><Group name="sources"/><Group name="filters"/></ProxyGroupDomain>
        <DataTypeDomain name="input_type"><DataType value="vtkPointSet"/></DataTypeDomain>
        <Documentation>Optional point sources (any dataset with points: polydata, unstructured grid, ...): every
          step each point injects smoke mass at a rate, spread over the fluid cells within its radius, so the
          total (density x cell volume) grows by the rate x TimeStep. Per-point arrays (names set by the
          Source*ArrayName properties; a missing array gives the Source* constant): "rate" (mass per second,
          density x model units^3 / s), "temperature" (set around the point), "radius" (model units; 0 = the
          cell holding the point), "velocity" (3 components, set on the faces around the point; none if
          absent). Points outside the domain or in solid cells emit nothing.</Documentation>
        <Hints><Optional/></Hints>
      </InputProperty>
      <DoubleVectorProperty name="TimestepValues" information_only="1" repeatable="1">
        <TimeStepsInformationHelper/>
        <Documentation>The simulation's times (k * TimeStep, k = 0 .. NumberOfTimeSteps).</Documentation>
      </DoubleVectorProperty>
)";
  for (const auto& p : smoke.GetParameters())
  {
    WriteProperty(os, smoke, p, "", IsIntegerVector(smoke, p));
  }
  for (const auto& [group, params] : Groups(smoke, "Smoke"))
  {
    os << "      <PropertyGroup label=\"" << Escape(group) << "\">\n";
    for (const auto* p : params)
    {
      os << "        <Property name=\"" << p->Property << "\"/>\n";
    }
    os << "      </PropertyGroup>\n";
  }
  os << R"(      <Hints><ShowInMenu category="Plume"/></Hints>
    </SourceProxy>
  </ProxyGroup>
</ServerManagerConfiguration>
)";

  std::ofstream out(path);
  out << os.str();
  if (!out)
  {
    std::cerr << "plumeParaViewXML: cannot write " << path << "\n";
    return 1;
  }
  return 0;
}
