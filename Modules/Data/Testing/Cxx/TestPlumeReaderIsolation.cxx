// vtkPlumeFormatCheck::RunIsolated, the crash isolation of the formats no
// structural check covers: a crash, an exit() and a hang of the read become
// one sentence; a read that returns passes its result back. Then the dataset
// reader on files of those formats written here (HDF5 Exodus signature,
// VRML and ASCII EnSight that a reader rejects): one error, no second read.
#include "plumeDataTestUtilities.h"

#include "vtkPlumeFormatCheck.h"

#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <unistd.h>

using plumetest::Checker;

namespace
{
bool MessageContains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

int TestPlumeReaderIsolation(int, char*[])
{
  Checker check;
  vtkObject::GlobalWarningDisplayOff();

  check.Context = "RunIsolated";
  std::string result = "stale";
  std::string why = vtkPlumeFormatCheck::RunIsolated([]() { return std::string("reader said no"); }, &result);
  check.True(why.empty(), "a read that returns: \"\", got '" + why + "'");
  check.Equal(result, std::string("reader said no"), "its result is passed back");

  why = vtkPlumeFormatCheck::RunIsolated(
    []() {
      std::raise(SIGSEGV);
      return std::string();
    },
    &result);
  check.True(MessageContains(why, "crashed (signal " + std::to_string(SIGSEGV)), "a SIGSEGV: '" + why + "'");
  check.True(result.empty(), "no result from a crash");

  why = vtkPlumeFormatCheck::RunIsolated([]() {
    std::exit(3); // as the CGNS library does on some files
    return std::string();
  });
  check.True(MessageContains(why, "ended the process (exit code 3)"), "an exit(3): '" + why + "'");

  const auto t0 = std::chrono::steady_clock::now();
  why = vtkPlumeFormatCheck::RunIsolated(
    []() {
      std::this_thread::sleep_for(std::chrono::seconds(60));
      return std::string();
    },
    nullptr, 0.5);
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  check.True(MessageContains(why, "did not finish within 0.5 s (PLUME_READER_TIMEOUT)"), "a hang: '" + why + "'");
  check.True(waited < 10, "the hang is stopped at the limit (" + std::to_string(waited) + " s)");

  // the parent's state is untouched by what the child did
  int counter = 0;
  why = vtkPlumeFormatCheck::RunIsolated([&]() {
    counter = 42;
    return std::string();
  });
  check.True(why.empty() && counter == 0, "the child writes its own copy of memory");

  // ---- the dataset reader on exposed formats written here
  char folderTemplate[] = "/tmp/plume-isolation-XXXXXX";
  const std::string folder = mkdtemp(folderTemplate);
  auto read = [&](const std::string& file, bool isolate) {
    vtkNew<vtkPlumeDatasetReader> reader;
    reader->SetFileName(file.c_str());
    reader->SetIsolateReaders(isolate);
    const int ok = reader->GetExecutive()->Update();
    return ok ? std::string() : reader->GetLastError();
  };
  check.Context = "reader";
  {
    // an HDF5 signature under .ex2 is not netCDF classic: isolated, not checked
    const std::string file = folder + "/forged.ex2";
    std::ofstream(file, std::ios::binary) << std::string("\x89HDF\r\n\x1a\n", 8) << std::string(512, '\x7f');
    check.True(!vtkPlumeFormatCheck::IsNetCDFClassic(file), "not netCDF classic");
    const std::string message = read(file, true);
    check.True(MessageContains(message, "the exodus reader cannot read " + file + ": ") &&
        !MessageContains(message, "no details"),
      "the Exodus reader's own reason, from the child: '" + message + "'");
  }
  {
    const std::string file = folder + "/broken.wrl";
    std::ofstream(file) << "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 } } }\n";
    const std::string message = read(file, true);
    check.True(MessageContains(message, "the VRML importer found no geometry in " + file) && MessageContains(message, "parse error"),
      "VRML: the parser's reason in the one message: '" + message + "'");
  }
  {
    // inline XML is detected (and appended XML is not)
    const std::string inlineFile = folder + "/inline.vtp";
    std::ofstream(inlineFile) << "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"1\">"
                                 "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
                                 "0 0 0</DataArray></Points></Piece></PolyData></VTKFile>\n";
    check.True(vtkPlumeFormatCheck::HasInlineXMLData(inlineFile), "format=\"ascii\" is inline");
    const std::string appendedFile = folder + "/appended.vtp";
    std::ofstream(appendedFile) << "<VTKFile><DataArray format=\"appended\" offset=\"0\"/><AppendedData encoding=\"raw\">"
                                   "_format=\"ascii\"</AppendedData></VTKFile>\n";
    check.True(!vtkPlumeFormatCheck::HasInlineXMLData(appendedFile), "appended only (the payload is not markup)");
  }
  return check.Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
