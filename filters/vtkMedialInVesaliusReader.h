/// \class vtkMedialInVesaliusReader
/// \brief Reads the CT volume of an InVesalius 3 project (.inv3: a gzip-compressed tar holding
/// `main.plist` and the raw voxel matrix it names).
///
/// `main.plist` gives the matrix file, its numpy dtype (int16 for CT in Hounsfield units) and its shape
/// (slices, rows, columns), and the spacing (x, y, z) in mm. The matrix is raw little-endian, x fastest,
/// with rows flipped with respect to DICOM; the reader flips them back so that the volume is in DICOM's LPS
/// orientation (+y towards posterior, +z towards superior; checked on the Cranium sample: dental metal in
/// the first slices, the face at low y).
/// The origin is (0, 0, 0): the project does not store the scanner's. The project's masks and surfaces
/// are not read.
#pragma once

#include "vtkMedialImageFileReader.h"

class MEDIALFILTERS_EXPORT vtkMedialInVesaliusReader : public vtkMedialImageFileReader {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialInVesaliusReader* New();
  vtkTypeMacro(vtkMedialInVesaliusReader, vtkMedialImageFileReader);
  ///@}

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialInVesaliusReader() = default;
  ~vtkMedialInVesaliusReader() override = default;
  ///@}
  bool ReadImage(const std::string& path, vtkImageData* image, std::string& error) override;

 private:
  vtkMedialInVesaliusReader(const vtkMedialInVesaliusReader&) = delete;
  void operator=(const vtkMedialInVesaliusReader&) = delete;
};
