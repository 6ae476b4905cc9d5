// Upload bookkeeping and error handling (no baseline):
//  - re-rendering does not re-upload; Modified() on the array does;
//  - changing only rendering parameters does not re-upload;
//  - missing / wrong arrays are reported (vtkErrorMacro) and nothing is drawn;
//  - ReleaseGraphicsResources frees everything and the next render re-uploads;
//  - screen-adaptive stride follows the documented formula, over the moving nodes.
#include "vtkPlumeVelocityGlyphMapper.h"
#include "vtkPlumeVortexSource.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"

#include "plumeGlyphTestUtil.h"

int TestVelocityGlyphUpload(int, char*[])
{
  int failures = 0;
  const double bg[3] = { 0, 0, 0 };
  vtkNew<vtkPlumeVortexSource> vortex;
  vortex->SetDimensions(24, 20, 16);
  vortex->Update();
  vtkNew<vtkImageData> image;
  image->DeepCopy(vortex->GetOutput());

  vtkNew<vtkPlumeVelocityGlyphMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> ren;
  ren->AddActor(actor);
  ren->SetBackground(bg[0], bg[1], bg[2]);
  auto window = plume::test::MakeOffscreenWindow(240, 200);
  window->AddRenderer(ren);
  ren->ResetCamera();

  window->Render();
  PLUME_CHECK(mapper->GetUploadCount() == 1);
  window->Render();
  PLUME_CHECK(mapper->GetUploadCount() == 1);
  ren->GetActiveCamera()->Azimuth(20);
  mapper->SetScaleMode(vtkPlumeVelocityGlyphMapper::SCALE_FIXED);
  mapper->SetScale(0.7);
  mapper->SetIntegrator(vtkPlumeVelocityGlyphMapper::RK2);
  mapper->SetLineWidth(2.5);
  window->Render();
  PLUME_CHECK(mapper->GetUploadCount() == 1);
  image->GetPointData()->GetVectors()->Modified();
  window->Render();
  PLUME_CHECK(mapper->GetUploadCount() == 2);
  window->Render();
  PLUME_CHECK(mapper->GetUploadCount() == 2);
  std::cout << "upload count after modify: " << mapper->GetUploadCount() << "\n";

  // screen-adaptive stride: the documented formula, from the volume's projected corners
  {
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE);
    mapper->SetScreenSpacing(10);
    window->Render();
    const int s1 = mapper->GetEffectiveStride();
    mapper->SetScreenSpacing(30);
    window->Render();
    const int s2 = mapper->GetEffectiveStride();
    ren->GetActiveCamera()->Dolly(0.2); // far away: small footprint, larger stride
    ren->ResetCameraClippingRange();
    window->Render();
    const int s3 = mapper->GetEffectiveStride();
    std::cout << "adaptive strides: " << s1 << " " << s2 << " " << s3 << "\n";
    PLUME_CHECK(s1 >= 1 && s2 > s1 && s3 > s2);
    PLUME_CHECK(mapper->GetUploadCount() == 2);
    // a lattice covers ceil(n/stride) nodes per axis
    const int n = (24 + s3 - 1) / s3 * ((20 + s3 - 1) / s3) * ((16 + s3 - 1) / s3);
    PLUME_CHECK(mapper->GetLastRootCount() == n);
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
    ren->ResetCamera();
  }

  // the adaptive stride counts the moving nodes only: the same grid with the
  // flow kept in a corner (6x6x16 of the 24x20x16 nodes, 7.5 %) and still
  // air elsewhere (1e-4 of the velocity) gets a finer lattice, so the flow
  // keeps about as many glyphs; counting every node gave it the full flow's
  // stride (carotid.vtk's vessels: a handful of glyphs)
  {
    vtkNew<vtkImageData> sparse;
    sparse->DeepCopy(image);
    vtkDataArray* velocity = sparse->GetPointData()->GetVectors();
    for (vtkIdType id = 0; id < sparse->GetNumberOfPoints(); ++id)
    {
      const vtkIdType i = id % 24, j = (id / 24) % 20;
      if (i >= 6 || j >= 6)
      {
        double v[3];
        velocity->GetTuple(id, v);
        for (double& c : v)
        {
          c *= 1e-4;
        }
        velocity->SetTuple(id, v);
      }
    }
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_SCREEN_ADAPTIVE);
    mapper->SetScreenSpacing(30);
    window->Render();
    const int full = mapper->GetEffectiveStride();
    mapper->SetInputData(sparse);
    window->Render();
    const int corner = mapper->GetEffectiveStride();
    std::cout << "adaptive stride, flow everywhere: " << full << ", flow in a corner: " << corner << "\n";
    // (moving / all nodes)^(1/3) = 0.42: 7 -> 3 in this view
    PLUME_CHECK(full >= 3 && corner <= (full + 1) / 2);
    mapper->SetInputData(image);
    mapper->SetRootMode(vtkPlumeVelocityGlyphMapper::ROOTS_LATTICE);
  }

  // errors: reported, nothing drawn, no crash
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->SetVectorArrayName("no_such_array");
  PLUME_CHECK(plume::test::CountForeground(plume::test::ReadBack(window), bg) == 0);
  PLUME_CHECK(errors->GetError());
  PLUME_CHECK(errors->GetErrorMessage().find("no_such_array") != std::string::npos);
  errors->Clear();

  mapper->SetVectorArrayName("speed"); // 1 component
  PLUME_CHECK(plume::test::CountForeground(plume::test::ReadBack(window), bg) == 0);
  PLUME_CHECK(errors->GetErrorMessage().find("'speed' has 1 components") != std::string::npos);
  errors->Clear();

  mapper->SetVectorArrayName("");
  vtkNew<vtkImageData> novectors;
  novectors->SetDimensions(4, 4, 4);
  mapper->SetInputData(novectors);
  PLUME_CHECK(plume::test::CountForeground(plume::test::ReadBack(window), bg) == 0);
  PLUME_CHECK(errors->GetErrorMessage().find("no active vectors") != std::string::npos);
  errors->Clear();
  PLUME_CHECK(plume::test::GLErrors(window).empty());

  // back to valid data; the named array path works too
  mapper->SetInputData(image);
  mapper->SetVectorArrayName("velocity");
  PLUME_CHECK(plume::test::CountForeground(plume::test::ReadBack(window), bg) > 100);
  PLUME_CHECK(!errors->GetError());
  const int before = mapper->GetUploadCount();

  // ReleaseGraphicsResources: everything freed, the next render uploads again
  mapper->ReleaseGraphicsResources(window);
  PLUME_CHECK(plume::test::CountForeground(plume::test::ReadBack(window), bg) > 100);
  PLUME_CHECK(mapper->GetUploadCount() == before + 1);
  PLUME_CHECK(plume::test::GLErrors(window).empty());

  // removing the actor and finalizing the window must not leave dangling GL state
  ren->RemoveActor(actor);
  window->Render();
  window->Finalize();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
