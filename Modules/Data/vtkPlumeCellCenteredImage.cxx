#include "vtkPlumeCellCenteredImage.h"

#include "vtkPlumeWholeInput.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkProbeFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkPlumeCellCenteredImage);

namespace
{
bool HasCellArrays(vtkDataSet* data)
{
  vtkCellData* cd = data->GetCellData();
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
  {
    if (cd->GetArray(i) && cd->GetArray(i)->GetName() &&
      std::string(cd->GetArray(i)->GetName()) != "vtkGhostType")
    {
      return true;
    }
  }
  return false;
}

/**
 * For cells that are equal axis-aligned boxes tiling the bounds: each cell's
 * lattice index (x fastest) in `slot`, and the lattice. False otherwise.
 */
bool BoxLattice(vtkDataSet* data, int dims[3], double origin[3], double spacing[3], std::vector<vtkIdType>* slot)
{
  const vtkIdType cells = data->GetNumberOfCells();
  double bounds[6];
  data->GetBounds(bounds);
  double first[6];
  data->GetCellBounds(0, first);
  vtkIdType total = 1;
  for (int a = 0; a < 3; ++a)
  {
    const double length = bounds[2 * a + 1] - bounds[2 * a];
    const double h = first[2 * a + 1] - first[2 * a];
    if (!(length >= 0) || !(h >= 0) || (h == 0) != (length == 0))
    {
      return false;
    }
    const double n = h > 0 ? length / h : 1.0;
    dims[a] = static_cast<int>(std::lround(n));
    if (dims[a] < 1 || std::abs(n - dims[a]) > 1e-6 * std::max(1.0, n) || dims[a] > (1 << 24))
    {
      return false;
    }
    spacing[a] = h > 0 ? h : 1.0;
    origin[a] = bounds[2 * a] + 0.5 * h;
    total *= dims[a];
  }
  if (total != cells)
  {
    return false;
  }
  std::vector<char> taken(static_cast<size_t>(cells), 0);
  if (slot)
  {
    slot->assign(static_cast<size_t>(cells), -1);
  }
  for (vtkIdType c = 0; c < cells; ++c)
  {
    double b[6];
    data->GetCellBounds(c, b);
    vtkIdType index = 0;
    vtkIdType stride = 1;
    for (int a = 0; a < 3; ++a)
    {
      const double h = first[2 * a + 1] - first[2 * a];
      if (std::abs((b[2 * a + 1] - b[2 * a]) - h) > 1e-6 * std::max(h, 1e-300))
      {
        return false; // another size: not one lattice
      }
      const double at = h > 0 ? (0.5 * (b[2 * a] + b[2 * a + 1]) - origin[a]) / h : 0.0;
      const long i = std::lround(at);
      if (std::abs(at - double(i)) > 1e-3 || i < 0 || i >= dims[a])
      {
        return false;
      }
      index += stride * i;
      stride *= dims[a];
    }
    if (taken[static_cast<size_t>(index)]++)
    {
      return false; // two cells in one box
    }
    if (slot)
    {
      (*slot)[static_cast<size_t>(c)] = index;
    }
  }
  return true;
}
}

vtkPlumeCellCenteredImage::vtkPlumeCellCenteredImage()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkPlumeCellCenteredImage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

bool vtkPlumeCellCenteredImage::ComputeLattice(
  vtkDataObject* object, int dims[3], double origin[3], double spacing[3], bool& exact)
{
  auto* input = vtkDataSet::SafeDownCast(object);
  exact = false;
  if (!input || input->GetNumberOfCells() == 0)
  {
    this->LastError = "cell-centred image: the input has no cells";
    return false;
  }
  if (!HasCellArrays(input))
  {
    this->LastError = "cell-centred image: the input has no cell arrays";
    return false;
  }
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    int d[3];
    image->GetDimensions(d);
    const double* o = image->GetOrigin();
    const double* s = image->GetSpacing();
    int extent[6];
    image->GetExtent(extent);
    for (int a = 0; a < 3; ++a)
    {
      dims[a] = std::max(1, d[a] - 1);
      spacing[a] = s[a];
      // cell i spans points i and i + 1 (an axis with one point: its one layer of cells)
      origin[a] = o[a] + (extent[2 * a] + (d[a] > 1 ? 0.5 : 0.0)) * s[a];
    }
    exact = true;
    return true;
  }
  if (BoxLattice(input, dims, origin, spacing, nullptr))
  {
    exact = true;
    return true;
  }
  double bounds[6];
  input->GetBounds(bounds);
  double longest = 0;
  for (int a = 0; a < 3; ++a)
  {
    longest = std::max(longest, bounds[2 * a + 1] - bounds[2 * a]);
  }
  for (int a = 0; a < 3; ++a)
  {
    const double length = bounds[2 * a + 1] - bounds[2 * a];
    if (!(longest > 0) || !(length > 1e-9 * longest))
    {
      dims[a] = 1;
      spacing[a] = 1;
      origin[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
      continue;
    }
    dims[a] = std::max(1, static_cast<int>(std::lround(length / longest * this->MaximumDimension)));
    spacing[a] = length / dims[a];
    origin[a] = bounds[2 * a] + 0.5 * spacing[a]; // centres of dims[a] equal boxes
  }
  return true;
}

int vtkPlumeCellCenteredImage::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // the lattice depends on the cells, which only the data knows: update the input now
  int upstreamPort = 0;
  vtkAlgorithm* upstream = this->GetInputAlgorithm(0, 0, upstreamPort);
  vtkDataObject* input = nullptr;
  if (upstream && upstream->GetExecutive()->Update(upstreamPort))
  {
    input = upstream->GetOutputDataObject(upstreamPort);
  }
  if (!input)
  {
    input = vtkDataObject::GetData(inputVector[0]->GetInformationObject(0));
  }
  int dims[3];
  double origin[3], spacing[3];
  bool exact = false;
  if (!input || !this->ComputeLattice(input, dims, origin, spacing, exact))
  {
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1;
  }
  const int extent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

int vtkPlumeCellCenteredImage::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // the whole input always (the output's extent is not in the input's index space)
  plume::RequestWholeExtent(inputVector[0]->GetInformationObject(0));
  return 1;
}

int vtkPlumeCellCenteredImage::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  this->Exact = false;
  int dims[3];
  double origin[3], spacing[3];
  bool exact = false;
  if (!this->ComputeLattice(input, dims, origin, spacing, exact))
  {
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  output->SetDimensions(dims);
  output->SetOrigin(origin);
  output->SetSpacing(spacing);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  const vtkIdType points = output->GetNumberOfPoints();
  vtkCellData* cells = input->GetCellData();

  std::vector<vtkIdType> slot;
  if (vtkImageData::SafeDownCast(input))
  {
    // point k of the output is cell k of the input: the arrays as they are
    for (int i = 0; i < cells->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = cells->GetArray(i);
      if (array && array->GetName() && std::string(array->GetName()) != "vtkGhostType" &&
        array->GetNumberOfTuples() == points)
      {
        output->GetPointData()->AddArray(array);
      }
    }
  }
  else if (exact && BoxLattice(input, dims, origin, spacing, &slot))
  {
    // each cell's value to its own lattice node (cells in any order)
    for (int i = 0; i < cells->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* array = cells->GetArray(i);
      if (!array || !array->GetName() || std::string(array->GetName()) == "vtkGhostType")
      {
        continue;
      }
      vtkSmartPointer<vtkDataArray> copy;
      copy.TakeReference(array->NewInstance());
      copy->SetName(array->GetName());
      copy->SetNumberOfComponents(array->GetNumberOfComponents());
      copy->SetNumberOfTuples(points);
      for (vtkIdType c = 0; c < static_cast<vtkIdType>(slot.size()); ++c)
      {
        copy->SetTuple(slot[static_cast<size_t>(c)], c, array);
      }
      output->GetPointData()->AddArray(copy);
    }
  }
  else
  {
    exact = false;
    // the value of the cell containing each sample: a probe of the cell arrays alone
    vtkSmartPointer<vtkDataSet> source;
    source.TakeReference(input->NewInstance());
    source->ShallowCopy(input);
    source->GetPointData()->Initialize();
    vtkNew<vtkImageData> lattice;
    lattice->SetDimensions(dims);
    lattice->SetOrigin(origin);
    lattice->SetSpacing(spacing);
    vtkNew<vtkProbeFilter> probe;
    probe->SetInputData(lattice);
    probe->SetSourceData(source);
    probe->SetValidPointMaskArrayName("vtkValidPointMask");
    probe->Update();
    vtkPointData* sampled = probe->GetOutput()->GetPointData();
    for (int i = 0; i < sampled->GetNumberOfArrays(); ++i)
    {
      if (sampled->GetArray(i))
      {
        output->GetPointData()->AddArray(sampled->GetArray(i));
      }
    }
  }
  // the first cell scalars/vectors stay the active ones
  if (cells->GetScalars() && cells->GetScalars()->GetName())
  {
    output->GetPointData()->SetActiveScalars(cells->GetScalars()->GetName());
  }
  if (cells->GetVectors() && cells->GetVectors()->GetName())
  {
    output->GetPointData()->SetActiveVectors(cells->GetVectors()->GetName());
  }
  this->Exact = exact;
  return 1;
}

void vtkPlumeCellCenteredImage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDimension: " << this->MaximumDimension << "\n";
  os << indent << "Exact: " << this->Exact << "\n";
}
