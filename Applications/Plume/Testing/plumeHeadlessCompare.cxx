// SPDX-License-Identifier: BSD-3-Clause
//
// plumeHeadlessCompare: renders one asymmetric scene (coloured background,
// cone + sphere at different places, a plane drawn through a geometry shader,
// a small volume through vtkGPUVolumeRayCastMapper = 3D texture) with two
// backends and requires byte-identical, non-trivial RGBA images.
//
//   plumeHeadlessCompare [--first B] [--second B] [--size WxH]
//                        [--write-prefix PATH] [--perturb]
//   plumeHeadlessCompare --render B [--size WxH] --write-raw FILE
//
// Defaults: --first osmesa --second x, both in this process (one after the
// other: backends must not be alive at the same time). --perturb flips one
// pixel of the second image to prove that the comparison fails. --render only
// renders with one backend and writes raw RGBA (for a two-process compare).
// Exit code: 0 identical and non-trivial, 1 mismatch/trivial, 2 error.
//
// Build (any CMake project, C and CXX enabled because Debian's VTK uses MPI):
//   find_package(VTK REQUIRED COMPONENTS CommonCore RenderingCore RenderingOpenGL2
//     RenderingVolumeOpenGL2 FiltersSources InteractionStyle IOImage)
//   include(<repo>/Applications/Plume/HeadlessBackend.cmake)
//   add_executable(plumeHeadlessCompare <repo>/Applications/Plume/Testing/plumeHeadlessCompare.cxx)
//   target_link_libraries(plumeHeadlessCompare PRIVATE ${VTK_LIBRARIES})
//   plume_add_headless_backend(plumeHeadlessCompare)
//   vtk_module_autoinit(TARGETS plumeHeadlessCompare MODULES ${VTK_LIBRARIES})
// Run (the X backend needs a display, OSMesa does not):
//   xvfb-run -a -s "-screen 0 1024x768x24" ./plumeHeadlessCompare
//   env -u DISPLAY ./plumeHeadlessCompare --render osmesa --write-raw os.raw
//   xvfb-run -a -s "-screen 0 1024x768x24" ./plumeHeadlessCompare --render x --write-raw x.raw
//   ./plumeHeadlessCompare --compare-raw os.raw x.raw
#include "plumeRenderWindowFactory.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkConeSource.h>
#include <vtkGPUVolumeRayCastMapper.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Shrinks every triangle towards its centroid: visible only if the GS runs.
const char* ShrinkGS = R"GLSL(
//VTK::System::Dec
//VTK::PositionVC::Dec
//VTK::PrimID::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TCoord::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

void main()
{
  vec4 centre = (gl_in[0].gl_Position + gl_in[1].gl_Position + gl_in[2].gl_Position) / 3.0;
  for (int i = 0; i < 3; i++)
  {
    //VTK::PrimID::Impl
    //VTK::Clip::Impl
    //VTK::Color::Impl
    //VTK::Normal::Impl
    //VTK::Light::Impl
    //VTK::TCoord::Impl
    //VTK::DepthPeeling::Impl
    //VTK::Picking::Impl
    //VTK::PositionVC::Impl
    gl_Position = mix(centre, gl_in[i].gl_Position, 0.6);
    EmitVertex();
  }
  EndPrimitive();
}
)GLSL";

struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> RGBA;
  std::vector<float> Depth;
};

void BuildScene(vtkRenderer* ren)
{
  ren->SetBackground(0.10, 0.20, 0.45);

  vtkNew<vtkConeSource> cone;
  cone->SetResolution(24);
  cone->SetDirection(0.3, 1.0, 0.2);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->SetPosition(-1.3, 0.4, 0.0);
  coneActor->GetProperty()->SetColor(0.9, 0.25, 0.15);
  ren->AddActor(coneActor);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  sphere->SetRadius(0.45);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->SetPosition(1.1, -0.6, 0.3);
  sphereActor->GetProperty()->SetColor(0.2, 0.85, 0.3);
  sphereActor->GetProperty()->SetSpecular(0.4);
  sphereActor->GetProperty()->SetSpecularPower(20.0);
  ren->AddActor(sphereActor);

  // Geometry shader: a 5x3 plane whose triangles the GS shrinks.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, -1.6, -0.8);
  plane->SetPoint1(0.2, -1.6, -0.8);
  plane->SetPoint2(-2.0, -0.3, -0.5);
  plane->SetResolution(5, 3);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(0.95, 0.85, 0.2);
  planeActor->GetShaderProperty()->SetGeometryShaderCode(ShrinkGS);
  ren->AddActor(planeActor);

  // Volume (3D texture): a 24^3 blob, off-centre, top right.
  vtkNew<vtkImageData> image;
  const int n = 24;
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  image->SetOrigin(0.6, 0.5, -0.5);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* voxels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = (i - 0.35 * n) / n;
        const double y = (j - 0.5 * n) / n;
        const double z = (k - 0.6 * n) / n;
        const double r = std::sqrt(x * x + 1.5 * y * y + z * z);
        voxels[(k * n + j) * n + i] =
          static_cast<unsigned char>(std::max(0.0, 255.0 * (1.0 - 2.2 * r)));
      }
    }
  }
  vtkNew<vtkGPUVolumeRayCastMapper> volumeMapper;
  volumeMapper->SetInputData(image);
  volumeMapper->SetAutoAdjustSampleDistances(false);
  volumeMapper->SetSampleDistance(0.01);
  vtkNew<vtkColorTransferFunction> colours;
  colours->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  colours->AddRGBPoint(80.0, 0.9, 0.4, 0.9);
  colours->AddRGBPoint(255.0, 1.0, 1.0, 0.6);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(40.0, 0.0);
  opacity->AddPoint(255.0, 0.9);
  vtkNew<vtkVolumeProperty> volumeProperty;
  volumeProperty->SetColor(colours);
  volumeProperty->SetScalarOpacity(opacity);
  volumeProperty->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->SetProperty(volumeProperty);
  ren->AddVolume(volume);

  ren->ResetCamera();
  ren->GetActiveCamera()->Azimuth(20.0);
  ren->GetActiveCamera()->Elevation(15.0);
  ren->GetActiveCamera()->Zoom(1.5);
  ren->ResetCameraClippingRange();
}

// Renders the scene with `backend`; returns false (message printed) on error.
bool RenderWith(plume::Backend backend, int w, int h, Image& out, const std::string& png)
{
  plume::Backend used = plume::Backend::Auto;
  std::string error;
  const auto t0 = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkRenderWindow> win = plume::CreateRenderWindow(backend, w, h, &used, &error);
  if (!win)
  {
    std::cerr << "requested backend " << plume::BackendName(backend) << ": " << error << "\n";
    return false;
  }
  const auto t1 = std::chrono::steady_clock::now();
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  BuildScene(ren);
  win->Render();
  const auto t2 = std::chrono::steady_clock::now();
  win->Render();
  const auto t3 = std::chrono::steady_clock::now();
  out.Width = w;
  out.Height = h;
  vtkNew<vtkUnsignedCharArray> rgba;
  win->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, rgba);
  out.RGBA.assign(rgba->GetPointer(0), rgba->GetPointer(0) + rgba->GetNumberOfValues());
  out.Depth.resize(static_cast<size_t>(w) * h);
  win->GetZbufferData(0, 0, w - 1, h - 1, out.Depth.data());

  // Also through vtkWindowToImageFilter (must agree with the direct read).
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(win);
  grab->SetInputBufferTypeToRGBA();
  grab->ReadFrontBufferOff();
  // Read exactly the frame read above: the filter's own re-render is not
  // bit-identical to a plain Render() for the volume (VTK 9.1, any backend).
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* shot = grab->GetOutput();
  const auto* shotPixels = static_cast<unsigned char*>(shot->GetScalarPointer());
  const bool filterAgrees = shot->GetNumberOfPoints() == static_cast<vtkIdType>(w) * h &&
    std::memcmp(shotPixels, out.RGBA.data(), out.RGBA.size()) == 0;
  if (!png.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(png.c_str());
    writer->Write();
  }

  auto ms = [](std::chrono::steady_clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  auto* glwin = vtkOpenGLRenderWindow::SafeDownCast(win);
  int major = 0;
  int minor = 0;
  if (glwin)
  {
    glwin->GetOpenGLVersion(major, minor);
  }
  std::printf("backend used: %s (requested %s, %s, GL %d.%d) create %.1f ms, first render "
              "%.1f ms, re-render %.1f ms, vtkWindowToImageFilter %s\n",
    plume::BackendName(used), plume::BackendName(backend), win->GetClassName(), major, minor,
    ms(t1 - t0), ms(t2 - t1), ms(t3 - t2), filterAgrees ? "agrees" : "DIFFERS");
  std::fflush(stdout);
  return filterAgrees;
}

bool ParseSize(const char* s, int& w, int& h)
{
  return std::sscanf(s, "%dx%d", &w, &h) == 2 && w > 0 && h > 0;
}

int Compare(const Image& a, const Image& b)
{
  if (a.RGBA.size() != b.RGBA.size() || a.RGBA.empty())
  {
    std::printf("FAIL: image sizes differ (%zu vs %zu bytes)\n", a.RGBA.size(), b.RGBA.size());
    return 1;
  }
  // Non-trivial: enough pixels differ from the background (corner pixel).
  const unsigned char* bg = a.RGBA.data();
  size_t foreground = 0;
  for (size_t p = 0; p < a.RGBA.size(); p += 4)
  {
    if (std::memcmp(&a.RGBA[p], bg, 3) != 0)
    {
      ++foreground;
    }
  }
  const size_t pixels = a.RGBA.size() / 4;
  size_t differing = 0;
  size_t first = pixels;
  for (size_t p = 0; p < a.RGBA.size(); p += 4)
  {
    if (std::memcmp(&a.RGBA[p], &b.RGBA[p], 4) != 0)
    {
      if (first == pixels)
      {
        first = p / 4;
      }
      ++differing;
    }
  }
  const bool depthSame = a.Depth.size() == b.Depth.size() &&
    std::memcmp(a.Depth.data(), b.Depth.data(), a.Depth.size() * sizeof(float)) == 0;
  std::printf("foreground pixels: %zu of %zu; differing RGBA pixels: %zu; depth %s\n", foreground,
    pixels, differing, depthSame ? "identical" : "differs");
  if (foreground < pixels / 20)
  {
    std::printf("FAIL: image is (nearly) all background\n");
    return 1;
  }
  if (differing != 0)
  {
    std::printf("FAIL: images differ, first at pixel (%zu, %zu)\n", first % a.Width,
      first / a.Width);
    return 1;
  }
  std::printf("PASS: byte-identical RGBA images\n");
  return 0;
}

int Usage()
{
  std::cerr << "usage: plumeHeadlessCompare [--first auto|osmesa|x] [--second auto|osmesa|x]\n"
               "         [--size WxH] [--write-prefix PATH] [--perturb]\n"
               "       plumeHeadlessCompare --render B [--size WxH] --write-raw FILE\n"
               "       plumeHeadlessCompare --compare-raw FILE FILE\n";
  return 2;
}

bool WriteRaw(const std::string& file, const Image& img)
{
  std::ofstream f(file, std::ios::binary);
  f.write(reinterpret_cast<const char*>(&img.Width), sizeof(int));
  f.write(reinterpret_cast<const char*>(&img.Height), sizeof(int));
  f.write(reinterpret_cast<const char*>(img.RGBA.data()), img.RGBA.size());
  f.write(reinterpret_cast<const char*>(img.Depth.data()), img.Depth.size() * sizeof(float));
  return static_cast<bool>(f);
}

bool ReadRaw(const std::string& file, Image& img)
{
  std::ifstream f(file, std::ios::binary);
  f.read(reinterpret_cast<char*>(&img.Width), sizeof(int));
  f.read(reinterpret_cast<char*>(&img.Height), sizeof(int));
  if (!f || img.Width <= 0 || img.Height <= 0)
  {
    return false;
  }
  const size_t n = static_cast<size_t>(img.Width) * img.Height;
  img.RGBA.resize(n * 4);
  img.Depth.resize(n);
  f.read(reinterpret_cast<char*>(img.RGBA.data()), img.RGBA.size());
  f.read(reinterpret_cast<char*>(img.Depth.data()), img.Depth.size() * sizeof(float));
  return static_cast<bool>(f);
}
}

int main(int argc, char* argv[])
{
  plume::Backend first = plume::Backend::OSMesa;
  plume::Backend second = plume::Backend::X;
  int w = 400;
  int h = 300;
  bool perturb = false;
  std::string prefix;
  std::string renderOnly;
  std::string rawOut;
  std::vector<std::string> rawIn;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--first" && more)
    {
      if (!plume::ParseBackend(argv[++i], first))
      {
        return Usage();
      }
    }
    else if (a == "--second" && more)
    {
      if (!plume::ParseBackend(argv[++i], second))
      {
        return Usage();
      }
    }
    else if (a == "--render" && more)
    {
      renderOnly = argv[++i];
    }
    else if (a == "--write-raw" && more)
    {
      rawOut = argv[++i];
    }
    else if (a == "--compare-raw" && i + 2 < argc)
    {
      rawIn = { argv[i + 1], argv[i + 2] };
      i += 2;
    }
    else if (a == "--size" && more)
    {
      if (!ParseSize(argv[++i], w, h))
      {
        return Usage();
      }
    }
    else if (a == "--write-prefix" && more)
    {
      prefix = argv[++i];
    }
    else if (a == "--perturb")
    {
      perturb = true;
    }
    else
    {
      return Usage();
    }
  }

  if (!rawIn.empty())
  {
    Image a;
    Image b;
    if (!ReadRaw(rawIn[0], a) || !ReadRaw(rawIn[1], b))
    {
      std::cerr << "cannot read raw images\n";
      return 2;
    }
    return Compare(a, b);
  }

  if (!renderOnly.empty())
  {
    plume::Backend b;
    if (!plume::ParseBackend(renderOnly, b) || rawOut.empty())
    {
      return Usage();
    }
    Image img;
    if (!RenderWith(b, w, h, img, prefix.empty() ? std::string() : prefix + ".png"))
    {
      return 2;
    }
    return WriteRaw(rawOut, img) ? 0 : 2;
  }

  Image a;
  Image b;
  if (!RenderWith(first, w, h, a, prefix.empty() ? std::string() : prefix + "-first.png") ||
    !RenderWith(second, w, h, b, prefix.empty() ? std::string() : prefix + "-second.png"))
  {
    return 2;
  }
  if (perturb)
  {
    b.RGBA[4 * (static_cast<size_t>(h / 2) * w + w / 3) + 1] ^= 1;
    std::printf("perturbed one byte of the second image\n");
  }
  return Compare(a, b);
}
