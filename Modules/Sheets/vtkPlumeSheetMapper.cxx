#include "vtkPlumeSheetMapper.h"
#include "vtkPlumeSheetTriangles.h"

#include "vtkPlumeInputValidation.h"

#include "vtkPlumeGLMatrix.h"
#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeOpaqueDepthTexture.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"
#include "vtkPlumeThrottledDraw.h"

#include "vtkPlumeSheetCompositeFS.h"
#include "vtkPlumeSheetCompositeVS.h"
#include "vtkPlumeSheetFS.h"
#include "vtkPlumeSheetGS.h"
#include "vtkPlumeSheetVS.h"

#include "vtkPlumeSheetDensityGrid.h"
#include "vtkPlumeVolumeMapper.h"
#include "vtkPlumeWindowChange.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtk_glew.h"

#include <algorithm>
#include <limits>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

namespace
{
// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre polynomial)
void GaussLegendre(int n, std::vector<double>& x, std::vector<double>& w)
{
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    double z = std::cos(vtkMath::Pi() * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it)
    {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k)
      {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      dp = n * (z * p0 - p1) / (z * z - 1.0);
      const double dz = p0 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-15)
      {
        break;
      }
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

double Clean(double value)
{
  return std::isfinite(value) && value > 0.0 ? value : 0.0;
}

vtkDataArray* NamedArray(vtkPolyData* poly, const std::string& name, int components)
{
  if (name.empty())
  {
    return nullptr;
  }
  vtkDataArray* a = poly->GetPointData()->GetArray(name.c_str());
  if (!a || a->GetNumberOfTuples() != poly->GetNumberOfPoints() ||
    a->GetNumberOfComponents() < components)
  {
    return nullptr;
  }
  return a;
}
} // namespace

//------------------------------------------------------------------------------
class vtkPlumeSheetMapper::Internals
{
public:
  // What one Render() works out and its steps pass on.
  struct Frame
  {
    vtkRenderer* Renderer = nullptr;
    vtkActor* Actor = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkOpenGLCamera* Camera = nullptr;
    vtkPolyData* Mesh = nullptr;
    int Viewport[4] = { 0, 0, 0, 0 }; // x, y, width, height
    // centre-relative model -> eye, eye -> clip and back, composed in double
    double MCVCRel[16];
    double VCDC[16];
    double DCVC[16];
    double ModelScale = 1.0;    // the actor's length scale cbrt|det| (sigmas scale by it)
    float Factors[3] = { 0, 0, 0 }; // density, sigma_b, sigma_t multipliers (SheetFactors)
    bool Bounded = false;           // integrate up to the opaque depth
    vtkTextureObject* DepthTexture = nullptr;
  };

  // The render steps, in order (Render() calls them).
  bool UpdateTriangles(vtkPlumeSheetMapper* self, Frame& frame);
  bool ComputeFrame(vtkPlumeSheetMapper* self, Frame& frame);
  void AcquireDepth(vtkPlumeSheetMapper* self, Frame& frame);
  vtkShaderProgram* ReadyProgram(vtkPlumeSheetMapper* self, Frame& frame);
  bool SigmaMayVary(vtkPlumeSheetMapper* self, const Frame& frame) const;
  void UpdateTarget(const Frame& frame);
  void SetUniforms(vtkPlumeSheetMapper* self, const Frame& frame, vtkShaderProgram* program);
  void Draw(vtkPlumeSheetMapper* self, const Frame& frame, vtkShaderProgram* program);
  // grid mode
  bool UpdateGrid(vtkPlumeSheetMapper* self, Frame& frame);
  void DrawGrid(vtkPlumeSheetMapper* self, const Frame& frame);

  // what the triangle buffer was built from: the mesh and which arrays feed
  // it (constant density, blur and thickness are uniforms: changing them
  // uploads nothing)
  using Signature = std::tuple<vtkPolyData*, vtkMTimeType, std::string, std::string, std::string,
    std::string>;
  Signature Uploaded;
  bool HaveUpload = false;
  bool DensityFromArray = false, BlurFromArray = false, ThicknessFromArray = false;
  double Centre[3] = { 0, 0, 0 };
  GLsizei VertexCount = 0;

  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVAO;
  vtkShaderProgram* VAOProgram = nullptr;
  bool BufferChanged = true;
  vtkNew<vtkPlumeOpaqueDepthTexture> Depth; // the opaque scene's depth (MSAA resolved by a blit)
  bool WarnedDepth = false;
  vtkNew<vtkTextureObject> AccumTexture;
  vtkNew<vtkOpenGLFramebufferObject> FBO;
  int TargetSize[2] = { 0, 0 };
  vtkNew<vtkPlumeShaderProgramCache> Programs;
  bool WarnedCells = false;

  // grid mode: what the grid was computed from, the grid, and its raycaster
  using GridSignature = std::tuple<vtkPolyData*, vtkMTimeType, std::string, std::string, std::string,
    std::array<double, 9>>;
  GridSignature GridFrom;
  bool HaveGrid = false;
  bool WarnedAbsorption = false;
  double GridMaxDensity = 0;
  vtkNew<vtkPlumeSheetDensityGrid> Grid;
  vtkNew<vtkPlumeVolumeMapper> GridMapper;
  vtkNew<vtkVolume> GridVolume;
  vtkNew<vtkVolumeProperty> GridProperty;
  vtkNew<vtkPiecewiseFunction> GridOpacity;
  vtkNew<vtkColorTransferFunction> GridColor;

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Buffer->ReleaseGraphicsResources();
    this->VAO->ReleaseGraphicsResources();
    this->EmptyVAO->ReleaseGraphicsResources();
    this->Depth->ReleaseGraphicsResources(window);
    this->AccumTexture->ReleaseGraphicsResources(window);
    this->FBO->ReleaseGraphicsResources(window);
    this->Programs->ReleaseGraphicsResources(window);
    this->GridMapper->ReleaseGraphicsResources(window);
    this->VAOProgram = nullptr;
    this->HaveUpload = false;
    this->TargetSize[0] = this->TargetSize[1] = 0;
    this->Window = nullptr;
  }
};

//------------------------------------------------------------------------------
namespace
{
// What the exact mode's triangle count costs, bounded before allocating: 96
// bytes per triangle twice (the vertex data and the GL buffer), and a vertex
// count that fits the draw call's GLsizei. "" or the message.
std::string ExactBudget(vtkPolyData* poly)
{
  double triangles = 0;
  plume::ForEachSheetTriangle(poly, [&](vtkIdType, vtkIdType, vtkIdType) { triangles += 1; });
  const std::string what = "the vertex data of the sheet's " + std::to_string(static_cast<long long>(triangles)) + " triangles";
  std::string tooMany = vtkPlumeInputValidation::CheckMemory(triangles * 2.0 * 3 * 8 * sizeof(float), what);
  if (tooMany.empty() && 3.0 * triangles > double(std::numeric_limits<GLsizei>::max()))
  {
    tooMany = "the sheet's " + std::to_string(static_cast<long long>(triangles)) + " triangles exceed the " +
      std::to_string(std::numeric_limits<GLsizei>::max() / 3) + " one OpenGL draw call can take";
  }
  return tooMany;
}
}

vtkStandardNewMacro(vtkPlumeSheetMapper);

vtkPlumeSheetMapper::vtkPlumeSheetMapper()
  : Impl(new Internals)
{
  vtkPlumeCompositingPass::SetStage(this, vtkPlumeCompositingPass::STAGE_MEDIA);
  GetParameterTable().ApplyDefaults(this);
}

const vtkPlumeParameterTable& vtkPlumeSheetMapper::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeSheetMapper;
    vtkPlumeParameterTable t("vtkPlumeSheetMapper", "sheet");
    t.Real("density", "Density", 1.0)
      .Between(0.0, 1e30)
      .Units("optical depth per unit area")
      .Panel("Smoke")
      .Doc("Density d of the smoke where no density array is used.")
      .Bind(&T::SetDensity, &T::GetDensity);
    t.Text("density_array", "DensityArrayName", "")
      .Panel("Smoke")
      .Doc("Point array of density (1 component); empty: the constant `density`.")
      .Bind(&T::SetDensityArrayName, &T::GetDensityArrayName);
    t.Real("density_scale", "DensityScale", 1.0)
      .Between(0.0, 1e30)
      .Panel("Smoke")
      .Doc("Multiplies every density (array or constant).")
      .Bind(&T::SetDensityScale, &T::GetDensityScale);
    t.Real("blur", "BlurRadius", 0.05)
      .Between(0.0, MaximumSigma)
      .Units("model units")
      .Panel("Smoke")
      .Doc("Blurring radius sigma_b in the surface where no blur array is used.")
      .Bind(&T::SetBlurRadius, &T::GetBlurRadius);
    t.Text("blur_array", "BlurArrayName", "")
      .Panel("Smoke")
      .Doc("Point array of sigma_b (1 component); empty: the constant `blur`.")
      .Bind(&T::SetBlurArrayName, &T::GetBlurArrayName);
    t.Real("thickness", "Thickness", 0.05)
      .Between(0.0, MaximumSigma)
      .Units("model units")
      .Panel("Smoke")
      .Doc("Thickness sigma_t across the surface where no thickness array is used.")
      .Bind(&T::SetThickness, &T::GetThickness);
    t.Text("thickness_array", "ThicknessArrayName", "")
      .Panel("Smoke")
      .Doc("Point array of sigma_t (1 component); empty: the constant `thickness`.")
      .Bind(&T::SetThicknessArrayName, &T::GetThicknessArrayName);
    t.Text("absorption_array", "AbsorptionArrayName", "")
      .Panel("Smoke")
      .Doc("3-component point array of per-channel absorption (coloured smoke); empty: grey smoke.")
      .Bind(&T::SetAbsorptionArrayName, &T::GetAbsorptionArrayName);
    t.Color("smoke_color", "SmokeColor", { 0.0, 0.0, 0.0 })
      .Panel("Smoke")
      .Doc("Colour the smoke sends back: pixel = frame T + colour (1 - T); black: it only absorbs.")
      .Bind(static_cast<void (T::*)(const double*)>(&T::SetSmokeColor),
        static_cast<double* (T::*)()>(&T::GetSmokeColor));
    t.Boolean("thin", "ThinSheet", false)
      .Panel("Smoke")
      .Doc("sigma_t = 0 exactly: the density is a surface layer (thickness ignored).")
      .Bind(&T::SetThinSheet, &T::GetThinSheet);
    t.Boolean("opaque_depth", "BoundedByDepth", true)
      .Panel("Compositing")
      .Doc("Integrate only up to the opaque geometry; off: the whole line, as in the paper.")
      .Bind(&T::SetBoundedByDepth, &T::GetBoundedByDepth);
    t.Real("cutoff", "Cutoff", 3.5)
      .Between(1.0, 10.0)
      .Units("standard deviations")
      .Panel("Quality")
      .Advanced()
      .Doc("Support radius Lambda of each triangle's Gaussian.")
      .Bind(&T::SetCutoff, &T::GetCutoff);
    t.Real("min_sigma_pixels", "MinimumSigmaPixels", 1.0 / 3.0)
      .Between(0.0, 100.0)
      .Units("pixels")
      .Panel("Quality")
      .Advanced()
      .Doc("Lower bound on sigma_b and sigma_t at each corner's depth.")
      .Bind(&T::SetMinimumSigmaPixels, &T::GetMinimumSigmaPixels);
    t.Choice("quadrature", "Quadrature", "analytic")
      .Choice("grid", QUADRATURE_GRID, "seed 000's regular grid over the triangle, sampled twice.")
      .Choice("analytic", QUADRATURE_ANALYTIC,
        "closed form across the ray's footprint, Gauss-Legendre nodes along it.")
      .Panel("Quality")
      .Doc("How each fragment integrates over a triangle.")
      .Bind(&T::SetQuadrature, &T::GetQuadrature);
    t.Integer("grid_a", "GridA", 8)
      .Between(1, 32)
      .Panel("Quality")
      .Doc("Nodes per piece along the footprint (analytic; 8 is the smallest that met the accuracy goal "
           "on every test scene), or grid cells along it (grid).")
      .Bind(&T::SetGridA, &T::GetGridA);
    t.Integer("grid_b", "GridB", 5)
      .Between(1, 32)
      .Panel("Quality")
      .Doc("Grid cells across the footprint (grid), or Gauss-Legendre nodes across it per piece where "
           "sigma varies over a triangle (analytic).")
      .Bind(&T::SetGridB, &T::GetGridB);
    t.Boolean("adaptive_sampling", "AdaptiveSampling", true)
      .Panel("Quality")
      .Advanced()
      .Doc("Triangles smaller than sigma_b / 2 take a 3-point rule (analytic quadrature).")
      .Bind(&T::SetAdaptiveSampling, &T::GetAdaptiveSampling);
    t.Integer("maximum_triangles_per_draw", "MaximumTrianglesPerDraw", 16384)
      .Between(0, 1e15)
      .Panel("Quality")
      .Advanced()
      .Doc("Largest draw call; more triangles are drawn two draws in flight at a time, which bounds "
           "the driver's memory (0: one draw).")
      .Bind(&T::SetMaximumTrianglesPerDraw, &T::GetMaximumTrianglesPerDraw);
    t.Choice("mode", "RenderMode", "exact")
      .Choice("exact", RENDER_EXACT, "every triangle integrated along every pixel's ray (reference quality).")
      .Choice("grid", RENDER_GRID,
        "the smoke computed once on a grid following sigma, raycast every frame (interactive).")
      .Panel("Quality")
      .Doc("How the sheet is rendered.")
      .Bind(&T::SetRenderMode, &T::GetRenderMode);
    t.Real("grid_samples_per_sigma", "GridSamplesPerSigma", 2.0)
      .OnlyWith("mode", { "grid" })
      .Between(0.25, 16.0)
      .Panel("Quality")
      .Doc("Grid mode: grid nodes per smallest sigma (spacing = sigma / this).")
      .Bind(&T::SetGridSamplesPerSigma, &T::GetGridSamplesPerSigma);
    t.Real("grid_sample_distance", "GridSampleDistance", 1.0)
      .OnlyWith("mode", { "grid" })
      .Between(0.05, 16.0)
      .Units("grid spacings")
      .Panel("Quality")
      .Doc("Grid mode: raycast step.")
      .Bind(&T::SetGridSampleDistance, &T::GetGridSampleDistance);
    t.Boolean("auto_adjust_quality", "AutoAdjustQuality", true)
      .OnlyWith("mode", { "grid" })
      .Panel("Quality")
      .Doc("Grid mode: coarse frames while the camera moves (window DesiredUpdateRate above 1 frame/s), "
           "refined when it stops.")
      .Bind(&T::SetAutoAdjustQuality, &T::GetAutoAdjustQuality);
    t.Real("interactive_grid_sample_distance", "InteractiveGridSampleDistance", 2.0)
      .OnlyWith("mode", { "grid" })
      .Between(0.05, 16.0)
      .Units("grid spacings")
      .Panel("Quality")
      .Advanced()
      .Doc("Grid mode: raycast step while the camera moves.")
      .Bind(&T::SetInteractiveGridSampleDistance, &T::GetInteractiveGridSampleDistance);
    t.Integer("interactive_image_sample_distance", "InteractiveImageSampleDistance", 2)
      .OnlyWith("mode", { "grid" })
      .Between(1, 16)
      .Units("pixels")
      .Panel("Quality")
      .Advanced()
      .Doc("Grid mode: one ray per this many pixels while the camera moves (interpolated where the "
           "rays agree).")
      .Bind(&T::SetInteractiveImageSampleDistance, &T::GetInteractiveImageSampleDistance);
    t.Real("interactive_lattice_tolerance", "InteractiveLatticeTolerance", 0.004)
      .OnlyWith("mode", { "grid" })
      .Between(0.0, 1.0)
      .Panel("Quality")
      .Advanced()
      .Doc("Grid mode, while the camera moves: lattice rays that differ by more than this (transmittance) "
           "make the pixels between them cast their own rays.")
      .Bind(&T::SetInteractiveLatticeTolerance, &T::GetInteractiveLatticeTolerance);
    t.Real("grid_maximum_nodes", "GridMaximumNodes", 33554432.0)
      .OnlyWith("mode", { "grid" })
      .Between(8.0, 1e12)
      .Panel("Quality")
      .Advanced()
      .Doc("Grid mode: most grid nodes (4 bytes each); the spacing grows to fit.")
      .Bind(&T::SetGridMaximumNodes, &T::GetGridMaximumNodes);
    t.Real("grid_merge_cell_size", "GridMergeCellSize", 2.0)
      .OnlyWith("mode", { "grid" })
      .Between(0.0, 4.0)
      .Units("grid spacings")
      .Panel("Quality")
      .Advanced()
      .Doc("Grid mode: quadrature points within one cell of this size are merged into one Gaussian "
           "(mass, centroid and second moment kept) before the grid is computed; 0: every point splatted (minutes on large meshes).")
      .Bind(&T::SetGridMergeCellSize, &T::GetGridMergeCellSize);
    return t;
  }();
  return table;
}

vtkPlumeSheetMapper::~vtkPlumeSheetMapper() = default;

vtkPlumeSheetDensityGrid* vtkPlumeSheetMapper::GetDensityGrid()
{
  return this->Impl->Grid;
}

int vtkPlumeSheetMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkPlumeSheetMapper::SetInputData(vtkPolyData* input)
{
  this->SetInputDataInternal(0, input);
}

vtkPolyData* vtkPlumeSheetMapper::GetInput()
{
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    return nullptr;
  }
  return vtkPolyData::SafeDownCast(this->GetExecutive()->GetInputData(0, 0));
}

//------------------------------------------------------------------------------
double* vtkPlumeSheetMapper::GetBounds()
{
  vtkMath::UninitializeBounds(this->Bounds);
  if (!this->Static && this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkPolyData* poly = this->GetInput();
  if (!poly || poly->GetNumberOfPoints() < 1)
  {
    return this->Bounds;
  }
  poly->GetBounds(this->Bounds);
  double sigma = 0.0;
  const std::string* names[2] = { &this->BlurArrayName, &this->ThicknessArrayName };
  const double constants[2] = { this->BlurRadius, this->ThinSheet ? 0.0 : this->Thickness };
  for (int s = 0; s < 2; ++s)
  {
    if (s == 1 && this->ThinSheet)
    {
      continue;
    }
    vtkDataArray* a = NamedArray(poly, *names[s], 1);
    const double value = a ? a->GetRange(0)[1] : constants[s];
    sigma = std::max(sigma, Clean(value));
  }
  const double* b = this->Bounds;
  const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  double pad = this->Cutoff * sigma;
  if (diagonal > 0)
  {
    pad = std::min(pad, 10.0 * diagonal);
  }
  if (!std::isfinite(pad))
  {
    pad = 0.0;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Bounds[2 * a] -= pad;
    this->Bounds[2 * a + 1] += pad;
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
// Render(): checks, then the steps in order — triangles (resources), frame
// (viewport, matrices), opaque depth, program, target, uniforms, draw
// (accumulate + composite). The grid mode has its own two steps.
void vtkPlumeSheetMapper::Render(vtkRenderer* ren, vtkActor* actor)
{
  Internals& impl = *this->Impl;
  this->LastDrawCount = 0;
  if (!vtkPlumeCompositingPass::ShouldDraw(ren, this))
  {
    return; // a compositing pass draws the sheet in its media step
  }
  if (!this->Static && this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  Internals::Frame frame;
  frame.Renderer = ren;
  frame.Actor = actor;
  frame.Mesh = this->GetInput();
  if (!frame.Mesh)
  {
    vtkErrorMacro(<< "no input mesh");
    return;
  }
  if (ren->GetSelector())
  {
    return; // hardware selection is not supported
  }
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  frame.Camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  if (!frame.Window || !frame.Camera)
  {
    vtkErrorMacro(<< "an OpenGL render window and camera are required");
    return;
  }
  plume::ReleaseOnWindowChange(impl, frame.Window);
  if (this->RenderMode == RENDER_GRID)
  {
    if (impl.UpdateGrid(this, frame))
    {
      impl.DrawGrid(this, frame);
    }
    return;
  }

  if (!impl.UpdateTriangles(this, frame) || !impl.ComputeFrame(this, frame))
  {
    return;
  }
  impl.AcquireDepth(this, frame);
  vtkShaderProgram* program = impl.ReadyProgram(this, frame);
  if (!program)
  {
    return;
  }
  impl.UpdateTarget(frame);
  impl.SetUniforms(this, frame, program);
  impl.Draw(this, frame, program);
}

//------------------------------------------------------------------------------
// Step 1: the triangles, rebuilt only when the mesh or the arrays it takes
// change. A corner carries its array values, or 1 where a constant applies;
// the constants and the density scale multiply them as uniforms
// (SheetFactors, worked out here every frame: a slider move uploads nothing).
// False when there is nothing to draw.
bool vtkPlumeSheetMapper::Internals::UpdateTriangles(vtkPlumeSheetMapper* self, Frame& frame)
{
  vtkPolyData* poly = frame.Mesh;
  Signature sig{ poly, poly->GetMTime(), self->DensityArrayName, self->BlurArrayName,
    self->ThicknessArrayName, self->AbsorptionArrayName };
  if (!this->HaveUpload || sig != this->Uploaded || !this->Buffer->GetHandle())
  {
    // Readers hand out cells with point ids that do not exist: refuse them before reading any.
    std::string invalid = vtkPlumeInputValidation::CheckCells(poly);
    if (invalid.empty())
    {
      invalid = vtkPlumeInputValidation::CheckArrays(poly);
    }
    if (!invalid.empty())
    {
      vtkErrorWithObjectMacro(self, << "invalid input mesh, not drawn: " << invalid);
      this->HaveUpload = false;
      return false;
    }
    vtkDataArray* dArr = NamedArray(poly, self->DensityArrayName, 1);
    vtkDataArray* bArr = NamedArray(poly, self->BlurArrayName, 1);
    vtkDataArray* tArr = NamedArray(poly, self->ThicknessArrayName, 1);
    vtkDataArray* aArr = NamedArray(poly, self->AbsorptionArrayName, 3);
    const std::string* names[4] = { &self->DensityArrayName, &self->BlurArrayName,
      &self->ThicknessArrayName, &self->AbsorptionArrayName };
    vtkDataArray* found[4] = { dArr, bArr, tArr, aArr };
    for (int i = 0; i < 4; ++i)
    {
      if (!names[i]->empty() && !found[i])
      {
        vtkWarningWithObjectMacro(self, << "point array '" << *names[i] << "' is missing or has "
                        << (i == 3 ? "fewer than 3 components" : "no components")
                        << "; using the constant instead");
      }
    }
    if ((poly->GetNumberOfVerts() > 0 || poly->GetNumberOfLines() > 0) && !this->WarnedCells)
    {
      vtkWarningWithObjectMacro(self, << "vertices and lines of the input are ignored; only polygons and "
                         "triangle strips are drawn");
      this->WarnedCells = true;
    }
    double bounds[6];
    poly->GetBounds(bounds);
    for (int a = 0; a < 3; ++a)
    {
      this->Centre[a] = std::isfinite(bounds[2 * a]) && std::isfinite(bounds[2 * a + 1])
        ? 0.5 * (bounds[2 * a] + bounds[2 * a + 1])
        : 0.0;
    }
    {
      const std::string tooMany = ExactBudget(poly);
      if (!tooMany.empty())
      {
        vtkErrorWithObjectMacro(self, << "not drawn: " << tooMany);
        this->HaveUpload = false;
        return false;
      }
    }
    std::vector<float> data;
    vtkIdType skipped = 0;
    auto corner = [&](vtkIdType id, float* out, bool& finite, double p[3]) {
      poly->GetPoint(id, p);
      finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
      double d = dArr ? Clean(dArr->GetComponent(id, 0)) : 1.0;
      double rgb[3] = { 1, 1, 1 };
      if (aArr)
      {
        for (int c = 0; c < 3; ++c)
        {
          rgb[c] = Clean(aArr->GetComponent(id, c));
        }
      }
      for (int a = 0; a < 3; ++a)
      {
        out[a] = static_cast<float>(p[a] - this->Centre[a]);
        out[3 + a] = static_cast<float>(std::min(d * rgb[a], 1e30));
      }
      out[6] = bArr ? static_cast<float>(std::min(Clean(bArr->GetComponent(id, 0)), MaximumSigma)) : 1.0f;
      out[7] = tArr ? static_cast<float>(std::min(Clean(tArr->GetComponent(id, 0)), MaximumSigma)) : 1.0f;
    };
    auto addTriangle = [&](vtkIdType i0, vtkIdType i1, vtkIdType i2) {
      float c[3][8];
      double p[3][3];
      bool finite[3];
      corner(i0, c[0], finite[0], p[0]);
      corner(i1, c[1], finite[1], p[1]);
      corner(i2, c[2], finite[2], p[2]);
      if (!finite[0] || !finite[1] || !finite[2])
      {
        ++skipped;
        return;
      }
      bool any = false;
      for (int k = 0; k < 3; ++k)
      {
        any = any || c[k][3] > 0 || c[k][4] > 0 || c[k][5] > 0;
      }
      double e1[3], e2[3], n[3];
      vtkMath::Subtract(p[1], p[0], e1);
      vtkMath::Subtract(p[2], p[0], e2);
      vtkMath::Cross(e1, e2, n);
      if (!any || !(vtkMath::Norm(n) > 0.0))
      {
        return; // no density or no area: nothing to integrate
      }
      for (int k = 0; k < 3; ++k)
      {
        data.insert(data.end(), c[k], c[k] + 8);
      }
    };
    plume::ForEachSheetTriangle(poly, addTriangle);
    self->SkippedTriangles = skipped;
    if (skipped > 0)
    {
      vtkWarningWithObjectMacro(self, << skipped << " triangle(s) with a NaN or infinite corner position skipped");
    }
    self->TriangleCount = static_cast<vtkIdType>(data.size() / 24);
    this->VertexCount = static_cast<GLsizei>(data.size() / 8);
    if (!data.empty())
    {
      this->Buffer->Upload(data, vtkOpenGLBufferObject::ArrayBuffer);
    }
    this->BufferChanged = true;
    this->Uploaded = sig;
    this->HaveUpload = true;
    ++self->UploadCount;
    this->DensityFromArray = dArr != nullptr;
    this->BlurFromArray = bArr != nullptr;
    this->ThicknessFromArray = tArr != nullptr;
  }
  // what multiplies the uploaded corner values (the constants, where no array is used)
  frame.Factors[0] = static_cast<float>(
    std::min(Clean((this->DensityFromArray ? 1.0 : self->Density) * self->DensityScale), 1e30));
  frame.Factors[1] = static_cast<float>(
    this->BlurFromArray ? 1.0 : std::min(Clean(self->BlurRadius), MaximumSigma));
  frame.Factors[2] = static_cast<float>(self->ThinSheet
      ? 0.0
      : (this->ThicknessFromArray ? 1.0 : std::min(Clean(self->Thickness), MaximumSigma)));
  return this->VertexCount >= 3 && frame.Factors[0] > 0.0f; // else no triangle, or no density anywhere
}

//------------------------------------------------------------------------------
// Step 2: the viewport and the matrices, composed in double: centre-relative
// model -> eye, eye -> clip and back; the actor's length scale for sigma.
bool vtkPlumeSheetMapper::Internals::ComputeFrame(vtkPlumeSheetMapper* vtkNotUsed(self), Frame& frame)
{
  frame.Renderer->GetTiledSizeAndOrigin(
    &frame.Viewport[2], &frame.Viewport[3], &frame.Viewport[0], &frame.Viewport[1]);
  if (frame.Viewport[2] < 1 || frame.Viewport[3] < 1)
  {
    return false;
  }
  vtkMatrix4x4* wcvcT = nullptr;
  vtkMatrix4x4* vcdcT = nullptr;
  vtkMatrix4x4* wcdcT = nullptr;
  vtkMatrix3x3* normals = nullptr;
  frame.Camera->GetKeyMatrices(frame.Renderer, wcvcT, normals, vcdcT, wcdcT);
  double wcvc[16];
  vtkMatrix4x4::Transpose(wcvcT->GetData(), wcvc);
  vtkMatrix4x4::Transpose(vcdcT->GetData(), frame.VCDC);
  vtkMatrix4x4::Invert(frame.VCDC, frame.DCVC);
  double modelToWorld[16];
  vtkMatrix4x4::Identity(modelToWorld);
  if (!frame.Actor->GetIsIdentity())
  {
    std::copy(frame.Actor->GetMatrix()->GetData(), frame.Actor->GetMatrix()->GetData() + 16, modelToWorld);
  }
  double relToModel[16];
  vtkMatrix4x4::Identity(relToModel);
  for (int r = 0; r < 3; ++r)
  {
    relToModel[4 * r + 3] = this->Centre[r];
  }
  vtkMatrix4x4::Multiply4x4(modelToWorld, relToModel, frame.MCVCRel);
  vtkMatrix4x4::Multiply4x4(wcvc, frame.MCVCRel, frame.MCVCRel);
  double m3[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m3[r][c] = modelToWorld[4 * r + c];
    }
  }
  frame.ModelScale = std::cbrt(std::fabs(vtkMath::Determinant3x3(m3)));
  return true;
}

//------------------------------------------------------------------------------
// Step 3: the opaque scene's depth: the frame's shared copy under a
// vtkPlumeCompositingPass, else the depth buffer as it is now; without it the
// integral runs over the whole line (one warning).
void vtkPlumeSheetMapper::Internals::AcquireDepth(vtkPlumeSheetMapper* self, Frame& frame)
{
  frame.Bounded = self->BoundedByDepth;
  vtkPlumeOpaqueDepthTexture* depth =
    frame.Bounded ? vtkPlumeCompositingPass::AcquireDepth(frame.Renderer, this->Depth) : nullptr;
  if (frame.Bounded && !depth)
  {
    if (!this->WarnedDepth)
    {
      vtkWarningWithObjectMacro(self, << "cannot read the opaque depth (" << this->Depth->GetLastError()
                      << "): the sheet is drawn as if nothing opaque were in the scene");
      this->WarnedDepth = true;
    }
    frame.Bounded = false;
  }
  frame.DepthTexture = frame.Bounded ? depth->GetTextureObject() : nullptr;
}

//------------------------------------------------------------------------------
// Whether the sigmas can differ between a triangle's corners this frame: a
// blur or thickness array feeds them, or the geometry shader's per-corner
// floor (MinimumSigmaPixels at the corner's depth) can lift a constant sigma
// at some corner. Otherwise every corner has the same sigmas and the program
// is compiled without the varying-sigma path: llvmpipe pays for a branch that
// is never taken (about 1.55x the CPU time of the office and fire bench
// sheets). Conservative: the largest clip w over the mesh's bounding box,
// 1 % margin for the shader's float arithmetic.
bool vtkPlumeSheetMapper::Internals::SigmaMayVary(vtkPlumeSheetMapper* self, const Frame& frame) const
{
  const bool thick = !self->ThinSheet;
  if (this->BlurFromArray || (thick && this->ThicknessFromArray))
  {
    return true;
  }
  double bounds[6];
  frame.Mesh->GetBounds(bounds);
  double wMax = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    const double rel[4] = { bounds[(i & 1) ? 1 : 0] - this->Centre[0],
      bounds[(i & 2) ? 3 : 2] - this->Centre[1], bounds[(i & 4) ? 5 : 4] - this->Centre[2], 1.0 };
    double eye[4];
    vtkMatrix4x4::MultiplyPoint(frame.MCVCRel, rel, eye);
    double clipW = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      clipW += frame.VCDC[12 + c] * eye[c];
    }
    wMax = std::max(wMax, clipW);
  }
  if (!std::isfinite(wMax))
  {
    return true;
  }
  const double floorMax =
    self->MinimumSigmaPixels * 2.0 * wMax / (std::fabs(frame.VCDC[5]) * frame.Viewport[3]);
  double smallest = static_cast<double>(frame.Factors[1]) * frame.ModelScale;
  if (thick)
  {
    smallest = std::min(smallest, static_cast<double>(frame.Factors[2]) * frame.ModelScale);
  }
  return !(smallest > 1.01 * floorMax);
}

//------------------------------------------------------------------------------
// Step 4: the accumulation program of this frame's feature set (compiled once
// per set: depth bound, thin, quadrature, adaptive, node counts).
vtkShaderProgram* vtkPlumeSheetMapper::Internals::ReadyProgram(vtkPlumeSheetMapper* self, Frame& frame)
{
  const bool adaptive = self->AdaptiveSampling && self->Quadrature == QUADRATURE_ANALYTIC;
  vtkPlumeShaderFeatures features;
  features.Enable(frame.Bounded ? "BOUNDED" : "UNBOUNDED")
    .Enable(self->ThinSheet ? "THIN" : "THICK")
    .Enable(self->Quadrature == QUADRATURE_GRID ? "GRID" : "ANALYTIC")
    .Enable(adaptive ? "ADAPTIVE" : "FIXED")
    .Enable(this->SigmaMayVary(self, frame) ? "SIGMA_VARIES" : "SIGMA_CONSTANT")
    .Define("PLUME_GRID_A", self->GridA)
    .Define("PLUME_GRID_B", self->GridB)
    .Define("PLUME_SMALL_TRIANGLE", "0.5");
  if (self->Quadrature == QUADRATURE_ANALYTIC)
  {
    // along the footprint (GridA) and across it where the sigmas vary (GridB)
    const int counts[2] = { self->GridA, self->GridB };
    const char* names[2][2] = { { "PLUME_GL_NODES", "PLUME_GL_WEIGHTS" },
      { "PLUME_GLB_NODES", "PLUME_GLB_WEIGHTS" } };
    for (int q = 0; q < 2; ++q)
    {
      std::vector<double> x, w;
      GaussLegendre(counts[q], x, w);
      std::ostringstream nodes, weights;
      nodes.precision(9);
      weights.precision(9);
      for (int i = 0; i < counts[q]; ++i)
      {
        nodes << (i ? ", " : "") << std::fixed << x[i];
        weights << (i ? ", " : "") << std::fixed << w[i];
      }
      features.Define(names[q][0], nodes.str()).Define(names[q][1], weights.str());
    }
  }
  vtkShaderProgram* program =
    this->Programs->Ready(frame.Window, vtkPlumeSheetVS, vtkPlumeSheetGS, vtkPlumeSheetFS, features);
  if (!program)
  {
    vtkErrorWithObjectMacro(self, << "could not build the sheet shader program (" << features.GetKey() << ")");
  }
  return program;
}

//------------------------------------------------------------------------------
// Step 5: the viewport-sized float target of optical depth (reallocated only
// when the viewport's size changes).
void vtkPlumeSheetMapper::Internals::UpdateTarget(const Frame& frame)
{
  const int w = frame.Viewport[2], h = frame.Viewport[3];
  if (this->TargetSize[0] == w && this->TargetSize[1] == h && this->AccumTexture->GetHandle())
  {
    return;
  }
  this->AccumTexture->SetContext(frame.Window);
  this->AccumTexture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->AccumTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->AccumTexture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->AccumTexture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->AccumTexture->SetInternalFormat(GL_RGBA32F);
  this->AccumTexture->SetFormat(GL_RGBA);
  this->AccumTexture->SetDataType(GL_FLOAT);
  this->AccumTexture->Allocate2D(w, h, 4, VTK_FLOAT);
  this->TargetSize[0] = w;
  this->TargetSize[1] = h;
}

//------------------------------------------------------------------------------
// Step 6: the accumulation program's uniforms.
void vtkPlumeSheetMapper::Internals::SetUniforms(
  vtkPlumeSheetMapper* self, const Frame& frame, vtkShaderProgram* program)
{
  plume::SetUniformMatrix4x4(program, "MCVCRel", frame.MCVCRel);
  program->SetUniformf("ModelToEyeScale", static_cast<float>(frame.ModelScale));
  program->SetUniform3f("SheetFactors", frame.Factors);
  plume::SetUniformMatrix4x4(program, "Projection", frame.VCDC);
  plume::SetUniformMatrix4x4(program, "InverseProjection", frame.DCVC);
  const float vp[2] = { float(frame.Viewport[2]), float(frame.Viewport[3]) };
  program->SetUniform2f("ViewportSize", vp);
  program->SetUniformf("Cutoff", static_cast<float>(self->Cutoff));
  program->SetUniformf("MinSigmaPixels", static_cast<float>(self->MinimumSigmaPixels));
  program->SetUniformi("Parallel", frame.Camera->GetParallelProjection() ? 1 : 0);
  // (OpaqueDepth is set in Draw, once the depth texture has its unit)
}

//------------------------------------------------------------------------------
// Step 7: accumulate tau of every triangle into the float target (additive:
// order-independent), then composite: frame * T, then + SmokeColor (1 - T)
// if the smoke is not black. GL state is restored on return.
void vtkPlumeSheetMapper::Internals::Draw(
  vtkPlumeSheetMapper* self, const Frame& frame, vtkShaderProgram* program)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* state = renWin->GetState();
  const int vpX = frame.Viewport[0], vpY = frame.Viewport[1];
  const int vpWidth = frame.Viewport[2], vpHeight = frame.Viewport[3];
  vtkTextureObject* depthTexture = frame.DepthTexture;
  if (depthTexture)
  {
    depthTexture->Activate();
  }

  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglClearColor clearSaver(state);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);

  // ---- accumulate
  state->PushFramebufferBindings();
  this->FBO->SetContext(renWin);
  this->FBO->Bind();
  this->FBO->AddColorAttachment(0, this->AccumTexture);
  this->FBO->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, vpWidth, vpHeight);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  if (depthTexture)
  {
    program->SetUniformi("OpaqueDepth", depthTexture->GetTextureUnit());
  }
  this->VAO->Bind();
  if (this->VAOProgram != program || this->BufferChanged)
  {
    this->VAO->ShaderProgramChanged();
    this->VAO->Bind();
    const int stride = 8 * sizeof(float);
    bool ok = this->VAO->AddAttributeArray(
      program, this->Buffer, "sheetPosition", 0, stride, VTK_FLOAT, 3, false);
    ok = this->VAO->AddAttributeArray(program, this->Buffer, "sheetDensity", 3 * sizeof(float),
           stride, VTK_FLOAT, 3, false) && ok;
    ok = this->VAO->AddAttributeArray(program, this->Buffer, "sheetSigma", 6 * sizeof(float),
           stride, VTK_FLOAT, 2, false) && ok;
    if (!ok)
    {
      vtkErrorWithObjectMacro(self, << "could not bind the sheet vertex attributes");
    }
    this->VAOProgram = program;
    this->BufferChanged = false;
  }
  // chunked draws keep at most two draws queued in the driver (vtkPlumeThrottledDraw.h)
  self->LastDrawCount = plume::DrawArraysThrottled(
    GL_TRIANGLES, 3, this->VertexCount / 3, self->MaximumTrianglesPerDraw, 2);
  this->VAO->Release();
  this->FBO->RemoveColorAttachment(0);
  state->PopFramebufferBindings();
  if (depthTexture)
  {
    depthTexture->Deactivate();
  }

  // ---- composite
  state->vtkglViewport(vpX, vpY, vpWidth, vpHeight);
  const bool add = self->SmokeColor[0] > 0 || self->SmokeColor[1] > 0 || self->SmokeColor[2] > 0;
  this->AccumTexture->Activate();
  for (int pass = 0; pass < (add ? 2 : 1); ++pass)
  {
    vtkPlumeShaderFeatures compositing;
    compositing.Enable(pass == 0 ? "MULTIPLY" : "ADD");
    vtkShaderProgram* composite = this->Programs->Ready(
      renWin, vtkPlumeSheetCompositeVS, nullptr, vtkPlumeSheetCompositeFS, compositing);
    if (!composite)
    {
      vtkErrorWithObjectMacro(self, << "could not build the sheet composite program");
      break;
    }
    composite->SetUniformi("OpticalDepth", this->AccumTexture->GetTextureUnit());
    const float origin[2] = { float(vpX), float(vpY) };
    composite->SetUniform2f("ViewportOrigin", origin);
    if (pass == 0)
    {
      state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    else
    {
      const float color[3] = { float(self->SmokeColor[0]), float(self->SmokeColor[1]),
        float(self->SmokeColor[2]) };
      composite->SetUniform3f("SmokeColor", color);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    }
    this->EmptyVAO->Bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    this->EmptyVAO->Release();
  }
  this->AccumTexture->Deactivate();
}

//------------------------------------------------------------------------------
// Grid mode, step 1: the density grid, recomputed only when the mesh, its
// arrays or the density/sigma settings change (camera moves compute nothing).
// False when there is nothing to draw.
bool vtkPlumeSheetMapper::Internals::UpdateGrid(vtkPlumeSheetMapper* self, Frame& frame)
{
  vtkPolyData* poly = frame.Mesh;
  const GridSignature sig{ poly, poly->GetMTime(), self->DensityArrayName, self->BlurArrayName,
    self->ThicknessArrayName,
    { self->Density, self->DensityScale, self->BlurRadius, self->Thickness, self->ThinSheet ? 1.0 : 0.0,
      self->Cutoff, self->GridSamplesPerSigma, self->GridMaximumNodes, self->GridMergeCellSize } };
  if (!this->HaveGrid || sig != this->GridFrom)
  {
    this->HaveGrid = false;
    std::string invalid = vtkPlumeInputValidation::CheckCells(poly);
    if (invalid.empty())
    {
      invalid = vtkPlumeInputValidation::CheckArrays(poly);
    }
    if (!invalid.empty())
    {
      vtkErrorWithObjectMacro(self, << "invalid input mesh, not drawn: " << invalid);
      return false;
    }
    if (!self->AbsorptionArrayName.empty() && !this->WarnedAbsorption)
    {
      vtkWarningWithObjectMacro(self, << "the grid mode draws grey smoke: absorption array '"
                                      << self->AbsorptionArrayName
                                      << "' ignored (use the exact mode for coloured absorption)");
      this->WarnedAbsorption = true;
    }
    vtkPlumeSheetDensityGrid* grid = this->Grid;
    self->ConfigureGrid(grid, poly);
    if (!grid->Compute())
    {
      return false;
    }
    ++self->GridComputeCount;
    self->GridSpacing = grid->GetOutput()->GetSpacing()[0];
    self->GridComputeSeconds = grid->GetComputeSeconds();
    double range[2];
    grid->GetOutput()->GetPointData()->GetScalars()->GetRange(range);
    this->GridMaxDensity = std::isfinite(range[1]) ? range[1] : 0.0;
    this->GridMapper->SetInputData(grid->GetOutput());
    this->GridFrom = sig;
    this->HaveGrid = true;
  }
  return this->GridMaxDensity > 0.0; // else no smoke anywhere
}

//------------------------------------------------------------------------------
// Grid mode, step 2: the transfer functions and the internal volume mapper's
// settings, then its raycast.
void vtkPlumeSheetMapper::Internals::DrawGrid(vtkPlumeSheetMapper* self, const Frame& frame)
{
  vtkActor* actor = frame.Actor;
  // extinction per world unit = density / the actor's length scale (the grid
  // is in model units; the density stays per unit of world area, as in the
  // exact mode): alpha(s) = 1 - exp(-s c u) tabulated with u chosen so the
  // largest alpha is 1 - 1/e (the volume mapper takes -ln(1 - alpha) / u back)
  double modelScale = 1.0;
  if (!actor->GetIsIdentity())
  {
    double m3[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        m3[r][c] = actor->GetMatrix()->GetElement(r, c);
      }
    }
    modelScale = std::cbrt(std::fabs(vtkMath::Determinant3x3(m3)));
  }
  const double c = 1.0 / std::max(modelScale, 1e-300);
  const double top = this->GridMaxDensity;
  const double unit = 1.0 / (top * c);
  this->GridOpacity->RemoveAllPoints();
  const int points = 256;
  for (int i = 0; i <= points; ++i)
  {
    const double s = top * i / points;
    this->GridOpacity->AddPoint(s, 1.0 - std::exp(-s * c * unit));
  }
  this->GridColor->RemoveAllPoints();
  this->GridColor->AddRGBPoint(0.0, self->SmokeColor[0], self->SmokeColor[1], self->SmokeColor[2]);
  this->GridColor->AddRGBPoint(top, self->SmokeColor[0], self->SmokeColor[1], self->SmokeColor[2]);
  this->GridProperty->SetScalarOpacity(this->GridOpacity);
  this->GridProperty->SetColor(this->GridColor);
  this->GridProperty->SetScalarOpacityUnitDistance(unit);
  // also on the mapper, whose own value wins over any property's
  this->GridMapper->SetOpacityUnitDistance(unit);
  this->GridProperty->SetInterpolationTypeToLinear();
  this->GridProperty->ShadeOff();
  this->GridVolume->SetProperty(this->GridProperty);
  this->GridVolume->SetMapper(this->GridMapper);
  this->GridVolume->SetUserMatrix(actor->GetIsIdentity() ? nullptr : actor->GetMatrix());
  // coarse while the camera moves, refined when it stops (see AutoAdjustQuality):
  // the internal volume gets the actor's time budget, so its own lattice
  // choice follows the same rule
  const bool interactive = self->AutoAdjustQuality && actor->GetAllocatedRenderTime() < 1.0;
  this->GridVolume->SetAllocatedRenderTime(actor->GetAllocatedRenderTime(), frame.Renderer);
  this->GridMapper->SetAutoAdjustSampleDistances(self->AutoAdjustQuality);
  this->GridMapper->SetImageSampleDistance(1);
  this->GridMapper->SetInteractiveImageSampleDistance(self->InteractiveImageSampleDistance);
  this->GridMapper->SetLatticeTolerance(self->InteractiveLatticeTolerance); // (still frames: one ray per pixel)
  self->LastInteractive = interactive;
  self->LastGridSampleDistance =
    interactive ? self->InteractiveGridSampleDistance : self->GridSampleDistance;
  this->GridMapper->SetSampleDistance(self->LastGridSampleDistance);
  // a still frame yields to input the application reports as waiting (VTK's
  // AbortCheckEvent, as vtkFixedPointVolumeRayCastMapper does): an aborted
  // frame is not shown, so the last interactive frame stays and the user
  // keeps moving the camera without waiting for the refinement
  if (!interactive && frame.Window->CheckAbortStatus())
  {
    ++self->AbortedStillFrames;
    return;
  }
  // no other depth writer: the far plane everywhere, nothing to read (the
  // copy and the lattice's per-pixel depth checks cost more than its rays)
  self->LastOpaqueDepth =
    self->BoundedByDepth && vtkPlumeCompositingPass::HasOtherDepthWriters(frame.Renderer, actor);
  this->GridMapper->SetUseOpaqueDepth(self->LastOpaqueDepth);
  this->GridMapper->SetTerminationError(0.001); // unlit: rays stop at opacity 0.999
  this->GridMapper->SetEmptySpaceSkipping(true);
  this->GridMapper->SetJitter(true);
  this->GridMapper->Render(frame.Renderer, this->GridVolume);
  self->LastImageSampleDistance = this->GridMapper->GetLastImageSampleDistance();
}
//------------------------------------------------------------------------------
void vtkPlumeSheetMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPlumeSheetMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityArrayName: " << this->DensityArrayName << "\n";
  os << indent << "Density: " << this->Density << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "BlurArrayName: " << this->BlurArrayName << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "ThicknessArrayName: " << this->ThicknessArrayName << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "AbsorptionArrayName: " << this->AbsorptionArrayName << "\n";
  os << indent << "SmokeColor: " << this->SmokeColor[0] << " " << this->SmokeColor[1] << " "
     << this->SmokeColor[2] << "\n";
  os << indent << "ThinSheet: " << this->ThinSheet << "\n";
  os << indent << "BoundedByDepth: " << this->BoundedByDepth << "\n";
  os << indent << "Cutoff: " << this->Cutoff << "\n";
  os << indent << "MinimumSigmaPixels: " << this->MinimumSigmaPixels << "\n";
  os << indent << "GridA: " << this->GridA << "\n";
  os << indent << "GridB: " << this->GridB << "\n";
  os << indent << "Quadrature: " << this->Quadrature << "\n";
  os << indent << "AdaptiveSampling: " << this->AdaptiveSampling << "\n";
  os << indent << "MaximumTrianglesPerDraw: " << this->MaximumTrianglesPerDraw << "\n";
  os << indent << "RenderMode: " << this->RenderMode << "\n";
  os << indent << "GridSamplesPerSigma: " << this->GridSamplesPerSigma << "\n";
  os << indent << "GridSampleDistance: " << this->GridSampleDistance << "\n";
  os << indent << "GridMaximumNodes: " << this->GridMaximumNodes << "\n";
  os << indent << "GridMergeCellSize: " << this->GridMergeCellSize << "\n";
  os << indent << "AutoAdjustQuality: " << this->AutoAdjustQuality << "\n";
  os << indent << "InteractiveGridSampleDistance: " << this->InteractiveGridSampleDistance << "\n";
  os << indent << "InteractiveImageSampleDistance: " << this->InteractiveImageSampleDistance << "\n";
  os << indent << "InteractiveLatticeTolerance: " << this->InteractiveLatticeTolerance << "\n";
  os << indent << "UploadCount: " << this->UploadCount << "\n";
  os << indent << "TriangleCount: " << this->TriangleCount << "\n";
}

//------------------------------------------------------------------------------
void vtkPlumeSheetMapper::ConfigureGrid(vtkPlumeSheetDensityGrid* grid, vtkPolyData* poly)
{
  grid->SetInputData(poly);
  grid->SetDensityArrayName(this->DensityArrayName.c_str());
  grid->SetDensity(this->Density);
  grid->SetDensityScale(this->DensityScale);
  grid->SetBlurArrayName(this->BlurArrayName.c_str());
  grid->SetBlurRadius(this->BlurRadius);
  grid->SetThicknessArrayName(this->ThicknessArrayName.c_str());
  grid->SetThickness(this->Thickness);
  grid->SetThinSheet(this->ThinSheet);
  grid->SetCutoff(this->Cutoff);
  grid->SetSamplesPerSigma(this->GridSamplesPerSigma);
  grid->SetMaximumNodes(this->GridMaximumNodes);
  grid->SetMergeCellSize(this->GridMergeCellSize);
}

//------------------------------------------------------------------------------
std::string vtkPlumeSheetMapper::CheckBudget(vtkPolyData* mesh)
{
  if (!mesh)
  {
    return std::string();
  }
  if (this->RenderMode == RENDER_GRID)
  {
    vtkNew<vtkPlumeSheetDensityGrid> grid;
    this->ConfigureGrid(grid, mesh);
    return grid->CheckBudget();
  }
  return ExactBudget(mesh);
}
