// Every dataset of the shared data folder loads through vtkPlumeDatasetReader with the facts
// its README states (sizes, bounds, arrays and ranges), including time series and blocks.
#include "plumeDataTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdio>
#include <vector>

using plumetest::Checker;

namespace
{
vtkDataSet* Load(Checker& check, vtkPlumeDatasetReader* reader, const char* expectedType)
{
  reader->Update();
  if (!check.True(reader->GetLastError().empty(), "reader error: " + reader->GetLastError()))
  {
    return nullptr;
  }
  vtkDataObject* data = reader->GetOutputDataObject(0);
  if (!check.True(data != nullptr, "no output"))
  {
    return nullptr;
  }
  check.Equal(std::string(data->GetClassName()), std::string(expectedType), "output type");
  return vtkDataSet::SafeDownCast(data);
}

void Dims(Checker& check, vtkDataSet* ds, int x, int y, int z)
{
  int dims[3] = { -1, -1, -1 };
  if (auto* image = vtkImageData::SafeDownCast(ds))
  {
    image->GetDimensions(dims);
  }
  else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds))
  {
    sg->GetDimensions(dims);
  }
  check.Equal(dims[0], x, "dims x");
  check.Equal(dims[1], y, "dims y");
  check.Equal(dims[2], z, "dims z");
}

void Size(Checker& check, vtkDataSet* ds, vtkIdType points, vtkIdType cells)
{
  if (!check.True(ds != nullptr, "no dataset"))
  {
    return;
  }
  check.Equal(ds->GetNumberOfPoints(), points, "points");
  check.Equal(ds->GetNumberOfCells(), cells, "cells");
}

void Classic(Checker& check)
{
  {
    check.Context = "carotid.vtk";
    auto reader = plumetest::Reader("classic/carotid.vtk");
    vtkDataSet* ds = Load(check, reader, "vtkImageData");
    Dims(check, ds, 76, 49, 45);
    if (auto* image = vtkImageData::SafeDownCast(ds))
    {
      const double* o = image->GetOrigin();
      const double* s = image->GetSpacing();
      check.True(o[0] == 100 && o[1] == 80 && o[2] == 1, "origin (100, 80, 1)");
      check.True(s[0] == 1 && s[1] == 1 && s[2] == 1, "spacing 1");
    }
    const double b[6] = { 100, 175, 80, 128, 1, 45 };
    check.Bounds(ds, b, 1e-9);
    check.Array(ds, "scalars", 1, 0, 580);
    check.Array(ds, "vectors", 3, 0, 22.69);
  }
  {
    check.Context = "office.binary.vtk";
    auto reader = plumetest::Reader("classic/office.binary.vtk");
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Dims(check, ds, 21, 20, 20);
    Size(check, ds, 8400, 7220);
    const double b[6] = { 0.01, 4.5, 0.01, 4.5, 0.01, 2.5 };
    check.Bounds(ds, b, 1e-5);
    check.Array(ds, "scalars", 1, -3.87, 0.719, false, 2e-3, 1e-6);
    check.Array(ds, "vectors", 3, 0, 0.805);
  }
  {
    check.Context = "kitchen.vtk";
    auto reader = plumetest::Reader("classic/kitchen.vtk");
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Dims(check, ds, 28, 24, 17);
    Size(check, ds, 11424, 9936);
    const double b[6] = { 0.01, 7.0, 0.01, 5.0, 0.01, 2.5 };
    check.Bounds(ds, b, 1e-5);
    check.Array(ds, "velocity", 3, 0, 0.452);
    check.Array(ds, "p1", 1, -0.034, 0.187, false, 2e-2);
    check.Array(ds, "ke", 1, 1e-10, 0.031, false, 2e-2, 1e-9);
    check.Array(ds, "c1", 1, -2e-6, 0.208, false, 5e-3, 1e-6);
    if (auto* h1 = ds ? ds->GetPointData()->GetArray("h1") : nullptr)
    {
      check.Near(h1->GetRange(0)[1], 2.68e4, 5e-3, 0, "h1 max");
    }
    else
    {
      check.Fail("h1 missing");
    }
    for (const char* name : { "u1", "v1", "w1", "ep", "c11", "c12", "c13", "c14", "c15", "c16",
           "c17", "hpor", "npor", "epor", "vpor" })
    {
      check.HasArray(ds, name);
    }
  }
  {
    check.Context = "fire_ug.vtu";
    auto reader = plumetest::Reader("classic/fire_ug.vtu");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 12323, 10462);
    const double b[6] = { 0, 6, 0, 2.5, 0, 2.4 };
    check.Bounds(ds, b, 1e-6);
    check.Array(ds, "t", 1, 298.4, 692.2, false, 2e-4);
    check.Array(ds, "uvw", 3, 0.0099, 3.82, false, 5e-3, 1e-4);
    check.Array(ds, "mfrac", 1, 0, 0.516);
    for (const char* name : { "u", "v", "w" })
    {
      check.HasArray(ds, name);
    }
    check.True(reader->GetTimeValues().empty(), "a single .vtu has no time steps");
  }
  {
    check.Context = "disk_out_ref.ex2";
    auto reader = plumetest::Reader("classic/disk_out_ref.ex2");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 8499, 7472);
    const double b[6] = { -5.75, 5.75, -5.75, 5.75, -10, 10.16 };
    check.Bounds(ds, b, 1e-4);
    check.Equal(reader->GetTimeValues().size(), size_t(1), "time steps");
    check.Array(ds, "V", 3, 0, 22.42);
    check.Array(ds, "Temp", 1, 293.1, 913.2, false, 2e-4);
    check.Array(ds, "Pres", 1, 0.0068, 0.0288, false, 1e-2);
    for (const char* name : { "AsH3", "GaMe3", "CH4", "H2" })
    {
      check.HasArray(ds, name);
      if (ds && ds->GetPointData()->GetArray(name))
      {
        check.Equal(ds->GetPointData()->GetArray(name)->GetDataType(), VTK_DOUBLE,
          std::string(name) + " is double");
      }
    }
  }
  {
    check.Context = "blow.vtk";
    auto reader = plumetest::Reader("classic/blow.vtk");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 687, 1057);
    const double b[6] = { 0, 7, -12, 36, -11, 13 };
    check.Bounds(ds, b, 1e-4);
    double maxDisplacement = 0;
    for (int i = 0; i < 10; ++i)
    {
      const std::string d = "displacement" + std::to_string(i);
      const std::string t = "thickness" + std::to_string(i);
      check.HasArray(ds, t.c_str());
      vtkDataArray* array = ds ? ds->GetPointData()->GetArray(d.c_str()) : nullptr;
      if (check.True(array && array->GetNumberOfComponents() == 3, d + " float3 (all vectors read)"))
      {
        maxDisplacement = std::max(maxDisplacement, array->GetRange(-1)[1]);
      }
    }
    check.Near(maxDisplacement, 9.65, 5e-3, 0, "max |displacement|");
  }
}

void Plot3D(Checker& check)
{
  {
    check.Context = "combxyz.bin";
    auto reader = plumetest::Reader("plot3d/combxyz.bin"); // Q guessed: combq.bin
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Dims(check, ds, 57, 33, 25);
    check.Equal(ds ? ds->GetNumberOfPoints() : -1, vtkIdType(47025), "points");
    const double b[6] = { 0, 16.51, -5.66, 5.66, 23.33, 36.20 };
    check.Bounds(ds, b, 1e-2);
    check.Array(ds, "Density", 1, 0.198, 0.710, false, 2e-3);
    check.Array(ds, "Momentum", 3, 0, 446.7, false, 1e-3);
    check.Array(ds, "Velocity", 3, 0, 1529, false, 1e-3);
  }
  {
    check.Context = "bluntfin (explicit Q, reader name)";
    auto reader = plumetest::Reader("plot3d/bluntfinxyz.bin");
    reader->SetQFileName(plumetest::Data("plot3d/bluntfinq.bin").c_str());
    reader->SetReaderName("plot3d");
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Dims(check, ds, 40, 32, 32);
    check.Equal(ds ? ds->GetNumberOfPoints() : -1, vtkIdType(40960), "points");
    const double b[6] = { -7.82, 14.36, 0, 8.33, 0, 5.72 };
    check.Bounds(ds, b, 5e-3);
    check.Array(ds, "Density", 1, 0.193, 4.98, false, 3e-3);
    check.Array(ds, "Velocity", 3, 0, 3.12, false, 2e-3);
    check.Array(ds, "StagnationEnergy", 1, 0.77, 25.2, false, 3e-3);
    check.Array(ds, "Pressure", 1, 0.26, 10.0, false, 3e-3);
    check.Array(ds, "Temperature", 1, 0.60, 2.07, false, 3e-3);
  }
  {
    check.Context = "postxyz.bin (IBlank)";
    auto reader = plumetest::Reader("plot3d/postxyz.bin");
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Dims(check, ds, 38, 76, 38);
    check.Equal(ds ? ds->GetNumberOfPoints() : -1, vtkIdType(109744), "points");
    const double b[6] = { -15, 15, -15, 15, 0, 4.82 };
    check.Bounds(ds, b, 2e-2);
    check.Array(ds, "IBlank", 1, -1, 1);
    check.Array(ds, "Density", 1, 1, 1);
    check.Array(ds, "Velocity", 3, 0, 1.39, false, 2e-3);
    check.Array(ds, "Pressure", 1, -0.217, 1.76, false, 3e-3);
    check.HasArray(ds, "StagnationEnergy");
  }
}

void EnSight(Checker& check)
{
  {
    check.Context = "EnSight fluid part";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    reader->AddBlockName("fluid");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 14831, 14594);
    const double b[6] = { 0, 15, -3.75, 3.75, 0, 0 };
    check.Bounds(ds, b, 1e-5);
    check.Array(ds, "velocity", 3, 0, 49.55, false, 1e-3);
    check.Array(ds, "pressure", 1, -724.7, 1051, false, 1e-3);
    check.Array(ds, "vorticity_mag", 1, 0.066, 496.9, false, 2e-3);
    const auto& available = reader->GetAvailableBlockNames();
    for (const char* part : { "fluid", "inlet", "outlet", "outlet_top", "outlet_bottom",
           "wall_cylinder" })
    {
      check.True(std::find(available.begin(), available.end(), part) != available.end(),
        std::string("available block ") + part);
    }
  }
  {
    check.Context = "EnSight, all parts merged";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    // fluid + the five line parts: 14831 + 76 + 76 + 151 + 151 + 63
    check.Equal(ds ? ds->GetNumberOfPoints() : -1, vtkIdType(15348), "points");
    check.HasArray(ds, "velocity");
  }
  {
    check.Context = "EnSight, MergeBlocks off";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    reader->MergeBlocksOff();
    reader->Update();
    auto* mb = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    if (check.True(mb != nullptr, "composite output"))
    {
      check.Equal(mb->GetNumberOfBlocks(), 6u, "parts");
    }
  }
  {
    check.Context = "EnSight, two parts by name";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    reader->SetBlockNames({ "inlet", "wall_cylinder" });
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    check.Equal(ds ? ds->GetNumberOfPoints() : -1, vtkIdType(76 + 63), "points");
  }
}

void OpenFOAM(Checker& check)
{
  check.Context = "OpenFOAM cavity t=2.5";
  auto reader = plumetest::Reader("openfoam_cavity/cavity/case.foam");
  reader->UpdateInformation();
  const std::vector<double> expected = { 0, 0.5, 1, 1.5, 2, 2.5 };
  if (check.Equal(reader->GetTimeValues().size(), expected.size(), "time steps"))
  {
    for (size_t i = 0; i < expected.size(); ++i)
    {
      check.Near(reader->GetTimeValues()[i], expected[i], 0, 1e-12, "time " + std::to_string(i));
    }
  }
  reader->SetTimeValue(2.5);
  vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
  check.Equal(reader->GetTimeStepRead(), 5, "step read");
  Size(check, ds, 882, 400);
  const double b[6] = { 0, 0.1, 0, 0.1, 0, 0.01 };
  check.Bounds(ds, b, 1e-6);
  check.Array(ds, "U", 3, 0.00018, 0.853, true, 2e-3, 1e-6);
  check.Array(ds, "p", 1, -4.37, 4.85, true, 2e-3);
  check.Array(ds, "U", 3, 0, 1, false, 1e-6, 1e-6); // cell-to-point, lid at 1
  check.HasArray(ds, "p");
  const double pMax25 = (ds && ds->GetCellData()->GetArray("p"))
    ? ds->GetCellData()->GetArray("p")->GetRange(0)[1]
    : 0;

  check.Context = "OpenFOAM cavity step 1 (t=0.5)";
  reader->SetTimeStep(1);
  ds = Load(check, reader, "vtkUnstructuredGrid");
  check.Equal(reader->GetTimeStepRead(), 1, "step read");
  if (ds && ds->GetCellData()->GetArray("p"))
  {
    check.True(std::fabs(ds->GetCellData()->GetArray("p")->GetRange(0)[1] - pMax25) > 1e-6,
      "the field changes with the time step");
  }

  check.Context = "OpenFOAM patch movingWall";
  auto patch = plumetest::Reader("openfoam_cavity/cavity/case.foam");
  patch->AddBlockName("movingWall");
  patch->SetTimeStep(5);
  patch->Update();
  auto* wall = vtkDataSet::SafeDownCast(patch->GetOutputDataObject(0));
  if (check.True(patch->GetLastError().empty() && wall, "patch loads: " + patch->GetLastError()))
  {
    double wb[6];
    wall->GetBounds(wb);
    check.Near(wb[2], 0.1, 0, 1e-6, "movingWall at y = 0.1");
    check.Near(wb[3], 0.1, 0, 1e-6, "movingWall at y = 0.1");
    check.True(wall->GetNumberOfPoints() > 0 && wall->GetNumberOfPoints() < 882, "patch size");
  }
}

void CGNS(Checker& check)
{
  {
    check.Context = "CGNS 12 zones merged";
    auto reader = plumetest::Reader("cgns/sqnz_s.adf.cgns");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 15228, 11264);
    const double b[6] = { -1.2, 1.0, 0, 1, 0, 1 };
    check.Bounds(ds, b, 1e-6);
    check.Array(ds, "Density", 1, 0.160, 0.974, true, 3e-3);
    check.Array(ds, "Momentum", 3, 0.235, 0.581, true, 3e-3);
    check.Array(ds, "EnergyStagnationDensity", 1, 0.341, 1.767, true, 3e-3);
  }
  {
    check.Context = "CGNS MergeBlocks off";
    auto reader = plumetest::Reader("cgns/sqnz_s.adf.cgns");
    reader->MergeBlocksOff();
    reader->Update();
    auto* cds = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    int leaves = 0;
    vtkIdType points = 0;
    if (check.True(cds != nullptr, "composite output"))
    {
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(cds->NewIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        auto* sg = vtkStructuredGrid::SafeDownCast(it->GetCurrentDataObject());
        if (check.True(sg != nullptr, "zone is a structured grid"))
        {
          int dims[3];
          sg->GetDimensions(dims);
          check.True((dims[0] == 15 || dims[0] == 17) && dims[1] == 9 && dims[2] == 9,
            "zone dims 15x9x9 or 17x9x9");
          points += sg->GetNumberOfPoints();
        }
        ++leaves;
      }
    }
    check.Equal(leaves, 12, "zones");
    check.Equal(points, vtkIdType(15228), "points");
    const auto& names = reader->GetAvailableBlockNames();
    check.True(std::any_of(names.begin(), names.end(),
                 [](const std::string& n) { return n.find("dom1_1_1_1") != std::string::npos; }),
      "zone dom1_1_1_1 listed");
  }
  {
    check.Context = "CGNS one zone";
    auto reader = plumetest::Reader("cgns/sqnz_s.adf.cgns");
    reader->AddBlockName("dom1_3_1_1");
    vtkDataSet* ds = Load(check, reader, "vtkStructuredGrid");
    Size(check, ds, 1377, 1024);
  }
}

void Nek5000(Checker& check)
{
  const double twoPi = 2 * M_PI;
  const double b[6] = { 0, twoPi, 0, twoPi, 0, 0 };
  {
    check.Context = "eddy_uv.pvd step 0";
    auto reader = plumetest::Reader("nek5000_eddy_uv/vtu/eddy_uv.pvd");
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    if (check.Equal(reader->GetTimeValues().size(), size_t(11), "time steps"))
    {
      for (int i = 0; i <= 10; ++i)
      {
        check.Near(reader->GetTimeValues()[i], 0.01 * i, 0, 1e-12, "t" + std::to_string(i));
      }
    }
    Size(check, ds, 16384, 12544);
    check.Bounds(ds, b, 1e-5);
    check.Array(ds, "velocity", 3, 0.0074, 3.27, false, 5e-3, 1e-4);
    check.Array(ds, "pressure", 1, -3.60, 1.39, false, 5e-3);
  }
  {
    check.Context = "eddy_uv.pvd t=0.1";
    auto reader = plumetest::Reader("nek5000_eddy_uv/vtu/eddy_uv.pvd");
    reader->SetTimeValue(0.1);
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    check.Equal(reader->GetTimeStepRead(), 10, "step read");
    check.Array(ds, "velocity", 3, 0.0015, 3.00, false, 5e-3, 1e-4);
    check.Array(ds, "pressure", 1, -2.84, 1.08, false, 5e-3);
    vtkDataArray* tv = ds ? ds->GetFieldData()->GetArray("TimeValue") : nullptr;
    if (check.True(tv != nullptr, "field TimeValue"))
    {
      check.Near(tv->GetComponent(0, 0), 0.1, 0, 1e-9, "TimeValue of the file read");
    }
  }
  for (int i = 0; i <= 10; ++i)
  {
    char name[64];
    std::snprintf(name, sizeof(name), "nek5000_eddy_uv/vtu/eddy_uv_%03d.vtu", i);
    check.Context = name;
    auto reader = plumetest::Reader(name);
    vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
    Size(check, ds, 16384, 12544);
    check.HasArray(ds, "velocity");
    check.HasArray(ds, "pressure");
  }
}

void Derived(Checker& check)
{
  {
    check.Context = "fire_ug_image.vti";
    auto reader = plumetest::Reader("derived/fire_ug_image.vti");
    vtkDataSet* ds = Load(check, reader, "vtkImageData");
    Dims(check, ds, 97, 41, 39);
    if (auto* image = vtkImageData::SafeDownCast(ds))
    {
      check.Near(image->GetSpacing()[0], 0.0625, 0, 1e-6, "spacing x");
      check.Near(image->GetSpacing()[2], 0.0632, 0, 1e-4, "spacing z");
    }
    const double b[6] = { 0, 6, 0, 2.5, 0, 2.4 };
    check.Bounds(ds, b, 1e-5); // the stored image is inset by ~3e-6
    check.Array(ds, "mfrac", 1, 0, 0.417);
    check.Array(ds, "uvw", 3, 0, 3.66, false, 2e-3);
    check.HasArray(ds, "t");
    check.HasArray(ds, "vtkValidPointMask");
  }
  {
    check.Context = "kitchen_image.vti";
    auto reader = plumetest::Reader("derived/kitchen_image.vti");
    vtkDataSet* ds = Load(check, reader, "vtkImageData");
    Dims(check, ds, 71, 51, 26);
    check.Array(ds, "velocity", 3, 0, 0.433, false, 2e-3);
    check.Array(ds, "c1", 1, 0, 0.206, false, 3e-3, 1e-5);
    for (const char* name : { "h1", "p1", "ke" })
    {
      check.HasArray(ds, name);
    }
  }
  {
    check.Context = "office_image.vti";
    auto reader = plumetest::Reader("derived/office_image.vti");
    vtkDataSet* ds = Load(check, reader, "vtkImageData");
    Dims(check, ds, 46, 46, 26);
    check.Array(ds, "vectors", 3, 0, 0.655, false, 2e-3);
    check.Array(ds, "scalars", 1, -3.87, 0.72, false, 3e-3);
  }
  {
    check.Context = "combustor_image.vti";
    auto reader = plumetest::Reader("derived/combustor_image.vti");
    vtkDataSet* ds = Load(check, reader, "vtkImageData");
    Dims(check, ds, 67, 46, 53);
    check.Array(ds, "Density", 1, 0, 0.708, false, 2e-3);
    check.Array(ds, "Velocity", 3, 0, 1517, false, 1e-3);
  }
  {
    check.Context = "office_stream_sheet.vtp";
    auto reader = plumetest::Reader("derived/office_stream_sheet.vtp");
    vtkDataSet* ds = Load(check, reader, "vtkPolyData");
    Size(check, ds, 24060, 24000);
    for (const char* name : { "vectors", "scalars", "IntegrationTime" })
    {
      check.HasArray(ds, name);
    }
  }
  {
    check.Context = "kitchen_stream_sheet.vtp";
    auto reader = plumetest::Reader("derived/kitchen_stream_sheet.vtp");
    vtkDataSet* ds = Load(check, reader, "vtkPolyData");
    Size(check, ds, 31278, 31200);
    for (const char* name : { "velocity", "c1", "h1", "IntegrationTime" })
    {
      check.HasArray(ds, name);
    }
  }
}

void ReaderNamesAndProgress(Checker& check)
{
  check.Context = "explicit reader name";
  auto reader = plumetest::Reader("classic/fire_ug.vtu");
  reader->SetReaderName("xml");
  vtkDataSet* ds = Load(check, reader, "vtkUnstructuredGrid");
  Size(check, ds, 12323, 10462);
  check.Equal(reader->GetResolvedReaderName(), std::string("xml"), "resolved reader");

  check.Context = "progress forwarded";
  auto progressReader = plumetest::Reader("cgns/sqnz_s.adf.cgns");
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData));
  });
  progressReader->AddObserver(vtkCommand::ProgressEvent, observer);
  progressReader->Update();
  check.True(std::any_of(progress.begin(), progress.end(), [](double p) { return p > 0 && p < 1; }),
    "intermediate progress from the inner reader (got " + std::to_string(progress.size()) +
      " events)");
  check.True(!progress.empty() && progress.back() == 1.0, "progress ends at 1");
}
}

int TestPlumeDatasetReaderFormats(int, char*[])
{
  Checker check;
  Classic(check);
  Plot3D(check);
  EnSight(check);
  OpenFOAM(check);
  CGNS(check);
  Nek5000(check);
  Derived(check);
  ReaderNamesAndProgress(check);
  if (check.Failures)
  {
    std::cerr << check.Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
