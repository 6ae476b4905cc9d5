/**
 * @class   vtkPlumeFormatCheck
 * @brief   structural checks of file formats whose VTK readers crash on corrupt input
 *
 * Some of VTK 9.1's readers trust their files: the Exodus II reader indexes
 * its point array with the element connectivity as stored, so one flipped
 * bit in a `connect` variable is a segmentation fault, and a truncated file
 * reads as zeros. vtkPlumeDatasetReader runs these checks before handing a
 * file to such a reader. Each returns "" when the file is sound, else one
 * sentence naming the problem and the offending value.
 *
 * Covered: netCDF classic files (CDF-1, CDF-2 and CDF-5; Exodus II's format):
 * the header is parsed with every count bounded by the file length, every
 * variable's data must lie inside the file, and for Exodus II every
 * element connectivity entry (`connect*`) must name a node in
 * [1, num_nodes]. Exodus files stored as HDF5 (netCDF-4) are not checked.
 * EnSight Gold C-binary geometry: see CheckEnSightGold(). Legacy .vtk cell
 * lists: CheckLegacyVTK(). VTK XML appended data: CheckXMLAppended(). PLOT3D
 * grid headers: CheckPlot3DGrid(). The formats no check covers are read
 * once in a child process first: RunIsolated().
 */
#ifndef vtkPlumeFormatCheck_h
#define vtkPlumeFormatCheck_h

#include "PlumeDataModule.h"  // For export macro
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <functional> // For std::function
#include <string>     // For std::string

class PLUMEDATA_EXPORT VTK_WRAPEXCLUDE vtkPlumeFormatCheck
{
public:
  /**
   * "" if `path` is a sound netCDF classic file (or not a netCDF classic file
   * at all: HDF5-based files are left to their library); for Exodus II data
   * (a `num_nodes` dimension) also checks the element connectivity.
   */
  static std::string CheckNetCDFClassic(const std::string& path);

  /**
   * "" if the geometry file of an EnSight Gold case (C Binary, unstructured
   * parts) is sound: every part's coordinates and element blocks lie inside
   * the file and every element names a node of its part (VTK's reader reads
   * past the end of a cut file and indexes with corrupt ids: SEGV).
   * ASCII and Fortran-binary geometry, structured ("block") parts, `nfaced`
   * elements and time-series geometry (wildcards) are not checked ("").
   */
  static std::string CheckEnSightGold(const std::string& casePath);

  /**
   * "" if the cell sections (VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS,
   * CELLS) of a legacy .vtk file before version 5 hold as many values as
   * their header says: as integers in ASCII files, as bytes in binary ones.
   * VTK 9.1's legacy reader closes the file on a short or non-numeric cell
   * list and then reads on from it (SEGV; found by fuzzing). Version 5 files
   * (OFFSETS/CONNECTIVITY) are read safely by VTK and not checked here.
   */
  static std::string CheckLegacyVTK(const std::string& path);

  /**
   * "" if the grid header of a binary PLOT3D XYZ file, read with the layout
   * VTK's reader detected (byte order, Fortran byte counts, multi-grid, 2D,
   * precision, IBLANK), gives positive dimensions whose coordinates fit in
   * the file. VTK 9.1 sizes a memset from them unchecked (SEGV under ASan;
   * found by fuzzing).
   */
  /**
   * "" if every DataArray stored in the raw appended section of a VTK XML file
   * has its block header inside the file: for compressed data the block
   * count, block sizes and compressed sizes, which must fit the bytes that
   * follow and promise no more than zlib's best ratio (1032:1) allows; for
   * uncompressed data the byte count. VTK 9.1's parser trusts them (SEGV in
   * vtkXMLDataParser::ReadBlock, or tens of GB allocated; found by fuzzing).
   * Inline (base64) arrays are not checked.
   */
  static std::string CheckXMLAppended(const std::string& path);

  static std::string CheckPlot3DGrid(const std::string& path, bool bigEndian, bool byteCounts, bool multiGrid,
    bool twoDimensional, bool doublePrecision, bool iblanking);

  /**
   * Runs `read` in a forked child process and reports how it ended: "" when
   * it returned (what it returned, e.g. the reader's error, is passed back in
   * `result`), else one sentence: "crashed (signal 11, Segmentation
   * fault)", "ended the process (exit code 1)" or "did not finish within N s
   * (PLUME_READER_TIMEOUT)". For the formats whose corruptions no structural
   * check covers (HDF5 Exodus, ASCII EnSight, inline XML, PLOT3D Q,
   * OpenFOAM, CGNS, VRML): a reader crash becomes one clear error instead of
   * the end of the process. The child's output goes to /dev/null (the
   * in-process read prints the reader's messages once). `timeoutSeconds` <= 0
   * takes $PLUME_READER_TIMEOUT, default 300. When fork() fails the read is
   * not isolated and "" is returned.
   */
  static std::string RunIsolated(
    const std::function<std::string()>& read, std::string* result = nullptr, double timeoutSeconds = 0);

  /** The first bytes of `path` are a netCDF classic header ("CDF" + 1, 2 or 5). */
  static bool IsNetCDFClassic(const std::string& path);

  /**
   * True if a VTK XML file stores any DataArray inline (format="ascii" or
   * "binary"), which CheckXMLAppended() does not cover; scans the XML up to
   * the appended data section.
   */
  static bool HasInlineXMLData(const std::string& path);

  /**
   * True if the word "field" appears anywhere in `path`, in any case. VTK
   * 9.1's legacy readers dereference a null pointer when a FIELD section is
   * malformed (a bad header or array line, or a keyword that a failed number
   * read left in place), which no structural check short of a second parser
   * covers: files that may hold one are read once in a child process first.
   */
  static bool MayHoldLegacyFieldData(const std::string& path);
};

#endif
// VTK-HeaderTest-Exclude: vtkPlumeFormatCheck.h
