// vtkPlumeAirlightPass's parameter table against the class: after
// construction every getter returns the declared default; every numeric
// setter clamps to the declared range (checked at both ends); the scene
// reader's Set() rejects an out-of-range value naming the key. (The medium
// table of Documentation/SceneFormat.md is generated from this table and
// checked by Plume.Docs.ParameterTables.)
#include "plumeTestSupport.h"

#include "vtkPlumeAirlightPass.h"
#include "vtkPlumeParameterTable.h"

#include "vtkNew.h"

#include <limits>
#include <stdexcept>

int TestAirlightParameters(int, char*[])
{
  int failures = 0;
  using Kind = vtkPlumeParameterTable::Kind;
  const vtkPlumeParameterTable& table = vtkPlumeAirlightPass::GetParameterTable();
  PLUME_CHECK(table.GetSceneType() == "medium");
  PLUME_CHECK(table.GetParameters().size() == 14);

  vtkNew<vtkPlumeAirlightPass> pass;
  PLUME_CHECK(!pass->HasMedium()); // clear air by default: the pass only runs its delegate
  for (const auto& p : table.GetParameters())
  {
    PLUME_CHECK(p.Setter && p.Getter);
    const std::string got = vtkPlumeParameterTable::Format(p.Get(pass));
    const std::string expected = vtkPlumeParameterTable::Format(p.Default);
    if (got != expected)
    {
      std::cerr << p.Key << ": default " << expected << ", object has " << got << "\n";
      ++failures;
    }
    if (p.Type == Kind::Integer || p.Type == Kind::Real)
    {
      vtkNew<vtkPlumeAirlightPass> other;
      // the class's own setter clamps to the declared range
      auto setRaw = [&](double v) {
        if (p.Type == Kind::Integer)
        {
          p.Setter(other, static_cast<long long>(v));
        }
        else
        {
          p.Setter(other, v);
        }
      };
      auto number = [&]() {
        const auto v = p.Get(other);
        return std::holds_alternative<long long>(v) ? static_cast<double>(std::get<long long>(v))
                                                      : std::get<double>(v);
      };
      setRaw(p.Minimum - 1.0);
      PLUME_CHECK(number() == p.Minimum);
      if (p.Maximum < 1e9)
      {
        setRaw(p.Maximum + 1.0);
        PLUME_CHECK(number() == p.Maximum);
      }
      bool threw = false;
      try
      {
        if (p.Type == Kind::Integer)
        {
          p.Set(other, static_cast<long long>(p.Minimum) - 1);
        }
        else
        {
          p.Set(other, p.Minimum - 1.0);
        }
      }
      catch (const std::invalid_argument&)
      {
        threw = true;
      }
      PLUME_CHECK(threw);
    }
  }
  // vectors: a negative coefficient is rejected by the table
  const auto* scattering = table.Find("scattering");
  PLUME_CHECK(scattering && !scattering->Check(std::array<double, 3>{ 0.1, -0.2, 0.1 }).empty());
  PLUME_CHECK(scattering && scattering->Check(std::array<double, 3>{ 0.1, 0.2, 0.1 }).empty());
  pass->SetScattering(0.0, 0.1, 0.0);
  PLUME_CHECK(pass->HasMedium());
  // the C++ setters clamp each channel to [0, 1e30] (NaN counts as 0)
  pass->SetAbsorption(-1.0, std::numeric_limits<double>::quiet_NaN(), 1e40);
  const double* a = pass->GetAbsorption();
  PLUME_CHECK(a[0] == 0.0 && a[1] == 0.0 && a[2] == 1e30);
  // the phase's asymmetry: NaN counts as 0 (isotropic)
  pass->SetScatteringAnisotropy(0.5);
  pass->SetScatteringAnisotropy(std::numeric_limits<double>::quiet_NaN());
  PLUME_CHECK(pass->GetScatteringAnisotropy() == 0.0);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
