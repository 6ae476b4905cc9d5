#include "vtkPlumeVelocityGlyphMapper.h"

#include "vtkPlumeCompositingPass.h"
#include "vtkPlumeInputValidation.h"

#include "vtkPlumeGLMatrix.h"
#include "vtkPlumeImageFrame.h"
#include "vtkPlumeLookupTexture.h"
#include "vtkPlumeParameterTable.h"
#include "vtkPlumePercentile.h"
#include "vtkPlumeShaderFeatures.h"
#include "vtkPlumeShaderProgramCache.h"
#include "vtkPlumeShaderVariants.h"
#include "vtkPlumeVectorTexture3D.h"
#include "vtkPlumeThrottledDraw.h"

#include "vtkPlumeGlyphFS.h"
#include "vtkPlumeGlyphGS.h"
#include "vtkPlumeGlyphLineVS.h"
#include "vtkPlumeGlyphVS.h"
#include "vtkPlumeWindowChange.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace
{
// Offset of glyphs towards the viewer in NDC z: 1/8192 in NDC is 6.1e-5 in
// window depth, the size of VTK's own offset for coincident lines (4 × 1.6e-5).
constexpr double CoincidentDepthOffset = 1.0 / 8192.0;

void Apply(const double m[16], const double p[3], double out[4])
{
  for (int r = 0; r < 4; ++r)
  {
    out[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  }
}

} // namespace

//------------------------------------------------------------------------------
class vtkPlumeVelocityGlyphMapper::Internals
{
public:
  // What the CPU statistics were built from.
  struct Signature
  {
    vtkImageData* Image = nullptr;
    vtkDataArray* Vectors = nullptr;
    vtkDataArray* Mask = nullptr;
    vtkMTimeType Time = 0;
    bool operator==(const Signature& o) const
    {
      return this->Image == o.Image && this->Vectors == o.Vectors && this->Mask == o.Mask &&
        this->Time == o.Time;
    }
    bool operator!=(const Signature& o) const { return !(*this == o); }
  };

  // What one Render() works out and its steps pass on.
  struct Frame
  {
    vtkRenderer* Renderer = nullptr;
    vtkActor* Actor = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkImageData* Image = nullptr;
    int Dims[3] = { 0, 0, 0 };
    // index space -> centre-relative model -> clip, composed in double
    double Centre[4] = { 0, 0, 0, 1 };
    double IndexToRel[16];
    double RelToIndex[16];
    double MCDCRel[16];
    int Viewport[2] = { 0, 0 };
    // roots
    bool SeedMode = false;
    int Stride = 1;
    int LatticeOffset[3] = { 0, 0, 0 }; // first root's node (whole-grid lattice)
    int StridedDims[3] = { 0, 0, 0 };
    vtkIdType RootCount = 0;
    // colour
    bool UseLUT = false;
    double ColorRange[2] = { 0, 0 };
    // shader variant
    int Segments = 1;
    std::string Integrator = "STRAIGHT";
    bool Wide = false;
    bool LineVS = false;
    bool Opaque = true;
    std::vector<vtkOpenGLRenderPass*> Passes; // VTK's translucent pass, when it draws us
  };

  // Speed statistics of the valid nodes (SpeedRange, component ranges), one
  // slab at a time in the velocity texture's own layout.
  void BuildStatistics(vtkImageData* image, vtkDataArray* vectors, vtkDataArray* mask)
  {
    const vtkIdType n = image->GetNumberOfPoints();
    const vtkIdType slabPoints = vtkPlumeVectorTexture3D::SlabPoints;
    std::vector<float> slab(4 * static_cast<size_t>(std::min(n, slabPoints)));
    double range[2] = { VTK_DOUBLE_MAX, -1.0 };
    double low[3] = { 0, 0, 0 }, high[3] = { 0, 0, 0 };
    for (vtkIdType begin = 0; begin < n; begin += slabPoints)
    {
      const vtkIdType end = std::min(n, begin + slabPoints);
      vtkPlumeVectorTexture3D::ConvertSlab(vectors, mask, begin, end, slab.data());
      for (vtkIdType i = 0; i < end - begin; ++i)
      {
        const float* v = &slab[4 * static_cast<size_t>(i)];
        if (!(v[3] > 0.f))
        {
          continue; // invalid: non-finite or masked
        }
        const double s = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
        range[0] = std::min(range[0], s);
        range[1] = std::max(range[1], s);
        for (int a = 0; a < 3; ++a)
        {
          low[a] = std::min(low[a], double(v[a]));
          high[a] = std::max(high[a], double(v[a]));
        }
      }
    }
    const bool any = range[1] >= 0.0;
    this->SpeedRange[0] = any ? range[0] : 0.0;
    this->SpeedRange[1] = any ? range[1] : 0.0;
    std::copy(low, low + 3, this->ComponentLow);
    std::copy(high, high + 3, this->ComponentHigh);
  }

  // Speeds of the valid nodes (finite, not masked) whose grid index lies in
  // `extent` (nullptr: every node), one slab at a time.
  static void CollectSpeeds(vtkImageData* image, vtkDataArray* vectors, vtkDataArray* mask,
    const int* extent, std::vector<float>& speeds)
  {
    const vtkIdType n = image->GetNumberOfPoints();
    const vtkIdType slabPoints = vtkPlumeVectorTexture3D::SlabPoints;
    int dims[3];
    image->GetDimensions(dims);
    const int* own = image->GetExtent();
    std::vector<float> slab(4 * static_cast<size_t>(std::min(n, slabPoints)));
    for (vtkIdType begin = 0; begin < n; begin += slabPoints)
    {
      const vtkIdType end = std::min(n, begin + slabPoints);
      vtkPlumeVectorTexture3D::ConvertSlab(vectors, mask, begin, end, slab.data());
      for (vtkIdType i = 0; i < end - begin; ++i)
      {
        const float* v = &slab[4 * static_cast<size_t>(i)];
        if (!(v[3] > 0.f)) // invalid: non-finite or masked
        {
          continue;
        }
        if (extent)
        {
          const vtkIdType id = begin + i;
          const int node[3] = { own[0] + int(id % dims[0]), own[2] + int((id / dims[0]) % dims[1]),
            own[4] + int(id / (vtkIdType(dims[0]) * dims[1])) };
          if (node[0] < extent[0] || node[0] > extent[1] || node[1] < extent[2] ||
            node[1] > extent[3] || node[2] < extent[4] || node[2] > extent[5])
          {
            continue;
          }
        }
        speeds.push_back(
          static_cast<float>(std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2])));
      }
    }
  }

  // The valid speeds of a piece's nodes within `extent` (nullptr: all), with
  // the mapper's arrays; none without usable arrays (defined below).
  static std::vector<float> PieceSpeeds(vtkPlumeVelocityGlyphMapper* self, vtkImageData* image, const int* extent);

  // The pieces' speeds faster than StillFraction x `speed`, summed over the
  // pieces by `sum` (collective when given; defined below).
  static vtkIdType CountMoving(const std::vector<float>& speeds, double speed, const vtkPlumePercentile::Sum& sum);

  // The robust maximum (RobustSpeed) and the moving nodes of the whole input.
  void BuildRobustSpeed(vtkImageData* image, vtkDataArray* vectors, vtkDataArray* mask)
  {
    std::vector<float> speeds;
    CollectSpeeds(image, vectors, mask, nullptr, speeds);
    this->RobustSpeed = 0.0;
    this->MovingNodes = 0;
    if (!speeds.empty())
    {
      this->RobustSpeed = vtkPlumePercentile::Select(speeds, RobustPercentile);
      this->MovingNodes = CountMoving(speeds, this->RobustSpeed, nullptr);
    }
  }

  // The render steps, in order (Render() calls them).
  bool UpdateResources(vtkPlumeVelocityGlyphMapper* self, Frame& frame, vtkDataArray* vectors,
    vtkDataArray* mask);
  bool ComputeFrame(vtkPlumeVelocityGlyphMapper* self, Frame& frame);
  bool UpdateRoots(vtkPlumeVelocityGlyphMapper* self, Frame& frame);
  bool UpdateColors(vtkPlumeVelocityGlyphMapper* self, Frame& frame);
  vtkShaderProgram* ReadyProgram(vtkPlumeVelocityGlyphMapper* self, Frame& frame);
  void SetUniforms(vtkPlumeVelocityGlyphMapper* self, const Frame& frame, vtkShaderProgram* program);
  void Draw(vtkPlumeVelocityGlyphMapper* self, const Frame& frame, vtkShaderProgram* program);

  // GL objects
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkPlumeVectorTexture3D> Velocity;
  vtkNew<vtkPlumeLookupTexture> LUTTexture;
  vtkNew<vtkOpenGLVertexArrayObject> EmptyVAO;
  vtkNew<vtkOpenGLVertexArrayObject> SeedVAO;
  vtkNew<vtkOpenGLBufferObject> SeedBuffer;
  vtkNew<vtkPlumeShaderProgramCache> Programs;
  vtkShaderProgram* SeedVAOProgram = nullptr;

  // CPU-side bookkeeping
  Signature StatsSignature; // SpeedRange content
  Signature RobustSignature; // RobustSpeed content
  double RobustSpeed = 0.0;
  // the quantile of the valid speeds that is the robust maximum
  static constexpr double RobustPercentile = 0.99;
  // Valid nodes faster than StillFraction x RobustSpeed: the ones the
  // screen-adaptive stride spreads its glyph budget over. Below 5 % a glyph
  // is under a tenth of a cell long at the automatic scale; in carotid.vtk
  // that splits the still air around the vessels (|v| < 0.06, 97 % of the
  // nodes) from the blood (|v| > 0.3, robust maximum 5.9).
  static constexpr double StillFraction = 0.05;
  vtkIdType MovingNodes = 0;
  double SpeedRange[2] = { 0, 0 };
  // Per-axis range of the valid vectors, widened to include 0 (for bounds).
  double ComponentLow[3] = { 0, 0, 0 };
  double ComponentHigh[3] = { 0, 0, 0 };
  bool LUTOpaque = true; // every entry of the uploaded table has alpha 255
  static constexpr int LUTSize = 256;
  vtkMTimeType SeedTime = 0;
  vtkDataSet* SeedObject = nullptr;
  double SeedCentre[3] = { 0, 0, 0 };
  vtkIdType SeedCount = 0;
  bool SeedUploadChanged = false;

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Velocity->ReleaseGraphicsResources(window);
    this->LUTTexture->ReleaseGraphicsResources(window);
    this->EmptyVAO->ReleaseGraphicsResources();
    this->SeedVAO->ReleaseGraphicsResources();
    this->SeedBuffer->ReleaseGraphicsResources();
    this->Programs->ReleaseGraphicsResources(window);
    this->SeedVAOProgram = nullptr;
    this->SeedTime = 0;
    this->SeedObject = nullptr;
    this->Window = nullptr;
  }
};
//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkPlumeVelocityGlyphMapper);

vtkPlumeVelocityGlyphMapper::vtkPlumeVelocityGlyphMapper()
  : Impl(new Internals)
{
  this->SetNumberOfInputPorts(2);
  // after the opaque scene, before the media read its depth
  vtkPlumeCompositingPass::SetStage(this, vtkPlumeCompositingPass::STAGE_SURFACES);
  GetParameterTable().ApplyDefaults(this);
}

const vtkPlumeParameterTable& vtkPlumeVelocityGlyphMapper::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = vtkPlumeVelocityGlyphMapper;
    vtkPlumeParameterTable t("vtkPlumeVelocityGlyphMapper", "glyphs");
    t.Text("vectors", "VectorArrayName", "")
      .Doc("3-component point array to draw; empty: the active vectors.")
      .Bind(&T::SetVectorArrayName, &T::GetVectorArrayName);
    t.Text("mask", "ValidMaskArrayName", "vtkValidPointMask")
      .Advanced()
      .Doc("Point array whose zeros mark nodes without glyphs (ignored if absent).")
      .Bind(&T::SetValidMaskArrayName, &T::GetValidMaskArrayName);
    t.Choice("roots", "RootMode", "screen")
      .Choice("screen", ROOTS_SCREEN_ADAPTIVE,
        "a lattice thinned to about one glyph per `screen_spacing` squared pixels, recomputed as the camera "
        "moves.")
      .Choice("lattice", ROOTS_LATTICE, "every `stride`-th node.")
      .Choice("seeds", ROOTS_SEEDS, "the points of `seed_plane` or `seed_dataset`.")
      .Panel("Roots")
      .Doc("Where glyphs start.")
      .Bind(&T::SetRootMode, &T::GetRootMode);
    t.Integer("stride", "LatticeStride", 1)
      .OnlyWith("roots", { "lattice" })
      .Between(1, 1 << 20)
      .Panel("Roots")
      .Doc("Lattice stride in grid nodes (roots `lattice`).")
      .Bind(&T::SetLatticeStride, &T::GetLatticeStride);
    t.Real("screen_spacing", "ScreenSpacing", 12.0)
      .OnlyWith("roots", { "screen" })
      .Between(1.0, 1e6)
      .Units("pixels")
      .Panel("Roots")
      .Doc("Target distance between glyphs (roots `screen`).")
      .Bind(&T::SetScreenSpacing, &T::GetScreenSpacing);
    t.Real("scale", "Scale", 1.0)
      .OnlyWith("scale_mode", { "fixed" })
      .Between(-1e30, 1e30)
      .Units("world units per unit speed")
      .Doc("Glyph length per unit of velocity (scale_mode `fixed`).")
      .Bind(&T::SetScale, &T::GetScale);
    t.Choice("scale_mode", "ScaleMode", "auto")
      .Choice("fixed", SCALE_FIXED, "glyphs are `scale` x speed long.")
      .Choice("auto", SCALE_AUTO,
        "the scale that makes a glyph at the robust maximum speed (99th percentile of the valid nodes) "
        "about two root spacings long: 2 grid cells x the effective stride (`stride` for lattice roots; "
        "for screen roots the stride of each frame, so glyphs keep their length on screen as the camera "
        "zooms; 1 for seeds).")
      .Doc("How the glyph scale is chosen (a scene that gives `scale` alone means `fixed`).")
      .Bind(&T::SetScaleMode, &T::GetScaleMode);
    t.Choice("integrator", "Integrator", "straight")
      .Choice("straight", STRAIGHT, "one straight segment p to p + scale v(p) (seed 002).")
      .Choice("rk2", RK2, "a streamlet following the flow, midpoint rule.")
      .Choice("rk4", RK4, "a streamlet following the flow, classical Runge-Kutta.")
      .Doc("Shape of each glyph.")
      .Bind(&T::SetIntegrator, &T::GetIntegrator);
    t.Integer("segments", "StreamletSegments", 8)
      .OnlyWith("integrator", { "rk2", "rk4" })
      .Between(1, 32)
      .Doc("Segments per streamlet (rk2, rk4).")
      .Bind(&T::SetStreamletSegments, &T::GetStreamletSegments);
    t.Real("min_speed", "MinimumSpeed", 0.0)
      .Between(0.0, 1e30)
      .Doc("Roots with a speed at or below this draw nothing.")
      .Bind(&T::SetMinimumSpeed, &T::GetMinimumSpeed);
    t.Real("root_alpha", "RootAlpha", 0.0)
      .Between(0.0, 1.0)
      .Doc("Opacity at the root; the tip is opaque (seed 002's fade-in).")
      .Bind(&T::SetRootAlpha, &T::GetRootAlpha);
    t.Real("line_width", "LineWidth", 1.0)
      .Between(0.5, 64.0)
      .Units("pixels")
      .Doc("Line width.")
      .Bind(&T::SetLineWidth, &T::GetLineWidth);
    t.Choice("straight_line_shader", "StraightLineShader", "vertex")
      .Choice("vertex", VERTEX_SHADER, "GL_LINES from gl_VertexID.")
      .Choice("geometry", GEOMETRY_SHADER, "points expanded by a geometry shader.")
      .Advanced()
      .Doc("Shader path of straight 1-pixel lattice glyphs (same image).")
      .Bind(&T::SetStraightLineShader, &T::GetStraightLineShader);
    t.Integer("maximum_glyphs_per_draw", "MaximumGlyphsPerDraw", 262144)
      .Between(0, 1e15)
      .Advanced()
      .Doc("Largest draw call; more roots are drawn two draws in flight at a time, which bounds the "
           "driver's memory (0: one draw).")
      .Bind(&T::SetMaximumGlyphsPerDraw, &T::GetMaximumGlyphsPerDraw);
    return t;
  }();
  return table;
}

vtkPlumeVelocityGlyphMapper::~vtkPlumeVelocityGlyphMapper() = default;

int vtkPlumeVelocityGlyphMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

void vtkPlumeVelocityGlyphMapper::SetInputData(vtkImageData* input)
{
  this->SetInputDataInternal(0, input);
}

vtkImageData* vtkPlumeVelocityGlyphMapper::GetInput()
{
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    return nullptr;
  }
  return vtkImageData::SafeDownCast(this->GetExecutive()->GetInputData(0, 0));
}

void vtkPlumeVelocityGlyphMapper::SetSeedData(vtkDataSet* seeds)
{
  this->SetInputDataInternal(1, seeds);
}

void vtkPlumeVelocityGlyphMapper::SetSeedConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkPlumeVelocityGlyphMapper::UpdateInputs()
{
  if (this->Static)
  {
    return;
  }
  for (int port = 0; port < 2; ++port)
  {
    if (this->GetNumberOfInputConnections(port) > 0)
    {
      int algPort = 0;
      vtkAlgorithm* alg = this->GetInputAlgorithm(port, 0, algPort);
      if (alg)
      {
        alg->Update(algPort);
      }
    }
  }
}

namespace
{
vtkDataSet* SeedInput(vtkPlumeVelocityGlyphMapper* self)
{
  if (self->GetNumberOfInputConnections(1) < 1)
  {
    return nullptr;
  }
  return vtkDataSet::SafeDownCast(self->GetExecutive()->GetInputData(1, 0));
}

// Resolve the vector and mask arrays; reports errors through `self` when `report`.
bool ResolveArrays(vtkPlumeVelocityGlyphMapper* self, vtkImageData* image,
  const std::string& vectorName, const std::string& maskName, vtkDataArray*& vectors,
  vtkDataArray*& mask, std::string& error)
{
  vtkPointData* pd = image->GetPointData();
  vectors = vectorName.empty() ? pd->GetVectors() : pd->GetArray(vectorName.c_str());
  mask = maskName.empty() ? nullptr : pd->GetArray(maskName.c_str());
  std::ostringstream msg;
  if (!vectors)
  {
    if (vectorName.empty())
    {
      msg << "the input image has no active vectors; set VectorArrayName to a 3-component point "
             "array";
    }
    else
    {
      msg << "the input image has no point array named '" << vectorName << "'";
    }
  }
  else if (vectors->GetNumberOfComponents() != 3)
  {
    msg << "point array '" << (vectors->GetName() ? vectors->GetName() : "(unnamed)") << "' has "
        << vectors->GetNumberOfComponents() << " components; 3 are required";
  }
  else if (vectors->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    msg << "point array '" << (vectors->GetName() ? vectors->GetName() : "(unnamed)") << "' has "
        << vectors->GetNumberOfTuples() << " tuples for " << image->GetNumberOfPoints()
        << " points";
  }
  if (mask && mask->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    mask = nullptr; // not a usable mask: ignore it
  }
  (void)self;
  error = msg.str();
  return error.empty();
}
} // namespace

//------------------------------------------------------------------------------
double* vtkPlumeVelocityGlyphMapper::GetBounds()
{
  vtkMath::UninitializeBounds(this->Bounds);
  this->UpdateInputs();
  vtkImageData* image = this->GetInput();
  if (!image || image->GetNumberOfPoints() < 1)
  {
    return this->Bounds;
  }
  image->GetBounds(this->Bounds);
  if (this->RootMode == ROOTS_SEEDS)
  {
    vtkDataSet* seeds = SeedInput(this);
    if (seeds && seeds->GetNumberOfPoints() > 0)
    {
      const double* sb = seeds->GetBounds();
      for (int a = 0; a < 3; ++a)
      {
        this->Bounds[2 * a] = std::min(this->Bounds[2 * a], sb[2 * a]);
        this->Bounds[2 * a + 1] = std::max(this->Bounds[2 * a + 1], sb[2 * a + 1]);
      }
    }
  }
  // pad by how far glyphs can reach along each axis
  vtkDataArray* vectors = nullptr;
  vtkDataArray* mask = nullptr;
  std::string error;
  if (ResolveArrays(this, image, this->VectorArrayName, this->ValidMaskArrayName, vectors, mask,
        error))
  {
    Internals::Signature sig{ image, vectors, mask,
      std::max({ image->GetMTime(), vectors->GetMTime(), mask ? mask->GetMTime() : 0 }) };
    if (sig != this->Impl->StatsSignature)
    {
      this->Impl->BuildStatistics(image, vectors, mask);
      this->Impl->StatsSignature = sig;
    }
    // A glyph's displacement along each axis is Scale times a convex
    // combination of sampled vectors (straight lines, RK2 and RK4 steps alike,
    // with trilinear sampling), so it lies within Scale x that axis's range.
    // Screen-adaptive roots: the scale at stride 1, not the last render's
    // stride, so that the bounds (and the clipping range VTK derives from
    // them) do not depend on earlier frames: a render and a still frame of
    // an interactive view at the same camera are the same image.
    const double scale = this->ScaleMode == SCALE_AUTO && this->RootMode == ROOTS_SCREEN_ADAPTIVE
      ? this->GetAutomaticScale(1)
      : this->GetEffectiveScale();
    const double* ib = image->GetBounds();
    const double diagonal =
      std::sqrt((ib[1] - ib[0]) * (ib[1] - ib[0]) + (ib[3] - ib[2]) * (ib[3] - ib[2]) +
        (ib[5] - ib[4]) * (ib[5] - ib[4]));
    for (int a = 0; a < 3; ++a)
    {
      double lo = scale * this->Impl->ComponentLow[a];
      double hi = scale * this->Impl->ComponentHigh[a];
      if (lo > hi)
      {
        std::swap(lo, hi); // negative Scale
      }
      // absurd vectors (e.g. 1e30) must not wreck the automatic clipping
      // range: cap the padding at 10 data diagonals
      const double cap = diagonal > 0 ? 10.0 * diagonal : VTK_DOUBLE_MAX;
      lo = std::isfinite(lo) ? std::max(lo, -cap) : 0.0;
      hi = std::isfinite(hi) ? std::min(hi, cap) : 0.0;
      this->Bounds[2 * a] += std::min(lo, 0.0);
      this->Bounds[2 * a + 1] += std::max(hi, 0.0);
    }
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
double vtkPlumeVelocityGlyphMapper::GetRobustMaximumSpeed()
{
  this->UpdateInputs();
  vtkImageData* image = this->GetInput();
  vtkDataArray* vectors = nullptr;
  vtkDataArray* mask = nullptr;
  std::string error;
  if (!image || image->GetNumberOfPoints() < 1 ||
    !ResolveArrays(this, image, this->VectorArrayName, this->ValidMaskArrayName, vectors, mask, error))
  {
    return 0.0;
  }
  Internals::Signature sig{ image, vectors, mask,
    std::max({ image->GetMTime(), vectors->GetMTime(), mask ? mask->GetMTime() : 0 }) };
  if (sig != this->Impl->RobustSignature)
  {
    this->Impl->BuildRobustSpeed(image, vectors, mask);
    this->Impl->RobustSignature = sig;
  }
  return this->Impl->RobustSpeed;
}

//------------------------------------------------------------------------------
std::vector<float> vtkPlumeVelocityGlyphMapper::Internals::PieceSpeeds(
  vtkPlumeVelocityGlyphMapper* self, vtkImageData* image, const int* extent)
{
  std::vector<float> speeds;
  vtkDataArray* vectors = nullptr;
  vtkDataArray* mask = nullptr;
  std::string error;
  if (image && image->GetNumberOfPoints() > 0 &&
    ResolveArrays(self, image, self->VectorArrayName, self->ValidMaskArrayName, vectors, mask, error))
  {
    CollectSpeeds(image, vectors, mask, extent, speeds);
  }
  return speeds;
}

//------------------------------------------------------------------------------
vtkIdType vtkPlumeVelocityGlyphMapper::Internals::CountMoving(
  const std::vector<float>& speeds, double speed, const vtkPlumePercentile::Sum& sum)
{
  const double still = StillFraction * speed;
  std::vector<vtkIdType> count{ static_cast<vtkIdType>(
    std::count_if(speeds.begin(), speeds.end(), [still](float s) { return s > still; })) };
  if (sum)
  {
    sum(count); // collective: every piece sums, with or without speeds
  }
  return count[0];
}

//------------------------------------------------------------------------------
double vtkPlumeVelocityGlyphMapper::ComputeRobustMaximumSpeed(vtkImageData* image,
  const int extent[6], const vtkPlumePercentile::Sum& sum, vtkIdType* movingNodes)
{
  const std::vector<float> speeds = Internals::PieceSpeeds(this, image, extent);
  // collective: every piece selects, with or without speeds
  double speed = vtkPlumePercentile::Select(speeds, Internals::RobustPercentile, sum);
  speed = std::isfinite(speed) ? speed : 0.0;
  if (movingNodes)
  {
    // from the same speeds: one pass over the piece serves both
    *movingNodes = Internals::CountMoving(speeds, speed, sum);
  }
  return speed;
}

//------------------------------------------------------------------------------
vtkIdType vtkPlumeVelocityGlyphMapper::ComputeMovingNodes(
  vtkImageData* image, const int extent[6], double speed, const vtkPlumePercentile::Sum& sum)
{
  return Internals::CountMoving(Internals::PieceSpeeds(this, image, extent), speed, sum);
}

//------------------------------------------------------------------------------
double vtkPlumeVelocityGlyphMapper::GetEffectiveScale()
{
  if (this->ScaleMode != SCALE_AUTO)
  {
    return this->Scale;
  }
  // the root spacing in nodes: the last render's for screen-adaptive roots
  const int stride = this->RootMode == ROOTS_LATTICE ? this->LatticeStride
    : this->RootMode == ROOTS_SCREEN_ADAPTIVE      ? this->EffectiveStride
                                                   : 1;
  return this->GetAutomaticScale(stride);
}

//------------------------------------------------------------------------------
double vtkPlumeVelocityGlyphMapper::GetAutomaticScale(int stride)
{
  const double speed = std::isfinite(this->AutomaticScaleSpeed) && this->AutomaticScaleSpeed > 0.0
    ? this->AutomaticScaleSpeed
    : this->GetRobustMaximumSpeed();
  vtkImageData* image = this->GetInput();
  if (!image || !(speed > 0.0) || !std::isfinite(speed))
  {
    return this->Scale;
  }
  double spacing[3];
  image->GetSpacing(spacing);
  int dims[3];
  image->GetDimensions(dims);
  double cell = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    if (dims[a] > 1)
    {
      cell = std::max(cell, std::fabs(spacing[a]));
    }
  }
  if (!(cell > 0.0))
  {
    return this->Scale;
  }
  return 2.0 * cell * std::max(1, stride) / speed;
}

//------------------------------------------------------------------------------
void vtkPlumeVelocityGlyphMapper::Render(vtkRenderer* ren, vtkActor* actor)
{
  Internals& impl = *this->Impl;
  this->LastRootCount = 0;
  if (!vtkPlumeCompositingPass::ShouldDraw(ren, this))
  {
    return; // a compositing pass draws the glyphs in its surface step
  }

  this->UpdateInputs();
  vtkImageData* image = this->GetInput();
  if (!image)
  {
    vtkErrorMacro(<< "no input image");
    return;
  }
  Internals::Frame frame;
  frame.Renderer = ren;
  frame.Actor = actor;
  frame.Image = image;
  image->GetDimensions(frame.Dims);
  if (frame.Dims[0] < 1 || frame.Dims[1] < 1 || frame.Dims[2] < 1 || image->GetNumberOfPoints() < 1)
  {
    return;
  }
  // arrays shorter than the grid would be read past their end by the upload
  const std::string invalid = vtkPlumeInputValidation::CheckArrays(image);
  if (!invalid.empty())
  {
    vtkErrorMacro(<< "invalid input image, not drawn: " << invalid);
    return;
  }
  vtkDataArray* vectors = nullptr;
  vtkDataArray* mask = nullptr;
  std::string error;
  if (!ResolveArrays(
        this, image, this->VectorArrayName, this->ValidMaskArrayName, vectors, mask, error))
  {
    vtkErrorMacro(<< error);
    return;
  }
  if (ren->GetSelector())
  {
    return; // hardware selection is not supported
  }
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!frame.Window || !vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera()))
  {
    vtkErrorMacro(<< "an OpenGL render window and camera are required");
    return;
  }
  plume::ReleaseOnWindowChange(impl, frame.Window);

  if (!impl.UpdateResources(this, frame, vectors, mask) || !impl.ComputeFrame(this, frame) ||
    !impl.UpdateRoots(this, frame) || !impl.UpdateColors(this, frame))
  {
    return;
  }
  vtkShaderProgram* program = impl.ReadyProgram(this, frame);
  if (!program)
  {
    return;
  }
  impl.SetUniforms(this, frame, program);
  impl.Draw(this, frame, program);
}

//------------------------------------------------------------------------------
// Step 1: the data on the GPU (hand-over or upload, only when it changed) and
// its statistics (usually already computed by GetBounds).
bool vtkPlumeVelocityGlyphMapper::Internals::UpdateResources(
  vtkPlumeVelocityGlyphMapper* self, Frame& frame, vtkDataArray* vectors, vtkDataArray* mask)
{
  vtkImageData* image = frame.Image;
  const Signature sig{ image, vectors, mask,
    std::max({ image->GetMTime(), vectors->GetMTime(), mask ? mask->GetMTime() : 0 }) };
  if (sig != this->StatsSignature)
  {
    this->BuildStatistics(image, vectors, mask);
    this->StatsSignature = sig;
  }
  if (self->RootMode == ROOTS_SCREEN_ADAPTIVE && sig != this->RobustSignature)
  {
    this->BuildRobustSpeed(image, vectors, mask); // MovingNodes, for the stride
    this->RobustSignature = sig;
  }
  if (!this->Velocity->Update(frame.Window, image, vectors, mask))
  {
    vtkErrorWithObjectMacro(self, << this->Velocity->GetLastError());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Step 2: index space -> centre-relative model -> clip, composed in double
// (the image's direction matrix and extent start honoured, as every renderer does).
bool vtkPlumeVelocityGlyphMapper::Internals::ComputeFrame(
  vtkPlumeVelocityGlyphMapper* vtkNotUsed(self), Frame& frame)
{
  const int* dims = frame.Dims;
  double indexToModel[16];
  plume::IndexToPhysical(frame.Image, indexToModel);
  const double mid[3] = { 0.5 * (dims[0] - 1), 0.5 * (dims[1] - 1), 0.5 * (dims[2] - 1) };
  Apply(indexToModel, mid, frame.Centre);
  std::copy(indexToModel, indexToModel + 16, frame.IndexToRel);
  for (int r = 0; r < 3; ++r)
  {
    frame.IndexToRel[4 * r + 3] = indexToModel[4 * r + 3] - frame.Centre[r];
  }
  vtkMatrix4x4::Invert(frame.IndexToRel, frame.RelToIndex);

  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdcT = nullptr;
  vtkMatrix3x3* normals = nullptr;
  vtkOpenGLCamera::SafeDownCast(frame.Renderer->GetActiveCamera())
    ->GetKeyMatrices(frame.Renderer, wcvc, normals, vcdc, wcdcT); // transposed for GL
  double wcdc[16];
  vtkMatrix4x4::Transpose(wcdcT->GetData(), wcdc);
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
    relToModel[4 * r + 3] = frame.Centre[r];
  }
  double* mcdcRel = frame.MCDCRel;
  vtkMatrix4x4::Multiply4x4(modelToWorld, relToModel, mcdcRel);
  vtkMatrix4x4::Multiply4x4(wcdc, mcdcRel, mcdcRel);
  // Coincident topology, as VTK does for lines: glyphs lying in a surface
  // (2D data over a pseudocolour plot) are pulled towards the viewer by a
  // constant window-depth offset (z_ndc -= CoincidentDepthOffset·w), so they
  // win the depth test against polygons in the same plane.
  for (int c = 0; c < 4; ++c)
  {
    mcdcRel[8 + c] -= CoincidentDepthOffset * mcdcRel[12 + c];
  }

  int vpX = 0, vpY = 0;
  frame.Renderer->GetTiledSizeAndOrigin(&frame.Viewport[0], &frame.Viewport[1], &vpX, &vpY);
  return frame.Viewport[0] >= 1 && frame.Viewport[1] >= 1;
}

//------------------------------------------------------------------------------
// Step 3: the glyph roots: a lattice (fixed stride or one adaptive to the
// projected footprint) or the seed points, uploaded only when they change.
bool vtkPlumeVelocityGlyphMapper::Internals::UpdateRoots(vtkPlumeVelocityGlyphMapper* self, Frame& frame)
{
  const int* dims = frame.Dims;
  frame.SeedMode = self->RootMode == ROOTS_SEEDS;
  int stride = 1;
  std::copy(dims, dims + 3, frame.StridedDims);
  vtkIdType rootCount = 0;
  if (!frame.SeedMode)
  {
    // the whole grid's first and last nodes in this input's index space (a
    // piece of the whole with WholeExtent set, else the input itself)
    const int* we = self->WholeExtent;
    const bool piece = we[0] <= we[1] && we[2] <= we[3] && we[4] <= we[5];
    const int* extent = frame.Image->GetExtent();
    int first[3], last[3];
    for (int a = 0; a < 3; ++a)
    {
      first[a] = piece ? we[2 * a] - extent[2 * a] : 0;
      last[a] = piece ? we[2 * a + 1] - extent[2 * a] : dims[a] - 1;
    }
    if (self->RootMode == ROOTS_LATTICE)
    {
      stride = self->LatticeStride;
    }
    else
    {
      // projected footprint of the (whole) volume's 8 corners, clipped to the viewport
      double xmin = VTK_DOUBLE_MAX, xmax = -VTK_DOUBLE_MAX;
      double ymin = VTK_DOUBLE_MAX, ymax = -VTK_DOUBLE_MAX;
      bool behind = false;
      double indexToClip[16];
      vtkMatrix4x4::Multiply4x4(frame.MCDCRel, frame.IndexToRel, indexToClip);
      for (int corner = 0; corner < 8; ++corner)
      {
        const double idx[3] = { double((corner & 1) ? last[0] : first[0]),
          double((corner & 2) ? last[1] : first[1]), double((corner & 4) ? last[2] : first[2]) };
        double c[4];
        Apply(indexToClip, idx, c);
        if (!(c[3] > 1e-12))
        {
          behind = true;
          break;
        }
        xmin = std::min(xmin, c[0] / c[3]);
        xmax = std::max(xmax, c[0] / c[3]);
        ymin = std::min(ymin, c[1] / c[3]);
        ymax = std::max(ymax, c[1] / c[3]);
      }
      const double vpWidth = frame.Viewport[0], vpHeight = frame.Viewport[1];
      double area = vpWidth * vpHeight;
      if (!behind)
      {
        const double w = std::max(0.0, std::min(xmax, 1.0) - std::max(xmin, -1.0));
        const double h = std::max(0.0, std::min(ymax, 1.0) - std::max(ymin, -1.0));
        area = 0.25 * w * h * vpWidth * vpHeight;
      }
      // The budget goes to the nodes that move: spread over the whole grid,
      // a flow filling a few percent of it (blood in carotid.vtk's vessels)
      // got a handful of glyphs. At least 1 % of the valid nodes reach the
      // robust maximum, so the lattice holds at most about 100 G roots when
      // every node is valid.
      // A piece counts the whole data's (MovingNodeCount), so all pieces
      // pick the same stride.
      const int wholeDims[3] = { last[0] - first[0] + 1, last[1] - first[1] + 1, last[2] - first[2] + 1 };
      const vtkIdType moving = self->MovingNodeCount >= 0 ? self->MovingNodeCount : this->MovingNodes;
      const double nodes = moving > 0 ? double(moving) : double(wholeDims[0]) * wholeDims[1] * wholeDims[2];
      const double target = std::max(1.0, area / (self->ScreenSpacing * self->ScreenSpacing));
      stride = std::max(1, static_cast<int>(std::ceil(std::cbrt(nodes / target) - 1e-9)));
      stride = std::min(stride, std::max({ wholeDims[0], wholeDims[1], wholeDims[2] }));
    }
    // roots on the whole grid's lattice: the first at or after this input's node 0
    for (int a = 0; a < 3; ++a)
    {
      frame.LatticeOffset[a] = ((first[a] % stride) + stride) % stride;
      frame.StridedDims[a] =
        dims[a] > frame.LatticeOffset[a] ? (dims[a] - frame.LatticeOffset[a] + stride - 1) / stride : 0;
    }
    rootCount = vtkIdType(frame.StridedDims[0]) * frame.StridedDims[1] * frame.StridedDims[2];
  }
  else
  {
    vtkDataSet* seeds = SeedInput(self);
    const vtkIdType n = seeds ? seeds->GetNumberOfPoints() : 0;
    const double* centre = frame.Centre;
    if (n > 0 &&
      (seeds != this->SeedObject || seeds->GetMTime() != this->SeedTime ||
        !std::equal(centre, centre + 3, this->SeedCentre) || !this->SeedBuffer->GetHandle()))
    {
      std::vector<float> positions(3 * static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        double p[3];
        seeds->GetPoint(i, p);
        for (int a = 0; a < 3; ++a)
        {
          positions[3 * i + a] = static_cast<float>(p[a] - centre[a]);
        }
      }
      this->SeedBuffer->Upload(positions, vtkOpenGLBufferObject::ArrayBuffer);
      this->SeedObject = seeds;
      this->SeedTime = seeds->GetMTime();
      std::copy(centre, centre + 3, this->SeedCentre);
      this->SeedCount = n;
      this->SeedUploadChanged = true;
    }
    rootCount = n > 0 ? this->SeedCount : 0;
  }
  frame.Stride = stride;
  frame.RootCount = rootCount;
  self->EffectiveStride = stride;
  self->LastRootCount = rootCount;
  return rootCount >= 1;
}

//------------------------------------------------------------------------------
// Step 4: the colour lookup texture, only when the table, its range or the data range changed.
bool vtkPlumeVelocityGlyphMapper::Internals::UpdateColors(vtkPlumeVelocityGlyphMapper* self, Frame& frame)
{
  frame.UseLUT = self->ColorByMagnitude;
  frame.ColorRange[0] = self->UseDataRange ? this->SpeedRange[0] : self->ScalarRange[0];
  frame.ColorRange[1] = self->UseDataRange ? this->SpeedRange[1] : self->ScalarRange[1];
  if (!frame.UseLUT)
  {
    return true;
  }
  vtkScalarsToColors* lut = self->GetLookupTable();
  lut->SetRange(frame.ColorRange);
  lut->Build();
  const int uploads = this->LUTTexture->GetUploadCount();
  if (!this->LUTTexture->Update(frame.Window, lut, lut->GetMTime(), frame.ColorRange, LUTSize,
        [lut](double value, float rgba[4]) {
          const unsigned char* c = lut->MapValue(value);
          for (int k = 0; k < 4; ++k)
          {
            rgba[k] = c[k] / 255.0f;
          }
        }))
  {
    vtkErrorWithObjectMacro(self, << "could not create the colour lookup texture");
    return false;
  }
  if (this->LUTTexture->GetUploadCount() != uploads)
  {
    const std::vector<float>& table = this->LUTTexture->GetTable();
    this->LUTOpaque = true;
    for (int i = 0; i < LUTSize; ++i)
    {
      this->LUTOpaque = this->LUTOpaque && table[4 * i + 3] >= 1.0f;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Step 5: the shader variant for the features in use (compiled once per variant).
vtkShaderProgram* vtkPlumeVelocityGlyphMapper::Internals::ReadyProgram(
  vtkPlumeVelocityGlyphMapper* self, Frame& frame)
{
  if (self->Integrator == RK2 || self->Integrator == RK4)
  {
    frame.Segments = self->StreamletSegments;
    frame.Integrator = self->Integrator == RK2 ? "RK2" : "RK4";
  }
  frame.Wide = self->LineWidth > 1.0;
  frame.LineVS = !frame.SeedMode && frame.Integrator == "STRAIGHT" && !frame.Wide &&
    self->StraightLineShader == VERTEX_SHADER;
  // Opaque glyphs (no fade, actor opacity 1, an opaque table or solid colour)
  // need no alpha varying, no discard and no blending: the same image with
  // less work per fragment, which dominates dense glyphs on llvmpipe.
  frame.Opaque = self->RootAlpha >= 1.0 && frame.Actor->GetProperty()->GetOpacity() >= 1.0 &&
    (!frame.UseLUT || this->LUTOpaque);
  vtkPlumeShaderFeatures features;
  features.Enable(frame.SeedMode ? "SEEDS" : "LATTICE")
    .Enable(frame.Integrator)
    .Enable(frame.Wide ? "WIDE" : "THIN")
    .Enable(frame.UseLUT ? "LUT" : "SOLID")
    .Enable(frame.Opaque ? "OPAQUE" : "FADE")
    .Define("PLUME_SEGMENTS", frame.Segments)
    .Define("PLUME_POINTS", frame.Segments + 1)
    .Define("PLUME_VERTICES_WIDE", 2 * (frame.Segments + 1));
  const char* vsTemplate = frame.LineVS ? vtkPlumeGlyphLineVS : vtkPlumeGlyphVS;
  const char* gsTemplate = frame.LineVS ? nullptr : vtkPlumeGlyphGS;
  // A translucent actor is drawn inside VTK's translucent pass (order-
  // independent transparency or depth peeling), which rewrites fragment
  // shaders through the actor's render-pass keys and owns the blending.
  vtkInformation* passKeys = frame.Actor->GetPropertyKeys();
  if (passKeys && passKeys->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    for (int i = 0; i < passKeys->Length(vtkOpenGLRenderPass::RenderPasses()); ++i)
    {
      frame.Passes.push_back(
        static_cast<vtkOpenGLRenderPass*>(passKeys->Get(vtkOpenGLRenderPass::RenderPasses(), i)));
    }
  }
  vtkShaderProgram* program = nullptr;
  if (!frame.Passes.empty())
  {
    // the passes' replacements change between their stages: the shader
    // cache (keyed by the final source) keeps one program per stage
    const std::string defines = features.GetDefines();
    std::string vs = vtkPlumeShaderVariants::Select(vsTemplate, features.GetEnabled(), defines);
    std::string gs =
      gsTemplate ? vtkPlumeShaderVariants::Select(gsTemplate, features.GetEnabled(), defines) : std::string();
    std::string fs = vtkPlumeShaderVariants::Select(vtkPlumeGlyphFS, features.GetEnabled(), defines);
    for (vtkOpenGLRenderPass* pass : frame.Passes)
    {
      pass->PreReplaceShaderValues(vs, gs, fs, self, frame.Actor);
    }
    for (vtkOpenGLRenderPass* pass : frame.Passes)
    {
      pass->PostReplaceShaderValues(vs, gs, fs, self, frame.Actor);
    }
    program = frame.Window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
  }
  else
  {
    program = this->Programs->Ready(frame.Window, vsTemplate, gsTemplate, vtkPlumeGlyphFS, features);
  }
  if (!program)
  {
    vtkErrorWithObjectMacro(self, << "could not build the glyph shader program (" << features.GetKey() << ")");
  }
  return program;
}

//------------------------------------------------------------------------------
// Step 6: uniforms and textures.
void vtkPlumeVelocityGlyphMapper::Internals::SetUniforms(
  vtkPlumeVelocityGlyphMapper* self, const Frame& frame, vtkShaderProgram* program)
{
  const int* dims = frame.Dims;
  plume::SetUniformMatrix4x4(program, "MCDCRel", frame.MCDCRel);
  plume::SetUniformMatrix4x4(program, "IndexToRel", frame.IndexToRel);
  plume::SetUniformMatrix4x4(program, "RelToIndex", frame.RelToIndex);
  const float fdims[3] = { float(dims[0]), float(dims[1]), float(dims[2]) };
  program->SetUniform3f("Dims", fdims);
  program->SetUniformf("Scale", static_cast<float>(self->GetEffectiveScale()));
  if (frame.Segments > 1 || frame.Integrator != "STRAIGHT")
  {
    // streamlets stay inside a grid that is one node thick along an axis
    const float axes[3] = { dims[0] > 1 ? 1.0f : 0.0f, dims[1] > 1 ? 1.0f : 0.0f,
      dims[2] > 1 ? 1.0f : 0.0f };
    program->SetUniform3f("StreamAxes", axes);
  }
  program->SetUniformf("MinimumSpeed", static_cast<float>(self->MinimumSpeed));
  program->SetUniformf("RootAlpha", static_cast<float>(self->RootAlpha));
  const double span = frame.ColorRange[1] - frame.ColorRange[0];
  const float cr[2] = { static_cast<float>(frame.ColorRange[0]),
    span > 0 && std::isfinite(1.0 / span) ? static_cast<float>(1.0 / span) : 0.0f };
  program->SetUniform2f("ColorRange", cr);
  vtkProperty* property = frame.Actor->GetProperty();
  program->SetUniformf("Opacity", static_cast<float>(property->GetOpacity()));
  if (frame.Wide)
  {
    const float vp[2] = { float(frame.Viewport[0]), float(frame.Viewport[1]) };
    program->SetUniform2f("ViewportSize", vp);
    program->SetUniformf("HalfWidth", static_cast<float>(0.5 * self->LineWidth));
  }
  if (!frame.SeedMode)
  {
    const int sd[2] = { frame.StridedDims[0], frame.StridedDims[1] };
    program->SetUniform2i("StridedDims", sd);
    program->SetUniformi("Stride", frame.Stride);
    // (VTK 9.1 has no SetUniform3i; small integers are exact as floats)
    const float offset[3] = { float(frame.LatticeOffset[0]), float(frame.LatticeOffset[1]),
      float(frame.LatticeOffset[2]) };
    program->SetUniform3f("LatticeOffset", offset);
  }
  vtkTextureObject* velocity = this->Velocity->GetTextureObject();
  velocity->Activate();
  program->SetUniformi("Velocity", velocity->GetTextureUnit());
  if (frame.UseLUT)
  {
    this->LUTTexture->GetTextureObject()->Activate();
    program->SetUniformi("ColorLUT", this->LUTTexture->GetTextureObject()->GetTextureUnit());
    program->SetUniformf("LUTSize", static_cast<float>(LUTSize));
  }
  else
  {
    double color[3];
    property->GetDiffuseColor(color);
    program->SetUniform3f("SolidColor", color);
  }
}

//------------------------------------------------------------------------------
// Step 7: GL state and the draws; the textures are released afterwards.
void vtkPlumeVelocityGlyphMapper::Internals::Draw(
  vtkPlumeVelocityGlyphMapper* self, const Frame& frame, vtkShaderProgram* program)
{
  // depth test + write, standard alpha blending (restored afterwards)
  vtkOpenGLState* state = frame.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  if (frame.Passes.empty()) // else the translucent pass has set depth and blending up
  {
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    // opaque: no blending, the same result without the read-modify-write of every fragment
    if (frame.Opaque)
    {
      state->vtkglDisable(GL_BLEND);
    }
    else
    {
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
  }
  auto passParameters = [&](vtkOpenGLVertexArrayObject* vao) {
    for (vtkOpenGLRenderPass* pass : frame.Passes)
    {
      if (!pass->SetShaderParameters(program, self, frame.Actor, vao))
      {
        vtkErrorWithObjectMacro(
          self, << "render pass " << pass->GetClassName() << " could not set its shader parameters");
      }
    }
  };

  // chunked draws keep at most two draws queued in the driver (see vtkPlumeThrottledDraw.h)
  const vtkIdType chunk = self->MaximumGlyphsPerDraw;
  const int inFlight = 2;
  if (frame.SeedMode)
  {
    this->SeedVAO->Bind();
    if (this->SeedVAOProgram != program || this->SeedUploadChanged)
    {
      this->SeedVAO->ShaderProgramChanged();
      this->SeedVAO->Bind();
      if (!this->SeedVAO->AddAttributeArray(program, this->SeedBuffer, "seedPosition", 0,
            3 * sizeof(float), VTK_FLOAT, 3, false))
      {
        vtkErrorWithObjectMacro(self, << "could not bind the seed positions");
      }
      this->SeedVAOProgram = program;
      this->SeedUploadChanged = false;
    }
    passParameters(this->SeedVAO);
    plume::DrawArraysThrottled(GL_POINTS, 1, frame.RootCount, chunk, inFlight);
    this->SeedVAO->Release();
  }
  else
  {
    this->EmptyVAO->Bind();
    passParameters(this->EmptyVAO);
    plume::DrawArraysThrottled(
      frame.LineVS ? GL_LINES : GL_POINTS, frame.LineVS ? 2 : 1, frame.RootCount, chunk, inFlight);
    this->EmptyVAO->Release();
  }

  this->Velocity->GetTextureObject()->Deactivate();
  if (frame.UseLUT)
  {
    this->LUTTexture->GetTextureObject()->Deactivate();
  }
}

//------------------------------------------------------------------------------
int vtkPlumeVelocityGlyphMapper::GetUploadCount()
{
  return this->Impl->Velocity->GetUploadCount();
}

//------------------------------------------------------------------------------
int vtkPlumeVelocityGlyphMapper::GetHandOverCount()
{
  return this->Impl->Velocity->GetHandOverCount();
}

//------------------------------------------------------------------------------
void vtkPlumeVelocityGlyphMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPlumeVelocityGlyphMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VectorArrayName: " << this->VectorArrayName << "\n";
  os << indent << "ValidMaskArrayName: " << this->ValidMaskArrayName << "\n";
  os << indent << "RootMode: " << this->RootMode << "\n";
  os << indent << "LatticeStride: " << this->LatticeStride << "\n";
  os << indent << "ScreenSpacing: " << this->ScreenSpacing << "\n";
  os << indent << "EffectiveStride: " << this->EffectiveStride << "\n";
  os << indent << "WholeExtent: " << this->WholeExtent[0] << " " << this->WholeExtent[1] << " "
     << this->WholeExtent[2] << " " << this->WholeExtent[3] << " " << this->WholeExtent[4] << " "
     << this->WholeExtent[5] << "\n";
  os << indent << "MovingNodeCount: " << this->MovingNodeCount << "\n";
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "ScaleMode: " << this->ScaleMode << "\n";
  os << indent << "AutomaticScaleSpeed: " << this->AutomaticScaleSpeed << "\n";
  os << indent << "Integrator: " << this->Integrator << "\n";
  os << indent << "StreamletSegments: " << this->StreamletSegments << "\n";
  os << indent << "MinimumSpeed: " << this->MinimumSpeed << "\n";
  os << indent << "RootAlpha: " << this->RootAlpha << "\n";
  os << indent << "LineWidth: " << this->LineWidth << "\n";
  os << indent << "ColorByMagnitude: " << this->ColorByMagnitude << "\n";
  os << indent << "UseDataRange: " << this->UseDataRange << "\n";
  os << indent << "StraightLineShader: "
     << (this->StraightLineShader == VERTEX_SHADER ? "VERTEX_SHADER" : "GEOMETRY_SHADER") << "\n";
  os << indent << "MaximumGlyphsPerDraw: " << this->MaximumGlyphsPerDraw << "\n";
  os << indent << "LastRootCount: " << this->LastRootCount << "\n";
  os << indent << "UploadCount: " << this->Impl->Velocity->GetUploadCount() << "\n";
  os << indent << "HandOverCount: " << this->Impl->Velocity->GetHandOverCount() << "\n";
}
