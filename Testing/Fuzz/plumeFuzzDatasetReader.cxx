// libFuzzer target: the dataset reader front (vtkPlumeDatasetReader with the
// checks it runs before and after VTK's readers). The first byte picks the
// format, the rest is the file: legacy .vtk, XML .vtp/.vtu/.vti, Exodus .ex2,
// EnSight Gold geometry (under a fixed .case), .pvd, PLOT3D .bin. A bad file
// must give GetLastError(); a crash or a sanitizer report is a finding. The
// output, when there is one, must pass vtkPlumeInputValidation (the reader
// promises consistent data), and what passes goes through what the
// representations run first (the surface filter, the resampling onto an 8^3
// image that glyphs and volumes use): data the validation lets through must
// not crash them (cells with fewer points than their type did).
#include "vtkPlumeDatasetReader.h"
#include "vtkPlumeInputValidation.h"

#include "vtkPlumeResampleToImage.h"

#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkSMPTools.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
std::string folder;
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  setenv("PLUME_MEMORY_BUDGET_MB", "64", 1);
  // One thread: code run by vtkSMPTools' worker threads (Debian's VTK links TBB)
  // gives coverage that depends on scheduling, so libFuzzer's feedback, and
  // with it the inputs a fixed seed explores, would differ from run to run.
  vtkSMPTools::SetBackend("Sequential");
  // A hanging reader in the isolated child (exposed formats) becomes a quick
  // clear error ("did not finish within 10 s") instead of libFuzzer's timeout.
  setenv("PLUME_READER_TIMEOUT", "10", 0);
  vtkObject::GlobalWarningDisplayOff();
  // The files go to one folder per working directory (run_fuzzer.sh: one per
  // test), not a random one: libFuzzer records the bytes compared by strcmp and
  // memcmp for its mutations, and a random path among them would change what a
  // fixed seed explores.
  char cwd[4096];
  folder = std::string(getcwd(cwd, sizeof(cwd)) ? cwd : "/tmp") + "/plume-fuzz-reader-files";
  mkdir(folder.c_str(), 0700);
  std::ofstream(folder + "/data.case") << "FORMAT\ntype:  ensight gold\nGEOMETRY\nmodel: data.geo\n";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  static const char* const extensions[] = { "vtk", "vtp", "vtu", "vti", "ex2", "geo", "pvd", "bin" };
  const std::string ext = extensions[data[0] % 8];
  const std::string file = folder + "/data." + ext;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  vtkNew<vtkPlumeDatasetReader> reader;
  reader->SetFileName(ext == "geo" ? (folder + "/data.case").c_str() : file.c_str());
  reader->Update();
  vtkDataObject* output = reader->GetOutputDataObject(0);
  if (reader->GetLastError().empty() && output)
  {
    const std::string invalid = vtkPlumeInputValidation::CheckDataObject(output, true);
    if (!invalid.empty())
    {
      std::fprintf(stderr, "reader output fails validation: %s\n", invalid.c_str());
      std::abort();
    }
    if (auto* data = vtkDataSet::SafeDownCast(output))
    {
      if (data->GetNumberOfCells() > 0 && data->GetNumberOfCells() < 100000)
      {
        vtkNew<vtkDataSetSurfaceFilter> surface;
        surface->SetInputData(data);
        surface->Update();
        vtkNew<vtkPlumeResampleToImage> resample;
        resample->SetInputData(data);
        resample->SetSamplingDimensions(8, 8, 8);
        resample->Update();
      }
    }
  }
  return 0;
}
