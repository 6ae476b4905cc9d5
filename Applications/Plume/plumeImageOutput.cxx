#include "plumeImageOutput.h"

#include "plumeSceneError.h"

#include "vtkCamera.h"
#include "vtkFramebufferPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPixelBufferObject.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtksys/SystemTools.hxx"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace plume
{

double LinearDepth(double d, vtkCamera* camera)
{
  if (d >= 1.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  double range[2];
  camera->GetClippingRange(range);
  const double n = range[0], f = range[1];
  if (camera->GetParallelProjection())
  {
    return n + d * (f - n);
  }
  const double ndc = 2.0 * d - 1.0;
  return 2.0 * n * f / ((f + n) - ndc * (f - n));
}

namespace
{
// Copies a texture's level 0 as floats (`components` per pixel).
std::vector<float> DownloadFloats(vtkTextureObject* texture, int components)
{
  vtkSmartPointer<vtkPixelBufferObject> pbo;
  pbo.TakeReference(texture->Download());
  if (!pbo)
  {
    throw SceneError("could not read back the float framebuffer");
  }
  const size_t n = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() * components;
  std::vector<float> values(n);
  const auto* mapped = static_cast<const float*>(pbo->MapPackedBuffer());
  if (!mapped)
  {
    throw SceneError("could not map the float framebuffer read-back");
  }
  std::copy(mapped, mapped + n, values.begin());
  pbo->UnmapPackedBuffer();
  return values;
}
}

FloatImage RenderFloat(vtkRenderWindow* window, vtkRenderer* renderer)
{
  vtkSmartPointer<vtkRenderPass> previous = renderer->GetPass();
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkFramebufferPass> framebuffer;
  framebuffer->SetDelegatePass(previous ? previous.Get() : steps.Get());
  framebuffer->SetColorFormat(vtkTextureObject::Float32);
  // depth keeps the window's format: the pass blits depth back into the
  // window's framebuffer, and a depth blit needs matching formats
  renderer->SetPass(framebuffer);
  window->Render();
  FloatImage image;
  try
  {
    vtkTextureObject* color = framebuffer->GetColorTexture();
    vtkTextureObject* depth = framebuffer->GetDepthTexture();
    if (!color || !depth || color->GetVTKDataType() != VTK_FLOAT || color->GetComponents() != 4)
    {
      throw SceneError("the float framebuffer was not created (no RGBA32F render target)");
    }
    image.Width = static_cast<int>(color->GetWidth());
    image.Height = static_cast<int>(color->GetHeight());
    image.RGBA = DownloadFloats(color, 4);
    image.Depth = DownloadFloats(depth, 1);
  }
  catch (...)
  {
    framebuffer->ReleaseGraphicsResources(window);
    renderer->SetPass(previous);
    throw;
  }
  framebuffer->ReleaseGraphicsResources(window);
  renderer->SetPass(previous);
  return image;
}

namespace
{
void WritePNG(const std::string& path, const FloatImage& image)
{
  vtkNew<vtkImageData> out;
  out->SetDimensions(image.Width, image.Height, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* pixels = static_cast<unsigned char*>(out->GetScalarPointer());
  for (size_t i = 0; i < image.RGBA.size(); ++i)
  {
    const float v = std::isfinite(image.RGBA[i]) ? image.RGBA[i] : 0.f;
    pixels[i] = static_cast<unsigned char>(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f);
  }
  // Opaque output: the framebuffer's alpha is VTK's internal coverage, not meant for viewers.
  for (size_t p = 3; p < image.RGBA.size(); p += 4)
  {
    pixels[p] = 255;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(out);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw SceneError("cannot write PNG '" + path + "'");
  }
}

void WriteEXR(const std::string& path, const FloatImage& image, vtkCamera* camera)
{
  const int w = image.Width, h = image.Height;
  // EXR rows run top to bottom; OpenGL's bottom to top.
  std::vector<float> channels[5];
  for (auto& c : channels)
  {
    c.resize(static_cast<size_t>(w) * h);
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t src = static_cast<size_t>(y) * w + x;
      const size_t dst = static_cast<size_t>(h - 1 - y) * w + x;
      for (int c = 0; c < 3; ++c)
      {
        channels[c][dst] = image.RGBA[4 * src + c];
      }
      // opaque output, as for PNG: the framebuffer's alpha is VTK's internal
      // coverage (in a float buffer it can leave [0, 1])
      channels[3][dst] = 1.0f;
      channels[4][dst] = static_cast<float>(LinearDepth(image.Depth[src], camera));
    }
  }
  try
  {
    Imf::Header header(w, h);
    const char* names[5] = { "R", "G", "B", "A", "Z" };
    Imf::FrameBuffer frame;
    for (int c = 0; c < 5; ++c)
    {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      frame.insert(names[c],
        Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channels[c].data()), sizeof(float), sizeof(float) * w));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
  }
  catch (const std::exception& e)
  {
    throw SceneError("cannot write EXR '" + path + "': " + e.what());
  }
}
}

void WriteImage(const std::string& path, const FloatImage& image, vtkCamera* camera)
{
  const std::string ext = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (ext == ".png")
  {
    WritePNG(path, image);
  }
  else if (ext == ".exr")
  {
    WriteEXR(path, image, camera);
  }
  else
  {
    throw SceneError("output '" + path + "': unknown image format '" + ext + "' (use .png or .exr)");
  }
}

}
