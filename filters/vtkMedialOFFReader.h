/// \class vtkMedialOFFReader
/// \brief Reads OFF meshes in all of their variants (OFF, COFF, NOFF, CNOFF, STOFF, binary) through
/// OpenMesh's reader into a vtkPolyData.
///
/// The faces are taken as the file lists them, without building a half-edge structure, so that
/// non-manifold or inconsistently oriented meshes arrive intact (the algorithms report or repair them;
/// a reader must not silently drop faces). Per-vertex colours become the `Colors` point array (RGB,
/// unsigned char), per-vertex normals the point normals. Comments ('#' to the end of a line, anywhere,
/// as CGAL's tools write them) are skipped. An unreadable file, an empty mesh, a file that ends before
/// the vertices and faces its header announces, or a face that refers to a missing vertex is an error
/// and leaves the output empty.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class MEDIALFILTERS_EXPORT vtkMedialOFFReader : public vtkPolyDataAlgorithm {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialOFFReader* New();
  vtkTypeMacro(vtkMedialOFFReader, vtkPolyDataAlgorithm);
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
  vtkMedialOFFReader();
  ~vtkMedialOFFReader() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  ///@}

 private:
  vtkMedialOFFReader(const vtkMedialOFFReader&) = delete;
  void operator=(const vtkMedialOFFReader&) = delete;

  std::string FileName;
};
