// vtkPlumeDatasetReader failures: never crash, one clear message naming the problem and the
// offending value, no pipeline "returned failure" dump, and the reader recovers.
#include "plumeDataTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPlumeResampleToImage.h"
#include "vtkStringOutputWindow.h"

using plumetest::Checker;

namespace
{
bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// Update, expect failure, and expect every `parts` in the message.
void ExpectError(Checker& check, vtkPlumeDatasetReader* reader,
  std::initializer_list<std::string> parts)
{
  const int ok = reader->GetExecutive()->Update();
  const std::string message = reader->GetLastError();
  check.True(!ok, "Update() reports failure");
  check.True(!message.empty(), "a message");
  for (const auto& part : parts)
  {
    check.True(Contains(message, part), "message '" + message + "' names '" + part + "'");
  }
  check.True(message.find('\n') == std::string::npos, "one line: '" + message + "'");
}
}

int TestPlumeDatasetReaderErrors(int, char*[])
{
  Checker check;
  // Capture VTK's own output (output window and logger) to check that the executive's
  // request dump is silenced.
  vtkNew<vtkStringOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  std::string logged;
  vtkLogger::AddCallback(
    "plume-test-capture",
    [](void* userData, const vtkLogger::Message& message) {
      *static_cast<std::string*>(userData) += std::string(message.message) + "\n";
    },
    &logged, vtkLogger::VERBOSITY_WARNING);

  {
    check.Context = "missing file";
    const std::string path = plumetest::Data("classic/no_such_file.vtk");
    auto reader = plumetest::Reader("classic/no_such_file.vtk");
    ExpectError(check, reader, { "file not found", path });
  }
  {
    check.Context = "no file name";
    vtkNew<vtkPlumeDatasetReader> reader;
    ExpectError(check, reader, { "no file name" });
  }
  {
    check.Context = "unknown extension";
    auto reader = plumetest::Reader("README.md");
    ExpectError(check, reader, { "unknown file extension", "'.md'", ".vtk", ".foam", ".cgns", ".pvd" });
  }
  {
    check.Context = "unknown reader name";
    auto reader = plumetest::Reader("classic/fire_ug.vtu");
    reader->SetReaderName("tecplot");
    ExpectError(check, reader, { "unknown reader name", "'tecplot'", "openfoam", "legacy" });
  }
  {
    check.Context = "time step out of range";
    auto reader = plumetest::Reader("openfoam_cavity/cavity/case.foam");
    reader->SetTimeStep(6);
    ExpectError(check, reader, { "time step 6", "0 to 5" });
    reader->SetTimeStep(-1);
    ExpectError(check, reader, { "time step -1", "0 to 5" });
  }
  {
    check.Context = "time value out of range";
    auto reader = plumetest::Reader("nek5000_eddy_uv/vtu/eddy_uv.pvd");
    reader->SetTimeValue(0.5);
    ExpectError(check, reader, { "time value 0.5", "0 to 0.1" });
  }
  {
    check.Context = "time step of a static dataset";
    auto reader = plumetest::Reader("classic/fire_ug.vtu");
    reader->SetTimeStep(2);
    ExpectError(check, reader, { "time step 2", "has no time steps", "leave the time step at 0" });
  }
  {
    check.Context = "unknown block";
    auto reader = plumetest::Reader("ensight_cylinder_re35/cylinder_Re35.case");
    reader->AddBlockName("fluids");
    ExpectError(check, reader, { "no block matched", "'fluids'", "fluid,", "wall_cylinder" });
  }
  {
    check.Context = "wrong reader for the file";
    auto reader = plumetest::Reader("classic/fire_ug.vtu");
    reader->SetReaderName("ensight");
    ExpectError(check, reader, { "ensight reader", "fire_ug.vtu" });
    reader->SetReaderName("cgns"); // the CGNS library would exit() on this file
    ExpectError(check, reader, { "not a CGNS file", "fire_ug.vtu" });
  }
  {
    check.Context = "missing PLOT3D solution";
    auto reader = plumetest::Reader("plot3d/combxyz.bin");
    reader->SetQFileName(plumetest::Data("plot3d/no_such_q.bin").c_str());
    ExpectError(check, reader, { "solution (Q) file not found", "no_such_q.bin" });
  }
  {
    check.Context = "recovery after an error";
    auto reader = plumetest::Reader("classic/no_such_file.vtk");
    ExpectError(check, reader, { "file not found" });
    reader->SetFileName(plumetest::Data("classic/office.binary.vtk").c_str());
    reader->Update();
    check.True(reader->GetLastError().empty(), "no error after fixing: " + reader->GetLastError());
    auto* ds = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    check.True(ds && ds->GetNumberOfPoints() == 8400, "data after fixing");
    reader->SetTimeStep(3);
    ExpectError(check, reader, { "time step 3" });
    check.True(!ds || ds->GetNumberOfPoints() == 0, "a failed update leaves an empty output");
    reader->SetTimeStep(0);
    reader->Update();
    check.True(reader->GetLastError().empty(), "no error after resetting the step");
  }
  {
    check.Context = "failing reader upstream of the resampler";
    auto reader = plumetest::Reader("classic/no_such_file.vtk");
    vtkNew<vtkPlumeResampleToImage> resample;
    resample->SetInputConnection(reader->GetOutputPort());
    resample->Update();
    check.True(Contains(reader->GetLastError(), "file not found"), "message through a pipeline");
  }

  vtkLogger::RemoveCallback("plume-test-capture");
  const std::string printed = window->GetOutput() + logged;
  check.Context = "VTK output";
  check.True(!Contains(printed, "returned failure for request"),
    "no executive request dump; VTK printed:\n" + printed);

  vtkOutputWindow::SetInstance(nullptr);
  if (check.Failures)
  {
    std::cerr << check.Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
