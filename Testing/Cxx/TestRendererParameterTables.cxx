// Each renderer's parameter table agrees with its C++ class: after
// construction every getter returns the table's default; every setter keeps
// the ends of the table's range and each named choice unchanged (a class that
// clamps tighter than its table, or a binding to the wrong property, fails);
// defaults lie in their own ranges; keys and properties are unique. An
// "automatic" real (NaN default) is checked on its own (CheckAutomatic).
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeDerivedGeometry.h"
#include "vtkPlumePressureSolver.h"
#include "vtkPlumeGaussianSplatter.h"
#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSmokeSolver.h"
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVolumeMapper.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace
{
using Table = vtkPlumeParameterTable;

bool Same(const Table::Value& a, const Table::Value& b)
{
  return Table::Format(a) == Table::Format(b);
}

int CheckTable(const Table& table, vtkObject* fresh, vtkObject* scratch)
{
  int failures = 0;
  std::set<std::string> keys, properties;
  for (const Table::Parameter& p : table.GetParameters())
  {
    auto fail = [&](const std::string& what) {
      std::printf("%s.%s: %s\n", table.GetClassName().c_str(), p.Key.c_str(), what.c_str());
      ++failures;
    };
    if (!keys.insert(p.Key).second || !properties.insert(p.Property).second)
    {
      fail("key or property declared twice");
    }
    if (!p.Setter || !p.Getter)
    {
      fail("not bound to the class");
      continue;
    }
    if (!p.Check(p.Default).empty())
    {
      fail("default outside its own range: " + p.Check(p.Default));
    }
    if (!Same(p.Get(fresh), p.Default))
    {
      fail("getter after construction " + Table::Format(p.Get(fresh)) + " != table default " +
        Table::Format(p.Default));
    }
    std::vector<Table::Value> probes;
    switch (p.Type)
    {
      case Table::Kind::Boolean:
        probes = { true, false };
        break;
      case Table::Kind::Integer:
        probes = { static_cast<long long>(p.Minimum), static_cast<long long>(p.Maximum) };
        break;
      case Table::Kind::Real:
        // an unbounded (e.g. automatic) real: finite values either side of 0
        probes = { std::isfinite(p.Minimum) ? p.Minimum : -2.5, std::isfinite(p.Maximum) ? p.Maximum : 3.5 };
        break;
      case Table::Kind::Choice:
        for (const auto& o : p.Options)
        {
          probes.emplace_back(o.Key);
        }
        break;
      case Table::Kind::Text:
        probes = { std::string("some_array"), std::string() };
        break;
      case Table::Kind::Vector3:
      {
        const double a = std::isfinite(p.Minimum) ? p.Minimum : -2.5;
        const double b = std::isfinite(p.Maximum) ? p.Maximum : 3.5;
        probes = { std::array<double, 3>{ a, b, a } };
        break;
      }
      case Table::Kind::Color:
        probes = { std::array<double, 3>{ 0.25, 0.5, 1.0 } };
        break;
    }
    for (const Table::Value& v : probes)
    {
      p.Set(scratch, v);
      if (!Same(p.Get(scratch), v))
      {
        fail("set " + Table::Format(v) + ", got back " + Table::Format(p.Get(scratch)));
      }
    }
  }
  std::printf("%s: %zu parameters checked\n", table.GetClassName().c_str(), table.GetParameters().size());
  return failures;
}

// An "automatic" real (the volume's iso_value): NaN is its default and stays
// valid (unset); a finite value is set; anything else is one error naming it;
// ordinary reals still refuse NaN; the markdown says "automatic".
int CheckAutomatic()
{
  int failures = 0;
  auto fail = [&](const std::string& what) {
    std::printf("automatic: %s\n", what.c_str());
    ++failures;
  };
  const Table& table = vtkPlumeVolumeMapper::GetParameterTable();
  const Table::Parameter* iso = table.Find("iso_value");
  if (!iso || iso->Property != "IsoValue" || !iso->IsAutomatic)
  {
    fail("vtkPlumeVolumeMapper declares no automatic iso_value bound to IsoValue");
    return failures;
  }
  vtkNew<vtkPlumeVolumeMapper> mapper;
  if (!std::isnan(mapper->GetIsoValue()) || !std::isnan(std::get<double>(iso->Default)))
  {
    fail("the default is not NaN (automatic)");
  }
  // absent: what a scene without the key leaves (defaults applied) is NaN
  mapper->SetIsoValue(3.0);
  table.ApplyDefaults(mapper);
  if (!std::isnan(mapper->GetIsoValue()))
  {
    fail("ApplyDefaults left " + std::to_string(mapper->GetIsoValue()) + ", not NaN");
  }
  // given: set, also as an integer (JSON 7)
  iso->Set(mapper, 0.25);
  if (mapper->GetIsoValue() != 0.25)
  {
    fail("Set(0.25) gave " + std::to_string(mapper->GetIsoValue()));
  }
  iso->Set(mapper, 7LL);
  if (mapper->GetIsoValue() != 7.0)
  {
    fail("Set(7) gave " + std::to_string(mapper->GetIsoValue()));
  }
  // bad values: one error naming the key and the value, nothing set
  const std::vector<std::pair<Table::Value, std::string>> bad = {
    { std::string("auto"), "\"auto\"" }, { std::numeric_limits<double>::infinity(), "inf" }, { true, "true" }
  };
  for (const auto& [value, shown] : bad)
  {
    try
    {
      iso->Set(mapper, value);
      fail("Set(" + shown + ") accepted");
    }
    catch (const std::invalid_argument& e)
    {
      const std::string what = e.what();
      if (what.find("'iso_value'") == std::string::npos || what.find(shown) == std::string::npos)
      {
        fail("the error for " + shown + " does not name key and value: " + what);
      }
    }
    if (mapper->GetIsoValue() != 7.0)
    {
      fail("a refused value changed the iso value");
    }
  }
  // NaN is a valid value only for an automatic parameter
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!iso->Check(nan).empty() || table.Find("sample_distance")->Check(nan).empty())
  {
    fail("NaN: accepted by an ordinary real or refused by the automatic one");
  }
  std::ostringstream markdown;
  table.WriteMarkdown(markdown);
  if (markdown.str().find("| `iso_value` | number | automatic (" + iso->AutomaticMeaning + ") |") ==
    std::string::npos)
  {
    fail("the markdown does not document iso_value's default as automatic");
  }
  // only reals can be automatic
  try
  {
    Table t("Test", "");
    t.Integer("n", "N", 1).Automatic("never");
    fail("an automatic integer was accepted");
  }
  catch (const std::logic_error&)
  {
  }
  std::printf("automatic iso_value checked\n");
  return failures;
}
}

int main()
{
  int failures = 0;
  {
    vtkNew<vtkPlumeSheetMapper> a, b;
    failures += CheckTable(vtkPlumeSheetMapper::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeVolumeMapper> a, b;
    failures += CheckTable(vtkPlumeVolumeMapper::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeVelocityGlyphMapper> a, b;
    failures += CheckTable(vtkPlumeVelocityGlyphMapper::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeGaussianSplatter> a, b; // its table makes the ParaView filter's properties
    failures += CheckTable(vtkPlumeGaussianSplatter::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeDerivedGeometry> a, b;
    failures += CheckTable(vtkPlumeDerivedGeometry::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeAirlightPass> a, b;
    failures += CheckTable(vtkPlumeAirlightPass::GetParameterTable(), a, b);
  }
  {
    vtkNew<vtkPlumeSmokeSolver> a, b;
    failures += CheckTable(vtkPlumeSmokeSolver::GetParameterTable(), a, b);
    // the pressure parameters are the pressure solver's own declaration,
    // reached through the smoke solver, which is marked modified by them
    const auto* tolerance = vtkPlumeSmokeSolver::GetParameterTable().Find("pressure_tolerance");
    const vtkMTimeType before = a->GetMTime();
    if (!tolerance || tolerance->Documentation !=
          vtkPlumePressureSolver::GetParameterTable().Find("pressure_tolerance")->Documentation)
    {
      std::printf("pressure_tolerance is not the pressure solver's declaration\n");
      ++failures;
    }
    else
    {
      tolerance->Set(a, 1e-4);
      if (a->GetPressureSolver()->GetTolerance() != 1e-4 || !(a->GetMTime() > before))
      {
        std::printf("pressure_tolerance did not reach the pressure solver or left the solver unmodified\n");
        ++failures;
      }
    }
  }
  failures += CheckAutomatic();
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
