/// \class vtkMedialSWCWriter
/// \brief Writes a docs/ARCHITECTURE.md §4 skeleton polydata as SWC (`id type x y z radius parent`).
///
/// SWC stores forests: every component is written as a tree rooted at `Root` (or, for components without
/// it, at their lowest node id), ids 1-based in breadth-first order so that a parent precedes its
/// children. The type column comes from `SWCType` when present, else `DefaultType` (0, "undefined").
/// Errors (empty output file never left behind): no `Radius` array, invalid skeleton (docs/ARCHITECTURE.md
/// §4), or a cycle, which SWC cannot represent. The file is written to a temporary name and renamed on
/// success.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class vtkPolyData;

class MEDIALFILTERS_EXPORT vtkMedialSWCWriter : public vtkWriter {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSWCWriter* New();
  vtkTypeMacro(vtkMedialSWCWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to write.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// SWC type written for nodes without an `SWCType` value (default 0, undefined).
  vtkSetMacro(DefaultType, int);
  vtkGetMacro(DefaultType, int);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialSWCWriter() = default;
  ~vtkMedialSWCWriter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  ///@}
  /// Writes the input skeleton to FileName; false (with vtkErrorMacro) on failure.
  bool WriteSkeleton();

 private:
  vtkMedialSWCWriter(const vtkMedialSWCWriter&) = delete;
  void operator=(const vtkMedialSWCWriter&) = delete;

  std::string FileName;
  int DefaultType = 0;
};
