/**
 * @class   vtkPlumeDatasetReader
 * @brief   reads any CFD dataset format that VTK 9.1 reads, chosen by extension or by name
 *
 * A source (no inputs) that wraps the stock VTK readers behind one API:
 *
 * | reader name | extensions                                  | VTK reader                         |
 * |-------------|---------------------------------------------|------------------------------------|
 * | legacy      | .vtk                                        | vtkDataSetReader (all attributes)  |
 * | xml         | .vti .vts .vtr .vtu .vtp .vtm .pvt[istrp]*  | vtkXMLGenericDataObjectReader      |
 * | pvd         | .pvd                                        | own parser (vtkXMLDataParser) + xml|
 * | plot3d      | .xyz .q .bin                                | vtkMultiBlockPLOT3DReader          |
 * | exodus      | .ex2 .e .exo                                | vtkExodusIIReader (nodal + element arrays) |
 * | ensight     | .case                                       | vtkGenericEnSightReader            |
 * | openfoam    | .foam                                       | vtkOpenFOAMReader (cell-to-point on)|
 * | cgns        | .cgns                                       | vtkCGNSReader (all arrays)         |
 * | vrml        | .wrl                                        | vtkVRMLImporter (a block per actor)|
 *
 * PLOT3D: FileName is the grid (XYZ) file; the solution (Q) file is QFileName or, when that
 * is unset, guessed from the grid name (`combxyz.bin` -> `combq.bin`, `x.xyz` -> `x.q`). A
 * guessed Q file that does not exist is skipped (grid only). Format auto-detection is on;
 * scalar function 100 (density) and vector function 200 (velocity) are computed.
 *
 * Time: after UpdateInformation() (or Update()), GetTimeValues() lists the time values
 * (empty for a static dataset). The step read is, in order of precedence: the time a
 * downstream consumer requests through the pipeline (UPDATE_TIME_STEP, snapped to the nearest
 * step), SetTimeValue() (nearest step), SetTimeStep() (index). For `.pvd` the step selects the
 * file (several files with the same time are read as one multiblock).
 *
 * Composite results: with MergeBlocks on (default) the selected leaves are merged into ONE
 * dataset: a single selected leaf is passed as is (a structured grid stays a
 * vtkStructuredGrid, an image stays a vtkImageData), several are appended into a
 * vtkUnstructuredGrid (vtkAppendFilter; arrays missing in some leaf are dropped by the append).
 * The leaves are selected by BlockNames (a leaf matches if its own name, the name of one of
 * its ancestors, or its "/"-joined path equals a given name); by default every leaf with
 * points, except OpenFOAM, where the default is `internalMesh` only (the patches duplicate
 * boundary points). With MergeBlocks off the composite is output as the reader produces it
 * (still restricted to the named blocks when BlockNames is not empty).
 *
 * The output type is only certain after RequestData: for composite readers with MergeBlocks
 * on, the data object is replaced during RequestData by the merged dataset's type.
 *
 * Errors never crash: RequestInformation/RequestData return 0, and GetLastError() returns one
 * message naming the problem and the offending value (missing file and its path, unknown
 * extension and the supported ones, unknown reader name, reader produced no data, time step
 * out of range and the valid range, no block matched and the available names). The inner
 * readers' error events are captured into that message instead of being printed, and the
 * executive's "returned failure for request" dump is silenced.
 *
 * Progress: the inner readers' progress is forwarded as this algorithm's progress.
 */
#ifndef vtkPlumeDatasetReader_h
#define vtkPlumeDatasetReader_h

#include "PlumeDataModule.h" // For export macro
#include "vtkDataObjectAlgorithm.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class PLUMEDATA_EXPORT vtkPlumeDatasetReader : public vtkDataObjectAlgorithm
{
public:
  static vtkPlumeDatasetReader* New();
  vtkTypeMacro(vtkPlumeDatasetReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read (for OpenFOAM the `.foam` file in the case folder, for EnSight the
   * `.case` file, for PLOT3D the grid/XYZ file). Default nullptr (reading fails with
   * "no file name").
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * PLOT3D solution (Q) file. Default nullptr: guessed from FileName (`combxyz.bin` ->
   * `combq.bin`, `x.xyz` -> `x.q`). Ignored by the other readers.
   */
  vtkSetStringMacro(QFileName);
  vtkGetStringMacro(QFileName);
  ///@}

  ///@{
  /**
   * Reader to use: "" or nullptr = chosen by the file extension (default); otherwise one of
   * legacy, xml, pvd, plot3d, exodus, ensight, openfoam, cgns, vrml (see SupportedReaderNames()).
   */
  vtkSetStringMacro(ReaderName);
  vtkGetStringMacro(ReaderName);
  ///@}

  ///@{
  /**
   * Index of the time step to read, 0 = first. Default 0. Out of range fails with the valid
   * range. A static dataset has the single step 0. Setting it cancels SetTimeValue().
   */
  virtual void SetTimeStep(int step);
  vtkGetMacro(TimeStep, int);
  ///@}

  ///@{
  /**
   * Read the step whose time is nearest to `time` (instead of TimeStep). Default: unset
   * (TimeStep is used). A time outside [first, last] time value fails with the valid range.
   * UnsetTimeValue() goes back to TimeStep; GetUseTimeValue() tells whether it is set.
   */
  virtual void SetTimeValue(double time);
  vtkGetMacro(TimeValue, double);
  virtual void UnsetTimeValue();
  vtkGetMacro(UseTimeValue, bool);
  ///@}

  /**
   * Time values of the dataset, sorted ascending; empty for a static dataset. Filled by
   * UpdateInformation() / Update().
   */
  const std::vector<double>& GetTimeValues() const { return this->TimeValues; }
  /** Wrapping-friendly access to GetTimeValues(). */
  int GetNumberOfTimeValues() const { return static_cast<int>(this->TimeValues.size()); }
  double GetTimeValueAt(int i) const;

  /** Index of the step read by the last successful Update(); -1 before. */
  vtkGetMacro(TimeStepRead, int);

  ///@{
  /**
   * Merge a composite result into one dataset (see the class description). Default true.
   */
  vtkSetMacro(MergeBlocks, bool);
  vtkGetMacro(MergeBlocks, bool);
  vtkBooleanMacro(MergeBlocks, bool);
  ///@}

  ///@{
  /**
   * Read the formats that VTK 9.1 reads unsafely and no structural check
   * covers (HDF5 Exodus, EnSight, XML with inline arrays, PLOT3D with a
   * solution file, OpenFOAM, CGNS, VRML, legacy files that mention FIELD)
   * once in a forked child process before reading them here, so that a
   * reader crash on a corrupt file is one error in GetLastError() ("the
   * cgns reader crashed (signal 11, ...)")
   * instead of the end of the process; a reader that runs longer than
   * $PLUME_READER_TIMEOUT seconds (default 300) is stopped with an error too.
   * Each time step of a series is read in a child before it is read here
   * (once per step and reader), with the step and its time in the error.
   * Costs one more read of such files. Default true; the environment
   * variable PLUME_READER_ISOLATION=0 turns it off as well.
   */
  vtkSetMacro(IsolateReaders, bool);
  vtkGetMacro(IsolateReaders, bool);
  vtkBooleanMacro(IsolateReaders, bool);
  ///@}

  ///@{
  /**
   * Restrict a composite result to the named leaves (e.g. EnSight part "fluid", OpenFOAM
   * "internalMesh" or a patch name). Default: empty = every leaf with points (OpenFOAM:
   * internalMesh only). A selection that matches nothing fails with the available names.
   */
  void SetBlockNames(const std::vector<std::string>& names);
  void AddBlockName(const char* name);
  void ClearBlockNames();
  const std::vector<std::string>& GetBlockNames() const { return this->BlockNames; }
  int GetNumberOfBlockNames() const { return static_cast<int>(this->BlockNames.size()); }
  const char* GetBlockName(int i) const;
  ///@}

  /**
   * "/"-joined paths of the leaves of the last composite the inner reader produced, with the
   * leaf type and whether it was selected; empty for a non-composite result. Filled by Update().
   */
  const std::vector<std::string>& GetAvailableBlockNames() const { return this->AvailableBlocks; }

  /** The reader actually used by the last UpdateInformation()/Update() ("" before). */
  const std::string& GetResolvedReaderName() const { return this->ResolvedReader; }

  /** The message of the last failure, "" when the last update succeeded. */
  std::string GetLastError() const { return this->LastError; }

  /** File extensions recognised (lower case, with the dot), e.g. ".vtk". */
  static std::vector<std::string> SupportedExtensions();
  /** Reader names accepted by SetReaderName(). */
  static std::vector<std::string> SupportedReaderNames();
  /** Reader name for a file name's extension, "" if not recognised. */
  static std::string ReaderNameForFile(const std::string& fileName);
  /** The guessed PLOT3D Q file for a grid file (see QFileName). */
  static std::string GuessQFileName(const std::string& xyzFileName);
  /** Name of child `index` of a composite (its NAME() metadata), or nullptr if unnamed. */
  static const char* GetChildBlockName(vtkDataObject* parent, unsigned int index);

  vtkMTimeType GetMTime() override;

protected:
  vtkPlumeDatasetReader();
  ~vtkPlumeDatasetReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkExecutive* CreateDefaultExecutive() override;
  // Turns std::bad_alloc from VTK's readers (headers announcing more than memory holds) into
  // GetLastError() and a failed request.
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* QFileName = nullptr;
  char* ReaderName = nullptr;
  int TimeStep = 0;
  double TimeValue = 0.0;
  bool UseTimeValue = false;
  bool MergeBlocks = true;
  bool IsolateReaders = true;
  std::vector<std::string> BlockNames;

  std::vector<double> TimeValues;
  std::vector<std::string> AvailableBlocks;
  std::string ResolvedReader;
  std::string LastError;
  int TimeStepRead = -1;

private:
  vtkPlumeDatasetReader(const vtkPlumeDatasetReader&) = delete;
  void operator=(const vtkPlumeDatasetReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
  friend struct Internals;
};

#endif
