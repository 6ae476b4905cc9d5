// Numeric test (no baseline): vtkPlumeAirlightPass with Plume's volume mapper
// in isosurface mode in the scene. The isosurface is opaque and writes its
// depth, so the medium's airlight stops at it like at an opaque polygon at the
// same place. The invariant: a black isosurface sphere (the iso value R of the
// distance field from a centre) in front of the room's wall, and a black
// polygonal sphere of radius R at the same centre: through the pass, both
// frames are airlight only, and on every pixel whose ray hits the sphere away
// from its silhouette
//  - the isosurface's depth is the exact sphere's (ray-sphere intersection)
//    within 1 % of the sphere's radius in distance;
//  - the isosurface frame matches the polygon frame to 0.5 % RMS and 2 % max of
//    the airlight range, and both match the independent reference computed
//    with the exact sphere's depth to the same goal.
// Without the depth write the airlight runs on to the wall behind the sphere
// (about 2.5 units more medium): checked to fail.
#include "plumeAirlightTestUtil.h"

#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/glm.hpp>

namespace
{
const double Centre[3] = { 0.3, 1.1, -1.2 };
const double Radius = 0.7;

// Distance from Centre on a 64^3 grid over the sphere's box with a margin.
vtkSmartPointer<vtkImageData> DistanceField()
{
  const int n = 64;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  const double half = 1.2 * Radius;
  const double h = 2.0 * half / (n - 1);
  image->SetSpacing(h, h, h);
  image->SetOrigin(Centre[0] - half, Centre[1] - half, Centre[2] - half);
  vtkNew<vtkDoubleArray> values;
  values->SetName("distance");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double p[3] = { Centre[0] - half + i * h, Centre[1] - half + j * h, Centre[2] - half + k * h };
        values->SetValue((static_cast<vtkIdType>(k) * n + j) * n + i,
          std::sqrt(vtkMath::Distance2BetweenPoints(p, Centre)));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

// The scene: the room's floor and back wall, a point light and a spot light.
void SetupVolumeDepth(airtest::Scene& s)
{
  s.AddBox(-5, 5, -0.1, 0, -4, 4, 0.6, 0.6, 0.55);
  s.AddBox(-5, 5, 0, 5, -4.1, -4, 0.5, 0.55, 0.6);
  s.AddPointLight(0.2, 1.3, -2.9, 1.0, 0.9, 0.8, 1.0); // behind the sphere: its glow is what the sphere hides
  const double p[3] = { 1.5, 3.5, 0.5 }, f[3] = { 0.3, 0.0, -1.5 };
  s.AddSpotLight(p, f, 30.0, 1.0, 0.8, 0.9, 1.0, 1.0);
  s.Pass->SetScattering(0.2, 0.22, 0.25);
  s.Pass->SetAbsorption(0.03, 0.03, 0.03);
  s.Pass->SetIntensityScale(8.0);
  s.Camera(1.0, 1.4, 4.0, 0.0, 1.0, -2.0);
}
}

int TestAirlightVolumeDepth(int, char*[])
{
  int failures = 0;
  const int W = 80, H = 60;

  // The isosurface sphere (black: no surface term, only airlight).
  airtest::Scene iso(W, H);
  SetupVolumeDepth(iso);
  vtkNew<vtkPlumeVolumeMapper> mapper;
  mapper->SetInputData(DistanceField());
  mapper->SetBlendModeToIsoSurface();
  mapper->SetIsoValue(Radius);
  mapper->SetAutoAdjustSampleDistances(false);
  mapper->SetImageSampleDistance(1);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0.0, 0, 0, 0);
  colour->AddRGBPoint(2.0, 0, 0, 0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 1.0);
  opacity->AddPoint(2.0, 1.0);
  volume->GetProperty()->SetColor(colour);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetInterpolationTypeToLinear(); // VTK's default is nearest
  volume->GetProperty()->SetScalarOpacityUnitDistance(0.0); // automatic: one voxel
  volume->GetProperty()->SetAmbient(0.0);
  volume->GetProperty()->SetDiffuse(0.0);
  volume->GetProperty()->SetSpecular(0.0);
  iso.Renderer->AddVolume(volume);
  iso.Camera(1.0, 1.4, 4.0, 0.0, 1.0, -2.0);
  const airtest::FloatImage isoPlain = iso.RenderFloat(nullptr);
  const airtest::FloatImage isoImage = iso.RenderFloat(iso.Pass);
  PLUME_CHECK(plume::test::GLErrors(iso.Window).empty());
  PLUME_CHECK(!plume::test::HasNonFinite(isoImage));

  // The polygonal sphere at the same place, black too.
  airtest::Scene poly(W, H);
  SetupVolumeDepth(poly);
  vtkActor* sphere = poly.AddSphere(Centre[0], Centre[1], Centre[2], Radius, 0, 0, 0);
  sphere->GetProperty()->SetAmbient(0.0);
  sphere->GetProperty()->SetDiffuse(0.0);
  sphere->GetProperty()->SetSpecular(0.0);
  poly.Camera(1.0, 1.4, 4.0, 0.0, 1.0, -2.0);
  const airtest::FloatImage polyPlain = poly.RenderFloat(nullptr);
  const airtest::FloatImage polyImage = poly.RenderFloat(poly.Pass);

  // The exact sphere's depth per pixel (ray-sphere intersection), the pixels
  // well inside its silhouette, and the isosurface's depth there.
  vtkCamera* cam = iso.Renderer->GetActiveCamera();
  double eye[3];
  cam->GetPosition(eye);
  vtkMatrix4x4* toClip = cam->GetCompositeProjectionTransformMatrix(iso.Renderer->GetTiledAspectRatio(), -1, 1);
  vtkNew<vtkMatrix4x4> fromClip;
  vtkMatrix4x4::Invert(toClip, fromClip);
  auto unproject = [&](double nx, double ny, double nz) {
    double in[4] = { nx, ny, nz, 1.0 }, out[4];
    fromClip->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
  };
  auto depthOf = [&](const glm::dvec3& p) {
    double in[4] = { p.x, p.y, p.z, 1.0 }, out[4];
    toClip->MultiplyPoint(in, out);
    return 0.5 * (out[2] / out[3]) + 0.5;
  };
  const glm::dvec3 e(eye[0], eye[1], eye[2]), c(Centre[0], Centre[1], Centre[2]);
  airtest::FloatImage exact = polyPlain; // the polygon scene's depth with the exact sphere's where it hits
  std::vector<char> inside(static_cast<size_t>(W) * H, 0);
  double worstDistance = 0;
  size_t hits = 0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const double nx = (i + 0.5) / W * 2 - 1, ny = (j + 0.5) / H * 2 - 1;
      const glm::dvec3 r = glm::normalize(unproject(nx, ny, 1.0) - e);
      const glm::dvec3 v = e - c;
      const double b = glm::dot(v, r), q = glm::dot(v, v) - Radius * Radius;
      const double disc = b * b - q;
      // well inside the silhouette: the ray passes at most 0.9 R from the centre
      if (disc <= 0.19 * Radius * Radius)
      {
        continue;
      }
      const double t = -b - std::sqrt(disc);
      const size_t p = static_cast<size_t>(j) * W + i;
      inside[p] = 1;
      ++hits;
      exact.Depth[p] = static_cast<float>(depthOf(e + t * r));
      // the isosurface's depth as a distance along the ray
      const glm::dvec3 hit = unproject(nx, ny, 2.0 * isoPlain.Depth[p] - 1.0);
      const double dd = std::fabs(glm::length(hit - e) - t);
      if (std::getenv("PLUME_AIRLIGHT_VERBOSE"))
      {
        std::cout << i << " " << j << " exact " << t << " iso " << glm::length(hit - e) << " polygon "
                  << glm::length(unproject(nx, ny, 2.0 * polyPlain.Depth[p] - 1.0) - e) << "\n";
      }
      worstDistance = std::max(worstDistance, dd);
    }
  }
  std::cout << hits << " pixels inside the silhouette; isosurface depth vs the exact sphere: largest "
            << worstDistance << " (" << 100 * worstDistance / Radius << " % of R)\n";
  PLUME_CHECK(hits > 150);
  PLUME_CHECK(worstDistance <= 0.01 * Radius);

  // The reference with the exact sphere's depth, black surfaces.
  airtest::FloatImage air;
  airtest::FloatImage black = exact;
  std::fill(black.RGBA.begin(), black.RGBA.end(), 0.0f);
  const airtest::FloatImage ref = poly.Reference(black, 1, &air, false);
  // Only the pixels inside the silhouette.
  airtest::FloatImage refInside = ref;
  for (size_t p = 0; p < inside.size(); ++p)
  {
    if (!inside[p])
    {
      refInside.RGBA[4 * p] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  // Errors in % of the whole frame's airlight range (Compare takes the range
  // over the compared pixels only: the short stretch of medium in front of the sphere).
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (size_t p = 0; p < inside.size(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo = std::min(lo, double(air.RGBA[4 * p + c]));
      hi = std::max(hi, double(air.RGBA[4 * p + c]));
    }
  }
  const double range = hi - lo;
  auto compare = [&](const airtest::FloatImage& image, const airtest::FloatImage& reference) {
    airtest::Error e = airtest::Compare(image, reference, air);
    e.RMS *= e.Range / range;
    e.Max *= e.Range / range;
    e.Range = range;
    return e;
  };
  const airtest::Error isoErr = compare(isoImage, refInside);
  const airtest::Error polyErr = compare(polyImage, refInside);
  airtest::FloatImage polyAsRef = polyImage;
  for (size_t p = 0; p < inside.size(); ++p)
  {
    if (!inside[p])
    {
      polyAsRef.RGBA[4 * p] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  const airtest::Error isoVsPoly = compare(isoImage, polyAsRef);
  // What the test tells apart: the airlight run on to the wall behind the
  // sphere (the room without it) differs from the sphere's by far more than the goal.
  airtest::Scene room(W, H);
  SetupVolumeDepth(room);
  room.Camera(1.0, 1.4, 4.0, 0.0, 1.0, -2.0);
  airtest::FloatImage wall = room.RenderFloat(nullptr);
  std::fill(wall.RGBA.begin(), wall.RGBA.end(), 0.0f);
  const airtest::FloatImage refWall = room.Reference(wall, 1, nullptr, false);
  const airtest::Error wallErr = compare(refWall, refInside);
  airtest::Print("the airlight up to the wall behind the sphere vs the reference", wallErr);
  PLUME_CHECK(wallErr.RMS >= 0.05);
  airtest::Print("isosurface sphere vs the reference (exact sphere depth)", isoErr);
  airtest::Print("polygonal sphere vs the reference", polyErr);
  airtest::Print("isosurface sphere vs polygonal sphere", isoVsPoly);
  airtest::Dump(isoImage, "volume depth iso", 2.0);
  airtest::Dump(polyImage, "volume depth poly", 2.0);
  PLUME_CHECK(isoErr.Range > 0.05);
  for (const airtest::Error* err : { &isoErr, &polyErr, &isoVsPoly })
  {
    PLUME_CHECK(err->RMS <= 0.005);
    PLUME_CHECK(err->Max <= 0.02);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
