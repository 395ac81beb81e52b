/// \class vtkMedialSWCReader
/// \brief Reads an SWC skeleton (neuron morphology: `id type x y z radius parent` per line) into the
/// docs/ARCHITECTURE.md §4 skeleton polydata.
///
/// Output point data: `Radius`, `NodeType`, and `SWCType` (the file's type column, kept for round trips).
/// Field data `Root`: the first node whose parent is -1. Node ids of the file may be any integers; nodes are
/// numbered in file order. Lines starting with '#' are comments. A malformed line, a duplicate id, a parent
/// that names no node, or any docs/ARCHITECTURE.md §4 validation problem (NaN, non-positive radius,
/// self-loop) is an error naming the file and line; the output is then empty.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialSWCReader : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialSWCReader* New();
  vtkTypeMacro(vtkMedialSWCReader, vtkPolyDataAlgorithm);
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
  vtkMedialSWCReader();
  ~vtkMedialSWCReader() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialSWCReader(const vtkMedialSWCReader&) = delete;
  void operator=(const vtkMedialSWCReader&) = delete;

  std::string FileName;
};
