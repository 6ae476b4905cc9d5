/**
 * @class   vtkPlumeCellCenteredImage
 * @brief   cell arrays as point arrays of an image whose points are the cell centres
 *
 * Renderers that sample point data (volume raycasting, glyph lattices,
 * contouring) cannot take finite-volume results (OpenFOAM, CGNS, a .vti with
 * cell arrays) as they are, and vtkCellDataToPointData averages cells into
 * their corner points, mixing boundary values into the cells next to the
 * boundary. This filter keeps every cell value exactly, as a point value:
 *
 * - vtkImageData input: the output has dimensions dims - 1 along each axis
 *   with cells (1 along an axis with one point), origin + spacing / 2 and the
 *   same spacing; point k of the output is cell k of the input (the same
 *   x-fastest order), so values are copied, not computed. Every cell appears
 *   once; the output spans the cell centres (half a spacing inside the input
 *   bounds on each side).
 * - any other vtkDataSet (composites: merge first): a lattice of cell centres
 *   over the input bounds whose sample takes the value of the cell containing
 *   it (vtkProbeFilter with the cell arrays only: no interpolation). When the
 *   cells are axis-aligned boxes of one size tiling the bounds (a uniform
 *   finite-volume mesh read as an unstructured grid, as OpenFOAM's blockMesh
 *   cases), the lattice is those cells' centres, and the result is again exact
 *   and complete. Otherwise it has MaximumDimension samples along the longest
 *   axis (others in proportion), at the centres of that many equal boxes, and
 *   the valid-point mask `vtkValidPointMask` marks samples outside the data.
 *
 * Point arrays of the input are not passed (they live on another grid). The
 * output's field data is the input's. Input without cell arrays is an error.
 */
#ifndef vtkPlumeCellCenteredImage_h
#define vtkPlumeCellCenteredImage_h

#include "PlumeDataModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

class PLUMEDATA_EXPORT vtkPlumeCellCenteredImage : public vtkImageAlgorithm
{
public:
  static vtkPlumeCellCenteredImage* New();
  vtkTypeMacro(vtkPlumeCellCenteredImage, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Samples along the longest axis when the input is not an image and its
   * cells are not one uniform lattice of boxes. Default 64; at least 1.
   */
  vtkSetClampMacro(MaximumDimension, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumDimension, int);
  ///@}

  /** Whether the last update kept every cell value exactly (an image, or a uniform box lattice). */
  vtkGetMacro(Exact, bool);

  /** Why the last update failed ("" if it did not), naming the problem. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkPlumeCellCenteredImage();
  ~vtkPlumeCellCenteredImage() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** The lattice for `input`: false (and LastError) if it has no cells or no cell arrays. */
  bool ComputeLattice(vtkDataObject* input, int dimensions[3], double origin[3], double spacing[3], bool& exact);

  int MaximumDimension = 64;
  bool Exact = false;
  std::string LastError;

private:
  vtkPlumeCellCenteredImage(const vtkPlumeCellCenteredImage&) = delete;
  void operator=(const vtkPlumeCellCenteredImage&) = delete;
};

#endif
