// plumeBenchFloorMapper: the cheapest frames a volume renderer could draw on
// this machine, for `plume bench volume`'s floor jobs (not a renderer).
//
// LatticeSize 0 draws one screen-filling quad of a constant premultiplied
// colour, blended over the frame (one trivial fragment per pixel). LatticeSize
// N > 0 first fills an N x N texture (one trivial fragment per texel, the
// stand-in for N^2 lattice rays that cost nothing) and then draws it over the
// screen rectangle of the volume's bounds with one bilinearly filtered quad,
// blended: what
// vtkFixedPointVolumeRayCastMapper's ImageSampleDistance > 1 does after its
// rays (vtkOpenGLRayCastImageDisplayHelper, an 8-bit texture).
#ifndef plumeBenchFloorMapper_h
#define plumeBenchFloorMapper_h

#include "vtkVolumeMapper.h"

#include <memory>

class plumeBenchFloorMapper : public vtkVolumeMapper
{
public:
  static plumeBenchFloorMapper* New();
  vtkTypeMacro(plumeBenchFloorMapper, vtkVolumeMapper);

  /** The lattice texture's size (0: no texture, a constant quad). Default 0. */
  vtkSetMacro(LatticeSize, int);
  /** Its channels' bits: 8 (unsigned normalised, the fixed-point mapper's), 16 or 32 (float). Default 8. */
  vtkSetMacro(Bits, int);

  /** The fraction of the viewport the last render's quad covered. */
  vtkGetMacro(LastCoverage, double);

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  plumeBenchFloorMapper();
  ~plumeBenchFloorMapper() override;

private:
  plumeBenchFloorMapper(const plumeBenchFloorMapper&) = delete;
  void operator=(const plumeBenchFloorMapper&) = delete;

  int LatticeSize = 0;
  int Bits = 8;
  double LastCoverage = 0;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
