#include "vtkPlumeDatasetReader.h"

#include "vtkPlumeFormatCheck.h"
#include "vtkPlumeInputValidation.h"

#include "vtkAppendFilter.h"
#include "vtkCGNSReader.h"
#include "vtkCallbackCommand.h"
#include "vtkPlumeQuietExecutive.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSet.h"
#include "vtkDataSetReader.h"
#include "vtkPolyData.h"
#include "vtkVRMLImporter.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTransform.h"
#include "vtkRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkMapper.h"
#include "vtkActorCollection.h"
#include "vtkActor.h"
#include "vtkExecutive.h"
#include "vtkExodusIIReader.h"
#include "vtkGenericEnSightReader.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenFOAMReader.h"
#include "vtkOutputWindow.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLGenericDataObjectReader.h"

#include <cstdio>
#include <unistd.h>
#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <new>
#include <cstring>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>
#include <set>

vtkStandardNewMacro(vtkPlumeDatasetReader);

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Join(const std::vector<std::string>& items, const char* separator = ", ")
{
  std::string out;
  for (size_t i = 0; i < items.size(); ++i)
  {
    out += (i ? separator : "") + items[i];
  }
  return out;
}

std::string Number(double v)
{
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// A PVD DataSet entry.
struct PvdEntry
{
  double Time = 0;
  std::string File;
  std::string Name;
};

// One leaf of a composite dataset, with the names of its ancestors.
struct Leaf
{
  std::string Path;               // "/"-joined names (index when unnamed)
  std::vector<std::string> Names; // ancestor names then own name (named levels only)
  vtkDataObject* Data = nullptr;
  bool Selected = false;
};

const char* ChildName(vtkDataObject* parent, unsigned int i)
{
  return vtkPlumeDatasetReader::GetChildBlockName(parent, i);
}

void CollectLeaves(vtkDataObject* node, const std::string& path,
  const std::vector<std::string>& names, std::vector<Leaf>& leaves)
{
  std::vector<std::pair<vtkDataObject*, const char*>> children;
  if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < mb->GetNumberOfBlocks(); ++i)
    {
      children.emplace_back(mb->GetBlock(i), ChildName(mb, i));
    }
  }
  else if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < pdc->GetNumberOfPartitionedDataSets(); ++i)
    {
      children.emplace_back(pdc->GetPartitionedDataSet(i), ChildName(pdc, i));
    }
  }
  else if (auto* pd = vtkPartitionedDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < pd->GetNumberOfPartitions(); ++i)
    {
      children.emplace_back(pd->GetPartitionAsDataObject(i), ChildName(pd, i));
    }
  }
  else
  {
    if (node)
    {
      Leaf leaf;
      leaf.Path = path;
      leaf.Names = names;
      leaf.Data = node;
      leaves.push_back(leaf);
    }
    return;
  }
  for (size_t i = 0; i < children.size(); ++i)
  {
    const char* name = children[i].second;
    const std::string component = (name && *name) ? std::string(name) : std::to_string(i);
    std::vector<std::string> childNames = names;
    if (name && *name)
    {
      childNames.emplace_back(name);
    }
    CollectLeaves(children[i].first, path.empty() ? component : path + "/" + component,
      childNames, leaves);
  }
}

bool LeafHasPoints(vtkDataObject* data)
{
  auto* ds = vtkDataSet::SafeDownCast(data);
  return ds && ds->GetNumberOfPoints() > 0;
}

vtkIdType CountPoints(vtkDataObject* data)
{
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    return ds->GetNumberOfPoints();
  }
  vtkIdType n = 0;
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
      {
        n += ds->GetNumberOfPoints();
      }
    }
  }
  return n;
}

// A copy that shares the arrays but none of the objects with `source`, so a later execution
// of the inner reader cannot change what this algorithm has output.
vtkSmartPointer<vtkDataObject> IndependentCopy(vtkDataObject* source)
{
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(source->NewInstance());
  copy->ShallowCopy(source);
  if (auto* cds = vtkCompositeDataSet::SafeDownCast(copy))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cds->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkDataObject* leaf = it->GetCurrentDataObject();
      vtkSmartPointer<vtkDataObject> leafCopy;
      leafCopy.TakeReference(leaf->NewInstance());
      leafCopy->ShallowCopy(leaf);
      cds->SetDataSet(it, leafCopy);
    }
  }
  return copy;
}
}

//------------------------------------------------------------------------------
struct vtkPlumeDatasetReader::Internals
{
  vtkPlumeDatasetReader* Self = nullptr;
  vtkSmartPointer<vtkAlgorithm> Reader; // inner reader (not used for pvd)
  std::string Key;                       // what Reader was made for
  std::string Kind;                      // resolved reader name
  std::string Path;                      // FileName
  std::string QPath;                     // PLOT3D solution file ("" = none)
  std::set<int> ProbedSteps;             // time steps of Reader already read in a child

  std::vector<double> PvdTimes;
  std::vector<std::vector<PvdEntry>> PvdSteps;

  vtkNew<vtkCallbackCommand> ErrorObserver;
  vtkNew<vtkCallbackCommand> ProgressObserver;
  vtkNew<vtkCallbackCommand> ExecutiveObserver;
  std::string Captured;
  double ProgressOffset = 0;
  double ProgressScale = 1;

  static void OnError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<Internals*>(clientData);
    std::string message = callData ? static_cast<const char*>(callData) : "unknown error";
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    // VTK's messages start with "ERROR: In <file>, line N\n<class> (<address>): text".
    const size_t paren = message.find("): ");
    if (message.compare(0, 6, "ERROR:") == 0 && paren != std::string::npos)
    {
      message = message.substr(paren + 3);
    }
    if (self->Captured.empty())
    {
      self->Captured = message;
    }
  }

  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<Internals*>(clientData);
    const double p = callData ? *static_cast<double*>(callData) : 0.0;
    self->Self->UpdateProgress(self->ProgressOffset + self->ProgressScale * p);
  }

  // Executive errors of the inner readers: the "returned failure for request" dump is
  // dropped (the reader's own message says why), anything else is captured.
  static void OnExecutiveError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    const char* message = static_cast<const char*>(callData);
    if (message && std::string(message).find("returned failure for request") != std::string::npos)
    {
      return;
    }
    OnError(nullptr, 0, clientData, callData);
  }

  void Watch(vtkAlgorithm* algorithm, bool progress = true)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->ErrorObserver);
    if (progress)
    {
      algorithm->AddObserver(vtkCommand::ProgressEvent, this->ProgressObserver);
    }
    vtkNew<vtkCompositeDataPipeline> executive;
    executive->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveObserver);
    algorithm->SetExecutive(executive);
  }

  std::string InnerMessage() const
  {
    return this->Captured.empty() ? std::string() : ": " + this->Captured;
  }
};

namespace
{
// VTK's legacy reader reports a truncated or corrupt file only through
// vtkGenericWarningMacro ("Error reading binary data!"), which reaches the
// output window, not the reader's observers. While a read runs, this window
// stands in for the current one: it forwards every message and remembers
// generic warnings about reading, so a damaged file fails instead of loading
// half-filled arrays.
class ReadWarningCatcher : public vtkOutputWindow
{
public:
  static ReadWarningCatcher* New()
  {
    auto* self = new ReadWarningCatcher;
    self->InitializeObjectBase();
    return self;
  }
  vtkTypeMacro(ReadWarningCatcher, vtkOutputWindow);

  std::string Caught;
  vtkSmartPointer<vtkOutputWindow> Previous;

  void DisplayText(const char* text) override { this->Previous->DisplayText(text); }
  // Errors of readers made inside the reader (vtkDataSetReader's vtkStructuredPointsReader,
  // "Number of points don't match data values!") reach no observer either.
  void DisplayErrorText(const char* text) override
  {
    this->Remember(text);
    this->Previous->DisplayErrorText(text);
  }
  void DisplayWarningText(const char* text) override { this->Previous->DisplayWarningText(text); }
  void DisplayDebugText(const char* text) override { this->Previous->DisplayDebugText(text); }
  void DisplayGenericWarningText(const char* text) override
  {
    if (text && std::strstr(text, "Error reading"))
    {
      this->Remember(text);
    }
    this->Previous->DisplayGenericWarningText(text);
  }

private:
  void Remember(const char* text)
  {
    if (!text || !this->Caught.empty())
    {
      return;
    }
    std::string message = text;
    // keep the last line (the message itself, not VTK's file and line) without "vtkClass (0x...): "
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
    {
      message.pop_back();
    }
    const auto newline = message.rfind('\n');
    message = newline == std::string::npos ? message : message.substr(newline + 1);
    const auto object = message.find("): ");
    if (message.compare(0, 3, "vtk") == 0 && object != std::string::npos && message.find(" (0x") < object)
    {
      message = message.substr(object + 3);
    }
    this->Caught = message;
  }
};

// Installs a ReadWarningCatcher for its lifetime.
class ScopedReadWarningCatcher
{
public:
  ScopedReadWarningCatcher()
  {
    this->Catcher->Previous = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(this->Catcher);
  }
  ~ScopedReadWarningCatcher() { vtkOutputWindow::SetInstance(this->Catcher->Previous); }
  const std::string& Caught() const { return this->Catcher->Caught; }

private:
  vtkNew<ReadWarningCatcher> Catcher;
};

// The VTK reader for a resolved kind (not "vrml" or "pvd"), configured as Plume reads it.
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& kind, const std::string& path, const std::string& qPath)
{
  if (kind == "legacy")
  {
    auto reader = vtkSmartPointer<vtkDataSetReader>::New();
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllNormalsOn();
    reader->ReadAllTensorsOn();
    reader->ReadAllColorScalarsOn();
    reader->ReadAllTCoordsOn();
    reader->ReadAllFieldsOn();
    return reader;
  }
  if (kind == "xml")
  {
    auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (kind == "plot3d")
  {
    auto reader = vtkSmartPointer<vtkMultiBlockPLOT3DReader>::New();
    reader->SetXYZFileName(path.c_str());
    if (!qPath.empty())
    {
      reader->SetQFileName(qPath.c_str());
    }
    reader->AutoDetectFormatOn();
    reader->SetScalarFunctionNumber(100); // density
    reader->SetVectorFunctionNumber(200); // velocity
    reader->AddFunction(110);             // pressure
    reader->AddFunction(120);             // temperature
    return reader;
  }
  if (kind == "exodus")
  {
    auto reader = vtkSmartPointer<vtkExodusIIReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (kind == "ensight")
  {
    auto reader = vtkSmartPointer<vtkGenericEnSightReader>::New();
    reader->SetCaseFileName(path.c_str());
    return reader;
  }
  if (kind == "openfoam")
  {
    auto reader = vtkSmartPointer<vtkOpenFOAMReader>::New();
    reader->SetFileName(path.c_str());
    reader->CreateCellToPointOn();
    return reader;
  }
  if (kind == "cgns")
  {
    auto reader = vtkSmartPointer<vtkCGNSReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  return nullptr;
}

// Array and block selections, known only after the reader's RequestInformation.
void SelectArrays(vtkAlgorithm* reader, bool patches)
{
  if (auto* exodus = vtkExodusIIReader::SafeDownCast(reader))
  {
    exodus->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
    exodus->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  }
  else if (auto* cgns = vtkCGNSReader::SafeDownCast(reader))
  {
    cgns->EnableAllCellArrays();
    cgns->EnableAllPointArrays();
  }
  else if (auto* foam = vtkOpenFOAMReader::SafeDownCast(reader))
  {
    foam->EnableAllCellArrays();
    foam->EnableAllPointArrays();
    // Patches only when blocks were asked for by name (they duplicate boundary points).
    for (int i = 0; i < foam->GetNumberOfPatchArrays(); ++i)
    {
      const char* name = foam->GetPatchArrayName(i);
      const bool internal = name && std::string(name) == "internalMesh";
      foam->SetPatchArrayStatus(name, (internal || patches) ? 1 : 0);
    }
  }
}

// The formats VTK 9.1 reads unsafely and no structural check here covers:
// HDF5 (netCDF-4) Exodus, EnSight (the check covers C-binary unstructured
// geometry only), XML with inline arrays, PLOT3D solution (Q) files,
// OpenFOAM, CGNS and VRML; legacy files that may hold a FIELD section.
bool IsExposed(const std::string& kind, const std::string& path, const std::string& qPath)
{
  if (kind == "legacy")
  {
    return vtkPlumeFormatCheck::MayHoldLegacyFieldData(path);
  }
  if (kind == "exodus")
  {
    return !vtkPlumeFormatCheck::IsNetCDFClassic(path);
  }
  if (kind == "xml")
  {
    return vtkPlumeFormatCheck::HasInlineXMLData(path);
  }
  if (kind == "plot3d")
  {
    return !qPath.empty();
  }
  return kind == "ensight" || kind == "openfoam" || kind == "cgns" || kind == "vrml";
}

// PLUME_READER_ISOLATION=0 reads every format in process (e.g. to debug a reader).
bool IsolationEnabled()
{
  const char* env = std::getenv("PLUME_READER_ISOLATION");
  return !(env && std::string(env) == "0");
}

vtkSmartPointer<vtkDataObject> ImportVRML(const std::string& path, std::string& error);

// The first error message a reader reports (VTK's "ERROR: In file, line N\nclass (0x..): " dropped).
struct FirstError : public vtkCommand
{
  static FirstError* New() { return new FirstError; }
  std::string Message;
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    std::string message = callData ? static_cast<const char*>(callData) : "unknown error";
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    const size_t paren = message.find("): ");
    if (message.compare(0, 6, "ERROR:") == 0 && paren != std::string::npos)
    {
      message = message.substr(paren + 3);
    }
    if (this->Message.empty() && message.find("returned failure for request") == std::string::npos)
    {
      this->Message = message;
    }
  }
};

// The number of points of a whole extent, in double (an absurd header overflows any integer).
double ExtentPoints(const int* we)
{
  double points = 1;
  for (int a = 0; a < 3; ++a)
  {
    points *= std::max(0.0, double(we[2 * a + 1]) - double(we[2 * a]) + 1.0);
  }
  return points;
}

// What the in-process read will do, in the child of RunIsolated(); returns the
// reader's first error, "" when it read without one (or stopped before reading
// on a problem the in-process read reports itself). `time`: the time step to
// read (nullptr: the reader's default, its first).
std::string ProbeRead(const std::string& kind, const std::string& path, const std::string& qPath, bool patches,
  const double* time = nullptr)
{
  // VTK's error macros invoke no ErrorEvent with the display off; the child's output goes to /dev/null
  vtkObject::GlobalWarningDisplayOn();
  if (kind == "vrml")
  {
    // VTK's VRML parser prints its reason ("Error near line 7: parse error") to stderr: keep it
    std::FILE* log = std::tmpfile();
    if (log)
    {
      std::fflush(stderr);
      dup2(fileno(log), 2);
    }
    std::string error;
    const bool read = ImportVRML(path, error) != nullptr;
    std::string reason;
    if (log)
    {
      std::fflush(stderr);
      std::rewind(log);
      char line[256];
      while (std::fgets(line, sizeof(line), log))
      {
        std::string text(line);
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        {
          text.pop_back();
        }
        if (text.find("rror") != std::string::npos && reason.empty())
        {
          reason = text;
        }
      }
    }
    return read ? std::string() : error + (reason.empty() ? std::string() : " (" + reason + ")");
  }
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(kind, path, qPath);
  if (!reader)
  {
    return std::string();
  }
  vtkNew<FirstError> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  // the XML parser's reason ("Error parsing XML in stream at line ...") comes from an
  // object the reader makes inside itself: it reaches the output window only
  ScopedReadWarningCatcher inner;
  if (!reader->GetExecutive()->UpdateInformation() || reader->GetErrorCode() != 0)
  {
    const std::string& why = errors->Message.empty() ? inner.Caught() : errors->Message;
    return why.empty() ? std::string("the reader failed (no details)") : why;
  }
  if (auto* plot3d = vtkMultiBlockPLOT3DReader::SafeDownCast(reader))
  {
    // a corrupt grid header is refused in process with its own message
    if (plot3d->GetBinaryFile() &&
      !vtkPlumeFormatCheck::CheckPlot3DGrid(path,
        plot3d->GetByteOrder() == vtkMultiBlockPLOT3DReader::FILE_BIG_ENDIAN, plot3d->GetHasByteCount(),
        plot3d->GetMultiGrid(), plot3d->GetTwoDimensionalGeometry(), plot3d->GetDoublePrecision(),
        plot3d->GetIBlanking())
         .empty())
    {
      return std::string();
    }
  }
  // an extent over the memory budget is refused in process, with its own message,
  // before the reader allocates it (under AddressSanitizer that allocation would end
  // the child instead of throwing std::bad_alloc)
  vtkInformation* info = reader->GetOutputInformation(0);
  if (info && info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()) &&
    !vtkPlumeInputValidation::CheckMemory(ExtentPoints(info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())), "")
       .empty())
  {
    return std::string();
  }
  SelectArrays(reader, patches);
  if (time)
  {
    reader->UpdateTimeStep(*time);
  }
  else
  {
    reader->Update();
  }
  return errors->Message;
}

// A VRML scene (vtkVRMLImporter) as data: one polydata block per actor,
// named "actor N", in world coordinates (the actor's matrix applied), so that
// scene geometry such as a room around a CFD domain loads like any dataset.
vtkSmartPointer<vtkDataObject> ImportVRML(const std::string& path, std::string& error)
{
  vtkNew<vtkVRMLImporter> importer;
  importer->SetFileName(path.c_str());
  vtkNew<vtkRenderer> renderer; // the importer fills a renderer; nothing is drawn
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  importer->SetRenderWindow(window);
  importer->Update();
  vtkActorCollection* actors = renderer->GetActors();
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  actors->InitTraversal();
  unsigned int n = 0;
  while (vtkActor* actor = actors->GetNextActor())
  {
    vtkMapper* mapper = actor->GetMapper();
    if (!mapper)
    {
      continue;
    }
    mapper->Update();
    auto* poly = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (!poly || poly->GetNumberOfPoints() == 0)
    {
      continue;
    }
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(actor->GetMatrix());
    vtkNew<vtkTransformPolyDataFilter> move;
    move->SetTransform(transform);
    move->SetInputData(poly);
    move->Update();
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(move->GetOutput());
    blocks->SetBlock(n, copy);
    blocks->GetMetaData(n)->Set(vtkCompositeDataSet::NAME(), ("actor " + std::to_string(n)).c_str());
    ++n;
  }
  if (n == 0)
  {
    error = "the VRML importer found no geometry in " + path;
    return nullptr;
  }
  return blocks;
}

}

//------------------------------------------------------------------------------
vtkPlumeDatasetReader::vtkPlumeDatasetReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
  this->Internal->Self = this;
  this->Internal->ErrorObserver->SetClientData(this->Internal.get());
  this->Internal->ErrorObserver->SetCallback(&Internals::OnError);
  this->Internal->ProgressObserver->SetClientData(this->Internal.get());
  this->Internal->ProgressObserver->SetCallback(&Internals::OnProgress);
  this->Internal->ExecutiveObserver->SetClientData(this->Internal.get());
  this->Internal->ExecutiveObserver->SetCallback(&Internals::OnExecutiveError);
}

vtkPlumeDatasetReader::~vtkPlumeDatasetReader()
{
  this->SetFileName(nullptr);
  this->SetQFileName(nullptr);
  this->SetReaderName(nullptr);
}

//------------------------------------------------------------------------------
void vtkPlumeDatasetReader::SetTimeStep(int step)
{
  if (this->TimeStep != step || this->UseTimeValue)
  {
    this->TimeStep = step;
    this->UseTimeValue = false;
    this->Modified();
  }
}

void vtkPlumeDatasetReader::SetTimeValue(double time)
{
  if (this->TimeValue != time || !this->UseTimeValue)
  {
    this->TimeValue = time;
    this->UseTimeValue = true;
    this->Modified();
  }
}

void vtkPlumeDatasetReader::UnsetTimeValue()
{
  if (this->UseTimeValue)
  {
    this->UseTimeValue = false;
    this->Modified();
  }
}

double vtkPlumeDatasetReader::GetTimeValueAt(int i) const
{
  return (i >= 0 && i < static_cast<int>(this->TimeValues.size())) ? this->TimeValues[i] : 0.0;
}

void vtkPlumeDatasetReader::SetBlockNames(const std::vector<std::string>& names)
{
  if (names != this->BlockNames)
  {
    this->BlockNames = names;
    this->Modified();
  }
}

void vtkPlumeDatasetReader::AddBlockName(const char* name)
{
  if (name)
  {
    this->BlockNames.emplace_back(name);
    this->Modified();
  }
}

void vtkPlumeDatasetReader::ClearBlockNames()
{
  if (!this->BlockNames.empty())
  {
    this->BlockNames.clear();
    this->Modified();
  }
}

const char* vtkPlumeDatasetReader::GetBlockName(int i) const
{
  return (i >= 0 && i < static_cast<int>(this->BlockNames.size())) ? this->BlockNames[i].c_str()
                                                                   : nullptr;
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkPlumeDatasetReader::SupportedExtensions()
{
  return { ".vtk", ".vti", ".vts", ".vtr", ".vtu", ".vtp", ".vtm", ".pvti", ".pvts", ".pvtr",
    ".pvtu", ".pvtp", ".pvd", ".xyz", ".q", ".bin", ".ex2", ".e", ".exo", ".case", ".foam",
    ".cgns", ".wrl" };
}

std::vector<std::string> vtkPlumeDatasetReader::SupportedReaderNames()
{
  return { "legacy", "xml", "pvd", "plot3d", "exodus", "ensight", "openfoam", "cgns", "vrml" };
}

std::string vtkPlumeDatasetReader::ReaderNameForFile(const std::string& fileName)
{
  const std::string ext = Lower(vtksys::SystemTools::GetFilenameLastExtension(fileName));
  if (ext == ".vtk")
  {
    return "legacy";
  }
  if (ext == ".vti" || ext == ".vts" || ext == ".vtr" || ext == ".vtu" || ext == ".vtp" ||
    ext == ".vtm" || ext == ".pvti" || ext == ".pvts" || ext == ".pvtr" || ext == ".pvtu" ||
    ext == ".pvtp")
  {
    return "xml";
  }
  if (ext == ".pvd")
  {
    return "pvd";
  }
  if (ext == ".wrl")
  {
    return "vrml";
  }
  if (ext == ".xyz" || ext == ".q" || ext == ".bin")
  {
    return "plot3d";
  }
  if (ext == ".ex2" || ext == ".e" || ext == ".exo")
  {
    return "exodus";
  }
  if (ext == ".case")
  {
    return "ensight";
  }
  if (ext == ".foam")
  {
    return "openfoam";
  }
  if (ext == ".cgns")
  {
    return "cgns";
  }
  return "";
}

std::string vtkPlumeDatasetReader::GuessQFileName(const std::string& xyz)
{
  const std::string dir = vtksys::SystemTools::GetFilenamePath(xyz);
  std::string name = vtksys::SystemTools::GetFilenameName(xyz);
  const std::string ext = vtksys::SystemTools::GetFilenameLastExtension(name);
  if (Lower(ext) == ".xyz")
  {
    name = name.substr(0, name.size() - ext.size()) + ".q";
  }
  else
  {
    const size_t at = Lower(name).rfind("xyz");
    if (at == std::string::npos)
    {
      return "";
    }
    name.replace(at, 3, "q");
  }
  return dir.empty() ? name : dir + "/" + name;
}

vtkMTimeType vtkPlumeDatasetReader::GetMTime()
{
  return this->Superclass::GetMTime();
}

//------------------------------------------------------------------------------
int vtkPlumeDatasetReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

vtkExecutive* vtkPlumeDatasetReader::CreateDefaultExecutive()
{
  return plume::NewQuietExecutive(); // RequestData reports the one error itself
}

//------------------------------------------------------------------------------
namespace
{
// ADF ("ADF Database Version" after a 4-byte tag) or HDF5 (signature at 0, 512, 1024, ...).
bool LooksLikeCGNS(const std::string& path)
{
  vtksys::ifstream file(path.c_str(), std::ios::in | std::ios::binary);
  if (!file)
  {
    return false;
  }
  char head[32] = {};
  file.read(head, sizeof(head));
  if (file.gcount() >= 24 && std::string(head + 4, 12) == "ADF Database")
  {
    return true;
  }
  static const char hdf5[8] = { '\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n' };
  for (std::streamoff offset = 0; offset <= 8192; offset = offset ? offset * 2 : 512)
  {
    file.clear();
    file.seekg(offset);
    char sig[8] = {};
    file.read(sig, 8);
    if (file.gcount() == 8 && std::equal(sig, sig + 8, hdf5))
    {
      return true;
    }
  }
  return false;
}

// Resolve the reader name and check the files; "" on success, else the message.
std::string Resolve(const char* fileName, const char* qFileName, const char* readerName,
  std::string& kind, std::string& path, std::string& qPath)
{
  kind.clear();
  path.clear();
  qPath.clear();
  if (!fileName || !*fileName)
  {
    return "no file name set";
  }
  path = fileName;
  if (readerName && *readerName)
  {
    const std::string name = Lower(readerName);
    const auto names = vtkPlumeDatasetReader::SupportedReaderNames();
    if (std::find(names.begin(), names.end(), name) == names.end())
    {
      return "unknown reader name '" + std::string(readerName) + "'; expected one of: " +
        Join(names) + " (or empty to choose by extension)";
    }
    kind = name;
  }
  else
  {
    kind = vtkPlumeDatasetReader::ReaderNameForFile(path);
    if (kind.empty())
    {
      const std::string ext = vtksys::SystemTools::GetFilenameLastExtension(path);
      if (Lower(ext) == ".nek5000")
      {
        return "Nek5000 output (" + path + ") has no reader in VTK 9.1 (vtkNek5000Reader came later): "
          "convert it to VTK files (e.g. .vtu + .pvd) first";
      }
      if (vtksys::SystemTools::FileIsDirectory(path))
      {
        // e.g. an OpenFOAM case folder: the reader wants the (possibly empty) .foam file in it
        return path + " is a folder, not a dataset file; for an OpenFOAM case give a .foam file inside it "
          "(create an empty one, e.g. case.foam, if there is none); supported files: " +
          Join(vtkPlumeDatasetReader::SupportedExtensions());
      }
      return "unknown file extension '" + (ext.empty() ? std::string("(none)") : ext) +
        "' of " + path + "; supported: " + Join(vtkPlumeDatasetReader::SupportedExtensions());
    }
  }
  // FIFOs and devices would block or never end; a NUL in the name would read another file.
  std::string notRegular = vtkPlumeInputValidation::CheckRegularFile(path);
  if (!notRegular.empty())
  {
    return notRegular;
  }
  if (kind == "exodus")
  {
    // VTK's Exodus reader indexes points with the stored connectivity and reads cut files as zeros
    const std::string corrupt = vtkPlumeFormatCheck::CheckNetCDFClassic(path);
    if (!corrupt.empty())
    {
      return "corrupt Exodus II file " + path + ": " + corrupt;
    }
  }
  if (kind == "legacy")
  {
    // VTK's legacy reader reads on from a closed file after a short cell list (SEGV)
    const std::string corrupt = vtkPlumeFormatCheck::CheckLegacyVTK(path);
    if (!corrupt.empty())
    {
      return "corrupt legacy VTK file " + path + ": " + corrupt;
    }
  }
  if (kind == "xml")
  {
    // VTK's XML parser trusts appended block headers (SEGV or tens of GB allocated)
    const std::string corrupt = vtkPlumeFormatCheck::CheckXMLAppended(path);
    if (!corrupt.empty())
    {
      return "corrupt VTK XML file " + path + ": " + corrupt;
    }
  }
  if (kind == "ensight")
  {
    // VTK's EnSight reader reads past the end of a cut geometry file (SEGV)
    const std::string corrupt = vtkPlumeFormatCheck::CheckEnSightGold(path);
    if (!corrupt.empty())
    {
      return "corrupt EnSight case " + path + ": " + corrupt;
    }
  }
  if (kind == "cgns" && !LooksLikeCGNS(path))
  {
    // The CGNS library exits the process on some files it cannot parse: check first.
    return "not a CGNS file (neither ADF nor HDF5): " + path;
  }
  if (kind == "plot3d")
  {
    if (qFileName && *qFileName)
    {
      qPath = qFileName;
      if (!vtksys::SystemTools::FileExists(qPath))
      {
        return "PLOT3D solution (Q) file not found: " + qPath;
      }
      notRegular = vtkPlumeInputValidation::CheckRegularFile(qPath);
      if (!notRegular.empty())
      {
        return "PLOT3D solution (Q) file: " + notRegular;
      }
    }
    else
    {
      qPath = vtkPlumeDatasetReader::GuessQFileName(path);
      if (!qPath.empty() && !vtksys::SystemTools::FileExists(qPath, true))
      {
        qPath.clear(); // a guess that does not exist: read the grid only
      }
    }
  }
  return "";
}
}

//------------------------------------------------------------------------------
vtkTypeBool vtkPlumeDatasetReader::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  try
  {
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);
  }
  catch (const std::bad_alloc&)
  {
    this->LastError = "the " + (this->Internal->Kind.empty() ? std::string("dataset") : this->Internal->Kind) +
      " reader ran out of memory reading " + (this->FileName ? this->FileName : "(no file)") +
      " (a header announcing more data than the file holds?)";
    this->Internal->Reader = nullptr; // start from scratch next time
    this->Internal->Key.clear();
    return 0;
  }
}

//------------------------------------------------------------------------------
int vtkPlumeDatasetReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  Internals& in = *this->Internal;

  // Predict the output type; RequestData replaces the object if the prediction was wrong.
  std::string kind, path, qPath;
  std::string predicted = "vtkUnstructuredGrid";
  if (Resolve(this->FileName, this->QFileName, this->ReaderName, kind, path, qPath).empty())
  {
    if (kind == "legacy" || kind == "xml")
    {
      vtkSmartPointer<vtkAlgorithm> probe;
      if (kind == "legacy")
      {
        auto reader = vtkSmartPointer<vtkDataSetReader>::New();
        reader->SetFileName(path.c_str());
        probe = reader;
      }
      else
      {
        auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
        reader->SetFileName(path.c_str());
        probe = reader;
      }
      in.Captured.clear();
      in.Watch(probe, false);
      probe->UpdateDataObject();
      vtkDataObject* data = probe->GetOutputDataObject(0);
      if (data && in.Captured.empty())
      {
        if (data->IsA("vtkStructuredPoints"))
        {
          predicted = "vtkImageData";
        }
        else if (!vtkCompositeDataSet::SafeDownCast(data) || !this->MergeBlocks)
        {
          predicted = data->GetClassName();
        }
      }
      in.Captured.clear();
    }
    else if (kind == "plot3d" && this->MergeBlocks)
    {
      predicted = "vtkStructuredGrid";
    }
    else if (!this->MergeBlocks && kind != "pvd")
    {
      predicted = kind == "ensight" || kind == "exodus" || kind == "openfoam" ||
          kind == "cgns" || kind == "plot3d" || kind == "vrml"
        ? "vtkMultiBlockDataSet"
        : predicted;
    }
  }
  vtkDataObject* current = vtkDataObject::GetData(outInfo);
  if (!current || predicted != current->GetClassName())
  {
    vtkSmartPointer<vtkDataObject> output;
    if (predicted == "vtkImageData")
    {
      output = vtkSmartPointer<vtkImageData>::New();
    }
    else if (predicted == "vtkStructuredGrid")
    {
      output = vtkSmartPointer<vtkStructuredGrid>::New();
    }
    else if (predicted == "vtkUnstructuredGrid")
    {
      output = vtkSmartPointer<vtkUnstructuredGrid>::New();
    }
    else if (predicted == "vtkMultiBlockDataSet")
    {
      output = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    }
    else
    {
      // Any other type the XML/legacy readers produce: create it by name.
      output.TakeReference(vtkDataObjectTypes::NewDataObject(predicted.c_str()));
      if (!output)
      {
        output = vtkSmartPointer<vtkUnstructuredGrid>::New();
      }
    }
    outInfo->Set(vtkDataObject::DATA_OBJECT(), output);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPlumeDatasetReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->LastError.clear();
  this->TimeValues.clear();
  this->ResolvedReader.clear();
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());

  std::string kind, path, qPath;
  std::string error =
    Resolve(this->FileName, this->QFileName, this->ReaderName, kind, path, qPath);
  if (!error.empty())
  {
    this->LastError = error;
    return 0;
  }
  this->ResolvedReader = kind;
  in.Kind = kind;
  in.Path = path;
  in.QPath = qPath;

  if (kind == "vrml")
  {
    // a scene importer, not a pipeline reader: read in RequestData
    in.Reader = nullptr;
    in.Key.clear();
    this->TimeValues.clear();
  }
  else if (kind == "pvd")
  {
    in.Reader = nullptr;
    in.Key.clear();
    in.PvdTimes.clear();
    in.PvdSteps.clear();
    vtkNew<vtkXMLDataParser> parser;
    in.Captured.clear();
    parser->AddObserver(vtkCommand::ErrorEvent, in.ErrorObserver);
    parser->SetFileName(path.c_str());
    vtkXMLDataElement* collection = nullptr;
    if (parser->Parse() && parser->GetRootElement())
    {
      vtkXMLDataElement* root = parser->GetRootElement();
      collection = root->GetName() && std::string(root->GetName()) == "Collection"
        ? root
        : root->FindNestedElementWithName("Collection");
    }
    if (!collection)
    {
      this->LastError = "cannot parse the PVD collection " + path +
        (in.Captured.empty() ? std::string(": no <Collection> element") : in.InnerMessage());
      return 0;
    }
    const std::string dir = vtksys::SystemTools::GetFilenamePath(path);
    std::vector<PvdEntry> entries;
    for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* e = collection->GetNestedElement(i);
      if (!e->GetName() || std::string(e->GetName()) != "DataSet" || !e->GetAttribute("file"))
      {
        continue;
      }
      PvdEntry entry;
      if (!e->GetScalarAttribute("timestep", entry.Time))
      {
        entry.Time = 0;
      }
      entry.File = e->GetAttribute("file");
      if (!vtksys::SystemTools::FileIsFullPath(entry.File) && !dir.empty())
      {
        entry.File = dir + "/" + entry.File;
      }
      const char* name = e->GetAttribute("name");
      const char* part = e->GetAttribute("part");
      entry.Name = name ? name
                        : (part ? std::string("part ") + part
                                : vtksys::SystemTools::GetFilenameWithoutLastExtension(entry.File));
      entries.push_back(entry);
    }
    if (entries.empty())
    {
      this->LastError = "the PVD collection " + path + " lists no DataSet entries with a file";
      return 0;
    }
    std::stable_sort(entries.begin(), entries.end(),
      [](const PvdEntry& a, const PvdEntry& b) { return a.Time < b.Time; });
    for (const auto& entry : entries)
    {
      if (in.PvdTimes.empty() || entry.Time != in.PvdTimes.back())
      {
        in.PvdTimes.push_back(entry.Time);
        in.PvdSteps.emplace_back();
      }
      in.PvdSteps.back().push_back(entry);
    }
    this->TimeValues = in.PvdTimes;
  }
  else
  {
    const std::string key = kind + "\n" + path + "\n" + qPath;
    if (!in.Reader || key != in.Key)
    {
      in.Reader = nullptr;
      in.Key = key;
      in.Reader = MakeReader(kind, path, qPath);
      in.ProbedSteps.clear();
      // formats no structural check covers: a first read in a child process
      // turns a crash of VTK's reader into one error
      if (this->IsolateReaders && IsExposed(kind, path, qPath) && IsolationEnabled())
      {
        const bool patches = !this->BlockNames.empty();
        std::string readError;
        const std::string crashed = vtkPlumeFormatCheck::RunIsolated(
          [&]() { return ProbeRead(kind, path, qPath, patches); }, &readError);
        if (!crashed.empty() || !readError.empty())
        {
          // a failed read is reported from the child: the libraries' own
          // prints (HDF5, CGNS, Exodus) went to its /dev/null
          this->LastError = !crashed.empty()
            ? "the " + kind + " reader " + crashed + " reading " + path + " in a child process (a corrupt file?); not read"
            : "the " + kind + " reader cannot read " + path + ": " + readError;
          in.Reader = nullptr;
          in.Key.clear();
          return 0;
        }
      }
      in.Watch(in.Reader);
    }

    in.Captured.clear();
    in.ProgressOffset = 0;
    in.ProgressScale = 1;
    int ok = 0;
    std::string inner; // the XML parser's reason reaches the output window only
    {
      ScopedReadWarningCatcher catcher;
      ok = in.Reader->GetExecutive()->UpdateInformation();
      inner = catcher.Caught();
    }
    if (!ok || !in.Captured.empty() || in.Reader->GetErrorCode() != 0)
    {
      this->LastError = "the " + kind + " reader cannot read " + path +
        (!in.Captured.empty() ? in.InnerMessage()
            : inner.empty() ? std::string(" (no details)")
                            : ": " + inner);
      in.Reader = nullptr; // start from scratch next time
      in.Key.clear();
      return 0;
    }

    // The grid header as the reader understood it (it sizes a memset from it unchecked).
    if (auto* plot3d = vtkMultiBlockPLOT3DReader::SafeDownCast(in.Reader))
    {
      const std::string corrupt = plot3d->GetBinaryFile()
        ? vtkPlumeFormatCheck::CheckPlot3DGrid(path,
            plot3d->GetByteOrder() == vtkMultiBlockPLOT3DReader::FILE_BIG_ENDIAN, plot3d->GetHasByteCount(),
            plot3d->GetMultiGrid(), plot3d->GetTwoDimensionalGeometry(), plot3d->GetDoublePrecision(),
            plot3d->GetIBlanking())
        : std::string();
      if (!corrupt.empty())
      {
        this->LastError = "corrupt PLOT3D file " + path + ": " + corrupt;
        in.Reader = nullptr;
        in.Key.clear();
        return 0;
      }
    }
    SelectArrays(in.Reader, !this->BlockNames.empty());

    vtkInformation* innerInfo = in.Reader->GetOutputInformation(0);
    if (innerInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    {
      const double* steps = innerInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      const int n = innerInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      this->TimeValues.assign(steps, steps + n);
    }
    // Structured single datasets: announce their extent and geometry downstream.
    vtkDataObject* innerData = in.Reader->GetOutputDataObject(0);
    if (innerData && !vtkCompositeDataSet::SafeDownCast(innerData) &&
      innerInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()) &&
      (vtkImageData::SafeDownCast(innerData) || vtkStructuredGrid::SafeDownCast(innerData) ||
        vtkRectilinearGrid::SafeDownCast(innerData)))
    {
      // A header may announce any extent: refuse one whose points cannot fit before the
      // reader allocates them (one byte per point, the least any point array takes; the
      // renderers check their own, larger needs later).
      const int* we = innerInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
      const double points = ExtentPoints(we);
      const std::string tooBig = vtkPlumeInputValidation::CheckMemory(points,
        "the extent [" + std::to_string(we[0]) + ", " + std::to_string(we[1]) + ", " + std::to_string(we[2]) +
          ", " + std::to_string(we[3]) + ", " + std::to_string(we[4]) + ", " + std::to_string(we[5]) +
          "] in " + path + " (" + Number(points) + " points)");
      if (!tooBig.empty())
      {
        this->LastError = tooBig;
        in.Reader = nullptr;
        in.Key.clear();
        return 0;
      }
      outInfo->CopyEntry(innerInfo, vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
      if (innerInfo->Has(vtkDataObject::ORIGIN()))
      {
        outInfo->CopyEntry(innerInfo, vtkDataObject::ORIGIN());
      }
      if (innerInfo->Has(vtkDataObject::SPACING()))
      {
        outInfo->CopyEntry(innerInfo, vtkDataObject::SPACING());
      }
    }
  }

  if (!this->TimeValues.empty())
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->TimeValues.data(),
      static_cast<int>(this->TimeValues.size()));
    const double range[2] = { this->TimeValues.front(), this->TimeValues.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPlumeDatasetReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->LastError.clear();
  this->AvailableBlocks.clear();
  this->TimeStepRead = -1;
  auto fail = [&](const std::string& message) {
    this->LastError = message;
    if (vtkDataObject* output = vtkDataObject::GetData(outInfo))
    {
      output->Initialize();
    }
    return 0;
  };
  if (in.Kind.empty() || (in.Kind != "pvd" && in.Kind != "vrml" && !in.Reader))
  {
    return fail("no reader (RequestInformation failed)");
  }

  // --- which step
  const std::vector<double>& times = this->TimeValues;
  const int n = static_cast<int>(times.size());
  auto nearest = [&](double t) {
    int best = 0;
    for (int i = 1; i < n; ++i)
    {
      if (std::fabs(times[i] - t) < std::fabs(times[best] - t))
      {
        best = i;
      }
    }
    return best;
  };
  int step = 0;
  if (n > 0 && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    step = nearest(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  }
  else if (this->UseTimeValue)
  {
    if (n == 0)
    {
      return fail("time value " + Number(this->TimeValue) + " requested but " + in.Path +
        " has no time steps");
    }
    const double span = times.back() - times.front();
    const double tolerance = 1e-9 * std::max(span, std::fabs(times.back())) + 1e-12;
    if (this->TimeValue < times.front() - tolerance || this->TimeValue > times.back() + tolerance)
    {
      return fail("time value " + Number(this->TimeValue) + " out of range: valid " +
        Number(times.front()) + " to " + Number(times.back()) + " (" + std::to_string(n) +
        " time steps)");
    }
    step = nearest(this->TimeValue);
  }
  else
  {
    const int count = std::max(n, 1);
    if (this->TimeStep < 0 || this->TimeStep >= count)
    {
      return fail(n == 0 ? "time step " + std::to_string(this->TimeStep) + " requested but " + in.Path +
            " has no time steps (it holds one dataset: leave the time step at 0)"
                         : "time step " + std::to_string(this->TimeStep) + " out of range: valid 0 to " +
            std::to_string(n - 1) + " (" + in.Path + " has " + std::to_string(n) + " time steps)");
    }
    step = this->TimeStep;
  }

  // --- read
  vtkSmartPointer<vtkDataObject> data;
  in.Captured.clear();
  if (in.Kind == "vrml")
  {
    std::string error;
    if (this->IsolateReaders && IsolationEnabled())
    {
      // VTK's VRML parser has no structural check here: a first read in a child process
      const std::string path = in.Path;
      std::string readError;
      const std::string crashed = vtkPlumeFormatCheck::RunIsolated(
        [&]() { return ProbeRead("vrml", path, std::string(), false); }, &readError);
      if (!crashed.empty())
      {
        return fail("the vrml importer " + crashed + " reading " + path + " in a child process (a corrupt file?); not read");
      }
      if (!readError.empty())
      {
        return fail(readError);
      }
    }
    data = ImportVRML(in.Path, error);
    if (!data)
    {
      return fail(error);
    }
  }
  else if (in.Kind == "pvd")
  {
    const auto& entries = in.PvdSteps[step];
    std::vector<vtkSmartPointer<vtkDataObject>> parts;
    for (size_t i = 0; i < entries.size(); ++i)
    {
      std::string notRegular = vtkPlumeInputValidation::CheckRegularFile(entries[i].File);
      if (notRegular.empty())
      {
        notRegular = vtkPlumeFormatCheck::CheckXMLAppended(entries[i].File);
        notRegular = notRegular.empty() ? notRegular : "corrupt VTK XML file " + entries[i].File + ": " + notRegular;
      }
      if (!notRegular.empty())
      {
        return fail(notRegular + " (listed in " + in.Path + ")");
      }
      if (this->IsolateReaders && IsolationEnabled() && vtkPlumeFormatCheck::HasInlineXMLData(entries[i].File))
      {
        const std::string file = entries[i].File;
        std::string readError;
        const std::string crashed = vtkPlumeFormatCheck::RunIsolated(
          [&]() { return ProbeRead("xml", file, std::string(), false); }, &readError);
        if (!crashed.empty() || !readError.empty())
        {
          return fail(!crashed.empty() ? "the xml reader " + crashed + " reading " + file + " (listed in " +
                in.Path + ") in a child process (a corrupt file?); not read"
                                       : "the xml reader cannot read " + file + " (listed in " + in.Path + "): " + readError);
        }
      }
      vtkNew<vtkXMLGenericDataObjectReader> reader;
      reader->SetFileName(entries[i].File.c_str());
      in.Watch(reader);
      in.ProgressOffset = double(i) / entries.size();
      in.ProgressScale = 1.0 / entries.size();
      try
      {
        reader->Update();
      }
      catch (const std::bad_alloc&)
      {
        return fail("the xml reader ran out of memory reading " + entries[i].File + " (listed in " + in.Path +
          "; a header announcing more data than the file holds?)");
      }
      vtkDataObject* part = reader->GetOutputDataObject(0);
      if (!part || !in.Captured.empty() || reader->GetErrorCode() != 0)
      {
        return fail("the xml reader produced no data from " + entries[i].File + " (listed in " +
          in.Path + ")" + in.InnerMessage());
      }
      parts.push_back(IndependentCopy(part));
    }
    if (parts.size() == 1)
    {
      data = parts[0];
    }
    else
    {
      auto mb = vtkSmartPointer<vtkMultiBlockDataSet>::New();
      mb->SetNumberOfBlocks(static_cast<unsigned int>(parts.size()));
      for (size_t i = 0; i < parts.size(); ++i)
      {
        mb->SetBlock(static_cast<unsigned int>(i), parts[i]);
        mb->GetMetaData(static_cast<unsigned int>(i))
          ->Set(vtkCompositeDataSet::NAME(), entries[i].Name.c_str());
      }
      data = mb;
    }
  }
  else
  {
    if (n > 1 && this->IsolateReaders && IsExposed(in.Kind, in.Path, in.QPath) && IsolationEnabled() &&
      in.ProbedSteps.count(step) == 0)
    {
      // RequestInformation's read in a child covered the reader's first step
      // only: each step of a series is its own files (EnSight, OpenFOAM) or
      // blocks (HDF5 Exodus), as exposed as the first
      const bool patches = !this->BlockNames.empty();
      const double time = times[step];
      const std::string kind = in.Kind, path = in.Path, qPath = in.QPath;
      std::string readError;
      const std::string crashed = vtkPlumeFormatCheck::RunIsolated(
        [&]() { return ProbeRead(kind, path, qPath, patches, &time); }, &readError);
      if (!crashed.empty() || !readError.empty())
      {
        in.Reader->Modified(); // nothing of this step was read here
        const std::string which = "time step " + std::to_string(step) + " (t = " + Number(time) + ") of " + path;
        return fail(!crashed.empty()
            ? "the " + kind + " reader " + crashed + " reading " + which + " in a child process (a corrupt file?); not read"
            : "the " + kind + " reader cannot read " + which + ": " + readError);
      }
      in.ProbedSteps.insert(step);
    }
    in.ProgressOffset = 0;
    in.ProgressScale = 1;
    ScopedReadWarningCatcher warnings;
    int ok = 0;
    try
    {
      ok = n > 0 ? in.Reader->UpdateTimeStep(times[step]) : in.Reader->GetExecutive()->Update();
    }
    catch (const std::bad_alloc&)
    {
      // VTK's readers allocate what a header announces (e.g. an XML compressed-block count)
      in.Reader = nullptr;
      in.Key.clear();
      return fail("the " + in.Kind + " reader ran out of memory reading " + in.Path +
        " (a header announcing more data than the file holds?)");
    }
    vtkDataObject* produced = in.Reader->GetOutputDataObject(0);
    if (!warnings.Caught().empty())
    {
      in.Reader->Modified(); // a later Update must read again, not keep the damaged output
      return fail("the " + in.Kind + " reader could not read all of " + in.Path +
        " (truncated or corrupt?): " + warnings.Caught());
    }
    if (!ok || !produced || !in.Captured.empty() || in.Reader->GetErrorCode() != 0)
    {
      const std::string what = in.Kind == "plot3d" && !in.QPath.empty()
        ? in.Path + " and " + in.QPath
        : in.Path;
      return fail("the " + in.Kind + " reader produced no data from " + what +
        (in.Captured.empty() ? std::string() : in.InnerMessage()));
    }
    data = IndependentCopy(produced);
  }
  if (CountPoints(data) == 0)
  {
    return fail("the " + in.Kind + " reader produced no data (no points) from " + in.Path);
  }

  if (!vtkCompositeDataSet::SafeDownCast(data) && !this->BlockNames.empty())
  {
    return fail(in.Path + " holds one dataset, not blocks: block selection (" + Join(this->BlockNames) +
      ") matches nothing");
  }

  // --- composite: select, then merge or prune
  if (vtkCompositeDataSet::SafeDownCast(data))
  {
    std::vector<Leaf> leaves;
    CollectLeaves(data, "", {}, leaves);
    for (const auto& leaf : leaves)
    {
      this->AvailableBlocks.push_back(leaf.Path);
    }
    auto describe = [&]() {
      std::vector<std::string> names;
      for (const auto& leaf : leaves)
      {
        if (LeafHasPoints(leaf.Data))
        {
          names.push_back(leaf.Path);
        }
      }
      return names.empty() ? std::string("(none)") : Join(names);
    };
    if (this->BlockNames.empty())
    {
      bool internalMesh = false;
      if (in.Kind == "openfoam")
      {
        for (auto& leaf : leaves)
        {
          if (!leaf.Names.empty() && leaf.Names.back() == "internalMesh" &&
            LeafHasPoints(leaf.Data))
          {
            leaf.Selected = internalMesh = true;
          }
        }
      }
      if (!internalMesh)
      {
        for (auto& leaf : leaves)
        {
          leaf.Selected = LeafHasPoints(leaf.Data);
        }
      }
    }
    else
    {
      for (const auto& wanted : this->BlockNames)
      {
        bool matched = false;
        for (auto& leaf : leaves)
        {
          const bool match = leaf.Path == wanted ||
            std::find(leaf.Names.begin(), leaf.Names.end(), wanted) != leaf.Names.end();
          if (match && LeafHasPoints(leaf.Data))
          {
            leaf.Selected = matched = true;
          }
        }
        if (!matched)
        {
          return fail("no block matched '" + wanted + "'; available blocks: " + describe());
        }
      }
    }
    std::vector<vtkDataSet*> selected;
    for (const auto& leaf : leaves)
    {
      if (leaf.Selected)
      {
        selected.push_back(vtkDataSet::SafeDownCast(leaf.Data));
      }
    }
    if (selected.empty())
    {
      return fail("the " + in.Kind + " reader produced no block with points from " + in.Path +
        "; available blocks: " + describe());
    }
    if (this->MergeBlocks)
    {
      if (selected.size() == 1)
      {
        data = selected[0];
      }
      else
      {
        vtkNew<vtkAppendFilter> append;
        append->MergePointsOff();
        for (vtkDataSet* ds : selected)
        {
          append->AddInputData(ds);
        }
        append->Update();
        data = append->GetOutputDataObject(0);
      }
    }
    else if (!this->BlockNames.empty())
    {
      auto* cds = vtkCompositeDataSet::SafeDownCast(data);
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(cds->NewIterator());
      std::vector<vtkDataObject*> keep(selected.begin(), selected.end());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        if (std::find(keep.begin(), keep.end(), it->GetCurrentDataObject()) == keep.end())
        {
          cds->SetDataSet(it, nullptr);
        }
      }
    }
  }

  // VTK's readers do not check connectivity or array lengths: every Plume filter and mapper
  // downstream would read out of bounds, so a dataset that lies is refused here.
  const std::string invalid = vtkPlumeInputValidation::CheckDataObject(data, true);
  if (!invalid.empty())
  {
    return fail("the " + in.Kind + " reader gave inconsistent data from " + in.Path + " (corrupt file?): " +
      invalid);
  }

  // Legacy STRUCTURED_POINTS comes as the old vtkStructuredPoints: hand out a plain image.
  if (data->IsA("vtkStructuredPoints"))
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->ShallowCopy(data);
    data = image;
  }

  // --- hand over
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  if (output && std::string(output->GetClassName()) == data->GetClassName())
  {
    output->ShallowCopy(data);
  }
  else
  {
    output = data;
    outInfo->Set(vtkDataObject::DATA_OBJECT(), data);
  }
  if (n > 0)
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), times[step]);
  }
  else
  {
    output->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
  }
  this->TimeStepRead = step;
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPlumeDatasetReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "QFileName: " << (this->QFileName ? this->QFileName : "(guessed)") << "\n";
  os << indent << "ReaderName: " << (this->ReaderName ? this->ReaderName : "(by extension)")
     << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "TimeValue: " << this->TimeValue << (this->UseTimeValue ? "" : " (unset)")
     << "\n";
  os << indent << "MergeBlocks: " << this->MergeBlocks << "\n";
  os << indent << "BlockNames: " << Join(this->BlockNames) << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
}

//------------------------------------------------------------------------------
const char* vtkPlumeDatasetReader::GetChildBlockName(vtkDataObject* parent, unsigned int i)
{
  vtkInformation* md = nullptr;
  if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(parent))
  {
    md = mb->HasMetaData(i) ? mb->GetMetaData(i) : nullptr;
  }
  else if (auto* pdc = vtkPartitionedDataSetCollection::SafeDownCast(parent))
  {
    md = pdc->HasMetaData(i) ? pdc->GetMetaData(i) : nullptr;
  }
  else if (auto* pd = vtkPartitionedDataSet::SafeDownCast(parent))
  {
    md = pd->HasMetaData(i) ? pd->GetMetaData(i) : nullptr;
  }
  if (md && md->Has(vtkCompositeDataSet::NAME()))
  {
    return md->Get(vtkCompositeDataSet::NAME());
  }
  return nullptr;
}
