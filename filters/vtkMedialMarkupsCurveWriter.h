/// \class vtkMedialMarkupsCurveWriter
/// \brief Writes the polylines of a centerline as 3D Slicer markups curves (`.mrk.json`, Slicer 5's
/// markups schema v1.0.3), so that Slicer's Markups and VMTK modules take them as curves.
///
/// One markup of type "Curve" per polyline (a tree's branches, in order; a branch starts at its junction on
/// its parent), named Name ("Centerline"; branches "Centerline branch K"), with one control point per
/// polyline point and the point data `Radius` (and `Bridged`, 1 on a bridged gap) as per-control-point
/// measurements (`measurements[].controlPointValues`, as Slicer's Extract Centerline writes them), and the
/// curve's length. The coordinates are written as they are, labelled CoordinateSystem: "LPS" (the default)
/// is ITK's patient frame, which volumes read through ITK (DICOM, NIfTI, MetaImage, NRRD) have; "RAS" for
/// data known to be in Slicer's frame. Millimetres.
/// Errors (no file left behind): no input, no polyline, a file that cannot be written.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialMarkupsCurveWriter : public vtkWriter {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialMarkupsCurveWriter* New();
  vtkTypeMacro(vtkMedialMarkupsCurveWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to write.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}
  ///@{
  /// The first curve's name (default "Centerline"); further polylines are "NAME branch K".
  vtkSetStdStringFromCharMacro(Name);
  vtkGetCharFromStdStringMacro(Name);
  ///@}
  ///@{
  /// "LPS" (default) or "RAS": the frame the input's coordinates are in (written, not converted).
  vtkSetStdStringFromCharMacro(CoordinateSystem);
  vtkGetCharFromStdStringMacro(CoordinateSystem);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialMarkupsCurveWriter() = default;
  ~vtkMedialMarkupsCurveWriter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  ///@}

 private:
  vtkMedialMarkupsCurveWriter(const vtkMedialMarkupsCurveWriter&) = delete;
  void operator=(const vtkMedialMarkupsCurveWriter&) = delete;
  bool WriteCurves();

  std::string FileName;
  std::string Name = "Centerline";
  std::string CoordinateSystem = "LPS";
};
