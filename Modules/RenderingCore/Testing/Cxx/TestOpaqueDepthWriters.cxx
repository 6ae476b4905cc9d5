// vtkPlumeCompositingPass::HasOtherDepthWriters: whether a medium must read
// the opaque depth (false: it is the far plane everywhere). Both ways, with
// and without the compositing pass (its stage set on the renderer's
// information, as the pass does while it draws the media):
//  - the medium alone, hidden props and 2D actors: no writer;
//  - an opaque actor: a writer (with and without the pass);
//  - a translucent actor: a writer without the pass (conservative), not with
//    it (the shared depth is captured before VTK's translucent pass), unless
//    its mapper draws in STAGE_SURFACES (glyph lines write depth there);
//  - another volume: a writer without the pass (an isosurface writes depth),
//    not with it (media draw after the shared depth);
//  - a renderer that keeps an earlier renderer's depth: always.
#include "vtkPlumeCompositingPass.h"

#include "plumeRenderingCoreTestUtil.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

namespace
{
void SetPass(vtkRenderer* ren, bool on)
{
  if (on)
  {
    ren->GetInformation()->Set(vtkPlumeCompositingPass::CURRENT_STAGE(), vtkPlumeCompositingPass::STAGE_MEDIA);
  }
  else
  {
    ren->GetInformation()->Remove(vtkPlumeCompositingPass::CURRENT_STAGE());
  }
}
}

int TestOpaqueDepthWriters(int, char*[])
{
  int failures = 0;
  using P = vtkPlumeCompositingPass;
  vtkNew<vtkRenderer> ren;
  vtkNew<vtkVolume> self;
  ren->AddVolume(self);
  vtkNew<vtkPolyData> surface; // (no geometry needed: only what the props say they draw)
  for (bool pass : { false, true })
  {
    SetPass(ren, pass);
    CHECK(!P::HasOtherDepthWriters(ren, self)); // the medium alone
  }
  SetPass(ren, false);
  CHECK(P::HasOtherDepthWriters(nullptr, self));

  // an opaque actor
  vtkNew<vtkPolyDataMapper> opaqueMapper;
  opaqueMapper->SetInputData(surface);
  vtkNew<vtkActor> opaque;
  opaque->SetMapper(opaqueMapper);
  ren->AddActor(opaque);
  for (bool pass : { false, true })
  {
    SetPass(ren, pass);
    CHECK(P::HasOtherDepthWriters(ren, self));
    // itself excluded; the volume counts only without the pass (an isosurface writes depth there)
    CHECK(P::HasOtherDepthWriters(ren, opaque) == !pass);
  }
  SetPass(ren, false);
  opaque->VisibilityOff();
  CHECK(!P::HasOtherDepthWriters(ren, self)); // hidden

  // a 2D actor (scalar bars, titles) draws over everything, writes no depth read by media
  vtkNew<vtkActor2D> overlay;
  ren->AddActor2D(overlay);
  CHECK(!P::HasOtherDepthWriters(ren, self));

  // a translucent actor
  vtkNew<vtkPolyDataMapper> translucentMapper;
  translucentMapper->SetInputData(surface);
  vtkNew<vtkActor> translucent;
  translucent->SetMapper(translucentMapper);
  translucent->GetProperty()->SetOpacity(0.5);
  ren->AddActor(translucent);
  CHECK(P::HasOtherDepthWriters(ren, self));
  SetPass(ren, true);
  CHECK(!P::HasOtherDepthWriters(ren, self));
  P::SetStage(translucentMapper, P::STAGE_SURFACES); // drawn before the shared depth, writes it
  CHECK(P::HasOtherDepthWriters(ren, self));
  translucent->VisibilityOff();
  CHECK(!P::HasOtherDepthWriters(ren, self));

  // another volume
  vtkNew<vtkVolume> other;
  ren->AddVolume(other);
  CHECK(!P::HasOtherDepthWriters(ren, self)); // under the pass: a medium, drawn after the shared depth
  SetPass(ren, false);
  CHECK(P::HasOtherDepthWriters(ren, self));
  other->VisibilityOff();
  CHECK(!P::HasOtherDepthWriters(ren, self));

  // the depth of an earlier renderer kept
  ren->PreserveDepthBufferOn();
  CHECK(P::HasOtherDepthWriters(ren, self));
  ren->PreserveDepthBufferOff();
  CHECK(!P::HasOtherDepthWriters(ren, self));

  std::printf("TestOpaqueDepthWriters: %d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
