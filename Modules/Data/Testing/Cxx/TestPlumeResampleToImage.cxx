// vtkPlumeResampleToImage: requested/automatic dimensions, the valid-point mask, zero outside
// the domain, values that match the source, cell data, image passthrough, composite input,
// time through the pipeline, and an analytic check against vtkPlumeVortexSource::Evaluate.
#include "plumeDataTestUtilities.h"

#include "vtkPlumeResampleToImage.h"
#include "vtkPlumeVortexSource.h"

#include "vtkAppendFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkCell.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStaticCellLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <vector>

using plumetest::Checker;

namespace
{
void ExpectDims(Checker& check, vtkImageData* image, int x, int y, int z)
{
  int dims[3] = { -1, -1, -1 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  check.Equal(dims[0], x, "dims x");
  check.Equal(dims[1], y, "dims y");
  check.Equal(dims[2], z, "dims z");
}

// Mask present; every other point array is 0 where the mask is 0. Returns the inside count.
vtkIdType CheckMask(Checker& check, vtkImageData* image, bool expectOutside)
{
  if (!image)
  {
    check.Fail("no image");
    return 0;
  }
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  if (!check.True(mask != nullptr, "vtkValidPointMask present"))
  {
    return 0;
  }
  vtkIdType inside = 0, outside = 0, dirty = 0;
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    if (mask->GetComponent(i, 0) != 0)
    {
      ++inside;
      continue;
    }
    ++outside;
    for (int a = 0; a < image->GetPointData()->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = image->GetPointData()->GetArray(a);
      if (!array || array == mask || std::string(array->GetName()) == "vtkGhostType")
      {
        continue;
      }
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        dirty += array->GetComponent(i, c) != 0 ? 1 : 0;
      }
    }
  }
  check.Equal(dirty, vtkIdType(0), "non-zero values where the mask is 0");
  check.True(inside > 0, "some points inside the domain");
  if (expectOutside)
  {
    check.True(outside > 0, "some points outside the domain");
  }
  return inside;
}

// Values at inside sample points equal the source interpolated independently (cell locator
// plus the cell's interpolation weights).
void CheckValues(Checker& check, vtkImageData* image, vtkDataSet* source, const char* name,
  double tolerance, int stride = 5)
{
  vtkDataArray* sampled = image ? image->GetPointData()->GetArray(name) : nullptr;
  vtkDataArray* original = source ? source->GetPointData()->GetArray(name) : nullptr;
  vtkDataArray* mask = image ? image->GetPointData()->GetArray("vtkValidPointMask") : nullptr;
  if (!check.True(sampled && original && mask, std::string("arrays for ") + name))
  {
    return;
  }
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(source);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  std::vector<double> weights(source->GetMaxCellSize());
  const int nc = original->GetNumberOfComponents();
  vtkIdType compared = 0;
  double worst = 0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); i += stride)
  {
    if (mask->GetComponent(i, 0) == 0)
    {
      continue;
    }
    double x[3], pcoords[3];
    image->GetPoint(i, x);
    const vtkIdType cellId = locator->FindCell(x, 1e-9, cell, pcoords, weights.data());
    if (cellId < 0)
    {
      continue; // on the boundary within tolerance: the probe may find it, the locator not
    }
    for (int c = 0; c < nc; ++c)
    {
      double expected = 0;
      for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k)
      {
        expected += weights[k] * original->GetComponent(cell->GetPointId(k), c);
      }
      worst = std::max(worst, std::fabs(sampled->GetComponent(i, c) - expected));
    }
    ++compared;
  }
  check.True(compared > 50, std::string("enough samples compared for ") + name);
  check.True(worst <= tolerance,
    std::string(name) + ": worst difference " + std::to_string(worst) + " > " +
      std::to_string(tolerance));
}

vtkDataSet* Read(Checker& check, vtkPlumeDatasetReader* reader)
{
  reader->Update();
  check.True(reader->GetLastError().empty(), "reader: " + reader->GetLastError());
  return vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
}
}

int TestPlumeResampleToImage(int, char*[])
{
  Checker check;

  {
    check.Context = "fire_ug.vtu, explicit dimensions";
    auto reader = plumetest::Reader("classic/fire_ug.vtu");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetSamplingDimensions(40, 19, 17);
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    ExpectDims(check, image, 40, 19, 17);
    const double b[6] = { 0, 6, 0, 2.5, 0, 2.4 };
    check.Bounds(image, b, 1e-6);
    const int* whole = resample->GetOutputInformation(0)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    check.True(whole && whole[1] == 39 && whole[3] == 18 && whole[5] == 16,
      "whole extent announced = the real extent");
    CheckMask(check, image, false);
    vtkDataSet* source = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    CheckValues(check, image, source, "t", 1e-3, 3);
    CheckValues(check, image, source, "uvw", 1e-5, 3);
    CheckValues(check, image, source, "mfrac", 1e-6, 3);
  }
  {
    check.Context = "office.binary.vtk, automatic dimensions";
    auto reader = plumetest::Reader("classic/office.binary.vtk");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetMaximumDimension(32);
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    // bounds 4.49 x 4.49 x 2.49: 32, 32, round(2.49 / 4.49 * 31) + 1 = 18
    ExpectDims(check, image, 32, 32, 18);
    const double b[6] = { 0.01, 4.5, 0.01, 4.5, 0.01, 2.5 };
    check.Bounds(image, b, 1e-5);
    CheckMask(check, image, false);
    vtkDataSet* source = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    CheckValues(check, image, source, "scalars", 1e-4);
    CheckValues(check, image, source, "vectors", 1e-5);
  }
  {
    check.Context = "combustor (curvilinear): zero outside";
    auto reader = plumetest::Reader("plot3d/combxyz.bin");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetMaximumDimension(48);
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    CheckMask(check, image, true);
    vtkDataArray* density = image->GetPointData()->GetArray("Density");
    vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
    if (check.True(density && mask, "Density resampled"))
    {
      double lo = 1e30, hi = -1e30;
      for (vtkIdType i = 0; i < density->GetNumberOfTuples(); ++i)
      {
        if (mask->GetComponent(i, 0) != 0)
        {
          lo = std::min(lo, density->GetComponent(i, 0));
          hi = std::max(hi, density->GetComponent(i, 0));
        }
      }
      // Interpolation is convex: inside values stay within the source range 0.198-0.710.
      check.True(lo >= 0.1978 && hi <= 0.7105, "inside density within the source range: [" +
          std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    CheckValues(check, image, Read(check, reader), "Density", 1e-4, 3);
  }
  {
    check.Context = "CGNS cell data -> point data, composite input";
    auto reader = plumetest::Reader("cgns/sqnz_s.adf.cgns");
    reader->MergeBlocksOff();
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetSamplingDimensions(23, 11, 11);
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    ExpectDims(check, image, 23, 11, 11);
    const double b[6] = { -1.2, 1.0, 0, 1, 0, 1 };
    check.Bounds(image, b, 1e-6);
    CheckMask(check, image, false);
    vtkDataArray* density = image->GetPointData()->GetArray("Density");
    vtkDataArray* momentum = image->GetPointData()->GetArray("Momentum");
    check.True(momentum && momentum->GetNumberOfComponents() == 3, "Momentum as point data");
    vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
    if (check.True(density && mask, "Density as point data"))
    {
      double lo = 1e30, hi = -1e30;
      for (vtkIdType i = 0; i < density->GetNumberOfTuples(); ++i)
      {
        if (mask->GetComponent(i, 0) != 0)
        {
          lo = std::min(lo, density->GetComponent(i, 0));
          hi = std::max(hi, density->GetComponent(i, 0));
        }
      }
      // Averaged cell values: inside the cell range 0.160-0.974, and not all alike.
      check.True(lo >= 0.16 && hi <= 0.974 && hi - lo > 0.3,
        "inside Density within the cell range: [" + std::to_string(lo) + ", " +
          std::to_string(hi) + "]");
      // Converted to point data first, the samples are interpolated, not piecewise constant:
      // few of them equal a cell value exactly.
      reader->MergeBlocksOn();
      reader->Update();
      auto* merged = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
      vtkDataArray* cellDensity = merged ? merged->GetCellData()->GetArray("Density") : nullptr;
      if (check.True(cellDensity != nullptr, "cell Density of the source"))
      {
        std::vector<float> cellValues;
        for (vtkIdType c = 0; c < cellDensity->GetNumberOfTuples(); ++c)
        {
          cellValues.push_back(static_cast<float>(cellDensity->GetComponent(c, 0)));
        }
        std::sort(cellValues.begin(), cellValues.end());
        vtkIdType inside = 0, exact = 0;
        for (vtkIdType i = 0; i < density->GetNumberOfTuples(); ++i)
        {
          if (mask->GetComponent(i, 0) != 0)
          {
            ++inside;
            exact += std::binary_search(cellValues.begin(), cellValues.end(),
                       static_cast<float>(density->GetComponent(i, 0)))
              ? 1
              : 0;
          }
        }
        check.True(exact * 4 < inside,
          "samples are interpolated point data (" + std::to_string(exact) + " of " +
            std::to_string(inside) + " equal a cell value)");
      }
    }
  }
  {
    check.Context = "OpenFOAM: point U kept, time through the pipeline";
    auto reader = plumetest::Reader("openfoam_cavity/cavity/case.foam");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetSamplingDimensions(21, 21, 2);
    resample->UpdateTimeStep(2.5);
    check.Equal(reader->GetTimeStepRead(), 5, "step read via UPDATE_TIME_STEP");
    vtkDataArray* u = resample->GetOutput()->GetPointData()->GetArray("U");
    if (check.True(u != nullptr, "U resampled"))
    {
      // The cell-to-point U of the reader reaches the lid speed 1; the cell U tops at 0.853.
      check.Near(u->GetRange(-1)[1], 1.0, 1e-3, 0, "max |U| at the lid");
    }
    resample->UpdateTimeStep(0.5);
    check.Equal(reader->GetTimeStepRead(), 1, "step read via UPDATE_TIME_STEP");
  }
  {
    check.Context = "EnSight fluid: flat axis";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    reader->AddBlockName("fluid");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetMaximumDimension(50);
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    // 15 x 7.5 x 0: 50, round(0.5 * 49) + 1 = 26, 1
    ExpectDims(check, image, 50, 26, 1);
    check.True(image->GetSpacing()[2] > 0, "positive spacing on the flat axis");
    CheckMask(check, image, true); // the cylinder is a hole
  }
  {
    check.Context = "image passthrough";
    auto reader = plumetest::Reader("classic/carotid.vtk");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->SetMaximumDimension(16); // ignored for images
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    auto* input = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
    ExpectDims(check, image, 76, 49, 45);
    check.True(input && image->GetPointData()->GetArray("scalars") ==
          input->GetPointData()->GetArray("scalars"),
      "arrays shared (shallow copy)");
    check.True(image->GetOrigin()[0] == 100 && image->GetSpacing()[0] == 1, "geometry kept");
    const int* whole = resample->GetOutputInformation(0)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    check.True(whole && whole[0] == 0 && whole[1] == 75 && whole[3] == 48 && whole[5] == 44,
      "whole extent announced = the input's");

    check.Context = "image with explicit dimensions";
    resample->SetSamplingDimensions(20, 13, 12);
    resample->Update();
    image = resample->GetOutput();
    ExpectDims(check, image, 20, 13, 12);
    const double b[6] = { 100, 175, 80, 128, 1, 45 };
    check.Bounds(image, b, 1e-9);
    CheckMask(check, image, false);
  }
  {
    check.Context = "analytic vortex through an unstructured grid";
    vtkNew<vtkPlumeVortexSource> vortex;
    vortex->SetDimensions(49, 49, 25);
    vortex->SetBounds(-1, 1, -1, 1, -0.5, 0.5);
    vtkNew<vtkAppendFilter> toUnstructured;
    toUnstructured->SetInputConnection(vortex->GetOutputPort());
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(toUnstructured->GetOutputPort());
    resample->SetSamplingDimensions(31, 29, 11); // not aligned with the source nodes
    resample->Update();
    vtkImageData* image = resample->GetOutput();
    ExpectDims(check, image, 31, 29, 11);
    CheckMask(check, image, false);
    vtkDataArray* velocity = image->GetPointData()->GetArray("velocity");
    int dims[3];
    image->GetDimensions(dims);
    double worst = 0;
    vtkIdType compared = 0;
    if (check.True(velocity != nullptr, "velocity resampled"))
    {
      for (int k = 1; k < dims[2] - 1; ++k)
      {
        for (int j = 1; j < dims[1] - 1; ++j)
        {
          for (int i = 1; i < dims[0] - 1; ++i)
          {
            const vtkIdType id = i + dims[0] * (j + static_cast<vtkIdType>(dims[1]) * k);
            double x[3], exact[3];
            image->GetPoint(id, x);
            vortex->Evaluate(x, exact);
            for (int c = 0; c < 3; ++c)
            {
              worst = std::max(worst, std::fabs(velocity->GetComponent(id, c) - exact[c]));
            }
            ++compared;
          }
        }
      }
    }
    // Trilinear interpolation on h = 1/24: error ~ h^2/8 * |v''| with |v''| ~ 5: ~1e-3.
    check.True(compared > 5000, "interior nodes compared");
    check.True(worst < 4e-3, "analytic field matched: worst error " + std::to_string(worst));
  }
  {
    check.Context = "ZeroOutsideMask";
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 3, 2);
    vtkNew<vtkUnsignedCharArray> mask;
    mask->SetName("vtkValidPointMask");
    vtkNew<vtkFloatArray> vectors;
    vectors->SetName("v");
    vectors->SetNumberOfComponents(3);
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetName("s");
    for (vtkIdType i = 0; i < 24; ++i)
    {
      mask->InsertNextValue(i % 3 == 0 ? 0 : 1);
      vectors->InsertNextTuple3(1.5, -2, 3);
      scalars->InsertNextValue(7);
    }
    image->GetPointData()->AddArray(mask);
    image->GetPointData()->AddArray(vectors);
    image->GetPointData()->AddArray(scalars);
    vtkPlumeResampleToImage::ZeroOutsideMask(image);
    bool ok = true;
    for (vtkIdType i = 0; i < 24; ++i)
    {
      const bool in = i % 3 != 0;
      ok = ok && (scalars->GetValue(i) == (in ? 7 : 0)) && (vectors->GetComponent(i, 0) == (in ? 1.5f : 0.f)) &&
        (vectors->GetComponent(i, 2) == (in ? 3.f : 0.f)) && mask->GetValue(i) == (in ? 1 : 0);
    }
    check.True(ok, "zero exactly where the mask is 0, untouched elsewhere");
  }
  {
    check.Context = "automatic dimensions";
    int dims[3];
    const double flat[6] = { 0, 10, 0, 5, 3, 3 };
    vtkPlumeResampleToImage::ComputeAutomaticDimensions(flat, 64, dims);
    check.True(dims[0] == 64 && dims[1] == 33 && dims[2] == 1, "10 x 5 x 0 -> 64 x 33 x 1");
    const double thin[6] = { 0, 100, 0, 0.1, 0, 1 };
    vtkPlumeResampleToImage::ComputeAutomaticDimensions(thin, 64, dims);
    check.True(dims[0] == 64 && dims[1] == 2 && dims[2] == 2, "thin axes get at least 2");
  }

  if (check.Failures)
  {
    std::cerr << check.Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
