#include "vtkPlumeVortexSource.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>

vtkStandardNewMacro(vtkPlumeVortexSource);

vtkPlumeVortexSource::vtkPlumeVortexSource()
{
  this->SetNumberOfInputPorts(0);
}

namespace
{
void GridGeometry(const int dims[3], const double bounds[6], double origin[3], double spacing[3])
{
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = bounds[2 * a];
    const int n = std::max(dims[a], 1);
    // A single sample sits at the lower bound; its spacing is the full width
    // (or 1 for an empty range) so the image stays valid.
    const double width = bounds[2 * a + 1] - bounds[2 * a];
    spacing[a] = n > 1 ? width / (n - 1) : (width > 0 ? width : 1.0);
  }
}
}

int vtkPlumeVortexSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  for (int a = 0; a < 3; ++a)
  {
    if (this->Dimensions[a] < 1)
    {
      vtkErrorMacro("Dimensions must be at least 1 along every axis; got " << this->Dimensions[a]
                                                                           << " along axis " << a);
      return 0;
    }
  }
  if (!(this->CoreRadius > 0))
  {
    vtkErrorMacro("CoreRadius must be > 0; got " << this->CoreRadius);
    return 0;
  }
  double origin[3], spacing[3];
  GridGeometry(this->Dimensions, this->Bounds, origin, spacing);
  int extent[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
    this->Dimensions[2] - 1 };
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

void vtkPlumeVortexSource::Evaluate(const double x[3], double v[3]) const
{
  const double dx = x[0] - this->Center[0];
  const double dy = x[1] - this->Center[1];
  const double r2 = dx * dx + dy * dy;
  const double rc2 = this->CoreRadius * this->CoreRadius;
  const double g = std::exp(-r2 / rc2);
  // v_θ / r = Γ (1 − g) / (2π r²); its limit at r → 0 is Γ / (2π rc²).
  const double vtOverR = r2 > 1e-12 * rc2 ? this->Circulation * (1.0 - g) / (2.0 * M_PI * r2)
                                          : this->Circulation / (2.0 * M_PI * rc2);
  v[0] = -dy * vtOverR + this->Drift[0];
  v[1] = dx * vtOverR + this->Drift[1];
  v[2] = this->AxialVelocity * g + this->Drift[2];
}

void vtkPlumeVortexSource::ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo)
{
  vtkImageData* image = this->AllocateOutputData(output, outInfo);
  image->GetPointData()->SetScalars(nullptr); // the allocated placeholder scalars
  const int nx = this->Dimensions[0], ny = this->Dimensions[1], nz = this->Dimensions[2];
  const vtkIdType n = static_cast<vtkIdType>(nx) * ny * nz;

  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> speed;
  speed->SetName("speed");
  speed->SetNumberOfTuples(n);

  double origin[3], spacing[3];
  GridGeometry(this->Dimensions, this->Bounds, origin, spacing);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      const vtkIdType i = id % nx, j = (id / nx) % ny, k = id / (static_cast<vtkIdType>(nx) * ny);
      const double x[3] = { origin[0] + i * spacing[0], origin[1] + j * spacing[1],
        origin[2] + k * spacing[2] };
      double v[3];
      this->Evaluate(x, v);
      velocity->SetTypedTuple(id, std::array<float, 3>{ float(v[0]), float(v[1]), float(v[2]) }.data());
      speed->SetValue(id, static_cast<float>(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])));
    }
  });
  image->GetPointData()->SetVectors(velocity);
  image->GetPointData()->SetScalars(speed);
}

void vtkPlumeVortexSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "Circulation: " << this->Circulation << "\n";
  os << indent << "CoreRadius: " << this->CoreRadius << "\n";
  os << indent << "AxialVelocity: " << this->AxialVelocity << "\n";
}
