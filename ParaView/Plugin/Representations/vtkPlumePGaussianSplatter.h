/**
 * @class   vtkPlumePGaussianSplatter
 * @brief   vtkPlumeGaussianSplatter over MPI ranks: one grid, the sum of every rank's splats
 *
 * What the "Plume Gaussian Splat" filter runs in ParaView. In serial it is
 * the splatter. With a controller of more than one process (pvbatch/pvserver
 * under mpirun), every rank splats the points and lines it holds into the
 * same global grid and the grids are combined (summed; maximum in
 * DISTANCE_MAX) with an all-reduce, so the field is the serial one: each
 * splat is a term of a sum, whichever rank holds it. Flow lines cut over
 * the ranks splat each vertex once (ghost cells and ghost points are left to
 * their owner, and a line ending where another rank's line starts continues
 * there: the ranks exchange their open lines' first vertices first).
 *
 * The global grid: the reference image's, or ModelBounds when valid, or (the
 * default) the union of the ranks' automatic bounds. The automatic bounds
 * are a min/max over the splats (each centre padded by its reach), so their
 * union is exactly the serial bounds; each rank finds its own with a splat
 * onto a 2x2x2 grid (cheap) and ranks holding no splat are left out.
 *
 * Output: the piece this rank is asked for (UPDATE_PIECE_NUMBER of
 * UPDATE_NUMBER_OF_PIECES, split by vtkExtentTranslator): the ranks' pieces
 * share their boundary planes and tile the grid, so a volume representation
 * integrates every ray segment once, as for an image read in slabs.
 *
 * Cost: the all-reduce moves the whole grid (4 or 12 bytes per node) on
 * every rank; the splatting itself is divided among the ranks.
 */
#ifndef vtkPlumePGaussianSplatter_h
#define vtkPlumePGaussianSplatter_h

#include "PlumeParaViewRepresentationsModule.h" // For export macro
#include "vtkPlumeGaussianSplatter.h"

class vtkMultiProcessController;

class PLUMEPARAVIEWREPRESENTATIONS_EXPORT vtkPlumePGaussianSplatter : public vtkPlumeGaussianSplatter
{
public:
  static vtkPlumePGaussianSplatter* New();
  vtkTypeMacro(vtkPlumePGaussianSplatter, vtkPlumeGaussianSplatter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The ranks to combine over. Default: the global controller (none: serial). */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkPlumePGaussianSplatter();
  ~vtkPlumePGaussianSplatter() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkMultiProcessController* Controller = nullptr;

private:
  vtkPlumePGaussianSplatter(const vtkPlumePGaussianSplatter&) = delete;
  void operator=(const vtkPlumePGaussianSplatter&) = delete;
};

#endif
