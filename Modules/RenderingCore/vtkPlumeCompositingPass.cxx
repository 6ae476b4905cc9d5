#include "vtkPlumeCompositingPass.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkOverlayPass.h"
#include "vtkPlumeOpaqueDepthTexture.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVolume.h"

#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
// One step of the frame: forwards to a member of the compositing pass.
// vtkRenderStepsPass takes passes, not callbacks.
class vtkPlumeCompositingStep : public vtkRenderPass
{
public:
  static vtkPlumeCompositingStep* New();
  vtkTypeMacro(vtkPlumeCompositingStep, vtkRenderPass);
  using Body = void (vtkPlumeCompositingPass::*)(const vtkRenderState*);
  vtkPlumeCompositingPass* Owner = nullptr; // not counted: the owner holds this step
  Body Step = nullptr;
  int* Rendered = nullptr;
  void Render(const vtkRenderState* s) override
  {
    int count = 0;
    this->Rendered = &count;
    (this->Owner->*this->Step)(s);
    this->NumberOfRenderedProps = count;
  }
};
vtkStandardNewMacro(vtkPlumeCompositingStep);

vtkSmartPointer<vtkPlumeCompositingStep> MakeStep(vtkPlumeCompositingPass* owner, vtkPlumeCompositingStep::Body body)
{
  auto step = vtkSmartPointer<vtkPlumeCompositingStep>::New();
  step->Owner = owner;
  step->Step = body;
  return step;
}

struct Entry
{
  vtkProp* Prop;
  double Distance;
  std::array<double, 6> Bounds;
};

// Back to front by the distance from the camera to the centre of the bounds;
// ties by the bounds, so that the order the props were added never matters.
std::vector<vtkProp*> SortBackToFront(std::vector<Entry>& entries)
{
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    if (a.Distance != b.Distance)
    {
      return a.Distance > b.Distance;
    }
    return a.Bounds < b.Bounds;
  });
  std::vector<vtkProp*> order;
  order.reserve(entries.size());
  for (const Entry& e : entries)
  {
    order.push_back(e.Prop);
  }
  return order;
}

Entry MakeEntry(vtkProp* prop, const double eye[3])
{
  Entry e{ prop, 0.0, { 0, 0, 0, 0, 0, 0 } };
  const double* b = prop->GetBounds();
  if (b && vtkMath::AreBoundsInitialized(b))
  {
    std::copy(b, b + 6, e.Bounds.begin());
    const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
    e.Distance = std::sqrt(vtkMath::Distance2BetweenPoints(c, eye));
    if (!std::isfinite(e.Distance))
    {
      e.Distance = 0.0;
    }
  }
  return e;
}

vtkMapper* StagedMapper(vtkProp* prop, int stage)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  return mapper && vtkPlumeCompositingPass::GetStage(mapper) == stage ? mapper : nullptr;
}
} // namespace

vtkStandardNewMacro(vtkPlumeCompositingPass);
vtkInformationKeyMacro(vtkPlumeCompositingPass, STAGE, Integer);
vtkInformationKeyMacro(vtkPlumeCompositingPass, CURRENT_STAGE, Integer);
vtkInformationKeyMacro(vtkPlumeCompositingPass, OPAQUE_DEPTH, ObjectBase);
vtkInformationKeyMacro(vtkPlumeCompositingPass, MEDIA_LAYER, ObjectBase);
vtkInformationKeyMacro(vtkPlumeCompositingPass, MEDIA_LAYER_DRAWN, Integer);
vtkInformationKeyMacro(vtkPlumeCompositingPass, MEDIA_LAYER_DEPTH, ObjectBase);
vtkInformationKeyMacro(vtkPlumeCompositingPass, MEDIA_TRANSMITTANCE, ObjectBase);
vtkInformationKeyMacro(vtkPlumeCompositingPass, MEDIA_TRANSMITTANCE_DRAWN, Integer);

bool vtkPlumeCompositingPass::IsMedium(vtkProp* prop)
{
  return prop && prop->GetVisibility() && (vtkVolume::SafeDownCast(prop) || StagedMapper(prop, STAGE_MEDIA));
}

//------------------------------------------------------------------------------
vtkPlumeCompositingPass::vtkPlumeCompositingPass()
  : Steps(vtkSmartPointer<vtkRenderStepsPass>::New())
  , Opaque(vtkSmartPointer<vtkOpaquePass>::New())
  , Translucent(vtkSmartPointer<vtkTranslucentPass>::New())
  , Overlay(vtkSmartPointer<vtkOverlayPass>::New())
  , Depth(vtkSmartPointer<vtkPlumeOpaqueDepthTexture>::New())
{
  // the frame's shared depth: anti-aliased edges of lines stop volumes and sheets (issue 15)
  this->Depth->SetResolveToNearestSample(true);
  auto oit = vtkSmartPointer<vtkOrderIndependentTranslucentPass>::New();
  oit->SetTranslucentPass(this->Translucent);
  this->OrderIndependent = oit;
  auto peeling = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
  peeling->SetTranslucentPass(this->Translucent);
  this->DepthPeeling = peeling;

  this->Steps->SetOpaquePass(MakeStep(this, &vtkPlumeCompositingPass::RenderOpaqueAndSurfaces));
  this->Steps->SetTranslucentPass(MakeStep(this, &vtkPlumeCompositingPass::RenderTranslucent));
  this->Steps->SetVolumetricPass(MakeStep(this, &vtkPlumeCompositingPass::RenderMedia));
  this->Steps->SetOverlayPass(MakeStep(this, &vtkPlumeCompositingPass::RenderOverlay));
}

vtkPlumeCompositingPass::~vtkPlumeCompositingPass() = default;

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::SetStage(vtkAlgorithm* mapper, int stage)
{
  if (mapper)
  {
    mapper->GetInformation()->Set(STAGE(), stage);
  }
}

int vtkPlumeCompositingPass::GetStage(vtkAlgorithm* mapper)
{
  vtkInformation* info = mapper ? mapper->GetInformation() : nullptr;
  return info && info->Has(STAGE()) ? info->Get(STAGE()) : -1;
}

bool vtkPlumeCompositingPass::ShouldDraw(vtkRenderer* renderer, vtkAlgorithm* mapper)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  if (!info || !info->Has(CURRENT_STAGE()))
  {
    return true; // no compositing pass: stand-alone behaviour
  }
  return info->Get(CURRENT_STAGE()) == GetStage(mapper);
}

vtkPlumeOpaqueDepthTexture* vtkPlumeCompositingPass::GetSharedDepth(vtkRenderer* renderer)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info ? vtkPlumeOpaqueDepthTexture::SafeDownCast(info->Get(OPAQUE_DEPTH())) : nullptr;
}

vtkPlumeOpaqueDepthTexture* vtkPlumeCompositingPass::AcquireDepth(
  vtkRenderer* renderer, vtkPlumeOpaqueDepthTexture* own)
{
  if (vtkPlumeOpaqueDepthTexture* shared = GetSharedDepth(renderer))
  {
    return shared;
  }
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  if (info && info->Has(CURRENT_STAGE()))
  {
    // the pass runs but could not read the depth: a copy now would hold
    // translucent geometry too, so behave as the pass said (unbounded)
    return nullptr;
  }
  return own && own->Capture(renderer) ? own : nullptr;
}

bool vtkPlumeCompositingPass::HasOtherDepthWriters(vtkRenderer* renderer, vtkProp* self)
{
  if (!renderer || renderer->GetPreserveDepthBuffer())
  {
    return true;
  }
  vtkInformation* info = renderer->GetInformation();
  const bool pass = info && info->Has(CURRENT_STAGE());
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop == self || !prop->GetVisibility() || vtkActor2D::SafeDownCast(prop))
    {
      continue;
    }
    const bool writes = pass
      ? !IsMedium(prop) && (prop->HasOpaqueGeometry() || StagedMapper(prop, STAGE_SURFACES))
      : prop->HasOpaqueGeometry() || prop->HasTranslucentPolygonalGeometry();
    if (writes)
    {
      return true;
    }
  }
  return false;
}

vtkPlumeCompositingPass* vtkPlumeCompositingPass::Install(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return nullptr;
  }
  if (auto* existing = vtkPlumeCompositingPass::SafeDownCast(renderer->GetPass()))
  {
    return existing;
  }
  vtkNew<vtkPlumeCompositingPass> pass;
  renderer->SetPass(pass);
  return pass;
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::Render(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkInformation* info = ren->GetInformation();
  info->Set(CURRENT_STAGE(), STAGE_VTK);
  this->LastSurfaceOrder.clear();
  this->LastMediaOrder.clear();
  this->LastDepthShared = false;
  this->Steps->Render(s);
  this->RestoreColorAttachment(); // (already done by the overlay step unless it did not run)
  this->NumberOfRenderedProps = this->Steps->GetNumberOfRenderedProps();
  // a renderer that later renders without the pass gets stand-alone mappers
  info->Remove(CURRENT_STAGE());
  info->Remove(OPAQUE_DEPTH());
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::RenderOpaqueAndSurfaces(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkInformation* info = ren->GetInformation();
  auto* step = static_cast<vtkPlumeCompositingStep*>(this->Steps->GetOpaquePass());

  info->Set(CURRENT_STAGE(), STAGE_VTK);
  this->Opaque->Render(s);
  *step->Rendered += this->Opaque->GetNumberOfRenderedProps();

  double eye[3];
  ren->GetActiveCamera()->GetPosition(eye);
  std::vector<Entry> surfaces;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop->GetVisibility() && StagedMapper(prop, STAGE_SURFACES))
    {
      surfaces.push_back(MakeEntry(prop, eye));
    }
  }
  this->LastSurfaceOrder = SortBackToFront(surfaces);
  info->Set(CURRENT_STAGE(), STAGE_SURFACES);
  for (vtkProp* prop : this->LastSurfaceOrder)
  {
    *step->Rendered += prop->HasOpaqueGeometry() ? prop->RenderOpaqueGeometry(ren)
                                                 : prop->RenderTranslucentPolygonalGeometry(ren);
  }
  info->Set(CURRENT_STAGE(), STAGE_VTK);

  // one copy of the opaque depth for every medium of the frame; none when
  // the frame has no medium (nothing would read it)
  bool anyMedium = false;
  for (int i = 0; i < s->GetPropArrayCount() && !anyMedium; ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    anyMedium = IsMedium(prop);
  }
  if (!anyMedium)
  {
    return;
  }
  this->LastDepthShared = this->Depth->Capture(ren);
  if (this->LastDepthShared)
  {
    info->Set(OPAQUE_DEPTH(), this->Depth);
  }
  else if (!this->WarnedDepth)
  {
    vtkWarningMacro(<< "media will not stop at opaque geometry: " << this->Depth->GetLastError());
    this->WarnedDepth = true;
  }
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::RenderTranslucent(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  auto* step = static_cast<vtkPlumeCompositingStep*>(this->Steps->GetTranslucentPass());
  // as vtkOpenGLRenderer does without a pass
  vtkRenderPass* pass = ren->GetUseDepthPeeling() ? this->DepthPeeling : this->OrderIndependent;
  ren->GetInformation()->Set(CURRENT_STAGE(), STAGE_VTK);
  pass->Render(s);
  *step->Rendered += pass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::RenderMedia(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  auto* step = static_cast<vtkPlumeCompositingStep*>(this->Steps->GetVolumetricPass());
  double eye[3];
  ren->GetActiveCamera()->GetPosition(eye);
  std::vector<Entry> media;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (IsMedium(prop))
    {
      media.push_back(MakeEntry(prop, eye));
    }
  }
  this->LastMediaOrder = SortBackToFront(media);
  vtkInformation* info = ren->GetInformation();
  info->Set(CURRENT_STAGE(), STAGE_MEDIA);
  // A media layer asked for by an outer pass: the media draw into it in place
  // of the frame's colour attachment (same depth attachment), cleared first.
  auto* layer = vtkTextureObject::SafeDownCast(info->Get(MEDIA_LAYER()));
  GLint framebuffer = 0, previous = 0, previousType = GL_NONE;
  if (layer && !this->LastMediaOrder.empty())
  {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0)
    {
      layer = nullptr; // the default framebuffer's attachments cannot be swapped
      if (!this->WarnedLayer)
      {
        vtkWarningMacro(<< "a media layer was asked for, but the frame is drawn into the default framebuffer");
        this->WarnedLayer = true;
      }
    }
  }
  auto drawMedia = [&](bool count) {
    int rendered = 0;
    for (vtkProp* prop : this->LastMediaOrder)
    {
      if (vtkVolume::SafeDownCast(prop))
      {
        rendered += prop->RenderVolumetricGeometry(ren);
      }
      else
      {
        rendered += prop->HasOpaqueGeometry() ? prop->RenderOpaqueGeometry(ren)
                                              : prop->RenderTranslucentPolygonalGeometry(ren);
      }
    }
    *step->Rendered += count ? rendered : 0;
  };
  if (!layer || framebuffer == 0)
  {
    drawMedia(true);
    info->Set(CURRENT_STAGE(), STAGE_VTK);
    return;
  }
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &previousType);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &previous);
  this->LayerAttachment = { static_cast<int>(previousType), static_cast<int>(previous) };
  this->LayerAttached = true;
  this->Layer = layer;
  this->Transmittance = nullptr;
  // Media that are not premultiplied "over" with one opacity (smoke sheets
  // multiply the frame by an RGB transmittance): drawn a second time over a
  // layer cleared to 1, whose difference from the first is their transmittance.
  auto* transmittance = vtkTextureObject::SafeDownCast(info->Get(MEDIA_TRANSMITTANCE()));
  bool anyStaged = false;
  for (vtkProp* prop : this->LastMediaOrder)
  {
    anyStaged = anyStaged || !vtkVolume::SafeDownCast(prop);
  }
  this->AttachAndClear(ren, layer, 0.0);
  drawMedia(true);
  if (transmittance && anyStaged)
  {
    this->Transmittance = transmittance;
    this->AttachAndClear(ren, transmittance, 1.0);
    drawMedia(false);
    info->Set(MEDIA_TRANSMITTANCE_DRAWN(), 1);
  }
  // The overlay (2D actors: colour bars, titles) draws over the media, so into
  // the layer(s) too; the frame's own colour attachment is put back after it.
  info->Set(MEDIA_LAYER_DRAWN(), static_cast<int>(this->LastMediaOrder.size()));
  if (this->LastDepthShared)
  {
    info->Set(MEDIA_LAYER_DEPTH(), this->Depth);
  }
  info->Set(CURRENT_STAGE(), STAGE_VTK);
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::RenderOverlay(const vtkRenderState* s)
{
  auto* step = static_cast<vtkPlumeCompositingStep*>(this->Steps->GetOverlayPass());
  if (this->LayerAttached)
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, this->Layer->GetHandle(), 0);
  }
  this->Overlay->Render(s);
  *step->Rendered += this->Overlay->GetNumberOfRenderedProps();
  if (this->LayerAttached && this->Transmittance)
  {
    glFramebufferTexture2D(
      GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, this->Transmittance->GetHandle(), 0);
    this->Overlay->Render(s);
  }
  this->RestoreColorAttachment();
}

void vtkPlumeCompositingPass::AttachAndClear(vtkRenderer* ren, vtkTextureObject* texture, double value)
{
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture->GetHandle(), 0);
  vtkOpenGLState* ostate = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglClearColor clearSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglClearColor(value, value, value, value);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

void vtkPlumeCompositingPass::RestoreColorAttachment()
{
  if (!this->LayerAttached)
  {
    return;
  }
  // the frame's own colour attachment back (the media layer took its place)
  const int type = this->LayerAttachment[0], name = this->LayerAttachment[1];
  if (type == GL_RENDERBUFFER)
  {
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, name);
  }
  else
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, type == GL_TEXTURE ? name : 0, 0);
  }
  this->LayerAttached = false;
  this->Layer = nullptr;
  this->Transmittance = nullptr;
}

//------------------------------------------------------------------------------
void vtkPlumeCompositingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Steps->ReleaseGraphicsResources(w);
  this->Opaque->ReleaseGraphicsResources(w);
  this->OrderIndependent->ReleaseGraphicsResources(w);
  this->DepthPeeling->ReleaseGraphicsResources(w);
  this->Translucent->ReleaseGraphicsResources(w);
  this->Overlay->ReleaseGraphicsResources(w);
  this->Depth->ReleaseGraphicsResources(w);
}

void vtkPlumeCompositingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastSurfaces: " << this->LastSurfaceOrder.size() << "\n";
  os << indent << "LastMedia: " << this->LastMediaOrder.size() << "\n";
  os << indent << "LastDepthShared: " << this->LastDepthShared << "\n";
}
