/// \class vtkMedialSkeletonValidator
/// \brief Checks that its input is a docs/ARCHITECTURE.md §4 skeleton and passes it through with `NodeType`
/// added.
///
/// Checks: only line cells (polylines are accepted and split into edges by later filters), finite
/// coordinates, one positive finite `Radius` per node when the array exists (required when RequireRadius
/// is on), a 9-component `EllipsoidAxes` when present, no self-loop edges, edge and `Root` ids in range.
/// On any problem: vtkErrorMacro listing the first problems, empty output. GetProblemCount() tells how
/// many were found.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class MEDIALFILTERS_EXPORT vtkMedialSkeletonValidator : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSkeletonValidator* New();
  vtkTypeMacro(vtkMedialSkeletonValidator, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// Whether a missing `Radius` array is a problem (default off: centerlines may come without one).
  vtkSetMacro(RequireRadius, bool);
  vtkGetMacro(RequireRadius, bool);
  vtkBooleanMacro(RequireRadius, bool);
  ///@}

  /// Problems found by the last update (0 when the skeleton is valid).
  vtkGetMacro(ProblemCount, int);

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSkeletonValidator() = default;
  ~vtkMedialSkeletonValidator() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialSkeletonValidator(const vtkMedialSkeletonValidator&) = delete;
  void operator=(const vtkMedialSkeletonValidator&) = delete;

  bool RequireRadius = false;
  int ProblemCount = 0;
};
