/// \class vtkMedialPolyDataWriter
/// \brief Writes a mesh or skeleton by extension: .vtp (binary, zlib), .vtk, .obj, .ply, .stl, .swc.
///
/// Atomic: the data goes to a temporary name in the same directory, renamed over FileName only once the
/// underlying writer has succeeded, so that a failure never leaves a partial file behind. Errors name the
/// file; Write() returns 0 on failure.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialPolyDataWriter : public vtkWriter {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialPolyDataWriter* New();
  vtkTypeMacro(vtkMedialPolyDataWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to write.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// Whether the extension of `fileName` is one this writer handles.
  static bool CanWriteFile(const char* fileName);
  static const char* GetExtensions() { return "*.vtp *.vtk *.obj *.ply *.stl *.swc"; }
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialPolyDataWriter() = default;
  ~vtkMedialPolyDataWriter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;
  ///@}

 private:
  vtkMedialPolyDataWriter(const vtkMedialPolyDataWriter&) = delete;
  void operator=(const vtkMedialPolyDataWriter&) = delete;
  bool WriteTo(const std::string& path, const std::string& extension);

  std::string FileName;
};
