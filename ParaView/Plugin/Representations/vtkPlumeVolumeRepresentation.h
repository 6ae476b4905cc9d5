/**
 * @class   vtkPlumeVolumeRepresentation
 * @brief   ParaView representation "Plume Volume": vtkPlumeVolumeMapper on image data
 *
 * Behaves like ParaView's own "Volume" representation: the colour map
 * (LookupTable, a vtkColorTransferFunction) and the opacity editor's
 * function (ScalarOpacityFunction) go into the vtkVolumeProperty the mapper
 * reads, ColorArrayName picks the rendered point array. The opacity unit
 * distance is the mapper's own OpacityUnitDistance (default: one voxel, the
 * same in serial and over MPI ranks), not ParaView's ScalarOpacityUnitDistance,
 * whose default ParaView derives from the data in serial runs only. Not coloured by an array (ParaView colours by one on its own only
 * for the types it names "Volume" or "Slice", so a first Apply of "Plume
 * Volume" comes without), it renders the active point scalars with
 * ParaView's defaults for a volume: "Cool to Warm" and an opacity ramp from
 * 0 to 1 over the scalars' range over all MPI ranks (the global
 * controller's ranks, reduced in RequestData). The mapper itself is the proxy's "Mapper" subproxy (its properties
 * are generated from vtkPlumeVolumeMapper's parameter table).
 *
 * Input: vtkImageData, or a composite dataset whose leaves are images (each
 * rank renders its leaf; a rank with several leaves renders the first and
 * warns). Cells marked as ghosts are cropped away.
 *
 * In parallel each rank ray-casts its own piece and ParaView composites the
 * ranks' images in visibility order (ordered compositing): the
 * representation asks for it and reports its local bounds, which the render
 * view sorts front to back. The mapper writes premultiplied colour with
 * (ONE, ONE_MINUS_SRC_ALPHA), which is what the ordered "over" compositing
 * expects.
 */
#ifndef vtkPlumeVolumeRepresentation_h
#define vtkPlumeVolumeRepresentation_h

#include "PlumeParaViewRepresentationsModule.h" // For export macro
#include "vtkPlumeRepresentation.h"
#include "vtkNew.h"          // For vtkNew
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkColorTransferFunction;
class vtkImageData;
class vtkPiecewiseFunction;
class vtkPlumeVolumeMapper;
class vtkScalarsToColors;
class vtkVolume;
class vtkVolumeProperty;

class PLUMEPARAVIEWREPRESENTATIONS_EXPORT vtkPlumeVolumeRepresentation : public vtkPlumeRepresentation
{
public:
  static vtkPlumeVolumeRepresentation* New();
  vtkTypeMacro(vtkPlumeVolumeRepresentation, vtkPlumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The mapper (the proxy's "Mapper" subproxy sets it). Default: one of its own. */
  void SetMapper(vtkPlumeVolumeMapper* mapper);
  vtkPlumeVolumeMapper* GetMapper();


  /** ParaView's colour map (a vtkColorTransferFunction). */
  void SetLookupTable(vtkScalarsToColors* lut);
  /** ParaView's opacity function. */
  void SetScalarOpacity(vtkPiecewiseFunction* pwf);
  /** ColorArrayName: the point array rendered (other associations are ignored). */
  void SetInputArrayToProcess(int idx, int port, int connection, int fieldAssociation, const char* name) override;
  using Superclass::SetInputArrayToProcess;

  /** The vtkVolume drawn (tests). */
  vtkVolume* GetVolume();

protected:
  vtkPlumeVolumeRepresentation();
  ~vtkPlumeVolumeRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool PrepareRender(vtkDataObject* piece) override;

  vtkSmartPointer<vtkPlumeVolumeMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkColorTransferFunction> ColorMap;        // ParaView's, when coloured by an array
  vtkSmartPointer<vtkPiecewiseFunction> OpacityFunction;     // ParaView's
  vtkNew<vtkColorTransferFunction> DefaultColor;             // the look without an array
  vtkNew<vtkPiecewiseFunction> DefaultOpacity;
  double DefaultRange[2] = { 0, 0 };
  double ScalarRange[2] = { 1, 0 }; // the active scalars' range over all ranks; empty: min > max

  void ReduceScalarRange(vtkImageData* image);

  void ApplyDefaultLook(vtkImageData* image);

private:
  vtkPlumeVolumeRepresentation(const vtkPlumeVolumeRepresentation&) = delete;
  void operator=(const vtkPlumeVolumeRepresentation&) = delete;
};

#endif
