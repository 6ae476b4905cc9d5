/**
 * @class   vtkPlumeVelocityLinesRepresentation
 * @brief   ParaView representation "Plume Velocity Lines": vtkPlumeVelocityGlyphMapper
 *
 * Velocity glyph lines and streamlets from a vector field on image data.
 * Other datasets are first resampled onto a ResampleDimensions image over
 * their bounds (vtkResampleToImage, as the plume command line does; nodes
 * outside the data get vtkValidPointMask = 0 and draw nothing).
 * The mapper is the proxy's "Mapper" subproxy (its properties are generated
 * from vtkPlumeVelocityGlyphMapper's parameter table).
 *
 * Colour: |v| through ParaView's colour map (LookupTable) over the colour
 * map's own range, so every rank colours alike. Without a colour map the
 * mapper's default (the data's speed range) is used.
 *
 * The automatic glyph scale (ScaleMode auto, the default) comes from the
 * robust maximum speed of all ranks' pieces together: RequestData computes
 * it with the global controller (vtkPlumeVelocityGlyphMapper::
 * ComputeRobustMaximumSpeed, exact; the seam nodes that pieces of one image
 * share count once) and sets the mapper's AutomaticScaleSpeed, so every
 * rank draws the same speed at the same length, as the serial run does.
 * Pieces resampled from other datasets, or several leaves merged on a rank,
 * count their own lattice nodes (approximate where pieces overlap).
 *
 * Roots: for image input, RequestData also gives the mapper the whole
 * image's extent (WholeExtent) and its moving nodes over all ranks
 * (ComputeMovingNodes, MovingNodeCount), so each rank picks the
 * screen-adaptive stride of the whole image and puts its roots on the whole
 * image's lattice: the ranks draw the glyphs of the serial render, at the
 * same automatic length (which follows the stride). Resampled pieces and
 * merged leaves choose their own roots.
 *
 * In parallel each rank draws the glyphs rooted in its piece; the lines are
 * opaque, so the ranks' images are composited by depth.
 */
#ifndef vtkPlumeVelocityLinesRepresentation_h
#define vtkPlumeVelocityLinesRepresentation_h

#include "PlumeParaViewRepresentationsModule.h" // For export macro
#include "vtkPlumeRepresentation.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkActor;
class vtkImageData;
class vtkPlumeVelocityGlyphMapper;
class vtkScalarsToColors;

class PLUMEPARAVIEWREPRESENTATIONS_EXPORT vtkPlumeVelocityLinesRepresentation
  : public vtkPlumeRepresentation
{
public:
  static vtkPlumeVelocityLinesRepresentation* New();
  vtkTypeMacro(vtkPlumeVelocityLinesRepresentation, vtkPlumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The mapper (the proxy's "Mapper" subproxy sets it). Default: one of its own. */
  void SetMapper(vtkPlumeVelocityGlyphMapper* mapper);
  vtkPlumeVelocityGlyphMapper* GetMapper();

  /** ParaView's colour map; nullptr: the mapper's own over the data's speed range. */
  void SetLookupTable(vtkScalarsToColors* lut);

  ///@{
  /** Grid for non-image input (resampled onto it). Default 64, 64, 64. */
  vtkSetVector3Macro(ResampleDimensions, int);
  vtkGetVector3Macro(ResampleDimensions, int);
  ///@}


protected:
  vtkPlumeVelocityLinesRepresentation();
  ~vtkPlumeVelocityLinesRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool PrepareRender(vtkDataObject* piece) override;
  /**
   * Sets the mapper's AutomaticScaleSpeed over all ranks' pieces (nodes of
   * `owned` only, if given) and, with `owned`, its MovingNodeCount.
   */
  void ReduceAutomaticScaleSpeed(const int* owned);

  vtkSmartPointer<vtkPlumeVelocityGlyphMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkScalarsToColors> LookupTable;
  int ResampleDimensions[3] = { 64, 64, 64 };

private:
  vtkPlumeVelocityLinesRepresentation(const vtkPlumeVelocityLinesRepresentation&) = delete;
  void operator=(const vtkPlumeVelocityLinesRepresentation&) = delete;
};

#endif
