#include "vtkPlumeWholeInput.h"

#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

void plume::RequestWholeExtent(vtkInformation* inInfo)
{
  inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT());
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
}
