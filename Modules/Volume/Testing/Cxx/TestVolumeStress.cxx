// Degenerate and extreme input: every case must give no NaN pixel, no GL
// error and no crash; where the model is well defined the image must also
// match vtkPlumeVolumeReference.
#include "plumeVolumeTestUtil.h"

#include <limits>

namespace
{
using namespace plumevolumetest;

vtkSmartPointer<vtkImageData> Field(int nx, int ny, int nz, double sx, double sy, double sz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(sx, sy, sz);
  vtkNew<vtkFloatArray> values;
  values->SetName("s");
  values->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny * nz);
  vtkIdType id = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++id)
      {
        const double x = nx > 1 ? double(i) / (nx - 1) : 0.5;
        const double y = ny > 1 ? double(j) / (ny - 1) : 0.5;
        const double z = nz > 1 ? double(k) / (nz - 1) : 0.5;
        values->SetValue(id, static_cast<float>(0.2 + 0.8 * std::exp(-8 * ((x - 0.4) * (x - 0.4) + (y - 0.55) * (y - 0.55) + (z - 0.5) * (z - 0.5)))));
      }
  image->GetPointData()->SetScalars(values);
  return image;
}

// render only: NaN / GL error check
int Sane(const char* name, Scene& s)
{
  const plume::test::FloatImage image = plume::test::ReadBack(s.Window);
  const std::string gl = plume::test::GLErrors(s.Window);
  const bool ok = !plume::test::HasNonFinite(image) && gl.empty();
  std::printf("%-40s %s%s\n", name, ok ? "sane" : "NaN pixel or GL error ", gl.c_str());
  return ok ? 0 : 1;
}
}

int TestVolumeStress(int, char*[])
{
  int failures = 0;
  {
    Scene s = MakeScene(Field(40, 30, 1, 0.025, 0.025, 0.025), 120, 100);
    failures += Check("one voxel thick", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 50);
  }
  {
    Scene s = MakeScene(Field(1, 1, 1, 0.1, 0.1, 0.1), 120, 100);
    s.Volume->GetProperty()->GetScalarOpacity()->AddPoint(0.0, 0.9); // make the lone voxel visible
    failures += Check("1x1x1", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 10);
    s.Mapper->SetBlendModeToIsoSurface();
    failures += Sane("1x1x1 isosurface", s);
  }
  {
    // spacing ratio 1e4
    Scene s = MakeScene(Field(24, 24, 24, 1.0, 1.0, 1e-4), 120, 100);
    s.Volume->GetProperty()->SetScalarOpacityUnitDistance(0.05);
    s.Renderer->GetActiveCamera()->SetPosition(10, -15, 20);
    s.Renderer->ResetCamera();
    failures += Check("spacing ratio 1e4", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 10);
    auto field = Field(24, 24, 24, 1e-4, 1.0, 1.0);
    Scene t = MakeScene(field, 120, 100);
    t.Renderer->GetActiveCamera()->SetPosition(-10, -15, 20);
    t.Renderer->ResetCamera();
    failures += Check("spacing ratio 1e4 (x)", CompareWithReference(t, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 10);
  }
  {
    // constant field: exact transmittance; zero gradient for the isosurface
    auto field = Field(16, 16, 16, 0.1, 0.1, 0.1);
    vtkDataArray* a = field->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      a->SetTuple1(i, 3.0);
    }
    Scene s = MakeScene(field, 120, 100);
    SetTransferFunctions(s.Volume->GetProperty(), 2.0, 4.0, 0.5, 0.5);
    failures += Check("constant field", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.004, 0.02, 100);
    s.Mapper->SetBlendModeToIsoSurface();
    s.Mapper->SetIsoValue(3.0);
    failures += Sane("constant field isosurface", s);
    s.Mapper->SetBlendModeToMaximumIntensity();
    failures += Check("constant field MIP", CompareWithReference(s, vtkPlumeVolumeReference::MAXIMUM_INTENSITY), 0.004, 0.02, 100);
  }
  {
    // NaN / Inf scalars
    auto field = Field(32, 32, 32, 1.0 / 31, 1.0 / 31, 1.0 / 31);
    vtkDataArray* a = field->GetPointData()->GetScalars();
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); i += 97)
    {
      a->SetTuple1(i, (i / 97) % 3 == 0 ? nan : ((i / 97) % 3 == 1 ? inf : -inf));
    }
    Scene s = MakeScene(field, 120, 100);
    SetTransferFunctions(s.Volume->GetProperty(), 0.2, 1.0, 0.6, 0.05);
    failures += Check("NaN/Inf scalars", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.08, 100);
    s.Mapper->SetBlendModeToIsoSurface();
    failures += Sane("NaN/Inf scalars isosurface", s);
    s.Mapper->SetBlendModeToMaximumIntensity();
    failures += Sane("NaN/Inf scalars MIP", s);
  }
  {
    // huge scalar range
    auto field = Field(24, 24, 24, 1.0 / 23, 1.0 / 23, 1.0 / 23);
    vtkNew<vtkDoubleArray> big;
    big->SetName("big");
    big->SetNumberOfTuples(field->GetNumberOfPoints());
    vtkDataArray* a = field->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      big->SetValue(i, a->GetTuple1(i) * 1e300 - 1e299);
    }
    field->GetPointData()->SetScalars(big);
    Scene s = MakeScene(field, 120, 100);
    failures += Check("huge scalar range (1e300)", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 100);
  }
  {
    // grazing rays: the camera in the plane of a face, looking along it; then exactly on a face
    Scene s = MakeScene(plumevolumetest::SmokeField(32), 120, 100);
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -2.0, 0.5);
    camera->SetFocalPoint(0.0, 0.5, 0.5);
    camera->SetViewUp(0, 0, 1);
    camera->SetClippingRange(0.1, 10);
    failures += Sane("grazing along the x=0 face", s);
    camera->SetPosition(1.0, -2.0, 1.0);
    camera->SetFocalPoint(1.0, 0.5, 1.0);
    failures += Sane("grazing along an edge", s);
    camera->SetPosition(0.5, 0.0, 0.5);
    camera->SetFocalPoint(0.5, 1.0, 0.5);
    camera->SetClippingRange(0.001, 10);
    failures += Check("camera exactly on a face", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.008, 0.08, 100);
  }
  {
    // extreme zoom in and out
    Scene s = MakeScene(plumevolumetest::SmokeField(32), 120, 100);
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.45, 0.5, 0.5);
    camera->SetPosition(0.45, 0.5, 3.0);
    camera->SetViewAngle(0.005);
    camera->SetClippingRange(1.0, 5.0);
    failures += Check("zoom in (0.005 deg)", CompareWithReference(s, vtkPlumeVolumeReference::COMPOSITE), 0.006, 0.06, 1000);
    camera->SetViewAngle(30);
    camera->SetPosition(0.45, 0.5, 1e5);
    camera->SetClippingRange(1e5 - 10, 1e5 + 10);
    failures += Sane("zoom out (sub-pixel volume)", s);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
