/// \class vtkMedialSketchReader
/// \brief Reads closed 2-D strokes for the sketch skeletonization (vtkMedialSketchSkeleton).
///
/// File format (.txt): one `x y` line per stroke point; parts are separated by blank lines; `#` starts a
/// comment. A part may end with four lines of four numbers, the row-major 4x4 matrix that places the
/// stroke's plane (x, y, 0) in 3-D (the identity when absent).
///
/// Output: a polydata with one closed polyline per part (its first point id repeated at the end; z = 0) and
/// cell data `Placement` (16 components, row-major). Values are not judged here (NaN is passed on for the
/// filter to report); a malformed line, a point after the matrix or an incomplete matrix is an error naming
/// the file and the line, and the output is then empty.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialSketchReader : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSketchReader* New();
  vtkTypeMacro(vtkMedialSketchReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSketchReader();
  ~vtkMedialSketchReader() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialSketchReader(const vtkMedialSketchReader&) = delete;
  void operator=(const vtkMedialSketchReader&) = delete;

  std::string FileName;
};
