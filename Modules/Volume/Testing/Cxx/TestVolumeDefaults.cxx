// The volume's defaults live in the library (vtkPlumeVolumeMapper), so C++,
// Python, ParaView and the plume command line get the same ones:
//  - opacity unit distance: a property at 0 means automatic, one voxel (the
//    image's mean |spacing|, here (0.02 + 0.01 + 0.03) / 3 = 0.02), and
//    draws exactly what the property set to that value draws; a property's
//    own value is honoured, 1 included (VTK's default and a user's 1 alike:
//    one world unit, as VTK's mappers read it; the mapper once read an exact
//    1 as "unset" and drew one voxel); the mapper's OpacityUnitDistance wins
//    over the property's; changing the automatic value re-tabulates (the
//    table holds it);
//  - iso value: unset (the mapper's NaN, the property at VTK's default, one
//    value 0, which only UsePropertyIsoValue says was meant; any other state,
//    a non-zero value or several values, is read as VTK's own mappers read
//    it), the middle of the colour transfer
//    function's range, drawing exactly what that value set explicitly draws;
//    0 is honoured, from the mapper and from the property alike;
//  - an iso value outside the data warns once per value (no surface shows);
//  - the unit distance and the iso value declared in the parameter table;
//  - the lighting per mode (ApplyDefaultLighting: smoke 0.3/1.0, else 0.15/0.75).
#include "plumeVolumeTestUtil.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContourValues.h"
#include "vtkPlumeParameterTable.h"

#include <cmath>
#include <limits>

int TestVolumeDefaults(int, char*[])
{
  using namespace plumevolumetest;
  int failures = 0;
  auto fail = [&](const char* what) {
    std::printf("FAIL: %s\n", what);
    ++failures;
  };
  auto field = SmokeField(32);
  field->SetSpacing(0.02, 0.01, 0.03);
  Scene s = MakeScene(field, 96, 96);
  vtkVolumeProperty* property = s.Volume->GetProperty();

  // ---- opacity unit distance
  property->SetScalarOpacityUnitDistance(0.0); // automatic
  const plume::test::FloatImage automatic = plume::test::ReadBack(s.Window);
  std::printf("automatic unit distance %.6g (want 0.02)\n", s.Mapper->GetEffectiveOpacityUnitDistance());
  if (std::abs(s.Mapper->GetEffectiveOpacityUnitDistance() - 0.02) > 1e-12 ||
    std::abs(vtkPlumeVolumeMapper::GetAutomaticOpacityUnitDistance(field) - 0.02) > 1e-12)
  {
    fail("the automatic opacity unit distance is not the mean spacing");
  }
  property->SetScalarOpacityUnitDistance(0.02);
  const plume::test::FloatImage explicitProperty = plume::test::ReadBack(s.Window);
  const double sameRMS = plume::test::Compare(automatic, explicitProperty).RMS;
  property->SetScalarOpacityUnitDistance(1.0); // a user's 1 (or VTK's default): one world unit
  const plume::test::FloatImage one = plume::test::ReadBack(s.Window);
  const double oneUnit = s.Mapper->GetEffectiveOpacityUnitDistance();
  const double oneRMS = plume::test::Compare(automatic, one).RMS;
  std::printf("property 1: unit %.6g (want 1), RMS %.3g against one voxel\n", oneUnit, oneRMS);
  if (oneUnit != 1.0 || oneRMS < 1e-3)
  {
    fail("a property's unit distance of 1 is not honoured");
  }
  property->SetScalarOpacityUnitDistance(0.2);
  const plume::test::FloatImage thinner = plume::test::ReadBack(s.Window);
  const double propertyUnit = s.Mapper->GetEffectiveOpacityUnitDistance();
  s.Mapper->SetOpacityUnitDistance(0.02); // the mapper's wins over the property's
  const plume::test::FloatImage mapperUnit = plume::test::ReadBack(s.Window);
  const double overrideRMS = plume::test::Compare(automatic, mapperUnit).RMS;
  const double thinnerRMS = plume::test::Compare(automatic, thinner).RMS;
  std::printf("automatic vs property 0.02: RMS %.3g; vs mapper 0.02: %.3g; vs property 0.2: %.3g (unit %.3g)\n",
    sameRMS, overrideRMS, thinnerRMS, propertyUnit);
  if (sameRMS > 0 || overrideRMS > 0)
  {
    fail("the automatic unit distance does not draw as the same value set explicitly");
  }
  if (propertyUnit != 0.2 || thinnerRMS < 1e-3)
  {
    fail("a property's own unit distance is not honoured");
  }
  // a new spacing changes the automatic value: the table follows without any data upload
  s.Mapper->SetOpacityUnitDistance(0.0);
  property->SetScalarOpacityUnitDistance(0.0);
  s.Window->Render();
  const int tables = s.Mapper->GetTableCount();
  const int uploads = s.Mapper->GetUploadCount();
  field->SetSpacing(0.04, 0.02, 0.06);
  s.Window->Render();
  std::printf("spacing doubled: unit %.3g, tables +%d\n", s.Mapper->GetEffectiveOpacityUnitDistance(),
    s.Mapper->GetTableCount() - tables);
  if (std::abs(s.Mapper->GetEffectiveOpacityUnitDistance() - 0.04) > 1e-12 || s.Mapper->GetTableCount() != tables + 1)
  {
    fail("the automatic unit distance does not follow the spacing");
  }
  field->SetSpacing(0.02, 0.01, 0.03);
  (void)uploads;

  // ---- iso value: the middle of the colour map
  s.Mapper->SetBlendModeToIsoSurface();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.2, 0.1, 0.3, 0.9);
  color->AddRGBPoint(0.6, 1.0, 0.6, 0.1);
  property->SetColor(color);
  const plume::test::FloatImage autoIso = plume::test::ReadBack(s.Window);
  std::printf("automatic iso value %.6g (want 0.4)\n", s.Mapper->GetEffectiveIsoValue());
  if (std::abs(s.Mapper->GetEffectiveIsoValue() - 0.4) > 1e-12)
  {
    fail("the automatic iso value is not the middle of the colour map");
  }
  s.Mapper->SetIsoValue(0.4);
  const double isoRMS = plume::test::Compare(autoIso, plume::test::ReadBack(s.Window)).RMS;
  s.Mapper->SetIsoValue(0.25);
  const double otherRMS = plume::test::Compare(autoIso, plume::test::ReadBack(s.Window)).RMS;
  std::printf("automatic iso vs 0.4 set: RMS %.3g; vs 0.25: %.3g\n", isoRMS, otherRMS);
  if (isoRMS > 0 || otherRMS < 1e-3)
  {
    fail("the automatic iso value does not draw as the same value set explicitly");
  }

  // the property's non-zero iso value with or without UsePropertyIsoValue (as
  // VTK's own mappers read it); its 0 (VTK's default, the same state as a 0
  // set on purpose) only with the switch, then as the mapper's own 0 is
  s.Mapper->SetIsoValue(std::numeric_limits<double>::quiet_NaN());
  property->GetIsoSurfaceValues()->SetValue(0, 0.3);
  s.Window->Render();
  const double unsetIso = s.Mapper->GetEffectiveIsoValue();
  s.Mapper->UsePropertyIsoValueOn();
  s.Window->Render();
  const double propertyIso = s.Mapper->GetEffectiveIsoValue();
  std::printf("property 0.3: in effect %.6g without UsePropertyIsoValue, %.6g with it (want 0.3 both)\n", unsetIso,
    propertyIso);
  if (unsetIso != 0.3 || propertyIso != 0.3)
  {
    fail("the property's non-zero iso value is not honoured");
  }
  // (0 lies just below this field's minimum: it draws no surface and warns,
  // which is what a 0 set on purpose must do here, unlike the automatic 0.4)
  property->GetIsoSurfaceValues()->SetValue(0, 0.0);
  const plume::test::FloatImage propertyZero = plume::test::ReadBack(s.Window);
  const double propertyZeroIso = s.Mapper->GetEffectiveIsoValue();
  s.Mapper->UsePropertyIsoValueOff();
  s.Mapper->SetIsoValue(0.0);
  const plume::test::FloatImage mapperZero = plume::test::ReadBack(s.Window);
  const double mapperZeroIso = s.Mapper->GetEffectiveIsoValue();
  const double zeroRMS = plume::test::Compare(propertyZero, mapperZero).RMS;
  const double zeroVsAuto = plume::test::Compare(autoIso, mapperZero).RMS;
  std::printf("iso 0: in effect %.6g (property) / %.6g (mapper); RMS %.3g between them, %.3g against automatic\n",
    propertyZeroIso, mapperZeroIso, zeroRMS, zeroVsAuto);
  if (propertyZeroIso != 0.0 || mapperZeroIso != 0.0 || zeroRMS > 0 || !(zeroVsAuto > 1e-3))
  {
    fail("an iso value of 0 is not honoured");
  }
  // several values are not VTK's default: the first, 0, without the switch too
  s.Mapper->SetIsoValue(std::numeric_limits<double>::quiet_NaN());
  property->GetIsoSurfaceValues()->SetNumberOfContours(2);
  property->GetIsoSurfaceValues()->SetValue(0, 0.0);
  property->GetIsoSurfaceValues()->SetValue(1, 0.3);
  s.Window->Render();
  const double listIso = s.Mapper->GetEffectiveIsoValue();
  std::printf("property values 0, 0.3: in effect %.6g without UsePropertyIsoValue (want 0)\n", listIso);
  if (listIso != 0.0)
  {
    fail("the first of several property iso values, 0, is not honoured");
  }
  property->GetIsoSurfaceValues()->SetNumberOfContours(1);
  property->GetIsoSurfaceValues()->SetValue(0, 0.0);

  // an iso value outside the data warns (no surface shows), once per value
  int warnings = 0;
  vtkNew<vtkCallbackCommand> onWarning;
  onWarning->SetClientData(&warnings);
  onWarning->SetCallback([](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  s.Mapper->AddObserver(vtkCommand::WarningEvent, onWarning);
  s.Mapper->SetIsoValue(1e3);
  s.Window->Render();
  s.Window->Render();
  const int sameValue = warnings;
  s.Mapper->SetIsoValue(2e3);
  s.Window->Render();
  s.Mapper->SetIsoValue(0.4);
  s.Window->Render();
  std::printf("out-of-range iso warnings: %d after two renders at 1e3, %d after 2e3 and 0.4 (want 1, 2)\n",
    sameValue, warnings);
  if (sameValue != 1 || warnings != 2)
  {
    fail("an iso value outside the data is not warned about once per value");
  }
  s.Mapper->RemoveObserver(onWarning);

  // ---- declared once, in the parameter table
  const auto* unit = vtkPlumeVolumeMapper::GetParameterTable().Find("opacity_unit_distance");
  if (!unit || unit->Property != "OpacityUnitDistance" || std::get<double>(unit->Default) != 0.0)
  {
    fail("opacity_unit_distance is not in the parameter table with default 0 (automatic)");
  }
  const auto* iso = vtkPlumeVolumeMapper::GetParameterTable().Find("iso_value");
  if (!iso || iso->Property != "IsoValue" || !iso->IsAutomatic || !std::isnan(std::get<double>(iso->Default)))
  {
    fail("iso_value is not in the parameter table as an automatic (NaN) IsoValue");
  }

  // ---- lighting: the mapper's, per mode (the command line starts from it)
  {
    vtkNew<vtkPlumeVolumeMapper> mapper;
    vtkNew<vtkVolumeProperty> lit;
    mapper->SetRenderMode(vtkPlumeVolumeMapper::RENDER_SMOKE);
    mapper->ApplyDefaultLighting(lit);
    const bool smoke = lit->GetAmbient() == 0.3 && lit->GetDiffuse() == 1.0 && lit->GetSpecular() == 0.3 &&
      lit->GetSpecularPower() == 20.0;
    mapper->SetRenderMode(vtkPlumeVolumeMapper::RENDER_ISOSURFACE);
    mapper->ApplyDefaultLighting(lit);
    const bool surface = lit->GetAmbient() == 0.15 && lit->GetDiffuse() == 0.75 && lit->GetSpecular() == 0.3 &&
      lit->GetSpecularPower() == 20.0;
    std::printf("default lighting: smoke %s, isosurface %s\n", smoke ? "0.3/1/0.3/20" : "WRONG",
      surface ? "0.15/0.75/0.3/20" : "WRONG");
    if (!smoke || !surface)
    {
      fail("ApplyDefaultLighting does not set the documented lighting");
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
